#include "physics/body.h"

namespace rbw {

MassProperties massProperties(const BodyDef& def)
{
    MassProperties mp;
    if (def.fixed) {
        return mp;   // infinite mass: 1/M = 0 and I^-1 = 0 (reference.md section 3)
    }
    mp.M = def.mass;
    mp.invM = 1.0 / def.mass;
    mp.I0_B = boxInertiaBody(def.size, def.mass);
    // I0 is diagonal for a box, so its inverse is the diagonal of reciprocals.
    for (int i = 0; i < 3; ++i) {
        mp.I0inv_B(i, i) = 1.0 / mp.I0_B(i, i);
    }
    return mp;
}

BodyState initialState(const BodyDef& def, const MassProperties& mp, InertiaConvention convention)
{
    BodyState s;
    s.x_W = def.x0_W;
    s.q_WB = def.q0_WB.normalized();
    if (!def.fixed) {
        s.v_W = def.v0_W;
        // L0 = I(r0) omega0, with the world inertia I = R I0 R^T (or R^T I0 R in the
        // course-template convention, so that omega0 = Iinv_W L0 holds in either).
        const Mat3 R_WB = s.q_WB.toRotationMatrix();
        const Mat3 I_W = convention == InertiaConvention::CourseTemplate
                             ? Mat3(R_WB.transpose() * mp.I0_B * R_WB)
                             : Mat3(R_WB * mp.I0_B * R_WB.transpose());
        s.L_W = I_W * def.omega0_W;
    }
    updateDerived(mp, s, convention);
    return s;
}

void updateDerived(const MassProperties& mp, BodyState& state, InertiaConvention convention)
{
    // R = R(r)
    state.R_WB = state.q_WB.toRotationMatrix();
    // I^-1 = R I0^-1 R^T  (TUM "Simulation Algorithm 3D", step 6)
    state.Iinv_W = inverseInertiaWorld(state.R_WB, mp.I0inv_B, convention);
    // omega = I^-1 L  (step 7)
    state.omega_W.noalias() = state.Iinv_W * state.L_W;
}

Vec3 pointVelocity(const BodyState& state, const Vec3& p_W)
{
    // v_p = v + omega x (p - x)  (step 8)
    return state.v_W + state.omega_W.cross(p_W - state.x_W);
}

} // namespace rbw
