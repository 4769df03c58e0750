// Box-box separating axis test; see box_box_sat.h for the rules and their source.
//
// Glossary
//   a_W[k], b_W[k]   unit face normals (body axes) of A and B, world frame        [-]
//   cornersA_W, ...  the 8 corners of a box in the template's order               [m]
//   Interval         [min, max] of a box's corners projected on an axis           [m]
//   axis_W           the winning axis, oriented so axis_W . toCenter_W > 0        [-]
//   pOne_W, dOne_W   a point on A's edge line and its unit direction (template's
//                    names in contactPoint); pTwo_W, dTwo_W the same for B        [m], [-]
#include "physics/engine/course/box_box_sat.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace rbw {

namespace {

// |a_i x b_j| of two unit vectors is sin(angle); at or below this the edges count
// as parallel and give no axis (the template: length > 0). See box_box_sat.h.
constexpr double kParallelSine = 1e-9;

// The template's parallel-line test in contactPoint(): |denom| < 0.0001, where
// denom = |d1|^2 |d2|^2 - (d1 . d2)^2 = sin^2(angle) for unit directions.
constexpr double kParallelDenominator = 1e-4;

struct Interval {
    double min;
    double max;
};

// Projection of the 8 corners on an axis (template: project()).
//   min = min_k corner_k . axis,  max = max_k corner_k . axis
Interval project(const std::array<Vec3, 8>& corners_W, const Vec3& axis_W)
{
    Interval iv{corners_W[0].dot(axis_W), corners_W[0].dot(axis_W)};
    for (size_t k = 1; k < corners_W.size(); ++k) {
        const double p = corners_W[k].dot(axis_W);
        if (p < iv.min) {
            iv.min = p;
        } else if (p > iv.max) {
            iv.max = p;
        }
    }
    return iv;
}

// Template overlap(): !((p1.max > p2.max && p1.min > p2.max) ||
//                      (p2.max > p1.max && p2.min > p1.max)).
// Since max >= min, p1.min > p2.max already implies p1.max > p2.max, so this is
// "separated iff minA > maxB or minB > maxA"; touching is not separated. Both forms
// also agree for NaN (every comparison false: not separated).
bool separated(const Interval& ivA, const Interval& ivB)
{
    return ivA.min > ivB.max || ivB.min > ivA.max;
}

// Template getOverlap(): min(maxA, maxB) - max(minA, minB).
double overlapOf(const Interval& ivA, const Interval& ivB)
{
    return std::min(ivA.max, ivB.max) - std::max(ivA.min, ivB.min);
}

// Template handleVertexToface(): the first corner with the smallest corner . dir
// (strict <, corners in the template's order). The template starts the search at
// 1000; +infinity makes it work for any position.
Vec3 cornerMinimising(const std::array<Vec3, 8>& corners_W, const Vec3& dir_W)
{
    double best = std::numeric_limits<double>::infinity();
    Vec3 bestCorner_W = corners_W[0];
    for (const Vec3& corner_W : corners_W) {
        const double value = corner_W.dot(dir_W);
        if (value < best) {
            best = value;
            bestCorner_W = corner_W;
        }
    }
    return bestCorner_W;
}

// Template contactPoint() (Millington, Cyclone's contactPoint), for two edge lines
// pOne + mua * dOne and pTwo + mub * dTwo with unit directions:
//   smOne = |dOne|^2, smTwo = |dTwo|^2, dpOneTwo = dOne . dTwo,
//   toSt = pOne - pTwo, dpStaOne = dOne . toSt, dpStaTwo = dTwo . toSt,
//   denom = smOne * smTwo - dpOneTwo^2                       (0 <=> parallel lines)
//   mua = (dpOneTwo * dpStaTwo - smTwo * dpStaOne) / denom
//   mub = (smOne * dpStaTwo - dpOneTwo * dpStaOne) / denom   (closest-point parameters)
// Parallel lines (|denom| < 1e-4), or mua outside [-oneSize, oneSize] or mub outside
// [-twoSize, twoSize]: return pOne if useOne, else pTwo. Otherwise the midpoint of
// the two closest points. The template passes the FULL edge length as oneSize and
// twoSize although pOne, pTwo are edge midpoints (a half length would be exact);
// kept as is.
Vec3 edgeContactPoint(const Vec3& pOne_W, const Vec3& dOne_W, double oneSize, const Vec3& pTwo_W,
                      const Vec3& dTwo_W, double twoSize, bool useOne)
{
    const double smOne = dOne_W.squaredNorm();
    const double smTwo = dTwo_W.squaredNorm();
    const double dpOneTwo = dTwo_W.dot(dOne_W);
    const Vec3 toSt_W = pOne_W - pTwo_W;
    const double dpStaOne = dOne_W.dot(toSt_W);
    const double dpStaTwo = dTwo_W.dot(toSt_W);
    const double denom = smOne * smTwo - dpOneTwo * dpOneTwo;
    if (std::abs(denom) < kParallelDenominator) {
        return useOne ? pOne_W : pTwo_W;
    }
    const double mua = (dpOneTwo * dpStaTwo - smTwo * dpStaOne) / denom;
    const double mub = (smOne * dpStaTwo - dpOneTwo * dpStaOne) / denom;
    if (mua > oneSize || mua < -oneSize || mub > twoSize || mub < -twoSize) {
        return useOne ? pOne_W : pTwo_W;
    }
    const Vec3 cOne_W = pOne_W + dOne_W * mua;
    const Vec3 cTwo_W = pTwo_W + dTwo_W * mub;
    return 0.5 * cOne_W + 0.5 * cTwo_W;
}

} // namespace

std::optional<ContactGeometry> collideBoxBoxSAT(const BoxPose& A, const BoxPose& B)
{
    // Face normals: the body axes, normalised as the template does
    // (getAxisNormalToFaces normalises the rows of the scaled object-to-world matrix).
    std::array<Vec3, 3> a_W;
    std::array<Vec3, 3> b_W;
    for (int k = 0; k < 3; ++k) {
        a_W[static_cast<size_t>(k)] = A.R_WB.col(k).normalized();
        b_W[static_cast<size_t>(k)] = B.R_WB.col(k).normalized();
    }
    const std::array<Vec3, 8> cornersA_W = boxCorners(A);
    const std::array<Vec3, 8> cornersB_W = boxCorners(B);

    // toCenter = c_B - c_A (template getVectorConnnectingCenters).
    const Vec3 toCenter_W = B.c_W - A.c_W;

    double smallOverlap = std::numeric_limits<double>::infinity();
    int bestAxis = -1;
    Vec3 bestAxis_W = Vec3::Zero();
    // Template: true iff at some point one of B's face normals became the running
    // minimum (even if an edge axis wins later). Selects contactPoint()'s fallback.
    bool bestSingleAxis = false;

    // Tests one axis. Returns false if it separates the boxes; otherwise updates the
    // running minimum (strict <: ties keep the earlier axis).
    const auto testAxis = [&](const Vec3& axis_W, int number) -> bool {
        const Interval ivA = project(cornersA_W, axis_W);
        const Interval ivB = project(cornersB_W, axis_W);
        if (separated(ivA, ivB)) {
            return false;
        }
        const double o = overlapOf(ivA, ivB);
        if (o < smallOverlap) {
            smallOverlap = o;
            bestAxis = number;
            bestAxis_W = axis_W;
            if (number >= 3 && number < 6) {
                bestSingleAxis = true;
            }
        }
        return true;
    };

    // Axes 0-2: A's face normals; 3-5: B's.
    for (int k = 0; k < 3; ++k) {
        if (!testAxis(a_W[static_cast<size_t>(k)], k)) {
            return std::nullopt;
        }
    }
    for (int k = 0; k < 3; ++k) {
        if (!testAxis(b_W[static_cast<size_t>(k)], 3 + k)) {
            return std::nullopt;
        }
    }
    // Axes 6 + 3i + j: normalize(a_i x b_j), skipped when |a_i x b_j| <= 1e-9.
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const Vec3 cross_W = a_W[static_cast<size_t>(i)].cross(b_W[static_cast<size_t>(j)]);
            const double length = cross_W.norm();
            if (!(length > kParallelSine)) {
                continue;
            }
            const Vec3 axis_W = cross_W / length;
            if (!testAxis(axis_W, 6 + 3 * i + j)) {
                return std::nullopt;
            }
        }
    }
    if (bestAxis < 0) {
        // Only reachable with non-finite input (every overlap NaN).
        return std::nullopt;
    }

    // Orient the axis along toCenter: flip it when axis . toCenter <= 0 (template).
    Vec3 axis_W = bestAxis_W;
    if (axis_W.dot(toCenter_W) <= 0.0) {
        axis_W = -axis_W;
    }

    ContactGeometry contact;
    contact.axis = bestAxis;
    // depth = the smallest overlap (template: info.depth = smallOverlap).
    contact.depth = smallOverlap;
    // n points from B to A: the negated oriented axis (template: normal * -1).
    contact.n_W = -axis_W;

    if (bestAxis < 3) {
        // A face wins: B's corner with the smallest corner . toCenter.
        contact.p_W = cornerMinimising(cornersB_W, toCenter_W);
        contact.where = std::source_location::current();
        contact.feature = ContactFeature::VertexFace;
    } else if (bestAxis < 6) {
        // B face wins: A's corner with the smallest corner . (-toCenter).
        const Vec3 toA_W = -toCenter_W;
        contact.p_W = cornerMinimising(cornersA_W, toA_W);
        contact.where = std::source_location::current();
        contact.feature = ContactFeature::FaceVertex;
    } else {
        const int i = (bestAxis - 6) / 3;
        const int j = (bestAxis - 6) % 3;
        // Template edge choice, in body coordinates of a unit box (+-0.5 = +-h):
        //   A: coordinate i = 0 (edge along a_i, through its midpoint); for k != i
        //      -h_k if a_k . axis < 0 else +h_k (A's edge furthest towards B);
        //   B: coordinate j = 0; for k != j -h_k if b_k . axis > 0 else +h_k
        //      (B's edge furthest towards A).
        Vec3 pOne_W = A.c_W;
        Vec3 pTwo_W = B.c_W;
        for (int k = 0; k < 3; ++k) {
            const size_t kk = static_cast<size_t>(k);
            if (k != i) {
                const double sA = a_W[kk].dot(axis_W) < 0.0 ? -1.0 : 1.0;
                pOne_W += (sA * A.halfExtents[k]) * A.R_WB.col(k);
            }
            if (k != j) {
                const double sB = b_W[kk].dot(axis_W) > 0.0 ? -1.0 : 1.0;
                pTwo_W += (sB * B.halfExtents[k]) * B.R_WB.col(k);
            }
        }
        // Sizes: full edge lengths 2 h (template getBoxSize), as the template passes.
        const double oneSize = 2.0 * A.halfExtents[i];
        const double twoSize = 2.0 * B.halfExtents[j];
        contact.p_W = edgeContactPoint(pOne_W, a_W[static_cast<size_t>(i)], oneSize, pTwo_W,
                                       b_W[static_cast<size_t>(j)], twoSize, bestSingleAxis);
        contact.where = std::source_location::current();
        contact.feature = ContactFeature::EdgeEdge;
    }
    return contact;
}

} // namespace rbw
