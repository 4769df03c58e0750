// The checks that stop a run before a blown-up number reaches a view
// (docs/stability.md, docs/architecture.md "Errors in layers"):
//   finite_check   the first non-finite x, v, r, R, L, I^-1 or omega names step, body and quantity;
// (energy_bound and energy_check, the rule on a jump of T, are in energy_jump_stage.h)
// and, outside the pipeline, the checks of everything else a view prints (World calls
// them: after a traced step, and from checkOutputs()):
//   the constants I0 and I0^-1, each body's P = M v, the diagnostics (energies and
//   momenta, per body and in total), the probes, the time t, and every trace entry
//   (contact numbers included).
// Each check is one sum first (NaN and infinity propagate through a sum, so a finite
// sum proves every term finite) and looks in detail only when the sum is not finite.
//
// Edge of the double range. A non-finite quantity is blamed on the inputs, not on the
// step, when
//   (a) it is in the initial state (before step 0: no step has been taken, so no dt
//       can help), or
//   (b) one of the step-0 magnitudes of the body it belongs to (of any body, for a sum
//       over the bodies) is at least kRangeEdge = 1e150, or a mass or edge length at
//       most 1/kRangeEdge: |x0|, |v0|, |omega0|, the mass M, an edge length, |L0| =
//       |I(r0) omega0|, the largest entry of I0 or I0^-1, |p0| of a probe on it. The
//       energies and momenta are products of two such magnitudes (1/2 M |v|^2,
//       1/2 omega.L, x x M v), and 1e150 squared is 1e300, within a factor ~1e8 of the
//       largest double (1.8e308): such inputs overflow without any growth over steps;
//   (c) the time t_{k+1} = (k+1) h is not finite: dt is at the edge.
// The message then names those inputs with their scene-file fields ("the inputs are at
// the edge of the double range: |ω0| = 1e308 (bodies[0].angular_velocity); reduce them").
// Otherwise a quantity grew beyond the range over the steps, and the message suggests a
// smaller dt or another integrator. The loads (forces, couples, gravity) do not count
// as step-0 magnitudes: what they add in a step is proportional to h, so a smaller dt
// does scale their effect down (1e300 N on 1e-10 kg overflows v with h = 1 s and runs
// with h = 1e-20 s; tst_cli). Gravity is named only in the initial state, where
// V = -M g.x can overflow before any step.
#pragma once

#include "physics/engine/stages/stage.h"

namespace rbw {

class FiniteCheckStage final : public PipelineStep {
public:
    PipelineStage kind() const override { return PipelineStage::FiniteCheck; }
    void run(StepContext& ctx) override;
};

// An input magnitude from this size on (or a mass or length from 1/kRangeEdge down) is
// at the edge of the double range (rule (b) above).
inline constexpr double kRangeEdge = 1e150;

// What the checks outside the pipeline read: the scene and its bodies' constants.
struct CheckScope {
    const SceneDef& scene;
    const std::vector<MassProperties>& mass;
    const std::vector<InertiaConvention>& conventions;   // per body
    const std::vector<Vec3>& probeOffsets_B;              // per probe: p_B
};

// Where a check runs: after step k, or on the initial state (step 0, before any step).
struct CheckPoint {
    long step = 0;
    bool initial = false;
};

// Each returns StepStatus::success() when everything it looks at is finite, else the
// blow-up status of the first non-finite quantity (kind "non-finite").
//   I0 and I0^-1 of every body (inertia_body, inverse_inertia_body):
StepStatus checkMassProperties(const CheckScope& scope, CheckPoint at);
//   x, v, r, R, L, I^-1, omega of every body (the finite_check stage's check):
StepStatus checkStates(const CheckScope& scope, const std::vector<BodyState>& states, CheckPoint at);
//   the time t_{k+1} at the end of step k (rule (c)):
StepStatus checkTime(const CheckScope& scope, double time, CheckPoint at);
//   each body's P = M v, the diagnostics d of these states and every probe:
StepStatus checkDerivedOutputs(const CheckScope& scope, const std::vector<BodyState>& states,
                               const Diagnostics& d, CheckPoint at);
//   every entry of a step's trace, in the order recorded:
StepStatus checkTrace(const CheckScope& scope, const StepTrace& trace, CheckPoint at);
// The status of body b's kinetic energy T = 1/2 M |v|^2 + 1/2 omega.L when it overflowed
// from a finite state (energy_check; a non-finite number, not a jump):
StepStatus nonFiniteKineticEnergy(const CheckScope& scope, CheckPoint at, int body);

} // namespace rbw
