// The position fix of the manifold model (non-linear Gauss-Seidel, Box2D
// b2ContactSolver::SolvePositionConstraints; docs/references.md §17), after the
// integration, on positions only: with the separation s re-measured from the anchors on
// both bodies,
//   C = clamp(beta (s + slop), -maxCorrection, 0),  K = 1/m_n at the current pose,
//   P = -C / K,  x_A += P n / M_A,  r_A <- rotate(I_A^-1 (r_A x P n)),  B opposite.
// v and L are not touched, so the fix adds no kinetic energy.
#pragma once

#include "physics/engine/body.h"
#include "physics/engine/manifold/manifold.h"
#include "physics/engine/manifold/settings.h"

#include <vector>

namespace rbw {

// The position iterations' copy of this step's manifolds: per manifold its bodies, the
// reference side and n_ref, per point its anchors on A and B. The iterations read only
// this, not the manifolds, which hold much more (the narrow phase's and the velocity
// solver's numbers per point).
class NgsSolver {
public:
    // `mass` and `angular` (per body: whether contacts turn it) as the world has them.
    void prepare(const std::vector<Manifold>& manifolds, const std::vector<MassProperties>& mass,
                 const std::vector<char>& angular);
    // One NGS iteration over every point, manifold by manifold: moves x and q of the
    // bodies by the corrections (R with q, I^-1 stays that of the step) and adds each
    // body's displacement to dx_W. Returns the smallest separation it measured before
    // correcting [m] (1e300 when there is no point).
    double iterate(std::vector<BodyState>& states, const ManifoldSettings& settings, std::vector<Vec3>& dx_W) const;

private:
    struct Row {
        int a, b;   // b = -1: a plane
        ReferenceSide reference;
        Vec3 nRef_R;
        int first, count;   // its points: anchors_[first, first + count)
        double invMA, invMB;
        bool angularA, angularB;
    };
    struct Anchors {
        Vec3 pA_A;
        Vec3 pB_B;
    };
    std::vector<Row> rows_;
    std::vector<Anchors> anchors_;
};

// A small rotation by theta (NGS, the soft step's push-out): r <- (r + 1/2 (0, theta) r) / |.|, R = R(r).
void rotateBy(BodyState& s, const Vec3& theta_W);

// The separation of point k of m at the bodies' current poses: s = n . (pA - pB).
double currentSeparation(const Manifold& m, int k, const BodyState& A, const BodyState* B);

} // namespace rbw
