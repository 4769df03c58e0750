// The manifold model's sleep stage, last of the contact stages ("sleep": true, the
// default of the manifold model; contact/sleep.h): rest times, islands, and islands at
// rest long enough go to sleep. With a trace it records each movable body's rest time
// and whether it sleeps.
#pragma once

#include "physics/engine/manifold/contact_scratch.h"
#include "physics/engine/stages/stage.h"

#include <memory>

namespace rbw {

class SleepStage final : public PipelineStep {
public:
    explicit SleepStage(std::shared_ptr<ContactScratch> world) : world_(std::move(world)) {}
    PipelineStage kind() const override { return PipelineStage::Sleep; }
    void run(StepContext& ctx) override;

private:
    std::shared_ptr<ContactScratch> world_;
};

} // namespace rbw
