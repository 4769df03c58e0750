// Vertex formats of the 3D view and the shapes built from them: boxes, arrows,
// marker balls and line segments, appended to CPU-side arrays that the renderer
// uploads in one buffer per kind (so 50 boxes are one draw call).
#pragma once

#include "app/gui/panels/view/view_style.h"
#include "physics/engine/math_types.h"

#include <vector>

namespace rbw::view {

// A lit triangle vertex: position and normal in the world frame, colour.
struct LitVertex {
    float p[3];
    float n[3];
    float c[4];
};

// A line vertex: position in the world frame, colour.
struct LineVertex {
    float p[3];
    float c[4];
};

// A vertex of a plane patch: world position and the coordinates (u, v) along the
// plane's two in-plane axes, for the checker pattern.
struct PlaneVertex {
    float p[3];
    float uv[2];
    float c[4];
};

// The 12 triangles of a box of edge lengths `size` at x_W with rotation R_WB.
void appendBox(std::vector<LitVertex>& out, const Vec3& x_W, const Mat3& R_WB, const Vec3& size, Rgba colour);

// The 12 edges of the same box as lines.
void appendBoxEdges(std::vector<LineVertex>& out, const Vec3& x_W, const Mat3& R_WB, const Vec3& size, Rgba colour);

// A solid arrow from origin_W to origin_W + vec_W: a prism shaft and a cone head.
// `radius` is the shaft radius; nothing is added for a (near) zero vector.
void appendArrow(std::vector<LitVertex>& out, const Vec3& origin_W, const Vec3& vec_W, double radius, Rgba colour);

// A small ball (a UV sphere of 8 x 6 facets) at p_W.
void appendBall(std::vector<LitVertex>& out, const Vec3& p_W, double radius, Rgba colour);

void appendLine(std::vector<LineVertex>& out, const Vec3& a_W, const Vec3& b_W, Rgba colour);

// Two unit vectors u, v with (u, v, n) right-handed, for a unit normal n.
void planeAxes(const Vec3& n_W, Vec3& u_W, Vec3& v_W);

} // namespace rbw::view
