// Probes (TUM algorithm step 8, docs/references.md §1): the world position and the
// velocity of points fixed to a body, p = x + R p_B and v_p = v + omega x (p - x).
// In the pipeline only when the scene has probes; it records, so it runs only with a
// trace. World::probe() reads one probe without a trace, through the same function.
#pragma once

#include "physics/engine/stages/stage.h"

namespace rbw {

struct ProbeReading {
    int body = -1;
    Vec3 p_W = Vec3::Zero();   // current position of the probe point
    Vec3 v_W = Vec3::Zero();   // its velocity v + omega x (p - x)
};

// Probe i of the scene in the current state; records p and v_p when given a trace.
ProbeReading readProbe(const SceneDef& scene, const std::vector<BodyState>& states,
                       const std::vector<Vec3>& probeOffsets_B, int i, StepTrace* trace = nullptr);

class ProbesStage final : public PipelineStep {
public:
    PipelineStage kind() const override { return PipelineStage::Probes; }
    void run(StepContext& ctx) override;
};

} // namespace rbw
