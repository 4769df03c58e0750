#include "physics/engine/body.h"

#include "physics/engine/quantities.h"

namespace rbw {

MassProperties massProperties(const BodyDef& def)
{
    MassProperties mp;
    if (def.fixed) {
        return mp;   // infinite mass: 1/M = 0 and I^-1 = 0 (docs/references.md §3)
    }
    mp.M = def.mass;
    mp.invM = 1.0 / def.mass;
    // I0 = M/12 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2)
    mp.I0_B = boxInertiaBody(def.size, def.mass); mp.I0_where = std::source_location::current();
    // I0 is diagonal for a box, so its inverse is the diagonal of reciprocals.
    for (int i = 0; i < 3; ++i) {
        mp.I0inv_B(i, i) = 1.0 / mp.I0_B(i, i); mp.I0inv_where = std::source_location::current();
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

namespace {

// I0 and I0^-1, computed once in massProperties(): their rows name that statement.
void recordMassProperties(StepTrace* trace, int body, const MassProperties& mp)
{
    if (trace == nullptr) return;
    trace->add(q::inertia_body, body, mp.I0_B, -1, mp.I0_where);
    trace->add(q::inverse_inertia_body, body, mp.I0inv_B, -1, mp.I0inv_where);
}

const QuantityInfo& inverseInertiaRow(InertiaConvention convention)
{
    return convention == InertiaConvention::CourseTemplate ? q::inverse_inertia_world_template
                                                           : q::inverse_inertia_world;
}

} // namespace

void updateDerived(const MassProperties& mp, BodyState& state, InertiaConvention convention, StepTrace* trace,
                   int body)
{
    recordMassProperties(trace, body, mp);
    // R = R(r)
    state.R_WB = state.q_WB.toRotationMatrix();
    record(trace, q::rotation_matrix, body, state.R_WB);
    // I^-1 = R I0^-1 R^T  (TUM "Simulation Algorithm 3D", step 6)
    state.Iinv_W = inverseInertiaWorld(state.R_WB, mp.I0inv_B, convention);
    record(trace, inverseInertiaRow(convention), body, state.Iinv_W);
    // omega = I^-1 L  (step 7)
    state.omega_W.noalias() = state.Iinv_W * state.L_W;
    record(trace, q::angular_velocity, body, state.omega_W);
}

void updateDerivedFromMatrix(const MassProperties& mp, BodyState& state, InertiaConvention convention,
                             StepTrace* trace, int body)
{
    recordMassProperties(trace, body, mp);
    // I^-1 = R I0^-1 R^T with this R (drifted unless orthonormalised)
    state.Iinv_W = inverseInertiaWorld(state.R_WB, mp.I0inv_B, convention);
    record(trace, inverseInertiaRow(convention), body, state.Iinv_W);
    // omega = I^-1 L
    state.omega_W = state.Iinv_W * state.L_W;
    record(trace, q::angular_velocity, body, state.omega_W);
}

Vec3 pointVelocity(const BodyState& state, const Vec3& p_W)
{
    // v_p = v + omega x (p - x)  (step 8)
    return state.v_W + state.omega_W.cross(p_W - state.x_W);
}

} // namespace rbw
