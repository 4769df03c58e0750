// A contact manifold: every point at which two shapes touch (or are about to touch),
// each with the feature id that lets the next step find "the same" point again, and
// the accumulated impulses the solver keeps per point (Catto, "Iterative dynamics with
// temporal coherence", GDC 2005; Box2D-lite Arbiter; docs/references.md §9, §17).
//
// Glossary (A is the first body; B the second body or a fixed plane)
//   n_W          unit normal from B to A: the direction of the normal impulse on A    [-]
//   t1_W, t2_W   unit tangents, t2 = n x t1 (t1, t2, n is right-handed)               [-]
//   pA_A         the point on A's surface, in A's body frame                          [m]
//   pB_B         the point on B's surface, in B's body frame (world frame for a plane) [m]
//   p_W          the manifold point: the middle of pA and pB, world frame            [m]
//   s            separation n . (pA - pB); < 0: the shapes overlap by -s = d          [m]
//   r_A_W, r_B_W lever arms p - x_A, p - x_B                                          [m]
//   m_n, m_t1, m_t2   effective masses along n, t1, t2                                 [kg]
//   v_target     the normal velocity the solver aims at (bounce, speculative)        [m/s]
//   lambda_n     accumulated normal impulse, >= 0                                     [N s]
//   lambda_t1, lambda_t2   accumulated friction impulses, |(l_t1, l_t2)| <= mu lambda_n [N s]
//   feature      which features made the point (warm-start key, manifold.cpp)        [-]
#pragma once

#include "physics/engine/math_types.h"

#include <array>
#include <cstdint>
#include <source_location>

namespace rbw {

// Which body the reference face belongs to (the face whose plane the other body's
// incident face is clipped against); a plane is always B.
enum class ReferenceSide { A, B, Plane, Edge };

struct ManifoldPoint {
    // Geometry (narrow phase)
    Vec3 p_W = Vec3::Zero();
    Vec3 pA_A = Vec3::Zero();
    Vec3 pB_B = Vec3::Zero();
    double separation = 0.0;
    std::uint32_t feature = 0;
    // Solver (contact_solver.cpp, ContactSolver::prepare and store; for the trace)
    Vec3 r_A_W = Vec3::Zero();
    Vec3 r_B_W = Vec3::Zero();
    double normalVelocity = 0.0;   // v_n at the start of the step
    double m_n = 0.0, m_t1 = 0.0, m_t2 = 0.0;
    double v_target = 0.0;
    double lambda_n = 0.0, lambda_t1 = 0.0, lambda_t2 = 0.0;
    // Soft step (soft_step_solver.cpp, store): the step's impulse, summed over substeps
    double P_n = 0.0;
    Vec3 P_t_W = Vec3::Zero();
    // Warm start (warm_start.cpp): what was carried over from the last step
    double warm_n = 0.0;
    Vec3 warm_t_W = Vec3::Zero();
    bool matched = false;
};

inline constexpr int kMaxManifoldPoints = 8;

struct Manifold {
    int a = -1;
    int b = -1;       // -1 when B is a plane
    int plane = -1;   // index into SceneDef::planes, or -1
    ReferenceSide reference = ReferenceSide::A;
    Vec3 n_W = Vec3::UnitY();
    Vec3 nRef_R = Vec3::UnitY();   // n in the reference body's frame (outward), for the position fix
    Vec3 t1_W = Vec3::UnitX();
    Vec3 t2_W = Vec3::UnitZ();
    double mu = 0.0;
    double restitution = 0.0;
    int count = 0;
    std::array<ManifoldPoint, kMaxManifoldPoints> points{};
    std::source_location where;   // the narrow-phase statement that computed the points

    // The key that identifies the pair across steps: (a, b) for two bodies, (a, plane)
    // for a body and a plane; sorted by it.
    std::uint64_t key() const;
    // "face-face", "edge-edge" or "vertex-plane" (trace headers).
    const char* featureName() const;
};

// The pair key and its parts, encoder and decoder side by side (manifold.cpp): a in the
// high half, b (or the plane, offset by 2^31) in the low half,
//   key = a 2^32 + b          for two bodies,
//   key = a 2^32 + 2^31 + p   for body a and plane p.
struct ManifoldKeyParts {
    int a = -1;
    int b = -1;       // -1 for a plane
    int plane = -1;   // -1 for two bodies
};
std::uint64_t manifoldKey(int a, int b, int plane);
ManifoldKeyParts decodeManifoldKey(std::uint64_t key);

// A right-handed orthonormal basis (t1, t2, n) from the unit normal n, chosen by a fixed
// rule so that the same n gives the same tangents in every step (Catto 2009 /
// Box2D's b2ComputeBasis): t1 = (n_y, -n_x, 0)/|.| if |n_x| >= 1/sqrt(3), else
// (0, n_z, -n_y)/|.|; t2 = n x t1.
void tangentBasis(const Vec3& n_W, Vec3& t1_W, Vec3& t2_W);

} // namespace rbw
