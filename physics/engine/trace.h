// The trace: the named intermediate quantities of one step, in the order they were
// computed. It is the one source of truth for every view: the app's panels and
// derivations, the CLI's JSON and CSV, the plots and the exports all read it.
//
// An entry points at a static QuantityInfo (id, symbol, formula, frame, unit, stage,
// index kind; see quantity_catalogue.h) and carries the body, an optional index
// (which force, which probe, which contact), the value and the source location of
// the physics statement that computed it (a std::source_location captured by the
// record call, which sits on the line that computes the value). Recording therefore
// costs a push_back of a small struct and never allocates a string; with the trace
// switched off (a null StepTrace*) nothing is recorded at all.
#pragma once

#include "physics/engine/diagnostics.h"
#include "physics/engine/math_types.h"

#include <source_location>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace rbw {

// The groups of a step's trace entries (views order their groups by this); which stage
// of the pipeline runs when: stages/pipeline_builder.cpp.
enum class Stage { Forces, Integration, Collision, Correction, Probes };
enum class Frame { None, World, Body };

const char* stageName(Stage s);   // "forces", "integration", ...
const char* frameName(Frame f);   // "", "world", "body"

// What an entry's index counts: which applied force f_i, which couple q_j, which
// probe, which contact, which RK stage k_i, which correction; None: no index (-1).
enum class IndexKind { None, Force, Torque, Probe, Contact, RkStage, Correction };
const char* indexKindName(IndexKind k);   // "", "force", "torque", "probe", ...

struct QuantityInfo {
    const char* key;       // unique in the catalogue: the C++ handle's name, e.g. "rk4_position"
    const char* id;        // the trace id, shared by a quantity's variants, e.g. "position"
    const char* name;      // plain English display name, one per id, e.g. "kinetic energy after"
    Stage stage;
    IndexKind indexKind;
    const char* symbol;    // LaTeX, e.g. "\\boldsymbol{\\omega}"
    const char* text;      // plain UTF-8 symbol for tables, e.g. "ω"
    const char* formula;   // LaTeX, e.g. "\\boldsymbol{\\omega} = I^{-1}\\mathbf{L}"
    Frame frame;
    const char* unit;      // UTF-8, e.g. "rad/s"
};

// A scalar, a 3-vector, a quaternion ([w, x, y, z] when written out) or a 3x3 matrix.
using TraceValue = std::variant<double, Vec3, Quat, Mat3>;

// Its numbers in one order: a scalar as itself, a vector as (x, y, z), a quaternion as
// (w, x, y, z) (the one order, math_types.h), a matrix row by row (9 numbers). What the
// checker compares, the plots draw and the tests read.
std::vector<double> traceValueComponents(const TraceValue& value);

struct TraceEntry {
    const QuantityInfo* info;
    int body;     // index into the world's bodies, -1 for a world-level quantity
    int index;    // which force / probe / contact, -1 when there is only one
    TraceValue value;
    std::source_location where;   // the physics statement that computed the value
};

// Where an entry was computed: the file relative to the repository root (e.g.
// "physics/engine/integrators/explicit_euler.cpp") and the line; sourceText gives "file:line".
std::string_view sourceFile(const TraceEntry& e);
unsigned sourceLine(const TraceEntry& e);
std::string sourceText(const TraceEntry& e);

// One velocity iteration of the manifold model at a contact point: the accumulated
// impulses after it (contact_solver.h). The last equals the contact's normal_impulse and
// tangent_impulse entries; the first iteration starts from the warm-start values.
struct ImpulseIterate {
    double lambda_n = 0.0;              // [N s]
    Vec3 lambda_t_W = Vec3::Zero();     // lambda_t1 t1 + lambda_t2 t2, world frame [N s]
};

// What a contact is, beside its numbers (which are entries of Stage::Collision whose
// index is the contact's number).
struct ContactHeader {
    int bodyA = -1;
    int bodyB = -1;            // -1 when B is a plane
    int plane = -1;            // index into SceneDef::planes, or -1
    const char* feature = "";  // "vertex-face", "face-vertex", "edge-edge", "vertex-plane"
    const char* resolution = "";   // "single-point" (SAT), "per-point" or "average" (planes), "manifold" (scene_words.h)
    int pointCount = 1;        // corners averaged into this contact ("average")
    bool separating = false;   // v_rel . n > 0: no impulse was applied
    std::vector<ImpulseIterate> iterations;   // manifold model: after each iteration, in order
    const char* iteration = "";   // manifold model: what one entry of `iterations` is (the solver's words)
};

// A probe point read at the start of the step: p = x + R p_B, v_p = v + omega x (p - x).
struct ProbeSample {
    int body = -1;
    Vec3 p_W = Vec3::Zero();
    Vec3 v_W = Vec3::Zero();
};

// The state at the start of the step (t_k), the numbers a hand calculation of the step
// starts from: every body's x, v, r, L and the derived R, I^-1 and omega, and every
// probe point. World::step() copies it before the pipeline runs, only with a trace.
// It is not an entry list: entries are what the step computed, this is what it read.
struct StartOfStep {
    std::vector<BodyState> bodies;    // indexed like the world's bodies
    std::vector<ProbeSample> probes;  // indexed like SceneDef::probes
};

struct StepTrace {
    long step = 0;        // k: this step advances t_k = k h to t_{k+1}
    double time = 0.0;    // t_{k+1}, the time at the end of the step
    std::vector<TraceEntry> entries;
    std::vector<ContactHeader> contacts;
    Diagnostics diagnostics;   // after the step
    StartOfStep start;         // before the step

    void clear()
    {
        entries.clear();
        contacts.clear();
        start.bodies.clear();
        start.probes.clear();
        step = 0;
        time = 0.0;
        diagnostics = Diagnostics{};
    }

    void add(const QuantityInfo& info, int body, const TraceValue& value, int index = -1,
             std::source_location where = std::source_location::current())
    {
        entries.push_back(TraceEntry{&info, body, index, value, where});
    }

    // The first entry with this id for this body (and index); nullptr if none.
    const TraceEntry* find(std::string_view id, int body, int index = -1) const;
};

// The value of a state quantity at the start of the step, for the rows that have one:
// position (x), linear_velocity (v), orientation (r), angular_momentum (L),
// rotation_matrix (R), inverse_inertia_world (I^-1), angular_velocity (omega) of a
// body, and probe_position (p) and point_velocity (v_p) of probe `index`. False for
// any other id, or when the trace holds no start state (an empty trace).
bool startValue(const StepTrace& trace, std::string_view id, int body, int index, TraceValue* out);
// Whether the quantity with this id has a start-of-step value at all.
bool hasStartValue(std::string_view id);

// Records into a trace only when one is given: `record(trace, q::force, b, F)`, on the
// line that computes the value (its source location is the entry's `where`).
// A template, so that with the trace off not even the TraceValue is built.
template <class T>
inline void record(StepTrace* trace, const QuantityInfo& info, int body, const T& value, int index = -1,
                   std::source_location where = std::source_location::current())
{
    if (trace != nullptr) {
        trace->add(info, body, TraceValue(value), index, where);
    }
}

} // namespace rbw
