// The manifold model's work limits; the table and the reasons in work_limits.h.
#include "physics/engine/manifold/work_limits.h"

#include "physics/engine/scene.h"

namespace rbw {

PairLimits manifoldPairLimits(int movableBodies)
{
    PairLimits limits;
    limits.maxPerBody = kMaxPairsPerBody;
    // maxPairs = 32 n_movable + 128: linear in the bodies, and never below what one box
    // may have on its own.
    limits.maxPairs = static_cast<long>(kMaxPairsPerBodyAverage) * movableBodies + kMaxPairsPerBody;
    return limits;
}

StepStatus workLimitStatus(const SceneDef& scene, long k, const PairLimits& limits, const BroadPhaseStats& stats)
{
    StepStatus st;
    st.ok = false;
    st.kind = "work-limit";
    st.step = k;
    const std::string advice =
        " Boxes that overlap this much (coincident, or placed inside each other) have no contact solution; "
        "place them apart.";
    if (stats.limitHit == PairLimitHit::PairsPerBody) {
        st.body = stats.limitBody;
        st.bodyName = scene.bodies[static_cast<std::size_t>(stats.limitBody)].name;
        st.quantity = "contact_pairs_per_body";
        st.message = "the manifold model stopped in step " + std::to_string(k) + ": the bounding box of body \"" +
                     st.bodyName + "\" overlaps more than " + std::to_string(limits.maxPerBody) +
                     " others, the limit of contact pairs per body (contact_pairs_per_body)." + advice;
    } else {
        st.quantity = "broad_phase_candidates";
        st.message = "the manifold model stopped in step " + std::to_string(k) + ": more than " +
                     std::to_string(limits.maxPairs) + " pairs of bounding boxes overlap, the limit of broad-phase "
                     "candidates (broad_phase_candidates: " + std::to_string(kMaxPairsPerBodyAverage) +
                     " per movable body and " + std::to_string(kMaxPairsPerBody) + ")." + advice;
    }
    return st;
}

} // namespace rbw
