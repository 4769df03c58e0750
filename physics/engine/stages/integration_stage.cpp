#include "physics/engine/stages/integration_stage.h"

namespace rbw {

IntegrationStage::IntegrationStage(std::unique_ptr<Integrator> integrator, std::vector<int> bodies,
                                   std::vector<char> active, bool all)
    : integrator_(std::move(integrator))
    , bodies_(std::move(bodies))
    , active_(std::move(active))
    , all_(all)
{
}

void IntegrationStage::run(StepContext& ctx)
{
    // Each body with its own inertia convention (I^-1 = R I0^-1 R^T or R^T I0^-1 R).
    const IntegrationInput in{ctx.scene.dt,      ctx.scene.bodies, ctx.mass, ctx.loads, ctx.scene.inertiaConvention,
                              &ctx.conventions, all_ ? nullptr : &active_};
    integrator_->integrate(in, ctx.states, ctx.trace);
}

} // namespace rbw
