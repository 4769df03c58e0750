// Box-box contact manifolds by face clipping (the manifold model's narrow phase).
//
// Method (Catto, "Contact manifolds", GDC 2007, and Box2D-lite's Collide(); ODE's
// dBoxBox; Ericson, "Real-Time Collision Detection", 4.4 and 5.1.9; Gregorius,
// "The separating axis test between convex polyhedra", GDC 2013; docs/references.md
// §10, §15, §17):
//   1. Separating axes: the 3 face normals of A, the 3 of B and the 9 edge directions
//      A_i x B_j. On axis L the separation is  s = |d . L| - (r_A + r_B),
//      d = c_B - c_A, r = sum_k h_k |L . axis_k|. Any s > margin: no contact.
//   2. The axis of largest s wins, with a bias towards faces (a face of B must beat a
//      face of A by s_B > 0.98 s_A + 0.001 m, an edge pair both by 0.98 s_face + 0.001 m),
//      so that a box resting flat keeps its face-face manifold from step to step.
//   3. Face axis: the box that owns it gives the reference face (outward normal
//      n_ref), the other box its incident face (the face whose outward normal is most
//      anti-parallel to n_ref). The incident face's 4 corners are clipped against the 4
//      side planes of the reference face (Sutherland-Hodgman); each clipped vertex
//      with separation s = n_ref . p - o_ref <= margin is a point: up to 8.
//   4. Edge axis: one point, the closest points of the two edges (Ericson 5.1.9).
//
// Feature ids (the warm-start key, Box2D-lite's FeaturePair): a clipped vertex lies on
// two "lines": incident edges (labels 0-3) and reference side planes (4-7); its id is
//   ((ref * 6 + refFace) * 6 + incFace) * 64 + 8 lo + hi
// with ref 0 for A and 1 for B, faces 2 axis + (sign > 0), lo < hi its two labels. An
// edge-edge point has id 2^16 + 12 edgeA + edgeB.
//
// n_W points from B to A, as in the course model (contact.h).
#pragma once

#include "physics/engine/collision/contact.h"
#include "physics/engine/manifold/manifold.h"

#include <array>

namespace rbw {

// A polygon vertex while clipping: its point and the two lines it lies on.
struct ClipVertex {
    Vec3 p_W = Vec3::Zero();
    int line0 = 0;
    int line1 = 0;
};

struct ClipPolygon {
    std::array<ClipVertex, 12> v{};
    int n = 0;
};

// Sutherland-Hodgman: the part of `in` with m . p <= o; a vertex made by the cut lies on
// the edge's line and on the plane's line `label`.
void clipPolygon(const ClipPolygon& in, const Vec3& m_W, double o, int label, ClipPolygon& out);

// Fills m's reference, n_W, nRef_R, count and points (p, pA_A, pB_B, separation,
// feature), and the tangents; returns false (count 0) when the boxes are apart by more
// than `margin` on some axis. m.a, m.b, mu and c are the caller's. More clipped points
// than maxPoints (1-8) are reduced to maxPoints by reduceManifold().
bool collideBoxBoxManifold(const BoxPose& A, const BoxPose& B, double margin, Manifold& m,
                           int maxPoints = kMaxManifoldPoints);

// Keeps at most maxPoints (>= 1) of m's points, chosen as ODE's cullPoints and Bullet's
// sortCachedPoints do: the deepest point, then the one farthest from it, then the two
// that span the largest triangles on either side of that line (signed area about n);
// a 4-point manifold then covers nearly all of the clipped polygon's area, which is
// what holds a box up, with half the constraints of an octagon.
void reduceManifold(Manifold& m, int maxPoints);

} // namespace rbw
