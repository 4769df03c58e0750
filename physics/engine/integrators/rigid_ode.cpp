#include "physics/engine/integrators/rigid_ode.h"

#include "physics/engine/quantities.h"

#include <cmath>

namespace rbw {

Quat orientationRate(const Vec3& omega_W, const Quat& r)
{
    // r' = 1/2 (0, omega) r
    const Quat omegaQuat(0.0, omega_W.x(), omega_W.y(), omega_W.z());
    Quat rDot = omegaQuat * r;
    rDot.coeffs() *= 0.5;
    return rDot;
}

Quat normalisedOrientation(const Quat& r)
{
    Quat out = r;
    const double norm2 = out.squaredNorm();
    if (std::isfinite(norm2)) {
        out.coeffs() /= std::sqrt(norm2);
    } else {
        out.coeffs().stableNormalize();
    }
    return out;
}

double orientationNorm(const Quat& r)
{
    const double norm2 = r.squaredNorm();
    return std::isfinite(norm2) ? std::sqrt(norm2) : r.coeffs().stableNorm();
}

Mat3 inverseInertiaAt(const Quat& r, const MassProperties& mp, InertiaConvention convention)
{
    // I^-1 = R I0^-1 R^T (or R^T I0^-1 R), R = R(r / |r|)
    const Mat3 R_WB = normalisedOrientation(r).toRotationMatrix();
    return inverseInertiaWorld(R_WB, mp.I0inv_B, convention);
}

Vec3 angularVelocityAt(const Quat& r, const Vec3& L_W, const MassProperties& mp,
                       InertiaConvention convention)
{
    // omega = I^-1(r) L
    return inverseInertiaAt(r, mp, convention) * L_W;
}

RigidOdeRate rigidOdeRate(const RigidOdeState& y, const BodyStep& step, int stage)
{
    RigidOdeRate k;
    // x' = v,  v' = F/M
    k.xDot = y.v_W;
    step.record(q::stage_velocity, k.xDot, stage);
    k.vDot = step.mp.invM * step.load.F_W;
    // omega = I^-1(r) L,  r' = 1/2 (0, omega) r
    const Mat3 Iinv_W = inverseInertiaAt(y.r, step.mp, step.convention);
    step.record(step.convention == InertiaConvention::CourseTemplate ? q::stage_inverse_inertia_template
                                                                     : q::stage_inverse_inertia,
                Iinv_W, stage);
    k.omega_W = Iinv_W * y.L_W;
    step.record(q::stage_angular_velocity, k.omega_W, stage);
    k.rDot = orientationRate(k.omega_W, y.r);
    step.record(q::stage_orientation_rate, k.rDot, stage);
    // L' = q
    k.LDot = step.load.q_W;
    step.record(q::stage_torque, k.LDot, stage);
    return k;
}

RigidOdeState advanced(const RigidOdeState& y, double a, const RigidOdeRate& k)
{
    RigidOdeState out;
    out.x_W = y.x_W + a * k.xDot;
    out.v_W = y.v_W + a * k.vDot;
    out.r.coeffs() = y.r.coeffs() + a * k.rDot.coeffs();
    out.L_W = y.L_W + a * k.LDot;
    return out;
}

bool isIsotropic(const Mat3& I0_B)
{
    return I0_B.isDiagonal(0.0) && I0_B(0, 0) == I0_B(1, 1) && I0_B(1, 1) == I0_B(2, 2);
}

} // namespace rbw
