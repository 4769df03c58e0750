// Sweep and prune over world AABBs; see broad_phase.h for the rules and sources.
//
// Glossary
//   e_W        half extents of the AABB along the world axes                   [m]
//   order_     box indices sorted by min_W.x(), persistent between calls
//   key(i)     boxes[i].min_W.x(), the sort key                                 [m]
#include "physics/engine/collision/broad_phase.h"

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

namespace {

constexpr int kLeafSize = 2;   // boxes per leaf of the AABB tree

// The AABB that holds a and b.
Aabb merged(const Aabb& a, const Aabb& b)
{
    return Aabb{a.min_W.cwiseMin(b.min_W), a.max_W.cwiseMax(b.max_W)};
}

} // namespace

void AabbTree::findPairs(const std::vector<Aabb>& boxes, const std::vector<char>& movable,
                         std::vector<std::pair<int, int>>& pairs, BroadPhaseStats& stats, const PairLimits& limits,
                         const std::vector<char>* resting)
{
    assert(movable.size() == boxes.size());
    assert(resting == nullptr || resting->size() == boxes.size());
    pairs.clear();
    stats = BroadPhaseStats{};
    nodes_.clear();
    const int n = static_cast<int>(boxes.size());
    if (n < 2) return;
    index_.clear();
    centres_W_.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        if (resting != nullptr && (*resting)[static_cast<std::size_t>(i)]) continue;
        index_.push_back(i);
        // the sort key of a box: its AABB's centre (min + max) / 2
        centres_W_[static_cast<std::size_t>(i)] =
            0.5 * (boxes[static_cast<std::size_t>(i)].min_W + boxes[static_cast<std::size_t>(i)].max_W);
    }
    boxes_ = &boxes;
    movable_ = &movable;
    pairs_ = &pairs;
    stats_ = &stats;
    limits_ = limits;
    if (limits.maxPerBody > 0) pairsOf_.assign(static_cast<std::size_t>(n), 0);
    const int members = static_cast<int>(index_.size());
    if (members > 0) {
        nodes_.reserve(static_cast<std::size_t>(2 * members));
        const int root = build(boxes, 0, members);
        selfPairs(root);
        // Each resting box against the tree, in the order of the boxes
        for (int i = 0; resting != nullptr && i < n && stats.limitHit == PairLimitHit::None; ++i) {
            if ((*resting)[static_cast<std::size_t>(i)]) queryBox(root, i);
        }
    }
    std::sort(pairs.begin(), pairs.end());
    stats.pairsOverlapping = static_cast<long>(pairs.size());
}

int AabbTree::build(const std::vector<Aabb>& boxes, int first, int count)
{
    const int id = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    Aabb box = boxes[static_cast<std::size_t>(index_[static_cast<std::size_t>(first)])];
    Vec3 lo_W = centres_W_[static_cast<std::size_t>(index_[static_cast<std::size_t>(first)])];
    Vec3 hi_W = lo_W;
    for (int k = first + 1; k < first + count; ++k) {
        const int i = index_[static_cast<std::size_t>(k)];
        box = merged(box, boxes[static_cast<std::size_t>(i)]);
        lo_W = lo_W.cwiseMin(centres_W_[static_cast<std::size_t>(i)]);
        hi_W = hi_W.cwiseMax(centres_W_[static_cast<std::size_t>(i)]);
    }
    nodes_[static_cast<std::size_t>(id)].box = box;
    if (count <= kLeafSize) {
        nodes_[static_cast<std::size_t>(id)].first = first;
        nodes_[static_cast<std::size_t>(id)].count = count;
        return id;
    }
    // Split at the median centre along the longest side of the centres' bounds; ties
    // broken by index, so the tree does not depend on the sort's implementation.
    int axis = 0;
    const Vec3 extent_W = hi_W - lo_W;
    if (extent_W.y() > extent_W[axis]) axis = 1;
    if (extent_W.z() > extent_W[axis]) axis = 2;
    const int half = count / 2;
    const auto begin = index_.begin() + first;
    std::nth_element(begin, begin + half, begin + count, [this, axis](int a, int b) {
        const double ka = centres_W_[static_cast<std::size_t>(a)][axis];
        const double kb = centres_W_[static_cast<std::size_t>(b)][axis];
        return ka < kb || (ka == kb && a < b);
    });
    const int left = build(boxes, first, half);
    const int right = build(boxes, first + half, count - half);
    nodes_[static_cast<std::size_t>(id)].left = left;
    nodes_[static_cast<std::size_t>(id)].right = right;
    return id;
}

void AabbTree::testLeaves(const Node& a, const Node& b)
{
    for (int x = a.first; x < a.first + a.count; ++x) {
        const int i = index_[static_cast<std::size_t>(x)];
        // Within one leaf, each pair once.
        const int yFirst = (&a == &b) ? x + 1 : b.first;
        for (int y = yFirst; y < b.first + b.count; ++y) {
            const int j = index_[static_cast<std::size_t>(y)];
            if (!(*movable_)[static_cast<std::size_t>(i)] && !(*movable_)[static_cast<std::size_t>(j)]) continue;
            ++stats_->pairsTested;
            if (aabbOverlap((*boxes_)[static_cast<std::size_t>(i)], (*boxes_)[static_cast<std::size_t>(j)]) &&
                !report(i, j)) {
                return;
            }
        }
    }
}

bool AabbTree::report(int i, int j)
{
    pairs_->emplace_back(std::min(i, j), std::max(i, j));
    if (limits_.maxPerBody > 0) {
        for (const int box : {i, j}) {
            if (!(*movable_)[static_cast<std::size_t>(box)]) continue;
            if (++pairsOf_[static_cast<std::size_t>(box)] > limits_.maxPerBody) {
                stats_->limitHit = PairLimitHit::PairsPerBody;
                stats_->limitBody = box;
                return false;
            }
        }
    }
    if (limits_.maxPairs > 0 && static_cast<long>(pairs_->size()) > limits_.maxPairs) {
        stats_->limitHit = PairLimitHit::Pairs;
        return false;
    }
    return true;
}

void AabbTree::selfPairs(int node)
{
    if (stats_->limitHit != PairLimitHit::None) return;
    const Node& nd = nodes_[static_cast<std::size_t>(node)];
    if (nd.left < 0) {
        testLeaves(nd, nd);
        return;
    }
    selfPairs(nd.left);
    selfPairs(nd.right);
    crossPairs(nd.left, nd.right);
}

void AabbTree::queryBox(int node, int i)
{
    if (stats_->limitHit != PairLimitHit::None) return;
    const Node& nd = nodes_[static_cast<std::size_t>(node)];
    const Aabb& box = (*boxes_)[static_cast<std::size_t>(i)];
    if (!aabbOverlap(nd.box, box)) return;
    if (nd.left >= 0) {
        queryBox(nd.left, i);
        queryBox(nd.right, i);
        return;
    }
    for (int y = nd.first; y < nd.first + nd.count; ++y) {
        const int j = index_[static_cast<std::size_t>(y)];
        if (!(*movable_)[static_cast<std::size_t>(j)]) continue;   // resting and fixed: never woken
        ++stats_->pairsTested;
        if (aabbOverlap(box, (*boxes_)[static_cast<std::size_t>(j)]) && !report(i, j)) return;
    }
}

void AabbTree::crossPairs(int a, int b)
{
    if (stats_->limitHit != PairLimitHit::None) return;
    const Node& na = nodes_[static_cast<std::size_t>(a)];
    const Node& nb = nodes_[static_cast<std::size_t>(b)];
    if (!aabbOverlap(na.box, nb.box)) return;
    if (na.left < 0 && nb.left < 0) {
        testLeaves(na, nb);
        return;
    }
    // Descend the larger volume (Ericson 6.3.3); a leaf is never descended.
    const double volA = (na.box.max_W - na.box.min_W).prod();
    const double volB = (nb.box.max_W - nb.box.min_W).prod();
    if (nb.left < 0 || (na.left >= 0 && volA >= volB)) {
        crossPairs(na.left, b);
        crossPairs(na.right, b);
    } else {
        crossPairs(a, nb.left);
        crossPairs(a, nb.right);
    }
}

} // namespace rbw
