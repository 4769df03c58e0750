// The manifold model's bounds on the work and memory of one step (issue 22).
//
// A pile of n overlapping boxes (coincident, or generated inside each other) has
// n (n - 1) / 2 overlapping bounding boxes: without a bound, one step built a manifold of
// about 2 kB for each pair (1 000 coincident boxes: 500 000 pairs, 1.8 GB, 15 s; 2 000:
// std::bad_alloc). Every per-step quantity of the model is bounded here, or by a fixed
// size elsewhere, so that a step's time and memory grow linearly with the bodies:
//
//   limit                     value                       where it is enforced
//   contact pairs per body    kMaxPairsPerBody = 128      AabbTree::findPairs (PairLimits)
//   broad-phase candidates    kMaxPairsPerBodyAverage     AabbTree::findPairs (PairLimits)
//                             = 32 per movable body
//                             (+ kMaxPairsPerBody)
//   points per manifold       kMaxManifoldPoints = 8      manifold.h (a fixed array; the
//                                                         clipped polygon has at most 8)
//   velocity iterations       solver_iterations <= 1000   checkContactModel (settings.h)
//   position-fix iterations   positionIterations = 3      ManifoldSettings (settings.h)
//
// Why these values: a box has at most 26 neighbours of its own size whose bounding
// boxes touch it (a 3 x 3 x 3 block), and every pair counts for both its boxes, so a
// dense pile of equal boxes has about 13 pairs per box; turned boxes have larger
// bounding boxes (up to sqrt 3 wider) and the speculative margin grows them by 2 cm.
// The limits are 5x and 2.5x that (a touching 10 x 10 x 10 block steps in full,
// tst_pile_limits), and far above what the 1000-box rain needs: at most 6 pairs of one
// box and 0.92 pairs per box in any of its 600 steps (rbw_bench_rain's census,
// docs/performance.md, "Three engines"). A fixed body (a floor made of a box) is not capped: each of its pairs has a
// movable box, which is.
//
// When a step exceeds a limit, the scene has no meaningful contact solution in this
// model (boxes inside boxes have no separating direction), and the run stops in that
// step like a blow-up: StepStatus kind "work-limit", quantity the limit's name, and a
// message naming the limit, the body and what to change (`rbw run` exits with 3). Jolt
// takes the same kind of caps (PhysicsSystem::Init's maxBodyPairs and
// maxContactConstraints, EPhysicsUpdateError::BodyPairCacheFull) but drops the
// contacts beyond them and steps on; Box2D v3 has no cap and allocates what the pile
// needs. A workbook must not show a result with contacts silently left out.
#pragma once

#include "physics/engine/collision/broad_phase.h"
#include "physics/engine/step_status.h"

#include <string>

namespace rbw {

struct SceneDef;

inline constexpr int kMaxPairsPerBody = 128;
inline constexpr int kMaxPairsPerBodyAverage = 32;

// The broad phase's caps for a scene with `movableBodies` movable bodies:
// maxPerBody = kMaxPairsPerBody, maxPairs = kMaxPairsPerBodyAverage * movable + kMaxPairsPerBody.
PairLimits manifoldPairLimits(int movableBodies);

// The status of a step k whose broad phase stopped at a limit (stats.limitHit != None).
StepStatus workLimitStatus(const SceneDef& scene, long k, const PairLimits& limits, const BroadPhaseStats& stats);

} // namespace rbw
