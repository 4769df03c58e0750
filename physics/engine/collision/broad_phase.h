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
//   PairLimits     caps on one AabbTree::findPairs call (the manifold model's work
//                  limits, manifold/work_limits.h): pairs in all, pairs of one movable box
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

#include "physics/engine/collision/contact.h"

#include <utility>
#include <vector>

namespace rbw {

struct Aabb {
    Vec3 min_W = Vec3::Zero();
    Vec3 max_W = Vec3::Zero();
};

// Caps on the pairs one AabbTree::findPairs call reports; 0: no cap.
struct PairLimits {
    long maxPairs = 0;     // pairs in all
    int maxPerBody = 0;    // pairs of one movable box (a pair counts for each movable box in it)
};

// Why a findPairs call stopped before it had every pair.
enum class PairLimitHit { None, Pairs, PairsPerBody };

// Counters of one findPairs call.
struct BroadPhaseStats {
    long pairsTested = 0;        // AABB overlap tests done in the sweep
    long pairsOverlapping = 0;   // pairs reported (= pairs.size())
    // A cap of PairLimits that was exceeded: the search stopped at the first pair beyond
    // it, and `pairs` holds the pairs found until then (limitBody: the box with more
    // pairs than maxPerBody; -1 otherwise).
    PairLimitHit limitHit = PairLimitHit::None;
    int limitBody = -1;
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

// The manifold model's broad phase: a bounding-volume tree over the AABBs, rebuilt in
// every call (top down, each node split at the median centre along the longest side of
// its centres' bounds; Ericson 6.2.1), and the tree tested against itself (Ericson
// 6.3.3, "descend the larger volume"): two subtrees are compared only when their
// bounds overlap, so a pile of n boxes costs about n log n node tests and a few box
// tests per box, where sweep and prune along one axis tests every box against every
// other box of its slab (a 10 x 10 x 10 pile: ~50 000 pair tests, docs/collisions.md).
// The output is the same as SweepAndPrune's: every overlapping pair with a movable box,
// each once, sorted by (i, j). pairsTested counts the box-box AABB tests.
// With `limits`, the search stops at the first pair beyond a cap and says which in
// stats.limitHit: a pile of n coincident boxes has n (n - 1) / 2 overlapping pairs, and
// the caps keep the work and the memory of the call linear in n (Jolt's PhysicsSystem
// likewise takes a maximum of body pairs and reports BodyPairCacheFull beyond it).
// With `resting` (one entry per box, non-zero for a movable box that sleeps), the tree
// holds the other boxes only and each resting box is tested against it (Box2D v3 keeps
// sleeping bodies out of its awake tree likewise): the pairs of two resting boxes, or of
// a resting and a fixed box, are not looked for (a pile asleep costs no tree at all);
// every other pair is found as without it.
class AabbTree {
public:
    void findPairs(const std::vector<Aabb>& boxes, const std::vector<char>& movable,
                   std::vector<std::pair<int, int>>& pairs, BroadPhaseStats& stats,
                   const PairLimits& limits = {}, const std::vector<char>* resting = nullptr);

private:
    struct Node {
        Aabb box;
        int left = -1;    // children (-1 for a leaf)
        int right = -1;
        int first = 0;    // a leaf's boxes: index_[first .. first + count - 1]
        int count = 0;
    };
    int build(const std::vector<Aabb>& boxes, int first, int count);
    void selfPairs(int node);
    void crossPairs(int a, int b);
    void testLeaves(const Node& a, const Node& b);
    void queryBox(int node, int i);   // resting box i against the tree's movable boxes
    bool report(int i, int j);   // adds the pair; false once a cap is exceeded

    std::vector<Node> nodes_;
    std::vector<int> index_;
    std::vector<Vec3> centres_W_;
    // Of the current call:
    const std::vector<Aabb>* boxes_ = nullptr;
    const std::vector<char>* movable_ = nullptr;
    std::vector<std::pair<int, int>>* pairs_ = nullptr;
    BroadPhaseStats* stats_ = nullptr;
    PairLimits limits_;
    std::vector<int> pairsOf_;   // per box: pairs reported so far (with a per-box cap)
};

} // namespace rbw
