// Box-box narrow phase: the separating axis test of the TUM course template
// (GamePhysicsTUM/gamephysicstemplate, Simulations/collisionDetect.h,
// checkCollisionSAT), reproduced rule for rule in double precision.
//
// Glossary
//   A, B        the two boxes; the result describes A's contact with B
//   c_W         box centre, world frame                                          [m]
//   R_WB        box rotation; its columns a_k (box A) / b_k (box B) are the body
//               axes and face normals in world coordinates                       [-]
//   h           half extents along the body axes                                 [m]
//   toCenter_W  c_B - c_A                                                        [m]
//   axis        a candidate separating direction (unit), numbered 0-14:
//               0-2 A's face normals a_0..a_2, 3-5 B's face normals b_0..b_2,
//               6 + 3i + j the edge-pair axis normalize(a_i x b_j)
//   overlap     min(maxA, maxB) - max(minA, minB) of the two boxes' projections on
//               an axis                                                          [m]
//   n_W         result normal, unit, pointing from B to A (direction of the impulse
//               on A); n_W = -axis, with the axis oriented so axis . toCenter > 0
//   p_W         the single contact point                                         [m]
//   depth       the smallest overlap over all tested axes                         [m]
//
// The rules (docs/references.md §2, and the template's source):
//   1. Axes in the order a_0, a_1, a_2, b_0, b_1, b_2, then a_i x b_j (i outer,
//      j inner), normalised. Cross products with |a_i x b_j| <= 1e-9 (the sine of
//      the angle between two unit edge directions) are skipped: parallel edges
//      give no new axis. The template skips only an exactly zero length; in double
//      precision a rotation built from a quaternion leaves ~1e-16 of noise in
//      "parallel" directions, whose normalised cross product is an arbitrary
//      direction, so a small threshold is used instead.
//   2. All 8 corners of each box are projected on the axis. The boxes are
//      separated on it iff minA > maxB or minB > maxA (the template's overlap());
//      touching (minA == maxB) is a collision with overlap 0. One separating axis
//      ends the test: no collision.
//   3. The best axis is the one with strictly the smallest overlap; ties go to the
//      earlier axis in the order above.
//   4. The contact point depends on the class of the best axis:
//      - a face of A: the corner of B with the smallest corner . toCenter
//        (feature VertexFace);
//      - a face of B: the corner of A with the smallest corner . (-toCenter)
//        (feature FaceVertex);
//      - an edge pair (i, j): the midpoint of the closest points of the edge line
//        of A along a_i and the edge line of B along b_j, the edges picked as the
//        ones furthest along the oriented axis (A) and against it (B); with the
//        template's fallback to one edge's midpoint when the lines are parallel or
//        a closest point lies outside the range it checks (feature EdgeEdge).
//      Corners are enumerated in the template's order (see boxCorners in
//      contact.h) and the first smallest wins.
//
// Known limits (the template's, kept on purpose so results match the course):
//   - One contact point only. A box resting on a face touches with four corners;
//     this test reports one of them, so resting contact jitters and a stack of
//     boxes never fully comes to rest.
//   - Edge-edge handling is approximate: the edges are chosen by sign tests, the
//     range check uses the full edge length instead of the half length, and the
//     fallback point is an edge midpoint, not a true closest point.
//   - The vertex-face point is chosen along toCenter, not along the face normal,
//     so for boxes far from centred on each other it may not be the deepest corner.
//   - The overlap on an axis where one projection contains the other is the length
//     of the inner one, not the distance needed to separate the boxes.
//   - Boxes with parallel axes (e.g. two boxes with the same orientation): then
//     a_i x b_j for i != j is +-a_k, a duplicate of a face normal with the same
//     overlap in exact arithmetic. Axis-aligned, the duplicate is exact and the face
//     (earlier) wins; for a generic common orientation the normalised cross product
//     differs from a_k by ~1e-16 and rounding decides: in about 60% of random
//     orientations of the reference case an edge axis wins by ~1e-16. n and depth
//     are then unchanged (to ~1e-16), but the point comes from the edge construction,
//     whose sign tests see dot products of ~1e-17, and may even lie outside A. The
//     template has the same behaviour (worse in float).
//   - Deliberate differences from the template: double instead of float; the
//     running minimum starts at +infinity instead of 10000 and the corner search at
//     +infinity instead of 1000 (the template returns garbage for overlaps or
//     corner . toCenter beyond those); the winning edge pair is tracked as (i, j)
//     directly (the template's whichEdges index counts only the non-skipped cross
//     products, so its i = whichEdges / 3, j = whichEdges % 3 pick the wrong edges
//     once a cross product has been skipped).
#pragma once

#include "physics/engine/collision/contact.h"

#include <optional>

namespace rbw {

// A's contact with B, or nullopt when some tested axis separates them (or the input
// is not finite). On a collision the result has p_W, n_W (B -> A), depth >= 0, the
// feature and the winning axis number 0-14.
std::optional<ContactGeometry> collideBoxBoxSAT(const BoxPose& A, const BoxPose& B);

} // namespace rbw
