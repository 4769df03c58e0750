// Contact geometry: what a narrow phase reports about two touching shapes, before
// any response is computed.
//
// Glossary
//   p_W     the contact point, world frame                                      [m]
//   n_W     unit normal pointing from B to A: the direction of the impulse on A  [-]
//           (TUM collisionDetect.h: "the negative of the collision face of A")
//   depth   penetration along n (the smallest SAT overlap; for a plane, how far
//           the corner lies below it). Not used by the impulse.                  [m]
#pragma once

#include "physics/engine/math_types.h"

#include <array>
#include <source_location>
#include <string>

namespace rbw {

// Which features touch. VertexFace: a corner of B on a face of A; FaceVertex: a
// corner of A on a face of B; EdgeEdge: an edge of A against an edge of B;
// VertexPlane: a corner of a box below a fixed plane (B is the plane).
enum class ContactFeature { VertexFace, FaceVertex, EdgeEdge, VertexPlane };

const char* featureName(ContactFeature f);   // "vertex-face", "face-vertex", "edge-edge", "vertex-plane"

struct ContactGeometry {
    Vec3 p_W = Vec3::Zero();
    Vec3 n_W = Vec3::Zero();
    double depth = 0.0;
    ContactFeature feature = ContactFeature::VertexFace;
    int axis = -1;   // SAT: the winning axis, 0-2 A faces, 3-5 B faces, 6-14 edge pairs (3*i + j)
    std::source_location where;   // the narrow-phase statement that computed p (trace rows of p, n, d)
};

// An oriented box in the world: centre, rotation (columns are the body axes in
// world coordinates) and half extents along the body axes.
struct BoxPose {
    Vec3 c_W = Vec3::Zero();
    Mat3 R_WB = Mat3::Identity();
    Vec3 halfExtents = Vec3::Constant(0.5);
};

// The 8 corners of a box in the world, in the TUM template's order (collisionDetect.h,
// getCorners): corner k has the sign - or + along body x, y, z given by bits 0, 1, 2
// of k, i.e. ---, +--, -+-, ++-, --+, +-+, -++, +++. Tie-breaking rules that pick
// "the first" corner depend on this order.
//   corner_k = c_W + sum_j s_j(k) * h_j * R_WB.col(j),  s_j(k) = bit j of k ? +1 : -1
inline std::array<Vec3, 8> boxCorners(const BoxPose& box)
{
    std::array<Vec3, 8> corners_W;
    for (int k = 0; k < 8; ++k) {
        Vec3 corner_W = box.c_W;
        for (int j = 0; j < 3; ++j) {
            const double s = ((k >> j) & 1) ? 1.0 : -1.0;
            corner_W += (s * box.halfExtents[j]) * box.R_WB.col(j);
        }
        corners_W[static_cast<size_t>(k)] = corner_W;
    }
    return corners_W;
}

// A fixed plane { p : n . (p - point) = 0 }; the free side is where n points.
struct PlaneDef {
    std::string name;
    Vec3 point_W = Vec3::Zero();
    Vec3 n_W = Vec3::UnitY();   // unit
};

} // namespace rbw
