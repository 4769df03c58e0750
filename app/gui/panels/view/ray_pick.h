// Ray casts for picking in the 3D view: a ray against an oriented box (slab test in
// the box's frame) and against a plane.
//
// Glossary
//   x_W, R_WB   box centre and rotation (columns: body axes in W)     [m], [-]
//   h_B         half extents along the body axes                       [m]
//   t           ray parameter: hit point = origin_W + t dir_W          [m]
#pragma once

#include "app/gui/panels/view/orbit_camera.h"
#include "app/gui/panels/view/view_snapshot.h"

#include <optional>

namespace rbw {

// The nearest t >= 0 at which the ray enters the box (t = 0 if it starts inside);
// nothing if it misses. Kay & Kajiya's slab test, done in the body frame.
std::optional<double> rayBoxHit(const Ray& ray, const Vec3& x_W, const Mat3& R_WB, const Vec3& h_B);

// The t >= 0 at which the ray meets the plane n . (p - point) = 0; nothing if the
// ray is parallel to it or points away.
std::optional<double> rayPlaneHit(const Ray& ray, const Vec3& point_W, const Vec3& n_W);

struct BoxHit {
    int body = -1;
    Vec3 hit_W = Vec3::Zero();
    double t = 0.0;
};

// The nearest body of the snapshot the ray hits (non-finite bodies are skipped).
std::optional<BoxHit> pickBody(const Ray& ray, const ViewSnapshot& snap);

} // namespace rbw
