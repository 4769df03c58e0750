#include "physics/engine/stages/probes_stage.h"

#include "physics/engine/quantities.h"

namespace rbw {

ProbeReading readProbe(const SceneDef& scene, const std::vector<BodyState>& states,
                       const std::vector<Vec3>& probeOffsets_B, int i, StepTrace* trace)
{
    ProbeReading r;
    r.body = scene.probes[i].body;
    const BodyState& s = states[r.body];
    // p = x + R p_B
    record(trace, q::p_B, r.body, probeOffsets_B[i], i);
    r.p_W = s.x_W + s.R_WB * probeOffsets_B[i];
    record(trace, q::probe_position, r.body, r.p_W, i);
    // v_p = v + omega x (p - x): the rotation's share first, for the derivation
    if (trace != nullptr) record(trace, q::omega_cross_r_W, r.body, s.omega_W.cross(r.p_W - s.x_W), i);
    r.v_W = pointVelocity(s, r.p_W);
    record(trace, q::point_velocity, r.body, r.v_W, i);
    return r;
}

void ProbesStage::run(StepContext& ctx)
{
    if (ctx.trace == nullptr) return;   // nothing to show
    for (int i = 0; i < static_cast<int>(ctx.scene.probes.size()); ++i) {
        readProbe(ctx.scene, ctx.states, ctx.probeOffsets_B, i, ctx.trace);
    }
}

} // namespace rbw
