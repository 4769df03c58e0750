// Mistake models (issue 10): each one recomputes a quantity of a step from the same
// inputs the way a student who makes that mistake would, so that a checker can name
// the mistake a wrong number shows. They model hand calculations of the course's
// algorithms: one explicit Euler step in the TUM order (docs/references.md §1) and
// one contact impulse (§3). Every model is one small function with its equation
// (mistakes.cpp; the catalogue in mistake_catalogue.cpp); handEulerStep() and
// handImpulse() run the whole hand calculation with one mistake, or two (MistakeSet),
// switched on, so a model also gives every later quantity the mistake carries into
// (a wrong I^-1 gives a wrong omega). The models of what a simulator keeps between
// steps (MistakeInfo::oneStep false) read it from BodyStepInputs' simulator fields.
//
// Glossary: as physics/engine/body.h and physics/engine/course/impulse.h. The step's inputs are
// the values at its start (x, v, r, L of the body, its forces f_i at p_i), h and the
// body's mass properties and size.
#pragma once

#include "physics/engine/body.h"
#include "physics/engine/collision/contact.h"
#include "physics/engine/trace.h"

#include <string>
#include <string_view>
#include <utility>
#include <optional>
#include <vector>

namespace rbw {

enum class Mistake {
    None,
    VelocityBeforePosition,       // x <- x + h v_{n+1}
    OmegaBeforeOrientation,       // r <- r + h/2 (0, omega_{n+1}) r
    TransposedInertia,            // I^-1 = R^T I0^-1 R
    BodyInverseInertia,           // omega = I0^-1 L
    InertiaNotInverted,           // omega = I L
    TorqueReversed,               // q = f x (p - x)
    LeverArmFromOrigin,           // q = p x f
    MissingTimeStep,              // L <- L + q, v <- v + F/M
    QuaternionMissingHalf,        // r <- r + h (0, omega) r
    QuaternionNotNormalised,      // r <- r + h/2 (0, omega) r, not normalised
    HalfExtentsForSize,           // I0 = M/12 diag(...) of the half extents
    PointVelocityWithoutRotation, // v_p = v
    RelativeVelocityReversed,     // v_rel = v_B - v_A
    ImpulseLinearOnly,            // J = -(1 + c) v_rel.n / (1/M_A + 1/M_B)
    ImpulseWithoutOnePlus,        // J = -c v_rel.n / (...)
    // Learned from students' code (issue 21 item 1)
    PointVelocityCrossReversed,   // v_p = v + (p - x) x omega
    PointVelocityLeverArmFromOrigin, // v_p = v + omega x p
    RestitutionOneMinus,          // numerator -(1 - c) v_rel.n
    InertiaAxesSwapped,           // two of I0's moments exchanged (variant 0: x-y, 1: y-z, 2: x-z)
    QuaternionWithoutHalfAngle,   // initial r = (cos th, n sin th) = r0^2 (step 0)
    InertiaHalfExtentsWithoutThird, // I0 = M diag(b^2 + c^2, ...) of the half extents (3x)
    OmegaAccumulated,             // omega' = omega + I^-1 L'
    NoSeparatingCheck,            // J applied although v_rel.n > 0
    ImpulseLeverArmFromOrigin,    // x_a = p, x_b = p in the impulse
    ImpulseDenominatorMissingCross, // (I^-1 (x_a x n)) . n in the denominator
    InertiaFromOldOrientation,    // omega' = R_n I0^-1 R_n^T L'
    InertiaNotUpdated,            // I^-1 = R_0 I0^-1 R_0^T from the first step, never again (simulator only)
    InertiaAccumulatedRotation,   // I^-1 <- R I^-1 R^T of last step's tensor (simulator only)
    QuaternionRightMultiplied,    // r <- r + h/2 r (0, omega)
    ForcesNotCleared,             // F, q keep acting in every later step (simulator only)
    GravityAlwaysOn,              // v <- v + h (F/M + g), g = (0, -9.81, 0) unasked (simulator only)
    OrientationZeroQuaternion,    // r never set stays (0, 0, 0, 0), R(0) = E (simulator only)
    AngleInDegrees,               // initial r = (cos th'/2, n sin th'/2), th' = th in degrees read as radians
    ImpulseBodyInverseInertia,    // the impulse's angular terms with I0^-1
};

// One mistake, or two at once (mistakes combine, issue 21 item 1: the checker considers
// pairs). `variant` is that of whichever of the two has variants.
struct MistakeSet {
    Mistake first = Mistake::None;
    Mistake second = Mistake::None;
    int variant = 0;
    bool has(Mistake m) const { return m != Mistake::None && (first == m || second == m); }
};

struct MistakeInfo {
    Mistake mistake;
    const char* id;            // stable, e.g. "transposed-inertia"
    const char* equation;      // the wrong equation, plain text
    const char* explanation;   // one sentence: what went wrong and the right equation
    int variants = 1;          // ways the mistake can be made (which two axes are swapped)
    // false: only a simulator shows it, over several steps (what it stores between steps);
    // one step checked from the workbook's state cannot, so the checker never names it.
    bool oneStep = true;
};

// Every model, in the order of the enum (without None).
const std::vector<MistakeInfo>& mistakeCatalogue();
const MistakeInfo* findMistake(std::string_view id);
// The explanation for a body in `convention`: for transposed-inertia in the course
// template's convention (lesson 8) the formula used is the standard one, and the right
// one is R^T I0^-1 R.
std::string mistakeExplanation(const MistakeInfo& m, InertiaConvention convention);

// One body at the start of an explicit Euler step, and what acts on it.
struct BodyStepInputs {
    double h = 0.0;
    double mass = 1.0;
    Vec3 size = Vec3::Ones();
    Vec3 x_W = Vec3::Zero();
    Vec3 v_W = Vec3::Zero();
    Quat q_WB = Quat::Identity();
    Vec3 L_W = Vec3::Zero();
    std::vector<std::pair<Vec3, Vec3>> forces;   // (p_i, f_i), world frame
    Vec3 couple_W = Vec3::Zero();                // sum of pure couples q_j
    Vec3 g_W = Vec3::Zero();                     // gravity, F += M g
    std::vector<Vec3> probes_B;                  // points fixed to the body, body frame
    InertiaConvention convention = InertiaConvention::Standard;
    bool firstStep = true;                       // r is the scene's initial orientation
    // The omega the step starts from: unset, the right I^-1(r_n) L_n (a hand step from
    // the workbook's state); set, a simulator's own omega_n, mistake and all (the probes'
    // replay, physics/workbook/probes/replay.cpp).
    std::optional<Vec3> omega_W;
    // What a simulator stores between steps (the probes' replay; a one-step check from the
    // workbook's state leaves these as they are):
    std::optional<Mat3> IinvStored_W;            // its world I^-1 of the last step (unset: R_n I0^-1 R_n^T)
    Vec3 keptF_W = Vec3::Zero();                 // loads of earlier steps it never cleared
    Vec3 keptq_W = Vec3::Zero();
    bool orientationSet = true;                  // false: set_orientation never came for this body
};

// The quantities of one hand-calculated explicit Euler step (trace ids in comments).
struct HandEulerStep {
    Mat3 I0_B, I0inv_B;          // inertia_body, inverse_inertia_body
    Vec3 F_W, q_W;               // force, torque
    Vec3 x_W, v_W;               // position, linear_velocity (after)
    Quat q_WB;                   // orientation (after)
    Vec3 L_W;                    // angular_momentum (after)
    Mat3 R_WB, Iinv_W;           // rotation_matrix, inverse_inertia_world (after)
    Vec3 omega_W;                // angular_velocity (after)
    std::vector<Vec3> probe_W, probeVelocity_W;   // probe_position, point_velocity (after)
    Vec3 loadsF_W, loadsq_W;     // this step's loads without gravity (what a simulator keeps)

    // The value of a trace id (index: the probe), or nullopt-like false.
    bool value(std::string_view id, int index, TraceValue& out) const;
};

// The explicit Euler step of the TUM algorithm by hand, with `m` (None: correct) in its
// `variant` (0 .. MistakeInfo::variants - 1).
HandEulerStep handEulerStep(const BodyStepInputs& in, const MistakeSet& ms);
inline HandEulerStep handEulerStep(const BodyStepInputs& in, Mistake m = Mistake::None, int variant = 0)
{
    return handEulerStep(in, MistakeSet{m, Mistake::None, variant});
}

// One contact impulse at its start: the two sides (B may be a plane: invM = 0, Iinv = 0).
struct ContactInputs {
    ContactGeometry g;
    double restitution = 0.0;
    Vec3 x_A = Vec3::Zero(), v_A = Vec3::Zero(), omega_A = Vec3::Zero();
    Mat3 Iinv_A = Mat3::Zero();
    double invM_A = 0.0;
    Vec3 x_B = Vec3::Zero(), v_B = Vec3::Zero(), omega_B = Vec3::Zero();
    Mat3 Iinv_B = Mat3::Zero();
    double invM_B = 0.0;
    Mat3 I0inv_A = Mat3::Zero(), I0inv_B = Mat3::Zero();   // body frame (impulse-body-inverse-inertia)
};

struct HandImpulse {
    Vec3 x_a, x_b;               // x_a, x_b
    Vec3 velocity_a, velocity_b; // velocity_a, velocity_b
    Vec3 v_rel;                  // relative_velocity
    double v_rel_n = 0.0;        // normal_velocity
    double numerator = 0.0;      // numerator
    double rotational_a = 0.0;   // rotational_a: [(I_A^-1 (x_a x n)) x x_a] . n
    double rotational_b = 0.0;   // rotational_b
    double denominator = 0.0;    // denominator
    double J = 0.0;              // impulse (0 when separating)

    bool value(std::string_view id, TraceValue& out) const;
};

// The normal impulse of the slides by hand (no friction), with `m` (None: correct).
HandImpulse handImpulse(const ContactInputs& in, const MistakeSet& ms);
inline HandImpulse handImpulse(const ContactInputs& in, Mistake m = Mistake::None)
{
    return handImpulse(in, MistakeSet{m, Mistake::None, 0});
}

} // namespace rbw
