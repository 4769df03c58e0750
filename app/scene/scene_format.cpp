#include "app/scene/scene_format.h"

#include "physics/engine/integrator_registry.h"
#include "physics/engine/scene_words.h"

#include <array>
#include <cassert>

namespace rbw::sceneformat {
namespace {

using S = Section;
using T = Type;
using C = Choices;
using K = Key;

// Each key once. The meanings are the scene editor's one-line tooltips; the long
// explanations are docs/scene-format.md's. Defaults are JSON text where JSON can say them.
constexpr std::array kRows{
    // the top level
    KeyRow{K::Name, S::Scene, "name", T::String, C::None, false, "", "", "title of the scene; unique name of a body or plane", S::Scene},
    KeyRow{K::Description, S::Scene, "description", T::String, C::None, false, "", "\"\"", "one-line summary", S::Scene},
    KeyRow{K::Dt, S::Scene, "dt", T::Number, C::None, true, "s", "", "time step h; > 0", S::Scene},
    KeyRow{K::Steps, S::Scene, "steps", T::Integer, C::None, false, "", "1", "steps `rbw run` takes; 0 \u2026 10^9", S::Scene},
    KeyRow{K::Integrator, S::Scene, "integrator", T::Word, C::Integrator, false, "", "\"explicit-euler\"", "integration method (rbw integrators)", S::Scene},
    KeyRow{K::InertiaConvention, S::Scene, "inertia_convention", T::Word, C::InertiaConvention, false, "", "\"standard\"",
           "standard: I\u207b\u00b9 = R I0\u207b\u00b9 R\u1d40; course-template: R\u1d40 I0\u207b\u00b9 R", S::Scene},
    KeyRow{K::Gravity, S::Scene, "gravity", T::Vector, C::None, false, "m/s\u00b2", "[0, 0, 0]", "gravitational acceleration g, world frame", S::Scene},
    KeyRow{K::Bodies, S::Scene, "bodies", T::List, C::None, true, "", "", "the rigid boxes; at least one", S::Body},
    KeyRow{K::Forces, S::Scene, "forces", T::List, C::None, false, "", "[]", "external forces at world points", S::Force},
    KeyRow{K::Torques, S::Scene, "torques", T::List, C::None, false, "", "[]", "pure couples on a body", S::Torque},
    KeyRow{K::Push, S::Scene, "push", T::Object, C::None, false, "", "", "the keyboard push; none: no pushes", S::Push},
    KeyRow{K::Probes, S::Scene, "probes", T::List, C::None, false, "", "[]", "points fixed to a body", S::Probe},
    KeyRow{K::Planes, S::Scene, "planes", T::List, C::None, false, "", "[]", "fixed planes: ground and walls", S::Plane},
    KeyRow{K::BoxCollisions, S::Scene, "box_collisions", T::Boolean, C::None, false, "", "true", "boxes collide with each other", S::Scene},
    KeyRow{K::Restitution, S::Scene, "restitution", T::Number, C::None, false, "", "1", "coefficient of restitution c, 0 \u2026 1", S::Scene},
    KeyRow{K::RestitutionThreshold, S::Scene, "restitution_threshold", T::Number, C::None, false, "m/s", "0",
           "approaches slower than this do not bounce; 0 is off", S::Scene},
    KeyRow{K::Friction, S::Scene, "friction", T::Number, C::None, false, "", "0", "Coulomb friction coefficient \u03bc \u2265 0", S::Scene},
    KeyRow{K::Pairs, S::Scene, "pairs", T::List, C::None, false, "", "[]", "restitution and friction of one pair", S::Pair},
    KeyRow{K::PositionCorrection, S::Scene, "position_correction", T::Boolean, C::None, false, "", "false",
           "push penetrating bodies apart after the impulses", S::Scene},
    KeyRow{K::PlaneContacts, S::Scene, "plane_contacts", T::Word, C::PlaneContacts, false, "", "\"per-point\"",
           "per-point: one impulse per corner; average: one at their mean", S::Scene},
    KeyRow{K::EnergyJump, S::Scene, "energy_jump", T::Object, C::None, false, "", "", "the blow-up bound", S::EnergyJump},
    KeyRow{K::ContactModel, S::Scene, "contact_model", T::Word, C::ContactModel, false, "", "\"course\"",
           "course: one impulse per contact point; manifold: manifolds and an iterative solver", S::Scene},
    KeyRow{K::SolverIterations, S::Scene, "solver_iterations", T::Integer, C::None, false, "", "",
           "manifold model: velocity iterations (empty: the default)", S::Scene},
    KeyRow{K::Sleep, S::Scene, "sleep", T::Boolean, C::None, false, "", "", "manifold model: bodies at rest sleep", S::Scene},
    KeyRow{K::PositionFix, S::Scene, "position_fix", T::Word, C::PositionFix, false, "", "", "manifold model: how overlap is removed", S::Scene},
    KeyRow{K::Solver, S::Scene, "solver", T::Word, C::ManifoldSolver, false, "", "",
           "manifold model: sequential impulses or the soft step (substeps, soft contacts)", S::Scene},
    KeyRow{K::Substeps, S::Scene, "substeps", T::Integer, C::None, false, "", "",
           "soft step: substeps per step, 1 to 64 (empty: the default)", S::Scene},
    // energy_jump
    KeyRow{K::EnergyJumpFactor, S::EnergyJump, "factor", T::Number, C::None, false, "", "10", "blow-up bound: 0 (off) or \u2265 1", S::Scene},
    KeyRow{K::EnergyJumpFloor, S::EnergyJump, "floor", T::Number, C::None, false, "J", "1e-09", "blow-up bound floor, \u2265 0", S::Scene},
    // a body
    KeyRow{K::BodyName, S::Body, "name", T::String, C::None, true, "", "", "title of the scene; unique name of a body or plane", S::Scene},
    KeyRow{K::BodySize, S::Body, "size", T::Vector, C::None, true, "m", "", "edge lengths a, b, c along body x, y, z", S::Scene},
    KeyRow{K::BodyMass, S::Body, "mass", T::Number, C::None, false, "kg", "", "M > 0 (a fixed body has none)", S::Scene},
    KeyRow{K::BodyFixed, S::Body, "fixed", T::Boolean, C::None, false, "", "false", "infinite mass: never moves", S::Scene},
    KeyRow{K::BodyPosition, S::Body, "position", T::Vector, C::None, false, "m", "[0, 0, 0]", "centre of mass at t = 0", S::Scene},
    KeyRow{K::BodyOrientation, S::Body, "orientation", T::Object, C::None, false, "", "",
           "unit quaternion w, x, y, z (body \u2192 world) at t = 0; normalised", S::Orientation},
    KeyRow{K::BodyLinearVelocity, S::Body, "linear_velocity", T::Vector, C::None, false, "m/s", "[0, 0, 0]", "v at t = 0", S::Scene},
    KeyRow{K::BodyAngularVelocity, S::Body, "angular_velocity", T::Vector, C::None, false, "rad/s", "[0, 0, 0]",
           "\u03c9 at t = 0, world frame", S::Scene},
    KeyRow{K::BodyAngularResponse, S::Body, "angular_response", T::Boolean, C::None, false, "", "true",
           "off: in collisions a particle (L never changes)", S::Scene},
    KeyRow{K::BodyIntegrator, S::Body, "integrator", T::Word, C::Integrator, false, "", "", "integration method (rbw integrators)", S::Scene},
    KeyRow{K::BodyInertiaConvention, S::Body, "inertia_convention", T::Word, C::InertiaConvention, false, "", "",
           "standard: I\u207b\u00b9 = R I0\u207b\u00b9 R\u1d40; course-template: R\u1d40 I0\u207b\u00b9 R", S::Scene},
    // an orientation: an axis with degrees or radians, or a quaternion
    KeyRow{K::OrientationAxis, S::Orientation, "axis", T::Vector, C::None, false, "", "", "rotation axis, not zero", S::Scene},
    KeyRow{K::OrientationDegrees, S::Orientation, "degrees", T::Number, C::None, false, "\u00b0", "", "angle about the axis", S::Scene},
    KeyRow{K::OrientationRadians, S::Orientation, "radians", T::Number, C::None, false, "rad", "", "angle about the axis", S::Scene},
    KeyRow{K::OrientationQuaternion, S::Orientation, "quaternion", T::Quaternion, C::None, false, "", "",
           "[w, x, y, z], scalar first; not all zero", S::Scene},
    // a force
    KeyRow{K::ForceBody, S::Force, "body", T::BodyRef, C::None, true, "", "", "the body it acts on", S::Scene},
    KeyRow{K::ForcePoint, S::Force, "point", T::Vector, C::None, true, "m", "", "world point at t = 0", S::Scene},
    KeyRow{K::ForceForce, S::Force, "force", T::Vector, C::None, true, "N", "", "force f, world frame", S::Scene},
    KeyRow{K::ForceFromStep, S::Force, "from_step", T::Integer, C::None, false, "", "0", "first step in which it acts", S::Scene},
    KeyRow{K::ForceToStep, S::Force, "to_step", T::Integer, C::None, false, "", "", "first step in which it no longer acts", S::Scene},
    // a torque
    KeyRow{K::TorqueBody, S::Torque, "body", T::BodyRef, C::None, true, "", "", "the body it acts on", S::Scene},
    KeyRow{K::TorqueTorque, S::Torque, "torque", T::Vector, C::None, true, "N m", "", "torque q, world frame", S::Scene},
    KeyRow{K::TorqueFromStep, S::Torque, "from_step", T::Integer, C::None, false, "", "0", "first step in which it acts", S::Scene},
    KeyRow{K::TorqueToStep, S::Torque, "to_step", T::Integer, C::None, false, "", "", "first step in which it no longer acts", S::Scene},
    KeyRow{K::TorqueSwitchable, S::Torque, "switchable", T::Boolean, C::None, false, "", "false", "the K key turns it off and on", S::Scene},
    KeyRow{K::TorqueEnabled, S::Torque, "enabled", T::Boolean, C::None, false, "", "true", "on at the start", S::Scene},
    // the push
    KeyRow{K::PushBody, S::Push, "body", T::BodyRef, C::None, true, "", "", "the body it acts on", S::Scene},
    KeyRow{K::PushPoint, S::Push, "point", T::Vector, C::None, false, "m", "[0, 0, 0]", "point of application, body frame", S::Scene},
    KeyRow{K::PushForce, S::Push, "force", T::Number, C::None, false, "N", "1", "magnitude of the push, > 0", S::Scene},
    // a probe
    KeyRow{K::ProbeBody, S::Probe, "body", T::BodyRef, C::None, true, "", "", "the body it acts on", S::Scene},
    KeyRow{K::ProbePoint, S::Probe, "point", T::Vector, C::None, true, "m", "", "world point at t = 0", S::Scene},
    // a plane
    KeyRow{K::PlaneName, S::Plane, "name", T::String, C::None, true, "", "", "title of the scene; unique name of a body or plane", S::Scene},
    KeyRow{K::PlanePoint, S::Plane, "point", T::Vector, C::None, true, "m", "", "world point at t = 0", S::Scene},
    KeyRow{K::PlaneNormal, S::Plane, "normal", T::Vector, C::None, true, "", "", "towards the free side; normalised", S::Scene},
    // a pair
    KeyRow{K::PairBodies, S::Pair, "bodies", T::NamePair, C::None, true, "", "", "a body, and a body or a plane", S::Scene},
    KeyRow{K::PairRestitution, S::Pair, "restitution", T::Number, C::None, false, "", "", "coefficient of restitution c, 0 \u2026 1", S::Scene},
    KeyRow{K::PairFriction, S::Pair, "friction", T::Number, C::None, false, "", "", "Coulomb friction coefficient \u03bc \u2265 0", S::Scene},
};

// The table is in the order of Key: row(k) is kRows[k].
constexpr bool inKeyOrder()
{
    for (std::size_t i = 0; i < kRows.size(); ++i) {
        if (static_cast<std::size_t>(kRows[i].id) != i) return false;
    }
    return true;
}
static_assert(inKeyOrder(), "kRows must list the keys in the order of enum Key");

} // namespace

std::span<const KeyRow> rows() { return kRows; }

const KeyRow& row(Key k) { return kRows[static_cast<std::size_t>(k)]; }

QString key(Key k) { return QString::fromLatin1(row(k).name); }

QStringList keysOf(Section s)
{
    QStringList keys;
    for (const KeyRow& r : kRows) {
        if (r.section == s) keys << QString::fromLatin1(r.name);
    }
    return keys;
}

const KeyRow* find(Section s, const QString& name)
{
    for (const KeyRow& r : kRows) {
        if (r.section == s && name == QLatin1String(r.name)) return &r;
    }
    return nullptr;
}

namespace {

QStringList wordList(std::span<const std::string_view> words)
{
    QStringList list;
    for (std::string_view w : words) list << QString::fromLatin1(w.data(), static_cast<qsizetype>(w.size()));
    return list;
}

} // namespace

QStringList words(Choices c)
{
    switch (c) {
    case Choices::None: return {};
    case Choices::Integrator: {
        QStringList names;
        for (const IntegratorInfo& i : integratorCatalogue()) names << QString::fromLatin1(i.name);
        return names;
    }
    // The enumerations' own words, in their order (physics/engine/scene_words.h).
    case Choices::InertiaConvention: return wordList(kInertiaConventionWords);
    case Choices::PlaneContacts: return wordList(kPlaneContactWords);
    case Choices::ContactModel: return wordList(kContactModelWords);
    case Choices::PositionFix: return wordList(kPositionFixWords);
    case Choices::ManifoldSolver: return wordList(kManifoldSolverWords);
    }
    return {};
}

QString choiceText(const QStringList& words, const QString& last)
{
    QStringList parts;
    for (const QString& w : words) parts << QStringLiteral("\"%1\"").arg(w);
    if (!last.isEmpty()) parts << last;
    if (parts.size() < 2) return parts.join(QString());
    return parts.mid(0, parts.size() - 1).join(QStringLiteral(", ")) + QStringLiteral(" or ") + parts.last();
}

namespace {

template <typename E>
constexpr Choices choicesOf();
template <>
constexpr Choices choicesOf<InertiaConvention>() { return Choices::InertiaConvention; }
template <>
constexpr Choices choicesOf<PlaneContactMode>() { return Choices::PlaneContacts; }
template <>
constexpr Choices choicesOf<ContactModel>() { return Choices::ContactModel; }
template <>
constexpr Choices choicesOf<PositionFix>() { return Choices::PositionFix; }
template <>
constexpr Choices choicesOf<ManifoldSolver>() { return Choices::ManifoldSolver; }

template <typename E>
QString wordOf(E v)
{
    return words(choicesOf<E>()).value(static_cast<int>(v));
}

} // namespace

QString word(InertiaConvention v) { return wordOf(v); }
QString word(PlaneContactMode v) { return wordOf(v); }
QString word(ContactModel v) { return wordOf(v); }
QString word(PositionFix v) { return wordOf(v); }
QString word(ManifoldSolver v) { return wordOf(v); }

template <typename E>
std::optional<E> fromWord(const QString& w)
{
    const qsizetype i = words(choicesOf<E>()).indexOf(w);
    if (i < 0) return std::nullopt;
    return static_cast<E>(i);
}

template std::optional<InertiaConvention> fromWord<InertiaConvention>(const QString&);
template std::optional<PlaneContactMode> fromWord<PlaneContactMode>(const QString&);
template std::optional<ContactModel> fromWord<ContactModel>(const QString&);
template std::optional<PositionFix> fromWord<PositionFix>(const QString&);
template std::optional<ManifoldSolver> fromWord<ManifoldSolver>(const QString&);

} // namespace rbw::sceneformat
