// What a student's simulator keeps from one step to the next besides x, v, r, L and
// omega (issue 21 item 1, issue 23): its stored world inverse inertia, the loads it may
// never clear, whether the body ever got an orientation. The models that only show over
// several steps (inertia-not-updated, inertia-accumulated-rotation, forces-not-cleared,
// orientation-zero-quaternion; mistakes.h) read it through BodyStepInputs; replay.cpp
// carries it from step to step with these three functions.
#pragma once

#include "physics/workbook/checker/mistakes.h"
#include "physics/workbook/probes/replay.h"

#include <utility>
#include <vector>

namespace rbw::probes {

struct SimulatorState {
    Mat3 IinvStored_W = Mat3::Identity();   // the world I^-1 it stored (add_body: I0^-1, R = E)
    Vec3 keptF_W = Vec3::Zero();            // the loads of the last step (kept by forces-not-cleared)
    Vec3 keptq_W = Vec3::Zero();
    bool orientationSet = false;            // set_orientation came for the body
    Quat r0_WB = Quat::Identity();          // the orientation add_body gives it (0 under orientation-zero-quaternion)
};

// One body as a student's simulator stores it: what the protocol sets and what a step
// carries over. replay() and the collision replay (collision_replay.h) share it, so a
// model steps the same way in both groups.
struct SimBody {
    double mass = 1.0;
    Vec3 size = Vec3::Ones();
    Vec3 x_W = Vec3::Zero(), v_W = Vec3::Zero();
    Quat r_WB = Quat::Identity();
    Vec3 L_W = Vec3::Zero();
    Vec3 omega_W = Vec3::Zero();                  // the simulator's own omega, with its mistake
    Mat3 Iinv_W = Mat3::Zero();                   // the world I^-1 its omega = I^-1 L used (the impulse's too)
    Mat3 I0inv_B = Mat3::Zero();                  // I0^-1 (impulse-body-inverse-inertia)
    std::vector<std::pair<Vec3, Vec3>> forces;    // (p, f) for the next step
    bool stepped = false;
    SimulatorState kept;                          // the several-step models' state
};

// add_body as the simulator with `model` does it (orientation-zero-quaternion: r = 0).
SimBody addSimBody(const Vec3& x_W, const Vec3& size, double mass, const ReplayModel& model);
// One explicit Euler step of the body as the simulator with `model` takes it, from its
// own omega_n; the loads act for this step only (forces-not-cleared keeps them in `kept`).
void stepSimBody(SimBody& b, double h, const ReplayModel& model);

// A body just added, as the simulator with `model` stores it.
SimulatorState newBodyState(const Vec3& size, double mass, const ReplayModel& model);
// The state into the step's inputs.
void enterState(const SimulatorState& s, BodyStepInputs& in);
// What the simulator keeps after the step.
void keepState(const HandEulerStep& step, SimulatorState& s);

} // namespace rbw::probes
