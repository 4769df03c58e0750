// The free rigid-body ODE that every integrator in this folder discretises, and the
// small pieces they share.
//
// State y = (x, r, P, L) with P = M v (kept as v here), world frame:
//   x' = v,   v' = F/M,   r' = 1/2 (0, omega) r,   L' = q,
//   omega = I^-1(r) L,   I^-1(r) = R(r) I0^-1 R(r)^T   (or R^T I0^-1 R, course template)
// (TUM "Simulation Algorithm 3D", docs/references.md §1; Baraff, "Physically Based
// Modeling: Rigid Body Simulation", SIGGRAPH 2001 notes, section 2.9.)
//
// Glossary
//   r, q_WB   orientation quaternion body -> world, written [w, x, y, z]
//   rDot      dr/dt = 1/2 (0, omega_W) r, a quaternion that is not unit    [1/s]
//   Q         the inertia frame: Iinv_W = Q I0^-1 Q^T, Q = R (standard) or R^T (template)
#pragma once

#include "physics/engine/body.h"
#include "physics/engine/integrator.h"
#include "physics/engine/trace.h"

namespace rbw {

// One point y = (x, v, r, L) of the ODE, e.g. an RK stage (r need not be unit).
struct RigidOdeState {
    Vec3 x_W = Vec3::Zero();
    Vec3 v_W = Vec3::Zero();
    Quat r = Quat::Identity();
    Vec3 L_W = Vec3::Zero();
};

// f(y) = (x', v', r', L'), with the omega it used.
struct RigidOdeRate {
    Vec3 xDot = Vec3::Zero();   // = v
    Vec3 vDot = Vec3::Zero();   // = F/M
    Quat rDot = Quat(0.0, 0.0, 0.0, 0.0);   // = 1/2 (0, omega) r
    Vec3 LDot = Vec3::Zero();   // = q
    Vec3 omega_W = Vec3::Zero();   // = I^-1(r) L
};

// f(y): the right-hand side above, with the step's constant load (F, q); records the
// rows of RK stage `stage` (index i = 1, 2, ...): k_x,i, omega_i, k_r,i, k_L,i.
RigidOdeRate rigidOdeRate(const RigidOdeState& y, const BodyStep& step, int stage);

// y + a k, componentwise (the RK stage combination).
RigidOdeState advanced(const RigidOdeState& y, double a, const RigidOdeRate& k);

// dr/dt = 1/2 (0, omega_W) r  (quaternion product, omega in the world frame).
Quat orientationRate(const Vec3& omega_W, const Quat& r);

// r / |r|, with the scaled norm when |r|^2 overflows (as explicit Euler does).
Quat normalisedOrientation(const Quat& r);
// |r|, the number normalisedOrientation divides by (the scaled norm when |r|^2 overflows).
double orientationNorm(const Quat& r);

// I^-1(r) = Q I0^-1 Q^T with R = R(r / |r|) (Q = R, or R^T in the template's convention).
Mat3 inverseInertiaAt(const Quat& r, const MassProperties& mp, InertiaConvention convention);

// omega = I^-1(r) L with R = R(r / |r|): the angular velocity of a (stage) state.
Vec3 angularVelocityAt(const Quat& r, const Vec3& L_W, const MassProperties& mp,
                       InertiaConvention convention);

// I0 = k E (a cube, a sphere): the gyroscopic term omega x I0 omega is exactly zero.
bool isIsotropic(const Mat3& I0_B);

} // namespace rbw
