#include "physics/engine/course/box_box_stage.h"

#include "physics/engine/course/box_box_sat.h"
#include "physics/engine/quantities.h"
#include "physics/engine/course/contact_response.h"

#include <optional>

namespace rbw {

void BoxBoxStage::run(StepContext& ctx)
{
    const int n = static_cast<int>(ctx.states.size());
    aabbs_.resize(n);
    for (int b = 0; b < n; ++b) {
        aabbs_[b] = boxAabb(poseOf(ctx, b));
    }
    BroadPhaseStats& stats = ctx.scratch.broadPhase;
    stats = BroadPhaseStats{};
    broadPhase_.findPairs(aabbs_, ctx.movable, pairs_, stats);
    record(ctx.trace, q::pairs_tested, -1, double(stats.pairsTested));
    record(ctx.trace, q::pairs_overlapping, -1, double(stats.pairsOverlapping));
    for (const auto& [a, b] : pairs_) {
        const std::optional<ContactGeometry> hit = collideBoxBoxSAT(poseOf(ctx, a), poseOf(ctx, b));
        if (hit) {
            resolveContact(ctx, *hit, a, b, -1, "single-point", 1);
        }
    }
}

} // namespace rbw
