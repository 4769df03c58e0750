// Inertia of a solid box, and the world-frame inverse inertia built from it.
//
// Glossary
//   size = (a, b, c)  edge lengths along the body axes x, y, z           [m]
//   M                 mass                                                [kg]
//   I0_B              body-frame inertia tensor, diagonal for a box      [kg m^2]
//   I0inv_B           its inverse                                         [1/(kg m^2)]
//   R_WB              rotation matrix of the body orientation r_WB
//   Iinv_W            world-frame inverse inertia                         [1/(kg m^2)]
#pragma once

#include "physics/engine/math_types.h"

namespace rbw {

// How the world inverse inertia is assembled from R and I0^-1.
//   Standard:       Iinv_W = R I0^-1 R^T (physically correct; TUM slides, Napier practical 7).
//   CourseTemplate: Iinv_W = R^T I0^-1 R (what the TUM template's reference solution
//                   effectively computes; docs/references.md §1).
enum class InertiaConvention { Standard, CourseTemplate };

// I0 = M/12 * diag(b^2 + c^2, a^2 + c^2, a^2 + b^2)
// (TUM exercise 2 tip 4; Napier practical 7: diag(m(h^2+d^2)/12, m(w^2+d^2)/12, m(w^2+h^2)/12)).
Mat3 boxInertiaBody(const Vec3& size, double mass);

// Iinv_W = R I0^-1 R^T (or R^T I0^-1 R for the course-template convention).
// I0inv_B must be diagonal (the body frame is the principal frame).
Mat3 inverseInertiaWorld(const Mat3& R_WB, const Mat3& I0inv_B,
                         InertiaConvention convention = InertiaConvention::Standard);

} // namespace rbw
