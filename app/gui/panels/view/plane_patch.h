// The finite piece of an infinite plane that the view draws: a large square on the
// plane, clipped by the free half-space of every other plane (so the ground ends at
// the walls and the walls stand on the ground) and by a box around the scene.
#pragma once

#include "app/gui/panels/view/view_snapshot.h"

#include <vector>

namespace rbw::view {

// Keeps the part of a convex polygon where n . (p - point) >= 0 (Sutherland-Hodgman
// against one half-space).
std::vector<Vec3> clipByHalfSpace(const std::vector<Vec3>& polygon, const Vec3& point_W, const Vec3& n_W);

// The convex polygon (corners in order) drawn for planes[i]; empty if nothing of it
// lies inside the box [boxMin_W, boxMax_W] and the other planes' free sides.
std::vector<Vec3> planePatch(const std::vector<ViewSnapshot::Plane>& planes, int i, const Vec3& boxMin_W,
                             const Vec3& boxMax_W);

} // namespace rbw::view
