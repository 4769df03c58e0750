#include "app/gui/panels/view/plane_patch.h"

#include "app/gui/panels/view/mesh_primitives.h"

namespace rbw::view {

std::vector<Vec3> clipByHalfSpace(const std::vector<Vec3>& polygon, const Vec3& point_W, const Vec3& n_W)
{
    std::vector<Vec3> out;
    const size_t count = polygon.size();
    for (size_t i = 0; i < count; ++i) {
        const Vec3& a = polygon[i];
        const Vec3& b = polygon[(i + 1) % count];
        // Signed distances d = n . (p - point); inside where d >= 0.
        const double da = n_W.dot(a - point_W);
        const double db = n_W.dot(b - point_W);
        if (da >= 0.0) out.push_back(a);
        if ((da >= 0.0) != (db >= 0.0)) {
            // The edge crosses the boundary at a + s (b - a), s = da / (da - db).
            const double s = da / (da - db);
            out.push_back(a + s * (b - a));
        }
    }
    return out;
}

std::vector<Vec3> planePatch(const std::vector<ViewSnapshot::Plane>& planes, int i, const Vec3& boxMin_W,
                             const Vec3& boxMax_W)
{
    const ViewSnapshot::Plane& plane = planes[static_cast<size_t>(i)];
    const Vec3 n_W = plane.n_W.normalized();
    if (!isFinite(n_W) || !isFinite(plane.point_W)) return {};
    Vec3 u_W;
    Vec3 v_W;
    planeAxes(n_W, u_W, v_W);
    // A square larger than the box, centred on the box centre projected onto the plane.
    const Vec3 centre_W = 0.5 * (boxMin_W + boxMax_W);
    const Vec3 onPlane_W = centre_W - n_W.dot(centre_W - plane.point_W) * n_W;
    const double half = 2.0 * (boxMax_W - boxMin_W).norm() + 1.0;
    std::vector<Vec3> polygon{onPlane_W + half * (-u_W - v_W), onPlane_W + half * (u_W - v_W),
                              onPlane_W + half * (u_W + v_W), onPlane_W + half * (-u_W + v_W)};
    // The other planes' free sides (parallel duplicates of this plane are skipped).
    for (int j = 0; j < static_cast<int>(planes.size()) && polygon.size() >= 3; ++j) {
        if (j == i) continue;
        const Vec3 m_W = planes[static_cast<size_t>(j)].n_W.normalized();
        if (!isFinite(m_W) || std::abs(m_W.dot(n_W)) > 0.999) continue;
        polygon = clipByHalfSpace(polygon, planes[static_cast<size_t>(j)].point_W, m_W);
    }
    // The scene box: six half-spaces.
    for (int axis = 0; axis < 3 && polygon.size() >= 3; ++axis) {
        polygon = clipByHalfSpace(polygon, boxMin_W, Vec3::Unit(axis));
        if (polygon.size() >= 3) polygon = clipByHalfSpace(polygon, boxMax_W, -Vec3::Unit(axis));
    }
    if (polygon.size() < 3) return {};
    return polygon;
}

} // namespace rbw::view
