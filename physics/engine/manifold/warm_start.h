// Warm starting (Catto, "Iterative dynamics with temporal coherence", GDC 2005;
// Box2D-lite Arbiter::Update): the accumulated impulses of last step's manifold points
// are the first guess of this step's, matched point by point by feature id. A box at
// rest then starts each step with the impulses that held it in the last one, and the
// iterations only have to correct the change.
//
// The cache is part of the world's state (ContactState, WorldSnapshot::contacts): a
// restored snapshot warm-starts its next step exactly as the first run did.
//
// Glossary
//   key            the pair's manifold key (manifold.h)                           [-]
//   feature        a point's feature id                                           [-]
//   lambda_n       last step's accumulated normal impulse                         [N s]
//   lambda_t_W     last step's accumulated friction impulse as a world vector:
//                  lambda_t1 t1 + lambda_t2 t2 (so a turned tangent basis keeps it)  [N s]
#pragma once

#include "physics/engine/manifold/manifold.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace rbw {

class ManifoldCache {
public:
    // Replaces the stored impulses by those of `manifolds` (any order), keeping the
    // stored pairs for which keepOld(key) is true (sleeping pairs, not solved this step).
    // The new contents are built in `spare` and swapped in, so `spare` (scratch, not
    // state) ends up holding the old ones and its storage is reused next time.
    void store(const std::vector<Manifold>& manifolds, const std::function<bool(std::uint64_t)>& keepOld,
               ManifoldCache& spare);
    void clear();
    // The heap bytes it holds (the history's memory budget).
    std::size_t bytes() const { return entries_.capacity() * sizeof(Entry) + points_.capacity() * sizeof(Point); }

    // Sets warm_n, warm_t_W, matched and the starting lambda_n, lambda_t1, lambda_t2 of
    // each of m's points: from the stored point of the same pair with the same feature
    // id, or else the stored point nearest to it on A (|pA_A - pA_A'| <= kMatchDistance,
    // Bullet's contact-cache rule, for a point whose id changed because its features
    // did), projected on m's tangents (lambda_t_i = lambda_t_W . t_i); 0 when there is
    // none. Returns the number of points matched.
    int warmStart(Manifold& m) const;

    std::size_t manifoldCount() const { return entries_.size(); }

private:
    static constexpr double kMatchDistance = 0.02;   // [m]

    struct Point {
        Vec3 pA_A;
        std::uint32_t feature;
        double lambda_n;
        Vec3 lambda_t_W;
    };
    struct Entry {
        std::uint64_t key;
        int first;
        int count;
    };
    std::vector<Entry> entries_;   // sorted by key
    std::vector<Point> points_;
};

} // namespace rbw
