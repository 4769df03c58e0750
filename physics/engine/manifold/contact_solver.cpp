// The sequential-impulse solver; equations and sources in contact_solver.h.
//
// Glossary
//   r_A_W, r_B_W   lever arms p - x_A, p - x_B                                  [m]
//   dv_W           relative velocity at the point: v_A(p) - v_B(p)              [m/s]
//   v_n, v_t       its normal part dv . n and tangential parts dv . t1, dv . t2  [m/s]
//   P_W            an impulse applied at the point (on A; -P on B)             [N s]
#include "physics/engine/manifold/contact_solver.h"

#include "physics/engine/manifold/contact_axis.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rbw {

namespace {

constexpr double kSlidingSpeed = 0.1;   // [m/s]: slower, the tangents stay those of n (a wobble does not turn them)

// An impulse P_W at lever arms r_A, r_B: v_A += P / M_A, omega_A += I_A^-1 (r_A x P),
// and the opposite for B.
void applyImpulse(SolverBody& A, SolverBody& B, const Vec3& r_A_W, const Vec3& r_B_W, const Vec3& P_W)
{
    A.v_W += A.invM * P_W;
    A.omega_W += A.Iinv_W * r_A_W.cross(P_W);
    B.v_W -= B.invM * P_W;
    B.omega_W -= B.Iinv_W * r_B_W.cross(P_W);
}

// A sliding pair: t1 along the sliding velocity at the first point, so that the
// friction rows find Coulomb's direction (opposite to the sliding) and not one bent by
// the rows' coupling (Bullet does the same); otherwise the fixed basis of n.
void slidingTangents(Manifold& m, const BodyState& startA, const BodyState* startB)
{
    const Vec3 r_W = m.points[0].p_W - startA.x_W;
    Vec3 dv_W = startA.v_W + startA.omega_W.cross(r_W);
    if (startB != nullptr) dv_W -= startB->v_W + startB->omega_W.cross(m.points[0].p_W - startB->x_W);
    // v_t = dv - (dv . n) n
    const Vec3 vt_W = dv_W - dv_W.dot(m.n_W) * m.n_W;
    if (vt_W.squaredNorm() > kSlidingSpeed * kSlidingSpeed) {
        m.t1_W = vt_W.normalized();
        m.t2_W = m.n_W.cross(m.t1_W);
    }
}

// The normal velocity the solver aims at: a bounce, a speculative approach, or rest.
double targetNormalVelocity(const ManifoldPoint& p, const Manifold& m, const ManifoldSettings& settings, double h,
                            double restitutionThreshold)
{
    // Bounce: v_n* = -c v_n for an approach faster than the threshold (Box2D
    // b2_velocityThreshold), if the point reaches the surface in this step.
    const double s = p.separation;
    const bool reaches = s <= 0.0 || -p.normalVelocity * h >= s;
    const double bounce = (p.normalVelocity < -restitutionThreshold && reaches) ? -m.restitution * p.normalVelocity : 0.0;
    double v_target = 0.0;
    if (bounce > 0.0) {
        v_target = bounce;
    } else if (s > 0.0) {
        // Speculative: apart by s, it may approach at s/h and arrive in this step.
        v_target = -s / h;
    }
    if (settings.positionFix == PositionFix::Baumgarte && s < 0.0) {
        // v_n* = max(v_bounce, beta/h max(0, d - slop)), d = -s (Catto 2005)
        v_target = std::max(v_target, settings.beta / h * std::max(0.0, -s - settings.slop));
    }
    return v_target;
}

// The normal sweeps of one manifold of N points, N fixed at compile time so that the
// rows stay in registers (they are a chain of dependent updates, and their latency, not
// their arithmetic, is the cost). Per point k, with s_k = m_n,k (v_target,k - v_n,k):
//   lambda_k <- max(0, lambda_k + s_k),  dn = the change,  s_i -= m_n,i K_ik dn for all i
// (W holds m_n,i K_ik by columns). Returns the largest |dn|.
template <int N>
double sweepRows(const double* W, int sweeps, double* stepIn, double* lambdaIn)
{
    std::array<double, N> step;
    std::array<double, N> lambda;
    for (int k = 0; k < N; ++k) {
        step[static_cast<std::size_t>(k)] = stepIn[k];
        lambda[static_cast<std::size_t>(k)] = lambdaIn[k];
    }
    double largest = 0.0;
    for (int sweep = 0; sweep < sweeps; ++sweep) {
        double changed = 0.0;
        for (int k = 0; k < N; ++k) {
            const std::size_t uk = static_cast<std::size_t>(k);
            const double candidate = lambda[uk] + step[uk];
            const double next = candidate > 0.0 ? candidate : 0.0;
            const double dn = next - lambda[uk];
            lambda[uk] = next;
            for (int i = 0; i < N; ++i) step[static_cast<std::size_t>(i)] -= W[k * N + i] * dn;
            changed = std::max(changed, std::abs(dn));
        }
        largest = std::max(largest, changed);
        // A sweep that changed nothing leaves the next one nothing to change.
        if (changed == 0.0) break;
    }
    for (int k = 0; k < N; ++k) lambdaIn[k] = lambda[static_cast<std::size_t>(k)];
    return largest;
}

double sweepNormalRows(int count, const double* W, int sweeps, double* step, double* lambda)
{
    switch (count) {
    case 1: return sweepRows<1>(W, sweeps, step, lambda);
    case 2: return sweepRows<2>(W, sweeps, step, lambda);
    case 3: return sweepRows<3>(W, sweeps, step, lambda);
    case 4: return sweepRows<4>(W, sweeps, step, lambda);
    case 5: return sweepRows<5>(W, sweeps, step, lambda);
    case 6: return sweepRows<6>(W, sweeps, step, lambda);
    case 7: return sweepRows<7>(W, sweeps, step, lambda);
    case 8: return sweepRows<8>(W, sweeps, step, lambda);
    default: return 0.0;
    }
}
static_assert(kMaxManifoldPoints == 8, "sweepNormalRows dispatches on 1 to 8 points");

} // namespace

void ContactSolver::prepare(std::vector<Manifold>& manifolds, std::vector<SolverBody>& bodies, int planeBody,
                            const std::vector<BodyState>& start, const ManifoldSettings& settings, double h,
                            double restitutionThreshold)
{
    constraints_.clear();
    points_.clear();
    friction_.clear();
    W_.clear();
    history_.clear();
    for (Manifold& m : manifolds) {
        const int bIndex = m.b >= 0 ? m.b : planeBody;
        SolverBody& A = bodies[static_cast<std::size_t>(m.a)];
        SolverBody& B = bodies[static_cast<std::size_t>(bIndex)];
        const BodyState& startA = start[static_cast<std::size_t>(m.a)];
        const BodyState* startB = m.b >= 0 ? &start[static_cast<std::size_t>(m.b)] : nullptr;
        const Vec3& xA_W = startA.x_W;
        const Vec3 xB_W = startB != nullptr ? startB->x_W : Vec3::Zero();
        if (m.count > 0) slidingTangents(m, startA, startB);
        Constraint c{m.n_W, m.t1_W, m.t2_W, m.mu, m.a, bIndex, static_cast<int>(points_.size()), m.count,
                     static_cast<int>(W_.size()), B.invM > 0.0 || !B.Iinv_W.isZero(0.0)};
        // The normal rows' axes, for their coupling K below.
        std::array<ContactAxis, kMaxManifoldPoints> normal{};
        const double invMAB = A.invM + B.invM;
        for (int k = 0; k < m.count; ++k) {
            const std::size_t uk = static_cast<std::size_t>(k);
            ManifoldPoint& mp = m.points[uk];
            Point p{};
            // r_A = p - x_A, r_B = p - x_B
            p.r_A_W = mp.p_W - xA_W;
            p.r_B_W = mp.p_W - xB_W;
            // The rows' axes d = n, t1, t2 (contact_axis.h): m_d = 1 / K_dd
            normal[uk] = ContactAxis(p.r_A_W, p.r_B_W, m.n_W, A.Iinv_W, B.Iinv_W);
            const ContactAxis t1(p.r_A_W, p.r_B_W, m.t1_W, A.Iinv_W, B.Iinv_W);
            const ContactAxis t2(p.r_A_W, p.r_B_W, m.t2_W, A.Iinv_W, B.Iinv_W);
            p.m_n = normal[uk].mass(invMAB);
            friction_.push_back(FrictionRows{t1.IArAxd_W, t2.IArAxd_W, t1.IBrBxd_W, t2.IBrBxd_W});
            p.m_t1 = t1.mass(invMAB);
            p.m_t2 = t2.mass(invMAB);
            // K_12 = (r_A x t1) . I_A^-1 (r_A x t2) + (r_B x t1) . I_B^-1 (r_B x t2)
            // (the linear part drops out: t1 . t2 = 0)
            p.K_t12 = t1.angularCoupling(t2);
            // v_n = (v_A + omega_A x r_A - v_B - omega_B x r_B) . n at the start of the step
            Vec3 dv_W = startA.v_W + startA.omega_W.cross(p.r_A_W);
            if (startB != nullptr) dv_W -= startB->v_W + startB->omega_W.cross(p.r_B_W);
            mp.normalVelocity = dv_W.dot(m.n_W);
            p.v_target = targetNormalVelocity(mp, m, settings, h, restitutionThreshold);
            // The warm start (applied by warmStart()): last step's impulses, lambda_n as
            // ManifoldCache::warmStart matched it and the friction impulse on this step's
            // tangents, lambda_ti = lambda_t^0 . t_i
            p.lambda_n = mp.lambda_n;
            p.lambda_t1 = mp.warm_t_W.dot(m.t1_W);
            p.lambda_t2 = mp.warm_t_W.dot(m.t2_W);
            // What the trace shows of the point
            mp.r_A_W = p.r_A_W;
            mp.r_B_W = p.r_B_W;
            mp.m_n = p.m_n;
            mp.m_t1 = p.m_t1;
            mp.m_t2 = p.m_t2;
            mp.v_target = p.v_target;
            mp.lambda_t1 = p.lambda_t1;
            mp.lambda_t2 = p.lambda_t2;
            points_.push_back(p);
        }
        // The coupling of the normal rows (the manifold's Delassus matrix): a normal
        // impulse at point j changes v_n at point i by K_ij times it,
        //   K_ij = 1/M_A + 1/M_B + (r_Ai x n) . I_A^-1 (r_Aj x n) + (r_Bi x n) . I_B^-1 (r_Bj x n)
        // kept as m_n,i K_ij, the change of point i's step m_n,i (v_target,i - v_n,i), by
        // columns: W_[firstW + j count + i] = m_n,i K_ij (solve()).
        for (int j = 0; j < m.count; ++j) {
            for (int i = 0; i < m.count; ++i) {
                const std::size_t ui = static_cast<std::size_t>(i);
                const std::size_t uj = static_cast<std::size_t>(j);
                const double K_ij = normal[ui].coupling(invMAB, normal[uj]);
                W_.push_back(points_[static_cast<std::size_t>(c.first + i)].m_n * K_ij);
            }
        }
        constraints_.push_back(c);
    }
}

void ContactSolver::warmStart(std::vector<SolverBody>& bodies) const
{
    for (const Constraint& c : constraints_) {
        SolverBody& A = bodies[static_cast<std::size_t>(c.a)];
        SolverBody& B = bodies[static_cast<std::size_t>(c.b)];
        for (int k = 0; k < c.count; ++k) {
            const Point& p = points_[static_cast<std::size_t>(c.first + k)];
            // P = lambda_n n + lambda_t1 t1 + lambda_t2 t2, last step's impulses
            const Vec3 P_W = p.lambda_n * c.n_W + p.lambda_t1 * c.t1_W + p.lambda_t2 * c.t2_W;
            applyImpulse(A, B, p.r_A_W, p.r_B_W, P_W);
        }
    }
}

double ContactSolver::solve(std::vector<SolverBody>& bodies, int normalSweeps)
{
    double largest = 0.0;
    for (const Constraint& c : constraints_) {
        SolverBody& A = bodies[static_cast<std::size_t>(c.a)];
        SolverBody& B = bodies[static_cast<std::size_t>(c.b)];
        // The bodies' velocities and the rows' directions as local copies for the whole
        // manifold (written back at its end): the compiler may then keep them in
        // registers, where stores to the points would otherwise force it to reload them.
        Vec3 vA_W = A.v_W;
        Vec3 omegaA_W = A.omega_W;
        Vec3 vB_W = B.v_W;
        Vec3 omegaB_W = B.omega_W;
        const double invMA = A.invM;
        const double invMB = B.invM;
        const Mat3 IinvA_W = A.Iinv_W;
        const Mat3 IinvB_W = B.Iinv_W;
        const Vec3 n_W = c.n_W;
        const Vec3 t1_W = c.t1_W;
        const Vec3 t2_W = c.t2_W;
        const double mu = c.mu;
        Point* points = points_.data() + c.first;
        const FrictionRows* friction = friction_.data() + c.first;
        const double* W = W_.data() + c.firstW;
        const int count = c.count;
        // The normal rows first, all points of the manifold, normalSweeps times:
        // lambda_n <- max(0, lambda_n + m_n (v_n* - v_n)), applied as the change. The
        // points share the two bodies, so their rows are coupled through the bodies'
        // rotation; one pass leaves a residual that depends on the order of the points
        // and turns the bodies (a symmetric tower starts to rock). A few passes over the
        // manifold approach the solution of its rows together, as Box2D's block solver
        // does for its two points (b2ContactSolver::SolveVelocityConstraints;
        // docs/collisions.md). The sweeps work on the points' v_n alone, through K: a
        // change dn at point j moves v_n at point i by K_ij dn, exactly what applying it
        // to the bodies would (sweepNormalRows). The bodies get the changes once, after
        // the sweeps.
        //   v_n = (v_A - v_B) . n + omega_A . (r_A x n) - omega_B . (r_B x n)
        //       = (v_A - v_B) . n + r_A . (n x omega_A) - r_B . (n x omega_B)
        const double vAB_n = (vA_W - vB_W).dot(n_W);
        const Vec3 nxomegaA_W = n_W.cross(omegaA_W);
        const Vec3 nxomegaB_W = n_W.cross(omegaB_W);
        std::array<double, kMaxManifoldPoints> lambda_n;
        std::array<double, kMaxManifoldPoints> step;
        for (int k = 0; k < count; ++k) {
            const std::size_t uk = static_cast<std::size_t>(k);
            // v_n, and the step to the target m_n (v_target - v_n)
            const double vn = vAB_n + points[k].r_A_W.dot(nxomegaA_W) - points[k].r_B_W.dot(nxomegaB_W);
            step[uk] = points[k].m_n * (points[k].v_target - vn);
            lambda_n[uk] = points[k].lambda_n;
        }
        largest = std::max(largest, sweepNormalRows(count, W, normalSweeps, step.data(), lambda_n.data()));
        // The changes dn_k together: v_A += (sum dn_k) n / M_A,
        // omega_A += I_A^-1 sum dn_k (r_A,k x n) = I_A^-1 ((sum dn_k r_A,k) x n); B opposite.
        double sum_dn = 0.0;
        Vec3 sum_dn_rA_W = Vec3::Zero();
        Vec3 sum_dn_rB_W = Vec3::Zero();
        for (int k = 0; k < count; ++k) {
            const double dn = lambda_n[static_cast<std::size_t>(k)] - points[k].lambda_n;
            points[k].lambda_n = lambda_n[static_cast<std::size_t>(k)];
            sum_dn += dn;
            sum_dn_rA_W += dn * points[k].r_A_W;
            sum_dn_rB_W += dn * points[k].r_B_W;
        }
        vA_W += (invMA * sum_dn) * n_W;
        omegaA_W += IinvA_W * sum_dn_rA_W.cross(n_W);
        if (c.movesB) {
            vB_W -= (invMB * sum_dn) * n_W;
            omegaB_W -= IinvB_W * sum_dn_rB_W.cross(n_W);
        }
        for (int k = 0; k < count; ++k) {
            Point& p = points[k];
            // Then friction, bounded by the normal impulse just found:
            // lambda_ti* = lambda_ti - m_ti v_ti, both from the same velocities. Inside
            // the Coulomb cone |lambda_t| <= mu lambda_n it sticks; outside, the point
            // slides and the 2-vector is scaled back onto the cone. With t1 along the
            // sliding velocity (prepare) the scaled vector's fixed point is Coulomb's:
            // lambda_t2 = 0, lambda_t1 = -mu lambda_n, opposite to the sliding.
            // dv = v_A + omega_A x r_A - v_B - omega_B x r_B
            const Vec3 dv_W = vA_W + omegaA_W.cross(p.r_A_W) - vB_W - omegaB_W.cross(p.r_B_W);
            const double vt1 = dv_W.dot(t1_W);
            const double vt2 = dv_W.dot(t2_W);
            const FrictionRows& f = friction[k];
            const double old1 = p.lambda_t1;
            const double old2 = p.lambda_t2;
            const double limit = mu * p.lambda_n;
            double l1 = old1 - p.m_t1 * vt1;
            double l2 = old2 - p.m_t2 * vt2;
            if (l1 * l1 + l2 * l2 <= limit * limit) {
                // Sticking: t1, then t2 from the velocity t1's change leaves
                // (Gauss-Seidel), v_t2 + K_12 (l1 - old1)
                l2 = old2 - p.m_t2 * (vt2 + p.K_t12 * (l1 - old1));
            }
            const double length2 = l1 * l1 + l2 * l2;
            if (length2 > limit * limit) {
                // Outside the cone: scaled back onto it, both rows together
                const double scale = length2 > 0.0 ? limit / std::sqrt(length2) : 0.0;
                l1 *= scale;
                l2 *= scale;
            }
            const double d1 = l1 - old1;
            const double d2 = l2 - old2;
            p.lambda_t1 = l1;
            p.lambda_t2 = l2;
            if (d1 == 0.0 && d2 == 0.0) continue;
            largest = std::max({largest, std::abs(d1), std::abs(d2)});
            // dP = d1 t1 + d2 t2 at the point: v_A += dP / M_A, omega_A += I_A^-1 (r_A x dP)
            // = d1 I_A^-1 (r_A x t1) + d2 I_A^-1 (r_A x t2)
            const Vec3 dP_W = d1 * t1_W + d2 * t2_W;
            vA_W += invMA * dP_W;
            omegaA_W += d1 * f.IArAxt1_W + d2 * f.IArAxt2_W;
            if (c.movesB) {
                vB_W -= invMB * dP_W;
                omegaB_W -= d1 * f.IBrBxt1_W + d2 * f.IBrBxt2_W;
            }
        }
        A.v_W = vA_W;
        A.omega_W = omegaA_W;
        if (c.movesB) {
            B.v_W = vB_W;
            B.omega_W = omegaB_W;
        }
    }
    return largest;
}

void ContactSolver::recordIteration()
{
    for (const Point& p : points_) history_.push_back(PointImpulses{p.lambda_n, p.lambda_t1, p.lambda_t2});
}

void ContactSolver::store(std::vector<Manifold>& manifolds, std::vector<SolverBody>& bodies) const
{
    for (std::size_t i = 0; i < constraints_.size() && i < manifolds.size(); ++i) {
        const Constraint& c = constraints_[i];
        SolverBody& A = bodies[static_cast<std::size_t>(c.a)];
        SolverBody& B = bodies[static_cast<std::size_t>(c.b)];
        for (int k = 0; k < c.count; ++k) {
            const Point& p = points_[static_cast<std::size_t>(c.first + k)];
            ManifoldPoint& mp = manifolds[i].points[static_cast<std::size_t>(k)];
            mp.lambda_n = p.lambda_n;
            mp.lambda_t1 = p.lambda_t1;
            mp.lambda_t2 = p.lambda_t2;
            // P = lambda_n n + lambda_t1 t1 + lambda_t2 t2 on A, -P on B; moments r x P
            const Vec3 P_W = p.lambda_n * c.n_W + p.lambda_t1 * c.t1_W + p.lambda_t2 * c.t2_W;
            addContactImpulse(A, B, p.r_A_W, p.r_B_W, P_W);
        }
    }
}

} // namespace rbw
