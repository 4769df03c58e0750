// Box-plane narrow phase: the corners of a box that lie on or below a fixed plane
// (Napier SET09119 practical 6, docs/references.md §4), and the rigid-body
// assessment's single averaged contact.
//
// Glossary
//   corner_W    one of the box's 8 corners, world frame                          [m]
//   d           signed distance of a corner from the plane,
//               d = n_plane . (corner_W - point_W); > 0 on the free side           [m]
//   p_W         contact point = the corner itself                                [m]
//   n_W         contact normal = the plane normal. The box is body A and the plane
//               body B, so n points from the plane to the box, as contact.h asks   [-]
//   depth       -d, how far the corner lies below the plane (>= 0)               [m]
//
// Touching counts: a corner with d <= 0 is a contact (depth 0 when d == 0). This is
// consistent with the SAT test, where touching is a collision with overlap 0. A box
// resting exactly on its face therefore reports 4 contacts of depth 0; the impulse
// response decides by the relative velocity whether anything happens.
#pragma once

#include "physics/engine/collision/contact.h"

#include <cstddef>
#include <vector>

namespace rbw {

// Appends one VertexPlane contact per corner of `box` with d <= 0 to `out`, corners in
// the order of boxCorners() (contact.h), and returns how many were appended (0-8;
// a box landing on a vertex, an edge or a face gives 1, 2 or 4). `plane.n_W` must be
// unit length.
int collideBoxPlane(const BoxPose& box, const PlaneDef& plane, std::vector<ContactGeometry>& out);

// The Napier assessment's single contact for a box against a plane: the mean of the
// points out[first .. first + count - 1], the normal of the first of them (they share
// the plane normal), the largest depth, feature VertexPlane. Requires count >= 1 and
// first + count <= contacts.size().
ContactGeometry averageContact(const std::vector<ContactGeometry>& contacts, std::size_t first,
                               std::size_t count);

} // namespace rbw
