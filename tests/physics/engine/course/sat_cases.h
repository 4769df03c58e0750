// The box-box SAT tests' shared cases (tst_sat.cpp: collisions; tst_sat_symmetry.cpp:
// no collision, swapping A and B, equally rotated boxes): the configurations, each
// derived in its comment, and an independent projection to check the hand claims with.
//
// Notation. c = s = cos 45 = sin 45 = 1/sqrt 2. A box is (centre, rotation, half
// extents h). Axis numbers: 0-2 A's faces a_0..a_2, 3-5 B's faces b_0..b_2, 6 + 3i + j
// the edge pair normalize(a_i x b_j). n points from B to A; the oriented axis is -n.
//
// Independent check. Besides the hand values, every collision row also checks the
// hand claim "this axis wins" with an independent projection (support function,
// not the implementation's corner loop): a box's extent on a unit axis u is
//   c_W . u -+ sum_j h_j |R_WB.col(j) . u|          (Ericson 4.4, the OBB radius),
// and the overlap is min(maxA, maxB) - max(minA, minB). The expected axis must have
// the smallest overlap, every earlier axis a strictly larger one (by > 1e-12).
//
// Tolerances. Expected values are exact numbers; the code gets them from rotations
// built with cos/sin of pi/4 etc. rounded to doubles and sums of a few products of
// size <= 10, so the errors are a few 1e-16 (relative) times the scale. 1e-12
// absolute leaves > 3 orders of magnitude of headroom; the smallest difference a
// wrong rule could make in these rows is 1e-9 (the "sunk by 1e-9" row), usually
// 1e-2 or more. Rows built from exactly representable numbers only (the reference
// case shifted to touching, the template's case 1) use tolerance 0: touching there is
// exact, and the depth must come out exactly 0.
#pragma once

#include "tests/test_support.h"

#include "physics/engine/course/box_box_sat.h"

#include <QMetaType>
#include <QString>

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

Q_DECLARE_METATYPE(rbw::Vec3)
Q_DECLARE_METATYPE(rbw::BoxPose)

namespace sat_test {

using rbw::BoxPose;
using rbw::ContactFeature;
using rbw::ContactGeometry;
using rbw::Mat3;
using rbw::Vec3;

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kSqrt2 = std::numbers::sqrt2;
inline constexpr double kSqrt3 = std::numbers::sqrt3;

inline Mat3 rotation(double angle, const Vec3& axis)
{
    return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

using rbw::test::box;

inline BoxPose unitCube(const Vec3& c, const Mat3& R = Mat3::Identity())
{
    return box(c, R, Vec3::Constant(0.5));
}

// The same box moved rigidly by the rotation Q about the world origin.
inline BoxPose rotated(const Mat3& Q, const BoxPose& b)
{
    return box(Q * b.c_W, Q * b.R_WB, b.halfExtents);
}

inline QString vecText(const Vec3& v)
{
    return QStringLiteral("(%1, %2, %3)").arg(v.x(), 0, 'g', 17).arg(v.y(), 0, 'g', 17).arg(v.z(), 0, 'g', 17);
}

inline bool near(const Vec3& a, const Vec3& b, double tol)
{
    return (a - b).cwiseAbs().maxCoeff() <= tol;
}

// The 15 candidate axes (unit), or nullopt for an edge pair with |a_i x b_j| <= 1e-9
// (the implementation's documented skip rule).
inline std::optional<Vec3> candidateAxis(const BoxPose& A, const BoxPose& B, int k)
{
    if (k < 3) {
        return Vec3(A.R_WB.col(k).normalized());
    }
    if (k < 6) {
        return Vec3(B.R_WB.col(k - 3).normalized());
    }
    const int i = (k - 6) / 3;
    const int j = (k - 6) % 3;
    const Vec3 cross = A.R_WB.col(i).normalized().cross(B.R_WB.col(j).normalized());
    if (cross.norm() <= 1e-9) {
        return std::nullopt;
    }
    return Vec3(cross.normalized());
}

// Overlap on axis k by the support function (see the file comment); +inf if skipped.
inline double independentOverlap(const BoxPose& A, const BoxPose& B, int k)
{
    const std::optional<Vec3> u = candidateAxis(A, B, k);
    if (!u) {
        return std::numeric_limits<double>::infinity();
    }
    const auto radius = [&u](const BoxPose& b) {
        double r = 0.0;
        for (int j = 0; j < 3; ++j) {
            r += b.halfExtents[j] * std::abs(b.R_WB.col(j).dot(*u));
        }
        return r;
    };
    const double cA = A.c_W.dot(*u);
    const double cB = B.c_W.dot(*u);
    const double rA = radius(A);
    const double rB = radius(B);
    return std::min(cA + rA, cB + rB) - std::max(cA - rA, cB - rB);
}

// --- The configurations, shared by several tests ---------------------------------

// Reference case (docs/references.md §2): unit cubes, A at the origin, B at (0.9, 0.2, 0.1).
inline BoxPose refA() { return unitCube(Vec3::Zero()); }
inline BoxPose refB() { return unitCube(Vec3(0.9, 0.2, 0.1)); }

// Edge pair: A is a unit cube at the origin rotated 45 deg about x, so its top edge
// runs along x at height h sqrt2 = sqrt2/2. B is a unit cube rotated 45 deg about z,
// its bottom edge along z at height c_B.y - sqrt2/2. With c_B = (0, sqrt2 - d, 0) the
// edges cross (in plan) at the origin, B's edge d below A's.
inline BoxPose edgeA() { return unitCube(Vec3::Zero(), rotation(kPi / 4, Vec3::UnitX())); }
inline BoxPose edgeB(double d) { return unitCube(Vec3(0.0, kSqrt2 - d, 0.0), rotation(kPi / 4, Vec3::UnitZ())); }

// Vertex-face: A is a slab, half extents (2, 0.5, 2), at the origin (top face y = 0.5).
// B is a unit cube turned so that its body diagonal is vertical with corner (-,-,-)
// at the bottom: R maps (-1,-1,-1)/sqrt3 to (0,-1,0). That corner lies sqrt3/2 below
// c_B, so with c_B = (0, 0.5 + sqrt3/2 - d, 0) it is at (0, 0.5 - d, 0), d inside A.
inline Mat3 diagonalDown()
{
    return rbw::Quat::FromTwoVectors(Vec3(-1, -1, -1).normalized(), Vec3(0, -1, 0)).toRotationMatrix();
}
inline BoxPose slabA() { return box(Vec3::Zero(), Mat3::Identity(), Vec3(2.0, 0.5, 2.0)); }
inline BoxPose vertexB(double d) { return unitCube(Vec3(0.0, 0.5 + kSqrt3 / 2 - d, 0.0), diagonalDown()); }

// B face: A a unit cube at the origin; B a cube of half extent 1 rotated 45 deg about
// z, so b_0 = (c, s, 0). Its centre is A's corner (1/2, 1/2, z) plus t b_0, t = 1 - d:
// B's -b_0 face then passes d beyond that corner.
inline BoxPose bFaceA() { return unitCube(Vec3::Zero()); }
inline BoxPose bFaceB(double d)
{
    const Vec3 b0(1.0 / kSqrt2, 1.0 / kSqrt2, 0.0);
    return box(Vec3(0.5, 0.5, 0.0) + (1.0 - d) * b0, rotation(kPi / 4, Vec3::UnitZ()), Vec3::Constant(1.0));
}

// Parallel-edge fallback: A has half extents (LA, 0.5, 0.5) rotated 45 deg about x
// (top edge along x at y = sqrt2/2); B has (LB, 0.5, 0.5), rotated 45 deg about x and
// then by phi = 0.5 deg about y (its bottom edge stays horizontal, turned by phi),
// centred at (0, sqrt2 - d, 0).
inline constexpr double kPhi = 0.5 * kPi / 180.0;
inline BoxPose fallbackA(double LA) { return box(Vec3::Zero(), rotation(kPi / 4, Vec3::UnitX()), Vec3(LA, 0.5, 0.5)); }
inline BoxPose fallbackB(double LB, double d)
{
    return box(Vec3(0.0, kSqrt2 - d, 0.0), rotation(kPhi, Vec3::UnitY()) * rotation(kPi / 4, Vec3::UnitX()),
               Vec3(LB, 0.5, 0.5));
}

// A generic rigid rotation for the "rotated" rows.
inline Mat3 Q() { return rotation(0.7, Vec3(1, 2, 2)); }

// The TUM template's testCheckCollision case 2: A has size (9, 2, 3) at (0.2, 5, 1),
// B has size (s, s, 2) rotated 45 deg about z at the origin.
inline BoxPose case2A(double sink) { return box(Vec3(0.2, 5.0 - sink, 1.0), Mat3::Identity(), Vec3(4.5, 1.0, 1.5)); }
inline BoxPose case2B(double size) { return box(Vec3::Zero(), rotation(kPi / 4, Vec3::UnitZ()), Vec3(size / 2, size / 2, 1.0)); }

// The template's case 3: A size (2.829, 2.829, 2) rotated 45 deg about z at (-2, 0, 1);
// B size (9, 2, 4) rotated 90 deg about z at (1, 0.5, 0).
inline BoxPose case3A() { return box(Vec3(-2.0, 0.0, 1.0), rotation(kPi / 4, Vec3::UnitZ()), Vec3(1.4145, 1.4145, 1.0)); }
inline BoxPose case3B() { return box(Vec3(1.0, 0.5, 0.0), rotation(kPi / 2, Vec3::UnitZ()), Vec3(4.5, 1.0, 2.0)); }

} // namespace sat_test
