// box_box_sat.h: the TUM template's box-box test checkCollisionSAT (docs/references.md
// §2), as the reference simulator uses it: the separating axis with the smallest
// overlap, the normal from B to A and one contact point (a corner, or the closest
// points of two edges). README.md, "Choices where the contract leaves room", says where
// it follows the template's rules rather than its code.
#pragma once

#include "vec_math.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rbwref {

template <typename Real>
struct Contact {
    Vec3<Real> p_W;   // the one contact point
    Vec3<Real> n_W;   // unit normal from B to A (the direction of the impulse on A)
    Real depth = 0;   // the smallest overlap (not used by the impulse)
    int axis = -1;    // winning axis: 0-2 faces of A, 3-5 faces of B, 6 + 3i + j edges a_i x b_j
};

template <typename Real>
struct Box {
    Vec3<Real> c_W;      // centre
    Mat3<Real> R_WB;     // columns: the body axes in the world
    Vec3<Real> h;        // half extents
};

// The 8 corners in the template's order: corner k has sign -/+ along body x, y, z
// by bits 0, 1, 2 of k.  corner_k = c + sum_j s_j(k) h_j R.col(j)
template <typename Real> void boxCorners(const Box<Real>& box, Vec3<Real> corners_W[8])
{
    const Real h[3] = {box.h.x, box.h.y, box.h.z};
    for (int k = 0; k < 8; ++k) {
        Vec3<Real> corner_W = box.c_W;
        for (int j = 0; j < 3; ++j) {
            const Real s = ((k >> j) & 1) ? Real(1) : Real(-1);
            corner_W = corner_W + box.R_WB.col(j) * (s * h[j]);
        }
        corners_W[k] = corner_W;
    }
}

// [min, max] of corner . axis over the 8 corners (template project()).
template <typename Real> void project(const Vec3<Real> corners_W[8], const Vec3<Real>& axis_W, Real& lo, Real& hi)
{
    lo = hi = dot(corners_W[0], axis_W);
    for (int k = 1; k < 8; ++k) {
        const Real p = dot(corners_W[k], axis_W);
        if (p < lo) {
            lo = p;
        } else if (p > hi) {
            hi = p;
        }
    }
}

// The first corner with the smallest corner . dir (template handleVertexToface()).
template <typename Real> Vec3<Real> cornerMinimising(const Vec3<Real> corners_W[8], const Vec3<Real>& dir_W)
{
    Real best = std::numeric_limits<Real>::infinity();
    Vec3<Real> bestCorner_W = corners_W[0];
    for (int k = 0; k < 8; ++k) {
        const Real value = dot(corners_W[k], dir_W);
        if (value < best) {
            best = value;
            bestCorner_W = corners_W[k];
        }
    }
    return bestCorner_W;
}

// Closest points of the lines pOne + mua dOne and pTwo + mub dTwo (template contactPoint()):
//   denom = |dOne|^2 |dTwo|^2 - (dOne.dTwo)^2; parallel (|denom| < 1e-4) or a parameter
//   outside [-size, size]: pOne if useOne else pTwo; otherwise the midpoint of the two
//   closest points.
template <typename Real>
Vec3<Real> edgeContactPoint(const Vec3<Real>& pOne, const Vec3<Real>& dOne, Real oneSize, const Vec3<Real>& pTwo,
                            const Vec3<Real>& dTwo, Real twoSize, bool useOne)
{
    const Real smOne = dot(dOne, dOne);
    const Real smTwo = dot(dTwo, dTwo);
    const Real dpOneTwo = dot(dTwo, dOne);
    const Vec3<Real> toSt = pOne - pTwo;
    const Real dpStaOne = dot(dOne, toSt);
    const Real dpStaTwo = dot(dTwo, toSt);
    const Real denom = smOne * smTwo - dpOneTwo * dpOneTwo;
    if (std::abs(denom) < Real(1e-4)) return useOne ? pOne : pTwo;
    const Real mua = (dpOneTwo * dpStaTwo - smTwo * dpStaOne) / denom;
    const Real mub = (smOne * dpStaTwo - dpOneTwo * dpStaOne) / denom;
    if (mua > oneSize || mua < -oneSize || mub > twoSize || mub < -twoSize) return useOne ? pOne : pTwo;
    const Vec3<Real> cOne = pOne + dOne * mua;
    const Vec3<Real> cTwo = pTwo + dTwo * mub;
    return cOne * Real(0.5) + cTwo * Real(0.5);
}

// A's contact with B; false when an axis separates them.
template <typename Real> bool collideBoxes(const Box<Real>& A, const Box<Real>& B, Contact<Real>& contact)
{
    // An edge pair whose |a_i x b_j| is at most this is parallel and gives no axis.
    const Real parallelSine = sizeof(Real) == sizeof(float) ? Real(1e-6) : Real(1e-9);
    Vec3<Real> a_W[3], b_W[3];
    for (int k = 0; k < 3; ++k) {
        a_W[k] = A.R_WB.col(k) / norm(A.R_WB.col(k));
        b_W[k] = B.R_WB.col(k) / norm(B.R_WB.col(k));
    }
    Vec3<Real> cornersA_W[8], cornersB_W[8];
    boxCorners(A, cornersA_W);
    boxCorners(B, cornersB_W);
    const Vec3<Real> toCenter_W = B.c_W - A.c_W;

    Real smallOverlap = std::numeric_limits<Real>::infinity();
    int bestAxis = -1;
    Vec3<Real> bestAxis_W;
    bool bestSingleAxis = false;   // a face of B was the running minimum at some point
    // overlap = min(maxA, maxB) - max(minA, minB); separated iff minA > maxB or minB > maxA.
    // Strict < keeps the earlier axis on a tie.
    auto testAxis = [&](const Vec3<Real>& axis_W, int number) -> bool {
        Real minA, maxA, minB, maxB;
        project(cornersA_W, axis_W, minA, maxA);
        project(cornersB_W, axis_W, minB, maxB);
        if (minA > maxB || minB > maxA) return false;
        const Real o = std::min(maxA, maxB) - std::max(minA, minB);
        if (o < smallOverlap) {
            smallOverlap = o;
            bestAxis = number;
            bestAxis_W = axis_W;
            if (number >= 3 && number < 6) bestSingleAxis = true;
        }
        return true;
    };
    for (int k = 0; k < 3; ++k)
        if (!testAxis(a_W[k], k)) return false;
    for (int k = 0; k < 3; ++k)
        if (!testAxis(b_W[k], 3 + k)) return false;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const Vec3<Real> cross_W = cross(a_W[i], b_W[j]);
            const Real length = norm(cross_W);
            if (!(length > parallelSine)) continue;
            if (!testAxis(cross_W / length, 6 + 3 * i + j)) return false;
        }
    }
    if (bestAxis < 0) return false;   // only with non-finite input

    // Orient the axis along toCenter; n = -axis points from B to A.
    Vec3<Real> axis_W = bestAxis_W;
    if (dot(axis_W, toCenter_W) <= 0) axis_W = axis_W * Real(-1);
    contact.axis = bestAxis;
    contact.depth = smallOverlap;
    contact.n_W = axis_W * Real(-1);
    if (bestAxis < 3) {
        // A face of A: B's corner with the smallest corner . toCenter.
        contact.p_W = cornerMinimising(cornersB_W, toCenter_W);
    } else if (bestAxis < 6) {
        // A face of B: A's corner with the smallest corner . (-toCenter).
        contact.p_W = cornerMinimising(cornersA_W, toCenter_W * Real(-1));
    } else {
        // Edge pair (i, j): A's edge along a_i furthest along the axis, B's edge along
        // b_j furthest against it (through their midpoints), then their closest points.
        const int i = (bestAxis - 6) / 3;
        const int j = (bestAxis - 6) % 3;
        const Real hA[3] = {A.h.x, A.h.y, A.h.z};
        const Real hB[3] = {B.h.x, B.h.y, B.h.z};
        Vec3<Real> pOne_W = A.c_W;
        Vec3<Real> pTwo_W = B.c_W;
        for (int k = 0; k < 3; ++k) {
            if (k != i) {
                const Real sA = dot(a_W[k], axis_W) < 0 ? Real(-1) : Real(1);
                pOne_W = pOne_W + A.R_WB.col(k) * (sA * hA[k]);
            }
            if (k != j) {
                const Real sB = dot(b_W[k], axis_W) > 0 ? Real(-1) : Real(1);
                pTwo_W = pTwo_W + B.R_WB.col(k) * (sB * hB[k]);
            }
        }
        // The template passes the full edge lengths as the parameter ranges.
        contact.p_W = edgeContactPoint(pOne_W, a_W[i], 2 * hA[i], pTwo_W, b_W[j], 2 * hB[j], bestSingleAxis);
    }
    return true;
}

}   // namespace rbwref
