#include "physics/engine/manifold/sleep_stage.h"

#include "physics/engine/quantities.h"

namespace rbw {

void SleepStage::run(StepContext& ctx)
{
    ContactScratch& w = *world_;
    SleepState& sleep = ctx.contacts.sleep;
    sleep.update(ctx.states, ctx.movable, w.manifolds, ctx.scene.dt, w.settings, w.sleepScratch);
    if (ctx.trace == nullptr) return;
    for (int b = 0; b < static_cast<int>(ctx.states.size()); ++b) {
        if (!ctx.movable[static_cast<std::size_t>(b)]) continue;
        record(ctx.trace, q::sleep_time, b, sleep.restTime(b));
        record(ctx.trace, q::asleep, b, sleep.asleep(b) ? 1.0 : 0.0);
    }
}

} // namespace rbw
