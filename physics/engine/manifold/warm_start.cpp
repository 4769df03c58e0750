#include "physics/engine/manifold/warm_start.h"

#include <algorithm>

namespace rbw {

void ManifoldCache::clear()
{
    entries_.clear();
    points_.clear();
}

void ManifoldCache::store(const std::vector<Manifold>& manifolds, const std::function<bool(std::uint64_t)>& keepOld,
                          ManifoldCache& spare)
{
    // The kept entries first, with their points, from the old arrays.
    std::vector<Entry>& keptEntries = spare.entries_;
    std::vector<Point>& keptPoints = spare.points_;
    keptEntries.clear();
    keptPoints.clear();
    for (const Entry& e : entries_) {
        if (!keepOld(e.key)) continue;
        keptEntries.push_back(Entry{e.key, static_cast<int>(keptPoints.size()), e.count});
        keptPoints.insert(keptPoints.end(), points_.begin() + e.first, points_.begin() + e.first + e.count);
    }
    entries_.swap(keptEntries);
    points_.swap(keptPoints);
    for (const Manifold& m : manifolds) {
        if (m.count == 0) continue;
        entries_.push_back(Entry{m.key(), static_cast<int>(points_.size()), m.count});
        for (int k = 0; k < m.count; ++k) {
            const ManifoldPoint& p = m.points[static_cast<std::size_t>(k)];
            // lambda_t_W = lambda_t1 t1 + lambda_t2 t2
            const Vec3 lambda_t_W = p.lambda_t1 * m.t1_W + p.lambda_t2 * m.t2_W;
            points_.push_back(Point{p.pA_A, p.feature, p.lambda_n, lambda_t_W});
        }
    }
    std::sort(entries_.begin(), entries_.end(), [](const Entry& x, const Entry& y) { return x.key < y.key; });
}

int ManifoldCache::warmStart(Manifold& m) const
{
    const std::uint64_t key = m.key();
    const auto it = std::lower_bound(entries_.begin(), entries_.end(), key,
                                     [](const Entry& e, std::uint64_t k) { return e.key < k; });
    const bool found = it != entries_.end() && it->key == key;
    int matched = 0;
    for (int k = 0; k < m.count; ++k) {
        ManifoldPoint& p = m.points[static_cast<std::size_t>(k)];
        p.warm_n = 0.0;
        p.warm_t_W = Vec3::Zero();
        p.matched = false;
        if (found) {
            // By feature id, else the nearest old point on A within kMatchDistance.
            int best = -1;
            double bestDistance2 = kMatchDistance * kMatchDistance;
            for (int j = it->first; j < it->first + it->count; ++j) {
                const Point& old = points_[static_cast<std::size_t>(j)];
                if (old.feature == p.feature) {
                    best = j;
                    break;
                }
                const double d2 = (old.pA_A - p.pA_A).squaredNorm();
                if (d2 <= bestDistance2) {
                    bestDistance2 = d2;
                    best = j;
                }
            }
            if (best >= 0) {
                const Point& old = points_[static_cast<std::size_t>(best)];
                p.warm_n = old.lambda_n;
                // the part of the old friction impulse in this step's tangent plane
                p.warm_t_W = old.lambda_t_W - old.lambda_t_W.dot(m.n_W) * m.n_W;
                p.matched = true;
                ++matched;
            }
        }
        // lambda_n = lambda_n^0 (the friction's lambda_t^0 is put on the tangents that
        // ContactSolver::prepare chooses)
        p.lambda_n = p.warm_n;
        p.lambda_t1 = 0.0;
        p.lambda_t2 = 0.0;
    }
    return matched;
}

} // namespace rbw
