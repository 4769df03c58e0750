#include "app/gui/panels/view/mesh_primitives.h"

#include <array>
#include <cmath>

namespace rbw::view {

namespace {

constexpr double kPi = 3.14159265358979323846;

LitVertex lit(const Vec3& p, const Vec3& n, Rgba c)
{
    return LitVertex{{float(p.x()), float(p.y()), float(p.z())},
                     {float(n.x()), float(n.y()), float(n.z())},
                     {c.r, c.g, c.b, c.a}};
}

void triangle(std::vector<LitVertex>& out, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& n, Rgba colour)
{
    out.push_back(lit(a, n, colour));
    out.push_back(lit(b, n, colour));
    out.push_back(lit(c, n, colour));
}

// Corner k of a box, in the TUM corner order of physics/engine/collision/contact.h:
// bit j of k set means + along body axis j.
Vec3 corner(const Vec3& x_W, const Mat3& R_WB, const Vec3& h_B, int k)
{
    const Vec3 s((k & 1) ? 1.0 : -1.0, (k & 2) ? 1.0 : -1.0, (k & 4) ? 1.0 : -1.0);
    return x_W + R_WB * s.cwiseProduct(h_B);
}

} // namespace

void appendBox(std::vector<LitVertex>& out, const Vec3& x_W, const Mat3& R_WB, const Vec3& size, Rgba colour)
{
    const Vec3 h_B = 0.5 * size;
    // Each face: the body axis it faces (+/-) and its four corners, counter-clockwise
    // seen from outside.
    struct Face {
        int axis;
        double sign;
        std::array<int, 4> k;
    };
    static constexpr std::array<Face, 6> faces{{
        {0, +1.0, {1, 3, 7, 5}},
        {0, -1.0, {0, 4, 6, 2}},
        {1, +1.0, {2, 6, 7, 3}},
        {1, -1.0, {0, 1, 5, 4}},
        {2, +1.0, {4, 5, 7, 6}},
        {2, -1.0, {0, 2, 3, 1}},
    }};
    for (const Face& f : faces) {
        const Vec3 n_W = f.sign * R_WB.col(f.axis);
        const Vec3 c0 = corner(x_W, R_WB, h_B, f.k[0]);
        const Vec3 c1 = corner(x_W, R_WB, h_B, f.k[1]);
        const Vec3 c2 = corner(x_W, R_WB, h_B, f.k[2]);
        const Vec3 c3 = corner(x_W, R_WB, h_B, f.k[3]);
        triangle(out, c0, c1, c2, n_W, colour);
        triangle(out, c0, c2, c3, n_W, colour);
    }
}

void appendBoxEdges(std::vector<LineVertex>& out, const Vec3& x_W, const Mat3& R_WB, const Vec3& size, Rgba colour)
{
    const Vec3 h_B = 0.5 * size;
    // Corners k and k ^ (1 << j) share an edge along axis j.
    for (int k = 0; k < 8; ++k) {
        for (int j = 0; j < 3; ++j) {
            const int other = k ^ (1 << j);
            if (other > k) appendLine(out, corner(x_W, R_WB, h_B, k), corner(x_W, R_WB, h_B, other), colour);
        }
    }
}

void appendArrow(std::vector<LitVertex>& out, const Vec3& origin_W, const Vec3& vec_W, double radius, Rgba colour)
{
    const double length = vec_W.norm();
    if (!(length > 1e-9) || !std::isfinite(length) || !isFinite(origin_W)) return;
    const Vec3 dir = vec_W / length;
    Vec3 u;
    Vec3 v;
    planeAxes(dir, u, v);
    // Head: a cone of radius 2.4 r and length min(0.35 L, 7 r); the shaft fills the rest.
    const double headLength = std::min(0.35 * length, 7.0 * radius);
    const double headRadius = 2.4 * radius;
    const Vec3 neck = origin_W + (length - headLength) * dir;
    const Vec3 tip = origin_W + vec_W;
    constexpr int kSides = 10;
    for (int s = 0; s < kSides; ++s) {
        const double a0 = 2.0 * kPi * s / kSides;
        const double a1 = 2.0 * kPi * (s + 1) / kSides;
        const Vec3 r0 = std::cos(a0) * u + std::sin(a0) * v;
        const Vec3 r1 = std::cos(a1) * u + std::sin(a1) * v;
        const Vec3 rm = (r0 + r1).normalized();
        // Shaft side: a quad between the origin and the neck, facing outwards.
        const Vec3 b0 = origin_W + radius * r0;
        const Vec3 b1 = origin_W + radius * r1;
        const Vec3 t0 = neck + radius * r0;
        const Vec3 t1 = neck + radius * r1;
        triangle(out, b0, b1, t1, rm, colour);
        triangle(out, b0, t1, t0, rm, colour);
        // Cone side: normal tilted towards the tip by the cone's half-angle.
        const Vec3 h0 = neck + headRadius * r0;
        const Vec3 h1 = neck + headRadius * r1;
        const Vec3 coneN = (headLength * rm + headRadius * dir).normalized();
        triangle(out, h0, h1, tip, coneN, colour);
        // Cone base, facing back.
        triangle(out, h1, h0, neck, -dir, colour);
    }
}

void appendBall(std::vector<LitVertex>& out, const Vec3& p_W, double radius, Rgba colour)
{
    if (!isFinite(p_W) || !(radius > 0.0)) return;
    constexpr int kSlices = 8;
    constexpr int kStacks = 6;
    auto point = [&](int i, int j) {
        const double theta = kPi * j / kStacks;   // from +y down to -y
        const double phi = 2.0 * kPi * i / kSlices;
        return Vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    };
    for (int j = 0; j < kStacks; ++j) {
        for (int i = 0; i < kSlices; ++i) {
            const Vec3 a = point(i, j);
            const Vec3 b = point(i + 1, j);
            const Vec3 c = point(i + 1, j + 1);
            const Vec3 d = point(i, j + 1);
            // Smooth shading: the normal of a sphere point is the point itself.
            out.push_back(lit(p_W + radius * a, a, colour));
            out.push_back(lit(p_W + radius * c, c, colour));
            out.push_back(lit(p_W + radius * b, b, colour));
            out.push_back(lit(p_W + radius * a, a, colour));
            out.push_back(lit(p_W + radius * d, d, colour));
            out.push_back(lit(p_W + radius * c, c, colour));
        }
    }
}

void appendLine(std::vector<LineVertex>& out, const Vec3& a_W, const Vec3& b_W, Rgba c)
{
    if (!isFinite(a_W) || !isFinite(b_W)) return;
    out.push_back(LineVertex{{float(a_W.x()), float(a_W.y()), float(a_W.z())}, {c.r, c.g, c.b, c.a}});
    out.push_back(LineVertex{{float(b_W.x()), float(b_W.y()), float(b_W.z())}, {c.r, c.g, c.b, c.a}});
}

void planeAxes(const Vec3& n_W, Vec3& u_W, Vec3& v_W)
{
    // Cross n with a world axis far from it, so the product is well conditioned.
    // For a ground with n = +y: v = y x x = -z, u = v x n = +x.
    const Vec3 a = std::abs(n_W.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    v_W = n_W.cross(a).normalized();
    u_W = v_W.cross(n_W);
}

} // namespace rbw::view
