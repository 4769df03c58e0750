#include "physics/engine/manifold/sleep_stage.h"

#include "physics/engine/quantities.h"

namespace rbw {

void SleepStage::run(StepContext& ctx)
{
    ContactWorld& w = *world_;
    if (static_cast<int>(ctx.states.size()) != static_cast<int>(w.bodies.size()) - 1) return;   // no contact stage ran
    w.sleep.update(ctx.states, ctx.movable, w.manifolds, ctx.scene.dt, w.settings);
    if (ctx.trace == nullptr) return;
    for (int b = 0; b < static_cast<int>(ctx.states.size()); ++b) {
        if (!ctx.movable[static_cast<std::size_t>(b)]) continue;
        record(ctx.trace, q::sleep_time, b, w.sleep.restTime(b));
        record(ctx.trace, q::asleep, b, w.sleep.asleep(b) ? 1.0 : 0.0);
    }
}

} // namespace rbw
