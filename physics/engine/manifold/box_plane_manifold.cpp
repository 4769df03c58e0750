#include "physics/engine/manifold/box_plane_manifold.h"

namespace rbw {

bool collideBoxPlaneManifold(const BoxPose& box, const PlaneDef& plane, double margin, Manifold& m)
{
    m.count = 0;
    m.reference = ReferenceSide::Plane;
    m.n_W = plane.n_W;
    m.nRef_R = plane.n_W;   // the plane never turns: its frame is the world's
    const std::array<Vec3, 8> corners_W = boxCorners(box);
    for (int k = 0; k < 8; ++k) {
        const Vec3& corner_W = corners_W[static_cast<std::size_t>(k)];
        // s = n . (corner - point); <= 0 on or below the plane
        const double s = plane.n_W.dot(corner_W - plane.point_W);
        if (s > margin) continue;
        ManifoldPoint& pt = m.points[static_cast<std::size_t>(m.count++)];
        pt = ManifoldPoint{};
        // p_B = corner - s n (on the plane); p = (corner + p_B) / 2
        const Vec3 pB_W = corner_W - s * plane.n_W;
        pt.p_W = 0.5 * (corner_W + pB_W);
        m.where = std::source_location::current();
        pt.separation = s;
        pt.pA_A = box.R_WB.transpose() * (corner_W - box.c_W);
        pt.pB_B = pB_W;
        pt.feature = static_cast<std::uint32_t>(k);
    }
    if (m.count == 0) return false;
    tangentBasis(m.n_W, m.t1_W, m.t2_W);
    return true;
}

} // namespace rbw
