// The integration of one integrator group: the bodies that share an integrator
// (the scene's, or a body's own) advance by one step of size h. A scene whose bodies
// all use one integrator has one such stage; lessons 8 and 9 have several.
#pragma once

#include "physics/engine/stages/stage.h"

#include <memory>

namespace rbw {

class IntegrationStage final : public PipelineStep {
public:
    // `bodies`: the movable bodies of this group; `active`: per body, non-zero for
    // them (nullptr when the group is every body).
    IntegrationStage(std::unique_ptr<Integrator> integrator, std::vector<int> bodies,
                     std::vector<char> active, bool all);
    PipelineStage kind() const override { return PipelineStage::Integration; }
    void run(StepContext& ctx) override;
    const char* integratorName() const override { return integrator_->name(); }
    const std::vector<int>* bodies() const override { return &bodies_; }
    const Integrator& integrator() const { return *integrator_; }

private:
    std::unique_ptr<Integrator> integrator_;
    std::vector<int> bodies_;
    std::vector<char> active_;
    bool all_;
};

} // namespace rbw
