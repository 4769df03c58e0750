// The position fix of the manifold model (non-linear Gauss-Seidel); equations and
// sources in position_fix.h.
#include "physics/engine/manifold/position_fix.h"

#include "physics/engine/manifold/contact_axis.h"

#include <algorithm>
#include <cmath>

namespace rbw {

namespace {

// The normal at the current poses: it turns with the reference body (a plane's does not).
Vec3 currentNormal(ReferenceSide reference, const Vec3& nRef_R, const BodyState& A, const BodyState& B)
{
    switch (reference) {
    case ReferenceSide::A: return -(A.R_WB * nRef_R);   // A's face points to B: n = -R_A n_ref
    case ReferenceSide::B: return B.R_WB * nRef_R;      // B's face points to A: n = R_B n_ref
    case ReferenceSide::Edge: return A.R_WB * nRef_R;
    case ReferenceSide::Plane: return nRef_R;
    }
    return nRef_R;
}

} // namespace

// r <- (r + 1/2 (0, theta) r) / |.|, and R = R(r): a small rotation by theta.
void rotateBy(BodyState& s, const Vec3& theta_W)
{
    const Quat dq(0.0, theta_W.x(), theta_W.y(), theta_W.z());
    const Quat rate = dq * s.q_WB;
    s.q_WB.coeffs() += 0.5 * rate.coeffs();
    // r / |r|, as one division and four multiplications
    s.q_WB.coeffs() *= 1.0 / s.q_WB.coeffs().norm();
    s.R_WB = s.q_WB.toRotationMatrix();
}

double currentSeparation(const Manifold& m, int k, const BodyState& A, const BodyState* B)
{
    const ManifoldPoint& p = m.points[static_cast<std::size_t>(k)];
    const Vec3 n_W = m.reference == ReferenceSide::Plane ? m.nRef_R : currentNormal(m.reference, m.nRef_R, A, *B);
    // p_A = x_A + R_A p_A^A, p_B = x_B + R_B p_B^B (a plane's point is already world)
    const Vec3 pA_W = A.x_W + A.R_WB * p.pA_A;
    const Vec3 pB_W = B != nullptr ? Vec3(B->x_W + B->R_WB * p.pB_B) : p.pB_B;
    // s = n . (p_A - p_B)
    return n_W.dot(pA_W - pB_W);
}

void NgsSolver::prepare(const std::vector<Manifold>& manifolds, const std::vector<MassProperties>& mass,
                        const std::vector<char>& angular)
{
    rows_.clear();
    anchors_.clear();
    for (const Manifold& m : manifolds) {
        const std::size_t a = static_cast<std::size_t>(m.a);
        const std::size_t b = static_cast<std::size_t>(m.b);
        rows_.push_back(Row{m.a, m.b, m.reference, m.nRef_R, static_cast<int>(anchors_.size()), m.count,
                            mass[a].invM, m.b >= 0 ? mass[b].invM : 0.0, angular[a] != 0,
                            m.b >= 0 && angular[b] != 0});
        for (int k = 0; k < m.count; ++k) {
            const ManifoldPoint& p = m.points[static_cast<std::size_t>(k)];
            anchors_.push_back(Anchors{p.pA_A, p.pB_B});
        }
    }
}

double NgsSolver::iterate(std::vector<BodyState>& states, const ManifoldSettings& settings,
                          std::vector<Vec3>& dx_W) const
{
    double smallest = 1e300;
    BodyState planeState;   // a plane's "body": at the origin, not turned (its anchors are world points)
    for (const Row& row : rows_) {
        BodyState& A = states[static_cast<std::size_t>(row.a)];
        BodyState& B = row.b >= 0 ? states[static_cast<std::size_t>(row.b)] : planeState;
        const Mat3 IinvA_W = row.angularA ? A.Iinv_W : Mat3::Zero();
        const Mat3 IinvB_W = row.angularB ? B.Iinv_W : Mat3::Zero();
        Vec3 dxA_W = Vec3::Zero();
        Vec3 dxB_W = Vec3::Zero();
        for (int k = 0; k < row.count; ++k) {
            const Anchors& p = anchors_[static_cast<std::size_t>(row.first + k)];
            const Vec3 n_W = currentNormal(row.reference, row.nRef_R, A, B);
            // p_A = x_A + R_A p_A^A, p_B = x_B + R_B p_B^B (a plane's point is already world)
            const Vec3 pA_W = A.x_W + A.R_WB * p.pA_A;
            const Vec3 pB_W = row.b >= 0 ? Vec3(B.x_W + B.R_WB * p.pB_B) : p.pB_B;
            // s = n . (p_A - p_B), re-measured at the current poses
            const double s = n_W.dot(pA_W - pB_W);
            smallest = std::min(smallest, s);
            // C = clamp(beta (s + slop), -maxCorrection, 0)
            const double C = std::clamp(settings.beta * (s + settings.slop), -settings.maxCorrection, 0.0);
            if (C >= 0.0) continue;
            const Vec3 mid_W = 0.5 * (pA_W + pB_W);
            const Vec3 r_A_W = mid_W - A.x_W;
            const Vec3 r_B_W = row.b >= 0 ? Vec3(mid_W - B.x_W) : Vec3::Zero();
            // K = 1/M_A + 1/M_B + (r_A x n) . I_A^-1 (r_A x n) + (r_B x n) . I_B^-1 (r_B x n)
            const double K = ContactAxis(r_A_W, r_B_W, n_W, IinvA_W, IinvB_W).inverseMass(row.invMA + row.invMB);
            if (K <= 0.0) continue;
            // P = -C / K along n
            const Vec3 P_W = (-C / K) * n_W;
            // x_A += P / M_A, r_A turned by I_A^-1 (r_A x P); B the opposite
            const Vec3 dxA = row.invMA * P_W;
            A.x_W += dxA;
            dxA_W += dxA;
            if (row.angularA) rotateBy(A, IinvA_W * r_A_W.cross(P_W));
            if (row.b >= 0) {
                const Vec3 dxB = -row.invMB * P_W;
                B.x_W += dxB;
                dxB_W += dxB;
                if (row.angularB) rotateBy(B, -(IinvB_W * r_B_W.cross(P_W)));
            }
        }
        dx_W[static_cast<std::size_t>(row.a)] += dxA_W;
        if (row.b >= 0) dx_W[static_cast<std::size_t>(row.b)] += dxB_W;
    }
    return smallest;
}

} // namespace rbw
