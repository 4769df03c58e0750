// The soft-step solver; equations and sources in soft_step_solver.h. Each function is
// one of Box2D v3's contact_solver.c stages (b2PrepareContactsTask, b2WarmStartContactsTask,
// b2SolveContactsTask with useBias true and false, b2ApplyRestitutionTask,
// b2StoreImpulsesTask) or solver.c's body stages (b2IntegrateVelocitiesTask,
// b2IntegratePositionsTask), in three dimensions and for manifolds of up to 8 points.
//
// Glossary
//   dv_W      relative velocity at the point: v_A(p) - v_B(p)                     [m/s]
//   v_n, v_t  its normal part dv . n, tangential parts dv . t1, dv . t2           [m/s]
//   dP_W      an impulse applied at the point (on A; -dP on B)                   [N s]
#include "physics/engine/manifold/soft_step_solver.h"

#include "physics/engine/manifold/contact_axis.h"

#include <algorithm>
#include <cmath>

namespace rbw {

namespace {

constexpr double kPi = 3.14159265358979323846;

// dP at lever arms r_A, r_B: v_A += dP / M_A, omega_A += I_A^-1 (r_A x dP); B opposite.
void applyImpulse(SolverBody& A, SolverBody& B, const Vec3& r_A_W, const Vec3& r_B_W, const Vec3& dP_W)
{
    A.v_W += A.invM * dP_W;
    A.omega_W += A.Iinv_W * r_A_W.cross(dP_W);
    B.v_W -= B.invM * dP_W;
    B.omega_W -= B.Iinv_W * r_B_W.cross(dP_W);
}

// dv = v_A + omega_A x r_A - v_B - omega_B x r_B
Vec3 relativeVelocity(const SolverBody& A, const SolverBody& B, const Vec3& r_A_W, const Vec3& r_B_W)
{
    return A.v_W + A.omega_W.cross(r_A_W) - B.v_W - B.omega_W.cross(r_B_W);
}

} // namespace

Softness makeSoft(double hertz, double zeta, double h)
{
    if (hertz == 0.0) return Softness{0.0, 1.0, 0.0};
    // omega = 2 pi f, a1 = 2 zeta + h omega, a2 = h omega a1, a3 = 1 / (1 + a2)
    const double omega = 2.0 * kPi * hertz;
    const double a1 = 2.0 * zeta + h * omega;
    const double a2 = h * omega * a1;
    const double a3 = 1.0 / (1.0 + a2);
    // biasRate = omega / a1, massScale = a2 a3, impulseScale = a3
    return Softness{omega / a1, a2 * a3, a3};
}

double softContactHertz(double hertzPerSubstepRate, double h_s)
{
    // f = k / h_s (k = 1/8: a quarter of the substep's Nyquist frequency 1 / (2 h_s))
    return hertzPerSubstepRate / h_s;
}

void SoftStepSolver::begin(const std::vector<Manifold>& manifolds, std::vector<SolverBody>& bodies, int planeBody,
                           const std::vector<char>& moving, const ManifoldSettings& settings, double h_s, int lanes)
{
    history_.clear();
    h_s_ = h_s;
    maxPushOut_ = settings.maxPushOut;
    // Box2D: stiffer against what cannot move, so that a pile does not sink into the ground
    const double f = softContactHertz(settings.contactHertzPerSubstepRate, h_s);
    contact_ = makeSoft(f, settings.contactDampingRatio, h_s);
    static_ = makeSoft(2.0 * f, settings.contactDampingRatio, h_s);
    // Each manifold's bodies and its points' place, in order
    constraints_.resize(manifolds.size());
    ends_.clear();
    weights_.clear();
    int first = 0;
    for (std::size_t i = 0; i < manifolds.size(); ++i) {
        const Manifold& m = manifolds[i];
        Constraint& c = constraints_[i];
        c.a = m.a;
        c.b = m.b >= 0 ? m.b : planeBody;
        c.first = first;
        c.count = m.count;
        first += m.count;
        ends_.push_back({c.a, c.b});
        weights_.push_back(m.count);
    }
    points_.resize(static_cast<std::size_t>(first));
    splitIntoLanes(ends_, weights_, moving, lanes, lanes_, islandScratch_);
    // Each lane's own static body (all zero, as every static solver body is)
    const int count = static_cast<int>(bodies.size());
    bodies.resize(static_cast<std::size_t>(count + laneCount()), SolverBody{});
    const auto moves = [&moving](int b) { return b < static_cast<int>(moving.size()) && moving[static_cast<std::size_t>(b)]; };
    for (int l = 0; l < laneCount(); ++l) {
        for (const int i : lanes_[static_cast<std::size_t>(l)].constraints) {
            Constraint& c = constraints_[static_cast<std::size_t>(i)];
            if (!moves(c.a)) c.a = count + l;
            if (!moves(c.b)) c.b = count + l;
        }
    }
}

void SoftStepSolver::prepare(std::vector<Manifold>& manifolds, const std::vector<SolverBody>& bodies,
                             const std::vector<BodyState>& start, int lane)
{
    for (const int i : lanes_[static_cast<std::size_t>(lane)].constraints) {
        Manifold& m = manifolds[static_cast<std::size_t>(i)];
        Constraint& c = constraints_[static_cast<std::size_t>(i)];
        const SolverBody& A = bodies[static_cast<std::size_t>(c.a)];
        const SolverBody& B = bodies[static_cast<std::size_t>(c.b)];
        const BodyState& startA = start[static_cast<std::size_t>(m.a)];
        const BodyState* startB = m.b >= 0 ? &start[static_cast<std::size_t>(m.b)] : nullptr;
        const Vec3 xB_W = startB != nullptr ? startB->x_W : Vec3::Zero();
        const bool movesB = B.invM > 0.0 || !B.Iinv_W.isZero(0.0);
        c.n_W = m.n_W;
        c.t1_W = m.t1_W;
        c.t2_W = m.t2_W;
        c.mu = m.mu;
        c.restitution = m.restitution;
        c.invM_A = A.invM;
        c.invM_B = B.invM;
        c.softness = movesB ? contact_ : static_;
        const double invMAB = A.invM + B.invM;
        for (int k = 0; k < m.count; ++k) {
            ManifoldPoint& mp = m.points[static_cast<std::size_t>(k)];
            Point& p = points_[static_cast<std::size_t>(c.first + k)];
            p = Point{};
            // r_A = p - x_A, r_B = p - x_B (fixed for the step, Box2D's anchors)
            p.r_A_W = mp.p_W - startA.x_W;
            p.r_B_W = mp.p_W - xB_W;
            // s_base = s_0 - n . (r_A - r_B)
            p.s_base = mp.separation - m.n_W.dot(p.r_A_W - p.r_B_W);
            // rn = r x n and I^-1 (r x n), for A and B
            p.rn_A_W = p.r_A_W.cross(m.n_W);
            p.rn_B_W = p.r_B_W.cross(m.n_W);
            p.Irn_A_W = A.Iinv_W * p.rn_A_W;
            p.Irn_B_W = B.Iinv_W * p.rn_B_W;
            p.It1_A_W = A.Iinv_W * p.r_A_W.cross(m.t1_W);
            p.It1_B_W = B.Iinv_W * p.r_B_W.cross(m.t1_W);
            p.It2_A_W = A.Iinv_W * p.r_A_W.cross(m.t2_W);
            p.It2_B_W = B.Iinv_W * p.r_B_W.cross(m.t2_W);
            // m_d = 1 / K_dd for d = n, t1, t2 (contact_axis.h)
            p.m_n = ContactAxis(p.r_A_W, p.r_B_W, m.n_W, A.Iinv_W, B.Iinv_W).mass(invMAB);
            p.m_t1 = ContactAxis(p.r_A_W, p.r_B_W, m.t1_W, A.Iinv_W, B.Iinv_W).mass(invMAB);
            p.m_t2 = ContactAxis(p.r_A_W, p.r_B_W, m.t2_W, A.Iinv_W, B.Iinv_W).mass(invMAB);
            // v_n0 = (v_A + omega_A x r_A - v_B - omega_B x r_B) . n at the start (the bounce)
            Vec3 dv_W = startA.v_W + startA.omega_W.cross(p.r_A_W);
            if (startB != nullptr) dv_W -= startB->v_W + startB->omega_W.cross(p.r_B_W);
            p.v_n0 = dv_W.dot(m.n_W);
            // The warm start: last step's last-substep impulses (ManifoldCache::warmStart)
            p.lambda_n = mp.lambda_n;
            p.lambda_t1 = mp.warm_t_W.dot(m.t1_W);
            p.lambda_t2 = mp.warm_t_W.dot(m.t2_W);
            mp.r_A_W = p.r_A_W;
            mp.r_B_W = p.r_B_W;
            mp.m_n = p.m_n;
            mp.m_t1 = p.m_t1;
            mp.m_t2 = p.m_t2;
            mp.normalVelocity = p.v_n0;
            mp.v_target = 0.0;
        }
    }
}

void SoftStepSolver::substep(std::vector<SolverBody>& bodies, std::vector<SubstepMotion>& motion, double h_s, int l)
{
    const SolverLane& lane = lanes_[static_cast<std::size_t>(l)];
    integrateVelocities(bodies, motion, h_s, lane);
    warmStart(bodies, lane);
    solve(bodies, motion, lane);
    integratePositions(bodies, motion, h_s, lane);
    relax(bodies, motion, lane);
}

void SoftStepSolver::integrateVelocities(std::vector<SolverBody>& bodies, const std::vector<SubstepMotion>& motion,
                                         double h_s, const SolverLane& lane)
{
    for (const int i : lane.bodies) {
        const std::size_t b = static_cast<std::size_t>(i);
        // v += h_s F / M, omega += h_s I^-1 q
        bodies[b].v_W += h_s * motion[b].a_W;
        bodies[b].omega_W += h_s * motion[b].alpha_W;
    }
}

void SoftStepSolver::warmStart(std::vector<SolverBody>& bodies, const SolverLane& lane)
{
    for (const int i : lane.constraints) {
        const Constraint& c = constraints_[static_cast<std::size_t>(i)];
        SolverBody& A = bodies[static_cast<std::size_t>(c.a)];
        SolverBody& B = bodies[static_cast<std::size_t>(c.b)];
        for (int k = 0; k < c.count; ++k) {
            Point& p = points_[static_cast<std::size_t>(c.first + k)];
            // P = lambda_n n + lambda_t1 t1 + lambda_t2 t2, the impulses of the last substep
            const Vec3 P_W = p.lambda_n * c.n_W + p.lambda_t1 * c.t1_W + p.lambda_t2 * c.t2_W;
            // v_A += P / M_A, omega_A += I_A^-1 (r_A x P) by the rows' precomputed images; B opposite
            A.v_W += c.invM_A * P_W;
            A.omega_W += p.lambda_n * p.Irn_A_W + p.lambda_t1 * p.It1_A_W + p.lambda_t2 * p.It2_A_W;
            B.v_W -= c.invM_B * P_W;
            B.omega_W -= p.lambda_n * p.Irn_B_W + p.lambda_t1 * p.It1_B_W + p.lambda_t2 * p.It2_B_W;
            p.P_n += p.lambda_n;
            p.P_t1 += p.lambda_t1;
            p.P_t2 += p.lambda_t2;
        }
    }
}

void SoftStepSolver::solveRows(std::vector<SolverBody>& bodies, const std::vector<SubstepMotion>& motion, bool useBias,
                               const SolverLane& lane)
{
    const double inv_h = 1.0 / h_s_;
    const SubstepMotion still;   // a plane, a fixed or a sleeping body: never moved
    for (const int i : lane.constraints) {
        const Constraint& c = constraints_[static_cast<std::size_t>(i)];
        SolverBody& A = bodies[static_cast<std::size_t>(c.a)];
        SolverBody& B = bodies[static_cast<std::size_t>(c.b)];
        const SubstepMotion& mA = c.a < static_cast<int>(motion.size()) ? motion[static_cast<std::size_t>(c.a)] : still;
        const SubstepMotion& mB = c.b < static_cast<int>(motion.size()) ? motion[static_cast<std::size_t>(c.b)] : still;
        // dx_A - dx_B, the bodies' relative displacement since prepare()
        // s = s_base + n . (dx_A - dx_B + dq_A r_A - dq_B r_B)
        //   = s_base + n . (dx_A - dx_B) + (dq_A^-1 n) . r_A - (dq_B^-1 n) . r_B
        // (a rotation keeps dot products): the normal turned back once per manifold,
        // not each lever arm turned forward at every point
        const double ndx = c.n_W.dot(mA.dx_W - mB.dx_W);
        const Vec3 nA_W = mA.dq_WB.conjugate() * c.n_W;
        const Vec3 nB_W = mB.dq_WB.conjugate() * c.n_W;
        for (int k = 0; k < c.count; ++k) {
            Point& p = points_[static_cast<std::size_t>(c.first + k)];
            const double s = p.s_base + (ndx + (nA_W.dot(p.r_A_W) - nB_W.dot(p.r_B_W)));
            double bias = 0.0;
            double massScale = 1.0;
            double impulseScale = 0.0;
            if (s > 0.0) {
                bias = s * inv_h;   // speculative: it may close the gap in this substep
            } else if (useBias) {
                bias = std::max(c.softness.biasRate * s, -maxPushOut_);
                massScale = c.softness.massScale;
                impulseScale = c.softness.impulseScale;
            }
            // v_n = (v_A + omega_A x r_A - v_B - omega_B x r_B) . n
            //     = n . (v_A - v_B) + omega_A . (r_A x n) - omega_B . (r_B x n)
            const double v_n = c.n_W.dot(A.v_W - B.v_W) + A.omega_W.dot(p.rn_A_W) - B.omega_W.dot(p.rn_B_W);
            // dlambda = -m_n massScale (v_n + bias) - impulseScale lambda_n, lambda_n >= 0
            const double candidate = p.lambda_n - p.m_n * massScale * (v_n + bias) - impulseScale * p.lambda_n;
            const double next = std::max(candidate, 0.0);
            const double dn = next - p.lambda_n;
            p.lambda_n = next;
            p.P_n += dn;
            // dP = dn n: v_A += dn n / M_A, omega_A += dn I_A^-1 (r_A x n); B opposite
            A.v_W += (dn * c.invM_A) * c.n_W;
            A.omega_W += dn * p.Irn_A_W;
            B.v_W -= (dn * c.invM_B) * c.n_W;
            B.omega_W -= dn * p.Irn_B_W;
        }
        // Friction in the relax pass only, as Box2D v3's b2SolveContact does (useBias ==
        // false): friction against the push-out velocities let the rain's columns topple
        // (1000 boxes, 4 substeps: mean height 4.82 m and 8 boxes still moving after
        // 10 s with friction in both passes; 4.95 m and none faster than 0.1 m/s with it
        // in the relax alone; docs/collisions.md, "The soft step").
        if (useBias) continue;
        for (int k = 0; k < c.count; ++k) {
            Point& p = points_[static_cast<std::size_t>(c.first + k)];
            // lambda_t* = lambda_t - m_t v_t, scaled back onto |lambda_t| <= mu lambda_n
            const Vec3 dv_W = relativeVelocity(A, B, p.r_A_W, p.r_B_W);
            double l1 = p.lambda_t1 - p.m_t1 * dv_W.dot(c.t1_W);
            double l2 = p.lambda_t2 - p.m_t2 * dv_W.dot(c.t2_W);
            const double limit = c.mu * p.lambda_n;
            const double length2 = l1 * l1 + l2 * l2;
            if (length2 > limit * limit) {
                const double scale = length2 > 0.0 ? limit / std::sqrt(length2) : 0.0;
                l1 *= scale;
                l2 *= scale;
            }
            const double d1 = l1 - p.lambda_t1;
            const double d2 = l2 - p.lambda_t2;
            p.lambda_t1 = l1;
            p.lambda_t2 = l2;
            p.P_t1 += d1;
            p.P_t2 += d2;
            // dP = d1 t1 + d2 t2: v_A += dP / M_A,
            // omega_A += d1 I_A^-1 (r_A x t1) + d2 I_A^-1 (r_A x t2); B opposite
            const Vec3 dP_W = d1 * c.t1_W + d2 * c.t2_W;
            A.v_W += c.invM_A * dP_W;
            A.omega_W += d1 * p.It1_A_W + d2 * p.It2_A_W;
            B.v_W -= c.invM_B * dP_W;
            B.omega_W -= d1 * p.It1_B_W + d2 * p.It2_B_W;
        }
    }
}

void SoftStepSolver::integratePositions(const std::vector<SolverBody>& bodies, std::vector<SubstepMotion>& motion,
                                        double h_s, const SolverLane& lane)
{
    for (const int i : lane.bodies) {
        const std::size_t b = static_cast<std::size_t>(i);
        SubstepMotion& m = motion[b];
        // dx += h_s v, dtheta += h_s omega
        m.dx_W += h_s * bodies[b].v_W;
        const Vec3 dtheta_W = h_s * bodies[b].omega_W;
        m.dtheta_W += dtheta_W;
        // dq <- (dq + 1/2 (0, dtheta) dq) / |.|
        const Quat rate = Quat(0.0, dtheta_W.x(), dtheta_W.y(), dtheta_W.z()) * m.dq_WB;
        m.dq_WB.coeffs() += 0.5 * rate.coeffs();
        m.dq_WB.normalize();
    }
}

void SoftStepSolver::applyRestitution(std::vector<SolverBody>& bodies, double threshold, int lane)
{
    for (const int i : lanes_[static_cast<std::size_t>(lane)].constraints) {
        const Constraint& c = constraints_[static_cast<std::size_t>(i)];
        if (c.restitution == 0.0) continue;
        SolverBody& A = bodies[static_cast<std::size_t>(c.a)];
        SolverBody& B = bodies[static_cast<std::size_t>(c.b)];
        for (int k = 0; k < c.count; ++k) {
            Point& p = points_[static_cast<std::size_t>(c.first + k)];
            // Only a point that approached faster than the threshold and was hit (an
            // impulse in the step; a speculative point that never closed has none)
            if (p.v_n0 > -threshold || p.P_n == 0.0) continue;
            const double v_n = relativeVelocity(A, B, p.r_A_W, p.r_B_W).dot(c.n_W);
            // dlambda = -m_n (v_n + e v_n0), lambda_n >= 0
            const double next = std::max(p.lambda_n - p.m_n * (v_n + c.restitution * p.v_n0), 0.0);
            const double dn = next - p.lambda_n;
            p.lambda_n = next;
            p.P_n += dn;
            applyImpulse(A, B, p.r_A_W, p.r_B_W, dn * c.n_W);
        }
    }
}

void SoftStepSolver::recordSubstep()
{
    for (const Point& p : points_) history_.push_back(PointImpulses{p.lambda_n, p.lambda_t1, p.lambda_t2});
}

void SoftStepSolver::store(std::vector<Manifold>& manifolds, std::vector<SolverBody>& bodies, int lane) const
{
    for (const int index : lanes_[static_cast<std::size_t>(lane)].constraints) {
        const std::size_t i = static_cast<std::size_t>(index);
        const Constraint& c = constraints_[i];
        SolverBody& A = bodies[static_cast<std::size_t>(c.a)];
        SolverBody& B = bodies[static_cast<std::size_t>(c.b)];
        for (int k = 0; k < c.count; ++k) {
            const Point& p = points_[static_cast<std::size_t>(c.first + k)];
            ManifoldPoint& mp = manifolds[i].points[static_cast<std::size_t>(k)];
            mp.lambda_n = p.lambda_n;
            mp.lambda_t1 = p.lambda_t1;
            mp.lambda_t2 = p.lambda_t2;
            mp.P_n = p.P_n;
            // The step's impulse P = P_n n + P_t1 t1 + P_t2 t2 on A, -P on B; moments r x P
            const Vec3 P_W = p.P_n * c.n_W + p.P_t1 * c.t1_W + p.P_t2 * c.t2_W;
            mp.P_t_W = p.P_t1 * c.t1_W + p.P_t2 * c.t2_W;
            addContactImpulse(A, B, p.r_A_W, p.r_B_W, P_W);
        }
    }
}

} // namespace rbw
