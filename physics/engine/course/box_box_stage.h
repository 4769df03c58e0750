// Box-box contacts: sweep-and-prune on world AABBs, the course's SAT on each
// overlapping pair (docs/references.md §2, course/box_box_sat.h) and one impulse per
// contact, with the lower-indexed body as A.
#pragma once

#include "physics/engine/stages/stage.h"

namespace rbw {

class BoxBoxStage final : public PipelineStep {
public:
    PipelineStage kind() const override { return PipelineStage::BoxBox; }
    void run(StepContext& ctx) override;

private:
    // Scratch kept between steps to avoid allocations.
    SweepAndPrune broadPhase_;
    std::vector<Aabb> aabbs_;
    std::vector<std::pair<int, int>> pairs_;
};

} // namespace rbw
