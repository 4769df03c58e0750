#include "physics/integrators/rigid_ode.h"

#include "physics/integrators/integrator_quantities.h"
#include "physics/quantities.h"

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

Vec3 angularVelocityAt(const Quat& r, const Vec3& L_W, const MassProperties& mp,
                       InertiaConvention convention)
{
    // omega = I^-1(r) L,  I^-1 = R I0^-1 R^T (or R^T I0^-1 R), R = R(r / |r|)
    const Mat3 R_WB = normalisedOrientation(r).toRotationMatrix();
    const Mat3 Iinv_W = inverseInertiaWorld(R_WB, mp.I0inv_B, convention);
    return Iinv_W * L_W;
}

RigidOdeRate rigidOdeRate(const RigidOdeState& y, const MassProperties& mp, const BodyLoad& load,
                          InertiaConvention convention)
{
    RigidOdeRate k;
    // x' = v,  v' = F/M
    k.xDot = y.v_W;
    k.vDot = mp.invM * load.F_W;
    // omega = I^-1(r) L,  r' = 1/2 (0, omega) r
    k.omega_W = angularVelocityAt(y.r, y.L_W, mp, convention);
    k.rDot = orientationRate(k.omega_W, y.r);
    // L' = q
    k.LDot = load.q_W;
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

void recordRkStage(StepTrace* trace, int body, int i, const RigidOdeRate& k)
{
    if (trace == nullptr) {
        return;
    }
    trace->add(q::stage_velocity, body, k.xDot, i);
    trace->add(q::stage_angular_velocity, body, k.omega_W, i);
    trace->add(q::stage_orientation_rate, body, k.rDot, i);
    trace->add(q::stage_torque, body, k.LDot, i);
}

bool isIsotropic(const Mat3& I0_B)
{
    return I0_B.isDiagonal(0.0) && I0_B(0, 0) == I0_B(1, 1) && I0_B(1, 1) == I0_B(2, 2);
}

void recordDerived(StepTrace* trace, int body, const MassProperties& mp, const BodyState& s,
                   InertiaConvention convention)
{
    if (trace == nullptr) {
        return;
    }
    trace->add(q::inertia_body, body, mp.I0_B);
    trace->add(q::inverse_inertia_body, body, mp.I0inv_B);
    trace->add(q::rotation_matrix, body, s.R_WB);
    trace->add(convention == InertiaConvention::CourseTemplate ? q::inverse_inertia_world_template
                                                               : q::inverse_inertia_world,
               body, s.Iinv_W);
    trace->add(q::angular_velocity, body, s.omega_W);
}

} // namespace rbw
