// The scene format, declared once: every key a scene file may hold (docs/scene-format.md),
// with its object, JSON type, unit, meaning, default and allowed words, in one table.
// The loader (scene_mapping.cpp) reads a file's keys by it and refuses the others with
// "did you mean"; the writer writes them by it; the scene editor shows and edits them by
// it (units, meanings, choices); the exercises and the lesson catalogue read a scene's
// JSON by it. docs/scene.schema.json must declare the same keys, types, required keys,
// words and defaults, and a left-out key must load as its default (tst_scene_format);
// docs/scene-format.md's key tables list the same keys, required keys, defaults and
// units (tst_scene_format_doc); no other file of app/ spells a key or a word
// (tst_scene_keys). The enumerations' words themselves are the physics'
// (physics/engine/scene_words.h); words() and word() give them as QStrings.
//
// Adding a key: the field in physics/engine/scene.h and its rule in validate(); its
// row here (and its Key); its reading in scene_mapping.cpp, its writing and comparison
// in scene_writer.cpp, its value in the editor (scene_editor_values.cpp); the schema;
// its row in docs/scene-format.md's table of its object.
#pragma once

#include "physics/engine/inertia.h"
#include "physics/engine/scene.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <span>

namespace rbw::sceneformat {

// The JSON objects of a scene file; each key belongs to one.
enum class Section { Scene, EnergyJump, Body, Orientation, Force, Torque, Push, Probe, Plane, Pair };

// Every key, as code names it; a row of the table each (row(), key()).
enum class Key {
    // the top level, in the order the loader lists them
    Name, Description, Dt, Steps, Integrator, InertiaConvention, Gravity, Bodies, Forces, Torques, Push, Probes,
    Planes, BoxCollisions, Restitution, RestitutionThreshold, Friction, Pairs, PositionCorrection, PlaneContacts,
    EnergyJump, ContactModel, SolverIterations, Sleep, PositionFix, Solver, Substeps,
    EnergyJumpFactor, EnergyJumpFloor,
    BodyName, BodySize, BodyMass, BodyFixed, BodyPosition, BodyOrientation, BodyLinearVelocity, BodyAngularVelocity,
    BodyAngularResponse, BodyIntegrator, BodyInertiaConvention,
    OrientationAxis, OrientationDegrees, OrientationRadians, OrientationQuaternion,
    ForceBody, ForcePoint, ForceForce, ForceFromStep, ForceToStep,
    TorqueBody, TorqueTorque, TorqueFromStep, TorqueToStep, TorqueSwitchable, TorqueEnabled,
    PushBody, PushPoint, PushForce,
    ProbeBody, ProbePoint,
    PlaneName, PlanePoint, PlaneNormal,
    PairBodies, PairRestitution, PairFriction,
};

// A value's JSON form.
enum class Type {
    Number,        // a finite number
    Integer,       // a whole number
    String,
    Boolean,
    Vector,        // [x, y, z]
    Quaternion,    // [w, x, y, z], scalar first
    Word,          // a string, one of the key's words (choices())
    BodyRef,       // the name of a body
    NamePair,      // [body, body or plane]
    Object,        // a JSON object (its keys: another Section)
    List,          // an array of objects
};

// The words a Word key allows (and the integrators a string names).
enum class Choices { None, Integrator, InertiaConvention, PlaneContacts, ContactModel, PositionFix, ManifoldSolver };

struct KeyRow {
    Key id;
    Section section;
    const char* name;        // the JSON key
    Type type;
    Choices choices;
    bool required;
    const char* unit;        // SI, "" for none
    const char* fallback;    // the value when left out, as JSON text; "" when none or not JSON (the meaning says)
    const char* meaning;     // one line, as the scene editor shows it
    Section object;          // Type Object and List: the section of its (elements') keys
};

// The table, in the order of the Key enumeration.
std::span<const KeyRow> rows();
const KeyRow& row(Key k);
// The JSON key of k ("mass").
QString key(Key k);
// The keys of one object, in the table's order (the loader's "allowed" list).
QStringList keysOf(Section s);
// The row of a key in a section; nullptr if the section has no such key.
const KeyRow* find(Section s, const QString& name);

// The words of a choice, in the order of its enumeration (an enum's value is its index).
QStringList words(Choices c);
// "\"a\" or \"b\"", "\"a\", \"b\" or \"c\"": the words for a message; `last`, when
// given, is added unquoted as the last choice ("(default)").
QString choiceText(const QStringList& words, const QString& last = QString());

// An enumeration's word, and back (nullopt for a word that is none of them).
QString word(InertiaConvention v);
QString word(PlaneContactMode v);
QString word(ContactModel v);
QString word(PositionFix v);
QString word(ManifoldSolver v);
template <typename E>
std::optional<E> fromWord(const QString& w);

} // namespace rbw::sceneformat
