// Broad phase: sweep and prune over world axis-aligned bounding boxes. It finds the
// pairs of boxes whose AABBs overlap, so that the exact (and costly) narrow phase
// runs only on those.
//
// Glossary
//   Aabb           axis-aligned bounding box, world frame: [min_W, max_W]          [m]
//   h_j            a box's half extent along its body axis j                       [m]
//   e_k            the AABB's half extent along world axis k                       [m]
//   movable        per box: non-zero if the body moves (a free body); fixed bodies
//                  (walls, ground) never collide with each other
//   sorted order   the box indices sorted by min_W.x(), kept between calls
//   pairsTested    AABB overlap tests done in the sweep
//   pairsOverlapping   pairs reported
//
// Rules:
//   - Tight AABB of an oriented box (e.g. Ericson, "Real-Time Collision Detection",
//     4.2.6): e_k = sum_j |R_WB(k, j)| h_j, the AABB is c_W -+ e.
//   - Two AABBs overlap iff on each world axis min_a <= max_b and min_b <= max_a.
//     Touching boundaries count as overlapping, consistent with the SAT narrow phase,
//     where touching is a collision of depth 0.
//   - Sweep and prune (Baraff 1992; Ericson 7.5.2) along x: walk the boxes in order
//     of min_W.x(); the candidates for box i are the boxes after it in that order
//     whose min_W.x() <= i's max_W.x(); each candidate gets one full AABB test.
//   - The sorted order persists between calls and is repaired with insertion sort,
//     which is O(n + number of swaps): for the nearly sorted order of consecutive
//     frames that is O(n), where a fresh sort would be O(n log n).
#pragma once

#include "physics/collision/contact.h"

#include <utility>
#include <vector>

namespace rbw {

struct Aabb {
    Vec3 min_W = Vec3::Zero();
    Vec3 max_W = Vec3::Zero();
};

// Counters of one findPairs call.
struct BroadPhaseStats {
    long pairsTested = 0;        // AABB overlap tests done in the sweep
    long pairsOverlapping = 0;   // pairs reported (= pairs.size())
};

// The tightest AABB of an oriented box: c_W -+ e, e_k = sum_j |R_WB(k, j)| h_j.
Aabb boxAabb(const BoxPose& box);

// AABB overlap test; touching boundaries count as overlapping.
bool aabbOverlap(const Aabb& a, const Aabb& b);

class SweepAndPrune {
public:
    // Clears `pairs` and fills it with every pair (i, j), i < j, of boxes whose AABBs
    // overlap and of which at least one is movable, each pair once, sorted by i then
    // j (so the order does not depend on the sweep order). A pair of two fixed boxes
    // is skipped before its AABB test and is not counted in pairsTested. `movable`
    // has one entry per box. `stats` is overwritten with this call's counters. The
    // boxes must be finite. The number of boxes may change between calls: indices
    // beyond the new count are dropped from the sorted order, new ones appended.
    void findPairs(const std::vector<Aabb>& boxes, const std::vector<char>& movable,
                   std::vector<std::pair<int, int>>& pairs, BroadPhaseStats& stats);

    // Forgets the persistent order (the next call sorts from scratch).
    void reset() { order_.clear(); }

    // The box indices in order of min_W.x() after the last call.
    const std::vector<int>& order() const { return order_; }

private:
    std::vector<int> order_;
};

} // namespace rbw
