// A rigid box: its definition (what the scene file says, never changed by a step)
// kept apart from its state (what the integrator changes).
//
// Glossary
//   x_W      centre of mass, world frame                         [m]
//   v_W      linear velocity of the centre of mass, world        [m/s]
//   q_WB     orientation r: unit quaternion, body -> world        [-]
//   L_W      angular momentum about the centre of mass, world    [kg m^2/s]
//   Iinv_W   inverse inertia in the world frame (derived)         [1/(kg m^2)]
//   omega_W  angular velocity, world frame (derived)              [rad/s]
//   M, invM  mass and inverse mass; a fixed body has invM = 0     [kg], [1/kg]
#pragma once

#include "physics/engine/inertia.h"
#include "physics/engine/math_types.h"

#include <optional>
#include <source_location>
#include <string>

namespace rbw {

struct StepTrace;

struct BodyDef {
    std::string name;
    Vec3 size = Vec3::Ones();   // edge lengths (a, b, c) along body x, y, z
    double mass = 1.0;          // ignored when fixed
    bool fixed = false;         // fixed bodies have infinite mass and inertia
    bool angularResponse = true;   // false: collisions treat it as a particle (no change of L)

    // Initial state, as the scene file gives it.
    Vec3 x0_W = Vec3::Zero();
    Quat q0_WB = Quat::Identity();
    Vec3 v0_W = Vec3::Zero();
    Vec3 omega0_W = Vec3::Zero();   // omega at t = 0; L0 = I(r0) omega0

    // Per-body variants of the scene's choices, so one scene can compare them side by
    // side (SceneDef::integratorOf / conventionOf resolve them).
    std::string integrator;                              // empty: the scene's integrator
    std::optional<InertiaConvention> inertiaConvention;  // none: the scene's convention
};

// Constants derived once from a BodyDef (the "model" side, as in MuJoCo's mjModel):
// computed when the world is built, never per step.
struct MassProperties {
    double M = 0.0;                   // mass; 0 stands for "infinite" when fixed
    double invM = 0.0;                // 1/M, 0 for a fixed body
    Mat3 I0_B = Mat3::Zero();         // body inertia, zero for a fixed body
    Mat3 I0inv_B = Mat3::Zero();      // its inverse, zero for a fixed body
    // The statements that computed I0 and I0^-1 (their trace rows point there).
    std::source_location I0_where;
    std::source_location I0inv_where;
};

MassProperties massProperties(const BodyDef& def);

struct BodyState {
    Vec3 x_W = Vec3::Zero();
    Vec3 v_W = Vec3::Zero();
    Quat q_WB = Quat::Identity();
    Vec3 L_W = Vec3::Zero();

    // Derived from the state above; kept up to date by updateDerived().
    Mat3 R_WB = Mat3::Identity();
    Mat3 Iinv_W = Mat3::Zero();
    Vec3 omega_W = Vec3::Zero();
};

// The state at t = 0: x0, v0, r0, and L0 = I(r0) * omega0 with I(r0) = R I0 R^T.
BodyState initialState(const BodyDef& def, const MassProperties& mp, InertiaConvention convention);

// R = R(r), Iinv_W from R and I0^-1, omega_W = Iinv_W L_W  (TUM algorithm steps 6 and 7).
// With a trace, records the rows every integrator shares for body `body`: I0, I0^-1, R,
// I^-1 (with the convention's formula) and omega.
void updateDerived(const MassProperties& mp, BodyState& state, InertiaConvention convention,
                   StepTrace* trace = nullptr, int body = -1);

// The same when the rotation matrix R_WB is itself the state (the rotation-matrix
// integrators, Napier practical 6): Iinv_W from this R, omega_W = Iinv_W L_W, and the
// rows I0, I0^-1, I^-1 and omega (R's row is the integrator's own).
void updateDerivedFromMatrix(const MassProperties& mp, BodyState& state, InertiaConvention convention,
                             StepTrace* trace, int body);

// P = M v (zero for a fixed body).
inline Vec3 linearMomentum(const MassProperties& mp, const BodyState& s) { return mp.M * s.v_W; }

// Velocity of the world point p attached to the body: v_p = v + omega x (p - x).
Vec3 pointVelocity(const BodyState& state, const Vec3& p_W);

} // namespace rbw
