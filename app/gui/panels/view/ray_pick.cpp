#include "app/gui/panels/view/ray_pick.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rbw {

std::optional<double> rayBoxHit(const Ray& ray, const Vec3& x_W, const Mat3& R_WB, const Vec3& h_B)
{
    // Into the body frame: o_B = R^T (o - x), d_B = R^T d.
    const Vec3 o_B = R_WB.transpose() * (ray.origin_W - x_W);
    const Vec3 d_B = R_WB.transpose() * ray.dir_W;
    double tEnter = 0.0;
    double tExit = std::numeric_limits<double>::infinity();
    for (int j = 0; j < 3; ++j) {
        if (std::abs(d_B[j]) < 1e-15) {
            // Parallel to slab j: inside it or never.
            if (std::abs(o_B[j]) > h_B[j]) return std::nullopt;
            continue;
        }
        // Slab j, |p_j| <= h_j, is crossed between t = (-h_j - o_j)/d_j and (h_j - o_j)/d_j.
        double t0 = (-h_B[j] - o_B[j]) / d_B[j];
        double t1 = (h_B[j] - o_B[j]) / d_B[j];
        if (t0 > t1) std::swap(t0, t1);
        tEnter = std::max(tEnter, t0);
        tExit = std::min(tExit, t1);
        if (tEnter > tExit) return std::nullopt;
    }
    return tEnter;
}

std::optional<double> rayPlaneHit(const Ray& ray, const Vec3& point_W, const Vec3& n_W)
{
    // n . (o + t d - point) = 0  ->  t = n . (point - o) / (n . d)
    const double denom = n_W.dot(ray.dir_W);
    if (std::abs(denom) < 1e-12) return std::nullopt;
    const double t = n_W.dot(point_W - ray.origin_W) / denom;
    if (!(t >= 0.0) || !std::isfinite(t)) return std::nullopt;
    return t;
}

std::optional<BoxHit> pickBody(const Ray& ray, const ViewSnapshot& snap)
{
    std::optional<BoxHit> best;
    for (int b = 0; b < static_cast<int>(snap.bodies.size()); ++b) {
        const ViewSnapshot::Body& body = snap.bodies[b];
        if (!body.finite) continue;
        const std::optional<double> t = rayBoxHit(ray, body.x_W, body.R_WB, 0.5 * body.size);
        if (t && (!best || *t < best->t)) {
            best = BoxHit{b, ray.origin_W + *t * ray.dir_W, *t};
        }
    }
    return best;
}

} // namespace rbw
