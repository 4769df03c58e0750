// The forces of a step (TUM "Simulation Algorithm 3D" step 1, docs/references.md §1):
// gravity f_g = M g, then every applied force f_i at its point p_i, every couple q_j
// and the one-step forces of the interaction, summed into F and q per body.
#pragma once

#include "physics/engine/stages/stage.h"

namespace rbw {

// f_g = M g at the centre of mass of every movable body (adds no torque).
class GravityStage final : public PipelineStep {
public:
    PipelineStage kind() const override { return PipelineStage::Gravity; }
    void run(StepContext& ctx) override;
};

// F = sum f_i (+ M g),  q = sum (p_i - x) x f_i + sum q_j, and their trace rows.
class LoadsStage final : public PipelineStep {
public:
    explicit LoadsStage(bool afterGravity) : afterGravity_(afterGravity) {}
    PipelineStage kind() const override { return PipelineStage::Loads; }
    void run(StepContext& ctx) override;

private:
    bool afterGravity_;   // F's formula names M g
};

} // namespace rbw
