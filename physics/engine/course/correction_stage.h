// Position correction (scene key position_correction): not part of the impulse of
// the slides, a projection that changes x only. Box pairs are pushed apart along n by
// their depth, shared in proportion to inverse mass; then every movable body is lifted
// out of every plane, so a box-box push never leaves a body inside the ground.
#pragma once

#include "physics/engine/stages/stage.h"

namespace rbw {

class CorrectionStage final : public PipelineStep {
public:
    PipelineStage kind() const override { return PipelineStage::Correction; }
    void run(StepContext& ctx) override;
};

} // namespace rbw
