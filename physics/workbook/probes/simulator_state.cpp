#include "physics/workbook/probes/simulator_state.h"

namespace rbw::probes {

SimulatorState newBodyState(const Vec3& size, double mass, const ReplayModel& model)
{
    SimulatorState s;
    // The stored tensor starts as I0^-1 of the body (R = E at add_body), with the model's I0.
    BodyStepInputs in;
    in.size = size;
    in.mass = mass;
    s.IinvStored_W = handEulerStep(in, model.mistake, model.variant).I0inv_B;
    // orientation-zero-quaternion: the body's r starts as (0, 0, 0, 0)
    if (model.mistake == Mistake::OrientationZeroQuaternion) s.r0_WB = Quat(0.0, 0.0, 0.0, 0.0);
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

} // namespace rbw::probes
