#include "physics/workbook/probes/simulator_state.h"

namespace rbw::probes {

SimulatorState newBodyState(const Vec3& size, double mass, const ReplayModel& model)
{
    SimulatorState s;
    // The stored tensor starts as I0^-1 of the body (R = E at add_body), with the model's I0.
    BodyStepInputs in;
    in.size = size;
    in.mass = mass;
    s.IinvStored_W = handEulerStep(in, model.set()).I0inv_B;
    // orientation-zero-quaternion: the body's r starts as (0, 0, 0, 0)
    if (model.has(Mistake::OrientationZeroQuaternion)) s.r0_WB = Quat(0.0, 0.0, 0.0, 0.0);
    return s;
}

void enterState(const SimulatorState& s, BodyStepInputs& in)
{
    in.IinvStored_W = s.IinvStored_W;
    in.keptF_W = s.keptF_W;
    in.keptq_W = s.keptq_W;
    in.orientationSet = s.orientationSet;
}

void keepState(const HandEulerStep& step, SimulatorState& s)
{
    s.IinvStored_W = step.Iinv_W;
    // F and q as the step used them (the models add the kept ones only under forces-not-cleared)
    s.keptF_W = step.loadsF_W;
    s.keptq_W = step.loadsq_W;
}

namespace {

// The inverse inertia the simulator stores after a step: the one its omega = Iinv_W L
// uses (body-inverse-inertia: I0^-1; inertia-not-inverted: R I0 R^T).
Mat3 storedInverseInertia(const HandEulerStep& s, const ReplayModel& m)
{
    if (m.has(Mistake::BodyInverseInertia)) return s.I0inv_B;   // as angularVelocity() (mistakes.cpp) decides
    if (m.has(Mistake::InertiaNotInverted)) return s.R_WB * s.I0_B * s.R_WB.transpose();
    return s.Iinv_W;
}

} // namespace

SimBody addSimBody(const Vec3& x_W, const Vec3& size, double mass, const ReplayModel& model)
{
    SimBody b;
    b.x_W = x_W;
    b.size = size;
    b.mass = mass;
    b.kept = newBodyState(size, mass, model);
    b.r_WB = b.kept.r0_WB;
    return b;
}

void stepSimBody(SimBody& b, double h, const ReplayModel& model)
{
    BodyStepInputs in;
    in.h = h;
    in.mass = b.mass;
    in.size = b.size;
    in.x_W = b.x_W;
    in.v_W = b.v_W;
    in.q_WB = b.r_WB;
    in.L_W = b.L_W;
    in.forces = b.forces;
    in.firstStep = !b.stepped;
    in.omega_W = b.omega_W;   // the step starts from the simulator's own omega_n
    enterState(b.kept, in);
    const HandEulerStep s = handEulerStep(in, model.set());
    b.x_W = s.x_W;
    b.v_W = s.v_W;
    b.r_WB = s.q_WB;
    b.L_W = s.L_W;
    b.omega_W = s.omega_W;
    b.Iinv_W = storedInverseInertia(s, model);
    b.I0inv_B = s.I0inv_B;
    keepState(s, b.kept);
    b.forces.clear();   // the loads act for one step
    b.stepped = true;
}

} // namespace rbw::probes
