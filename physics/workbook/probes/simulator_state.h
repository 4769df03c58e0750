// What a student's simulator keeps from one step to the next besides x, v, r, L and
// omega (issue 21 item 1, issue 23): its stored world inverse inertia, the loads it may
// never clear, whether the body ever got an orientation. The models that only show over
// several steps (inertia-not-updated, inertia-accumulated-rotation, forces-not-cleared,
// orientation-zero-quaternion; mistakes.h) read it through BodyStepInputs; replay.cpp
// carries it from step to step with these three functions.
#pragma once

#include "physics/workbook/checker/mistakes.h"
#include "physics/workbook/probes/replay.h"

namespace rbw::probes {

struct SimulatorState {
    Mat3 IinvStored_W = Mat3::Identity();   // the world I^-1 it stored (add_body: I0^-1, R = E)
    Vec3 keptF_W = Vec3::Zero();            // the loads of the last step (kept by forces-not-cleared)
    Vec3 keptq_W = Vec3::Zero();
    bool orientationSet = false;            // set_orientation came for the body
    Quat r0_WB = Quat::Identity();          // the orientation add_body gives it (0 under orientation-zero-quaternion)
};

// A body just added, as the simulator with `model` stores it.
SimulatorState newBodyState(const Vec3& size, double mass, const ReplayModel& model);
// The state into the step's inputs.
void enterState(const SimulatorState& s, BodyStepInputs& in);
// What the simulator keeps after the step.
void keepState(const HandEulerStep& step, SimulatorState& s);

} // namespace rbw::probes
