#include "physics/engine/manifold/manifold.h"

#include <cmath>

namespace rbw {

std::uint64_t manifoldKey(int a, int b, int plane)
{
    // key = a * 2^32 + (b, or 2^31 + plane)
    const std::uint64_t low = b >= 0 ? static_cast<std::uint64_t>(b) : (std::uint64_t{1} << 31) + static_cast<std::uint64_t>(plane);
    return (static_cast<std::uint64_t>(a) << 32) | low;
}

ManifoldKeyParts decodeManifoldKey(std::uint64_t key)
{
    // a = key / 2^32; low = key mod 2^32: b below 2^31, else 2^31 + plane
    ManifoldKeyParts parts;
    parts.a = static_cast<int>(key >> 32);
    const std::uint64_t low = key & 0xffffffffu;
    if (low >= (std::uint64_t{1} << 31)) {
        parts.plane = static_cast<int>(low - (std::uint64_t{1} << 31));
    } else {
        parts.b = static_cast<int>(low);
    }
    return parts;
}

std::uint64_t Manifold::key() const
{
    return manifoldKey(a, b, plane);
}

const char* Manifold::featureName() const
{
    switch (reference) {
    case ReferenceSide::A: return "face-face (reference A)";
    case ReferenceSide::B: return "face-face (reference B)";
    case ReferenceSide::Plane: return "vertex-plane";
    case ReferenceSide::Edge: return "edge-edge";
    }
    return "?";
}

void tangentBasis(const Vec3& n_W, Vec3& t1_W, Vec3& t2_W)
{
    // 1/sqrt(3): some component of a unit vector is at least this large
    constexpr double kInvSqrt3 = 0.57735026918962576451;
    if (std::abs(n_W.x()) >= kInvSqrt3) {
        // t1 = (n_y, -n_x, 0) / |.|
        t1_W = Vec3(n_W.y(), -n_W.x(), 0.0).normalized();
    } else {
        // t1 = (0, n_z, -n_y) / |.|
        t1_W = Vec3(0.0, n_W.z(), -n_W.y()).normalized();
    }
    // t2 = n x t1
    t2_W = n_W.cross(t1_W);
}

} // namespace rbw
