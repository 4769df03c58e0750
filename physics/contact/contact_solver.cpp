// The sequential-impulse solver and the position fix; equations and sources in
// contact_solver.h.
//
// Glossary
//   r_A_W, r_B_W   lever arms p - x_A, p - x_B                                  [m]
//   dv_W           relative velocity at the point: v_A(p) - v_B(p)              [m/s]
//   v_n, v_t       its normal part dv . n and tangential parts dv . t1, dv . t2  [m/s]
//   P_W            an impulse applied at the point (on A; -P on B)             [N s]
#include "physics/contact/contact_solver.h"

#include <algorithm>
#include <cmath>

namespace rbw {

namespace {

constexpr double kSlidingSpeed = 0.1;   // [m/s]: slower, the tangents stay those of n (a wobble does not turn them)

// 1/M_A + 1/M_B + (r_A x d) . I_A^-1 (r_A x d) + (r_B x d) . I_B^-1 (r_B x d)
// (= the course's [(I^-1 (r x d)) x r] . d terms, written as a quadratic form)
double inverseEffectiveMass(const SolverBody& A, const SolverBody& B, const Vec3& r_A_W, const Vec3& r_B_W,
                            const Vec3& d_W)
{
    const Vec3 rAxd_W = r_A_W.cross(d_W);
    const Vec3 rBxd_W = r_B_W.cross(d_W);
    return A.invM + B.invM + rAxd_W.dot(A.Iinv_W * rAxd_W) + rBxd_W.dot(B.Iinv_W * rBxd_W);
}

// Along row d of point p (0: n, 1: t1, 2: t2), the relative velocity
//   v_d = (v_A - v_B) . d + omega_A . (r_A x d) - omega_B . (r_B x d)
inline double rowVelocity(const SolverBody& A, const SolverBody& B, const ManifoldPoint& p, int row, const Vec3& d_W)
{
    const std::size_t r = static_cast<std::size_t>(row);
    return (A.v_W - B.v_W).dot(d_W) + A.omega_W.dot(p.rAxd_W[r]) - B.omega_W.dot(p.rBxd_W[r]);
}

// An impulse lambda along row d: v_A += lambda d / M_A, omega_A += lambda I_A^-1 (r_A x d),
// and the opposite for B.
inline void applyRow(SolverBody& A, SolverBody& B, const ManifoldPoint& p, int row, const Vec3& d_W, double lambda)
{
    const std::size_t r = static_cast<std::size_t>(row);
    A.v_W += (lambda * A.invM) * d_W;
    A.omega_W += lambda * p.IArAxd_W[r];
    B.v_W -= (lambda * B.invM) * d_W;
    B.omega_W -= lambda * p.IBrBxd_W[r];
}

// The normal at the current poses: it turns with the reference body (a plane's does not).
Vec3 currentNormal(const Manifold& m, const BodyState& A, const BodyState* B)
{
    switch (m.reference) {
    case ReferenceSide::A: return -(A.R_WB * m.nRef_R);   // A's face points to B: n = -R_A n_ref
    case ReferenceSide::B: return B->R_WB * m.nRef_R;      // B's face points to A: n = R_B n_ref
    case ReferenceSide::Edge: return A.R_WB * m.nRef_R;
    case ReferenceSide::Plane: return m.nRef_R;
    }
    return m.n_W;
}

// r <- (r + 1/2 (0, theta) r) / |.|, and R = R(r): a small rotation by theta.
void rotate(BodyState& s, const Vec3& theta_W)
{
    const Quat dq(0.0, theta_W.x(), theta_W.y(), theta_W.z());
    const Quat rate = dq * s.q_WB;
    s.q_WB.coeffs() += 0.5 * rate.coeffs();
    s.q_WB.normalize();
    s.R_WB = s.q_WB.toRotationMatrix();
}

} // namespace

void prepareManifold(Manifold& m, SolverBody& A, SolverBody& B, const Vec3& xA_W, const Vec3& xB_W,
                     const BodyState& startA, const BodyState* startB, const ManifoldSettings& settings, double h,
                     double restitutionThreshold)
{
    // A sliding pair: t1 along the sliding velocity at the first point, so that the
    // friction rows find Coulomb's direction (opposite to the sliding) and not one bent
    // by the rows' coupling (Bullet does the same); otherwise the fixed basis of n.
    {
        const Vec3 r_W = m.points[0].p_W - xA_W;
        Vec3 dv_W = startA.v_W + startA.omega_W.cross(r_W);
        if (startB != nullptr) dv_W -= startB->v_W + startB->omega_W.cross(m.points[0].p_W - xB_W);
        // v_t = dv - (dv . n) n
        const Vec3 vt_W = dv_W - dv_W.dot(m.n_W) * m.n_W;
        if (vt_W.squaredNorm() > kSlidingSpeed * kSlidingSpeed) {
            m.t1_W = vt_W.normalized();
            m.t2_W = m.n_W.cross(m.t1_W);
        }
    }
    for (int k = 0; k < m.count; ++k) {
        ManifoldPoint& p = m.points[static_cast<std::size_t>(k)];
        // r_A = p - x_A, r_B = p - x_B
        p.r_A_W = p.p_W - xA_W;
        p.r_B_W = p.p_W - xB_W;
        // m_n = 1 / (1/M_A + 1/M_B + [(I_A^-1 (r_A x n)) x r_A + (I_B^-1 (r_B x n)) x r_B] . n)
        // The rows' angular parts: r x d and I^-1 (r x d) for d = n, t1, t2
        const std::array<const Vec3*, 3> rows = {&m.n_W, &m.t1_W, &m.t2_W};
        for (std::size_t r = 0; r < 3; ++r) {
            p.rAxd_W[r] = p.r_A_W.cross(*rows[r]);
            p.rBxd_W[r] = p.r_B_W.cross(*rows[r]);
            p.IArAxd_W[r] = A.Iinv_W * p.rAxd_W[r];
            p.IBrBxd_W[r] = B.Iinv_W * p.rBxd_W[r];
        }
        const double kn = inverseEffectiveMass(A, B, p.r_A_W, p.r_B_W, m.n_W);
        p.m_n = kn > 0.0 ? 1.0 / kn : 0.0;
        // m_t1, m_t2 the same along t1 and t2
        const double kt1 = inverseEffectiveMass(A, B, p.r_A_W, p.r_B_W, m.t1_W);
        const double kt2 = inverseEffectiveMass(A, B, p.r_A_W, p.r_B_W, m.t2_W);
        p.m_t1 = kt1 > 0.0 ? 1.0 / kt1 : 0.0;
        p.m_t2 = kt2 > 0.0 ? 1.0 / kt2 : 0.0;
        // The warm-start friction impulse on this step's tangents: lambda_ti = lambda_t^0 . t_i
        p.lambda_t1 = p.warm_t_W.dot(m.t1_W);
        p.lambda_t2 = p.warm_t_W.dot(m.t2_W);
        // v_n = (v_A + omega_A x r_A - v_B - omega_B x r_B) . n at the start of the step
        Vec3 dv_W = startA.v_W + startA.omega_W.cross(p.r_A_W);
        if (startB != nullptr) dv_W -= startB->v_W + startB->omega_W.cross(p.r_B_W);
        p.normalVelocity = dv_W.dot(m.n_W);
        // Bounce: v_n* = -c v_n for an approach faster than the threshold (Box2D
        // b2_velocityThreshold), if the point reaches the surface in this step.
        const double s = p.separation;
        const bool reaches = s <= 0.0 || -p.normalVelocity * h >= s;
        const double bounce =
            (p.normalVelocity < -restitutionThreshold && reaches) ? -m.restitution * p.normalVelocity : 0.0;
        if (bounce > 0.0) {
            p.v_target = bounce;
        } else if (s > 0.0) {
            // Speculative: apart by s, it may approach at s/h and arrive in this step.
            p.v_target = -s / h;
        } else {
            p.v_target = 0.0;
        }
        if (settings.positionFix == PositionFix::Baumgarte && s < 0.0) {
            // v_n* = max(v_bounce, beta/h max(0, d - slop)), d = -s (Catto 2005)
            p.v_target = std::max(p.v_target, settings.beta / h * std::max(0.0, -s - settings.slop));
        }
        // Warm start: apply last step's accumulated impulses,
        // P = lambda_n n + lambda_t1 t1 + lambda_t2 t2
        applyRow(A, B, p, 0, m.n_W, p.lambda_n);
        applyRow(A, B, p, 1, m.t1_W, p.lambda_t1);
        applyRow(A, B, p, 2, m.t2_W, p.lambda_t2);
    }
    // The coupling of the normal rows (the manifold's Delassus matrix): a normal
    // impulse at point j changes v_n at point i by K_ij times it,
    //   K_ij = 1/M_A + 1/M_B + (r_Ai x n) . I_A^-1 (r_Aj x n) + (r_Bi x n) . I_B^-1 (r_Bj x n)
    for (int i = 0; i < m.count; ++i) {
        const ManifoldPoint& pi = m.points[static_cast<std::size_t>(i)];
        for (int j = 0; j < m.count; ++j) {
            const ManifoldPoint& pj = m.points[static_cast<std::size_t>(j)];
            m.K_n[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
                A.invM + B.invM + pi.rAxd_W[0].dot(pj.IArAxd_W[0]) + pi.rBxd_W[0].dot(pj.IBrBxd_W[0]);
        }
    }
}

double solveManifoldVelocities(Manifold& m, SolverBody& A, SolverBody& B, int normalSweeps)
{
    double largest = 0.0;
    // The normal rows first, all points of the manifold, normalSweeps times:
    // lambda_n <- max(0, lambda_n + m_n (v_n* - v_n)), applied as the change. The points
    // share the two bodies, so their rows are coupled through the bodies' rotation; one
    // pass leaves a residual that depends on the order of the points and turns the
    // bodies (a symmetric tower starts to rock). A few passes over the manifold
    // approach the solution of its rows together, as Box2D's block solver does for its
    // two points (b2ContactSolver::SolveVelocityConstraints; docs/collisions.md).
    // The sweeps work on the points' v_n alone, through K (prepareManifold): a change
    // dn at point j moves v_n at point i by K_ij dn, exactly what applying it to the
    // bodies would. The bodies get the sum of a point's changes once, after the sweeps.
    // (The points' numbers are copied next to each other for the sweeps.)
    const int count = m.count;
    std::array<double, kMaxManifoldPoints> vn{};
    std::array<double, kMaxManifoldPoints> lambda_n{};
    std::array<double, kMaxManifoldPoints> m_n{};
    std::array<double, kMaxManifoldPoints> v_target{};
    for (int k = 0; k < count; ++k) {
        const std::size_t uk = static_cast<std::size_t>(k);
        const ManifoldPoint& p = m.points[uk];
        vn[uk] = rowVelocity(A, B, p, 0, m.n_W);
        lambda_n[uk] = p.lambda_n;
        m_n[uk] = p.m_n;
        v_target[uk] = p.v_target;
    }
    for (int sweep = 0; sweep < normalSweeps; ++sweep) {
        for (int k = 0; k < count; ++k) {
            const std::size_t uk = static_cast<std::size_t>(k);
            const double lambda = std::max(0.0, lambda_n[uk] + m_n[uk] * (v_target[uk] - vn[uk]));
            const double dn = lambda - lambda_n[uk];
            if (dn == 0.0) continue;
            lambda_n[uk] = lambda;
            // v_n,i += K_ik dn
            const std::array<double, kMaxManifoldPoints>& K_k = m.K_n[uk];   // K is symmetric
            for (int i = 0; i < count; ++i) vn[static_cast<std::size_t>(i)] += K_k[static_cast<std::size_t>(i)] * dn;
            largest = std::max(largest, std::abs(dn));
        }
    }
    for (int k = 0; k < count; ++k) {
        const std::size_t uk = static_cast<std::size_t>(k);
        ManifoldPoint& p = m.points[uk];
        const double applied = lambda_n[uk] - p.lambda_n;
        p.lambda_n = lambda_n[uk];
        if (applied != 0.0) applyRow(A, B, p, 0, m.n_W, applied);
    }
    for (int k = 0; k < m.count; ++k) {
        ManifoldPoint& p = m.points[static_cast<std::size_t>(k)];
        // Then friction, bounded by the normal impulse just found:
        // lambda_ti* = lambda_ti - m_ti v_ti, both from the same velocities. Inside the
        // Coulomb cone |lambda_t| <= mu lambda_n it sticks; outside, the point slides and
        // the 2-vector is scaled back onto the cone. With t1 along the sliding velocity
        // (prepareManifold) the scaled vector's fixed point is Coulomb's: lambda_t2 = 0,
        // lambda_t1 = -mu lambda_n, opposite to the sliding.
        const double old1 = p.lambda_t1;
        const double old2 = p.lambda_t2;
        const double limit = m.mu * p.lambda_n;
        const double vt1 = rowVelocity(A, B, p, 1, m.t1_W);
        double l1 = old1 - p.m_t1 * vt1;
        double l2 = old2 - p.m_t2 * rowVelocity(A, B, p, 2, m.t2_W);
        if (l1 * l1 + l2 * l2 > limit * limit) {
            // Sliding: both rows from the same velocities, scaled onto the cone together
            const double scale = limit / std::sqrt(l1 * l1 + l2 * l2);
            l1 *= scale;
            l2 *= scale;
        } else {
            // Sticking: t1, then t2 from the velocity t1's change left (Gauss-Seidel),
            // still inside the cone
            applyRow(A, B, p, 1, m.t1_W, l1 - old1);
            l2 = old2 - p.m_t2 * rowVelocity(A, B, p, 2, m.t2_W);
            const double length2 = l1 * l1 + l2 * l2;
            if (length2 > limit * limit) {
                const double scale = limit / std::sqrt(length2);
                const double scaled1 = l1 * scale;
                applyRow(A, B, p, 1, m.t1_W, scaled1 - l1);
                l1 = scaled1;
                l2 *= scale;
            }
            applyRow(A, B, p, 2, m.t2_W, l2 - old2);
            p.lambda_t1 = l1;
            p.lambda_t2 = l2;
            largest = std::max({largest, std::abs(l1 - old1), std::abs(l2 - old2)});
            continue;
        }
        p.lambda_t1 = l1;
        p.lambda_t2 = l2;
        // both rows at once: v_A += (d1 t1 + d2 t2) / M_A,
        // omega_A += d1 I_A^-1 (r_A x t1) + d2 I_A^-1 (r_A x t2), B the opposite
        const double d1 = l1 - old1;
        const double d2 = l2 - old2;
        const Vec3 dP_W = d1 * m.t1_W + d2 * m.t2_W;
        A.v_W += A.invM * dP_W;
        A.omega_W += d1 * p.IArAxd_W[1] + d2 * p.IArAxd_W[2];
        B.v_W -= B.invM * dP_W;
        B.omega_W -= d1 * p.IBrBxd_W[1] + d2 * p.IBrBxd_W[2];
        largest = std::max({largest, std::abs(l1 - old1), std::abs(l2 - old2)});
    }
    return largest;
}

void accumulateImpulses(const Manifold& m, SolverBody& A, SolverBody& B)
{
    for (int k = 0; k < m.count; ++k) {
        const ManifoldPoint& p = m.points[static_cast<std::size_t>(k)];
        // P = lambda_n n + lambda_t1 t1 + lambda_t2 t2 on A, -P on B; moments r x P
        const Vec3 P_W = p.lambda_n * m.n_W + p.lambda_t1 * m.t1_W + p.lambda_t2 * m.t2_W;
        A.P_W += P_W;
        A.Lc_W += p.r_A_W.cross(P_W);
        B.P_W -= P_W;
        B.Lc_W -= p.r_B_W.cross(P_W);
    }
}

double currentSeparation(const Manifold& m, int k, const BodyState& A, const BodyState* B)
{
    const ManifoldPoint& p = m.points[static_cast<std::size_t>(k)];
    const Vec3 n_W = currentNormal(m, A, B);
    // p_A = x_A + R_A p_A^A, p_B = x_B + R_B p_B^B (a plane's point is already world)
    const Vec3 pA_W = A.x_W + A.R_WB * p.pA_A;
    const Vec3 pB_W = B != nullptr ? Vec3(B->x_W + B->R_WB * p.pB_B) : p.pB_B;
    // s = n . (p_A - p_B)
    return n_W.dot(pA_W - pB_W);
}

double solveManifoldPositions(const Manifold& m, BodyState& A, const MassProperties& massA, bool angularA,
                              BodyState* B, const MassProperties* massB, bool angularB,
                              const ManifoldSettings& settings, Vec3& dxA_W, Vec3& dxB_W)
{
    double smallest = 1e300;
    const double invMA = massA.invM;
    const double invMB = massB != nullptr ? massB->invM : 0.0;
    const Mat3 IinvA_W = angularA ? A.Iinv_W : Mat3::Zero();
    const Mat3 IinvB_W = (B != nullptr && angularB) ? B->Iinv_W : Mat3::Zero();
    for (int k = 0; k < m.count; ++k) {
        const ManifoldPoint& p = m.points[static_cast<std::size_t>(k)];
        const Vec3 n_W = currentNormal(m, A, B);
        const Vec3 pA_W = A.x_W + A.R_WB * p.pA_A;
        const Vec3 pB_W = B != nullptr ? Vec3(B->x_W + B->R_WB * p.pB_B) : p.pB_B;
        // s = n . (p_A - p_B), re-measured at the current poses
        const double s = n_W.dot(pA_W - pB_W);
        smallest = std::min(smallest, s);
        // C = clamp(beta (s + slop), -maxCorrection, 0)
        const double C = std::clamp(settings.beta * (s + settings.slop), -settings.maxCorrection, 0.0);
        if (C >= 0.0) continue;
        const Vec3 mid_W = 0.5 * (pA_W + pB_W);
        const Vec3 r_A_W = mid_W - A.x_W;
        const Vec3 r_B_W = B != nullptr ? Vec3(mid_W - B->x_W) : Vec3::Zero();
        const Vec3 rAxn_W = r_A_W.cross(n_W);
        const Vec3 rBxn_W = r_B_W.cross(n_W);
        // K = 1/M_A + 1/M_B + (r_A x n) . I_A^-1 (r_A x n) + (r_B x n) . I_B^-1 (r_B x n)
        const double K = invMA + invMB + rAxn_W.dot(IinvA_W * rAxn_W) + rBxn_W.dot(IinvB_W * rBxn_W);
        if (K <= 0.0) continue;
        // P = -C / K along n
        const Vec3 P_W = (-C / K) * n_W;
        // x_A += P / M_A, r_A turned by I_A^-1 (r_A x P); B the opposite
        const Vec3 dxA = invMA * P_W;
        A.x_W += dxA;
        dxA_W += dxA;
        if (angularA) rotate(A, IinvA_W * r_A_W.cross(P_W));
        if (B != nullptr) {
            const Vec3 dxB = -invMB * P_W;
            B->x_W += dxB;
            dxB_W += dxB;
            if (angularB) rotate(*B, -(IinvB_W * r_B_W.cross(P_W)));
        }
    }
    return smallest;
}

} // namespace rbw
