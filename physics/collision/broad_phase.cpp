// Sweep and prune over world AABBs; see broad_phase.h for the rules and sources.
//
// Glossary
//   e_W        half extents of the AABB along the world axes                   [m]
//   order_     box indices sorted by min_W.x(), persistent between calls
//   key(i)     boxes[i].min_W.x(), the sort key                                 [m]
#include "physics/collision/broad_phase.h"

#include <algorithm>
#include <cassert>
#include <cstddef>

namespace rbw {

Aabb boxAabb(const BoxPose& box)
{
    // Ericson 4.2.6: the half extent along world axis k of a box with rotation R and
    // half extents h is e_k = sum_j |R(k, j)| h_j, i.e. e = |R| h.
    const Vec3 e_W = box.R_WB.cwiseAbs() * box.halfExtents;
    Aabb aabb;
    aabb.min_W = box.c_W - e_W;
    aabb.max_W = box.c_W + e_W;
    return aabb;
}

bool aabbOverlap(const Aabb& a, const Aabb& b)
{
    // Overlap iff min_a <= max_b and min_b <= max_a on every world axis (touching counts).
    for (int k = 0; k < 3; ++k) {
        if (a.min_W[k] > b.max_W[k] || b.min_W[k] > a.max_W[k]) {
            return false;
        }
    }
    return true;
}

void SweepAndPrune::findPairs(const std::vector<Aabb>& boxes, const std::vector<char>& movable,
                              std::vector<std::pair<int, int>>& pairs, BroadPhaseStats& stats)
{
    assert(movable.size() == boxes.size());
    pairs.clear();
    stats = BroadPhaseStats{};
    const int n = static_cast<int>(boxes.size());

    // Keep the persistent order for the boxes that still exist; append new ones.
    if (static_cast<int>(order_.size()) != n) {
        std::erase_if(order_, [n](int index) { return index >= n; });
        std::vector<char> present(static_cast<std::size_t>(n), 0);
        for (int index : order_) {
            present[static_cast<std::size_t>(index)] = 1;
        }
        for (int index = 0; index < n; ++index) {
            if (!present[static_cast<std::size_t>(index)]) {
                order_.push_back(index);
            }
        }
    }

    // Insertion sort by key(i) = min_W.x(): O(n + swaps); stable, so equal keys keep
    // the order they had in the previous frame.
    const auto key = [&boxes](int index) { return boxes[static_cast<std::size_t>(index)].min_W.x(); };
    for (int a = 1; a < n; ++a) {
        const int moving = order_[static_cast<std::size_t>(a)];
        const double movingKey = key(moving);
        int b = a - 1;
        while (b >= 0 && key(order_[static_cast<std::size_t>(b)]) > movingKey) {
            order_[static_cast<std::size_t>(b + 1)] = order_[static_cast<std::size_t>(b)];
            --b;
        }
        order_[static_cast<std::size_t>(b + 1)] = moving;
    }

    // Sweep along x: every box after i in the order with min_x(j) <= max_x(i) overlaps
    // i on x (min_x(i) <= min_x(j) by the sort); the first with min_x(j) > max_x(i)
    // ends i's candidates, since all later ones start even further right.
    for (int a = 0; a < n; ++a) {
        const int i = order_[static_cast<std::size_t>(a)];
        const Aabb& boxI = boxes[static_cast<std::size_t>(i)];
        for (int b = a + 1; b < n; ++b) {
            const int j = order_[static_cast<std::size_t>(b)];
            const Aabb& boxJ = boxes[static_cast<std::size_t>(j)];
            if (boxJ.min_W.x() > boxI.max_W.x()) {
                break;
            }
            if (!movable[static_cast<std::size_t>(i)] && !movable[static_cast<std::size_t>(j)]) {
                continue;
            }
            ++stats.pairsTested;
            if (aabbOverlap(boxI, boxJ)) {
                pairs.emplace_back(std::min(i, j), std::max(i, j));
            }
        }
    }

    std::sort(pairs.begin(), pairs.end());
    stats.pairsOverlapping = static_cast<long>(pairs.size());
}

} // namespace rbw
