// The soft-step contact solver of the manifold model ("solver": "soft-step"; E. Catto,
// "Solver2D", 2024, and Box2D v3's contact_solver.c / solver.c, read side by side with
// this file; docs/collisions.md, "The soft step"). One step of length h is cut into
// n substeps of h_s = h / n (substeps, default 5); per step and per substep:
//
//   begin()                       once: the softness, the lanes of whole islands, one per
//                                 thread (solver_islands.h); then each lane on its own:
//   prepare()                     anchors, base separations, effective masses,
//                                 start normal velocities, warm-start impulses
//   for each substep (substep()):
//     integrateVelocities()       v += h_s F / M,  omega += h_s I^-1 q
//     warmStart()                 the accumulated impulses applied again
//     solve()                     soft normal rows with a push-out bias (useBias = true)
//     integratePositions()        dx += h_s v,  dq <- dq + h_s/2 (0, omega) dq
//     relax()                     the normal rows without the bias (useBias = false), then friction
//   applyRestitution()            once: v_n -> -e v_n0 at points that were hit
//   store()                       impulses into the manifolds (warm start, trace) and the
//                                 step's impulse sums into the bodies (contact loads)
//
// A soft contact (Box2D b2MakeSoft) is a spring-damper of frequency f (contact_hertz,
// f = 1/(8 h_s), a quarter of the substep rate's Nyquist: Box2D's cap, which its 30 Hz
// default meets at 4 substeps of 1/60 s; twice that against a fixed body or a plane)
// and damping ratio zeta:
//   omega = 2 pi f,  a1 = 2 zeta + h_s omega,  a2 = h_s omega a1,  a3 = 1 / (1 + a2)
//   biasRate = omega / a1,  massScale = a2 a3,  impulseScale = a3
// and a normal row at a point with current separation s and normal velocity v_n:
//   s > 0 (apart):        bias = s / h_s, massScale 1, impulseScale 0 (speculative)
//   s <= 0, solve():      bias = max(biasRate s, -maxPushOut)
//   s <= 0, relax():      bias = 0, massScale 1, impulseScale 0 (rigid)
//   dlambda = -m_n massScale (v_n + bias) - impulseScale lambda_n,
//   lambda_n <- max(0, lambda_n + dlambda)
// with s re-measured in every substep from the bodies' displacement since prepare():
//   s = s_base + n . (dx_A + dq_A r_A - dx_B - dq_B r_B),  s_base = s_0 - n . (r_A - r_B).
// Friction, in the relax pass only (as Box2D v3 does), as in the sequential impulses:
// lambda_t <- lambda_t - m_t v_t, the 2-vector scaled back onto the Coulomb cone
// |lambda_t| <= mu lambda_n.
//
// How it meets the rest of the step (every integrator): the step's impulses (the sums
// over substeps and the bounce) go to the integration as contact loads F_c = P/h,
// q_c = L_c/h, so the integrator moves the bodies with the final, relaxed velocities;
// what the substeps moved beyond that (the push-out, dx - h v and dtheta - h omega) is a
// position-only correction the position stage adds afterwards (pushOut()).
//
// Glossary (see also contact_solver.h and manifold.h)
//   h_s               substep length h / substeps                                  [s]
//   s_base            separation at the start less n . (r_A - r_B)                 [m]
//   dx_W, dtheta_W    a body's displacement and rotation over the substeps so far   [m], [rad]
//   dq_WB             the same rotation as a unit quaternion                       [-]
//   v_n0              the point's normal velocity at the start (for the bounce)     [m/s]
//   P_n, P_t1, P_t2   the step's impulse at the point: the sum over substeps        [N s]
#pragma once

#include "physics/engine/body.h"
#include "physics/engine/manifold/contact_solver.h"
#include "physics/engine/manifold/manifold.h"
#include "physics/engine/manifold/settings.h"
#include "physics/engine/manifold/solver_islands.h"

#include <vector>

namespace rbw {

// Box2D's b2Softness: how a soft row scales the bias, the effective mass and the impulse.
struct Softness {
    double biasRate = 0.0;       // [1/s]
    double massScale = 1.0;      // [-]
    double impulseScale = 0.0;   // [-]
};

// b2MakeSoft: the softness of a spring of frequency `hertz` and damping ratio `zeta`
// stepped with h (rigid, {0, 1, 0}, for hertz = 0). massScale + impulseScale = 1.
Softness makeSoft(double hertz, double zeta, double h);

// The contact frequency a step uses: f = k / h_s, k = hertzPerSubstepRate (1/8: Box2D's
// cap, a quarter of the substep's Nyquist frequency; Box2D's 30 Hz at its 4 substeps of
// 1/60 s). Relative to the substep rate, so more substeps make stiffer contacts.
double softContactHertz(double hertzPerSubstepRate, double h_s);

// A body's motion over the substeps (Box2D's b2BodyState delta position and rotation).
struct SubstepMotion {
    Vec3 a_W = Vec3::Zero();        // F / M                      [m/s^2]
    Vec3 alpha_W = Vec3::Zero();    // I^-1 q                     [rad/s^2]
    Vec3 dx_W = Vec3::Zero();
    Vec3 dtheta_W = Vec3::Zero();
    Quat dq_WB = Quat::Identity();
};

class SoftStepSolver {
public:
    // What one row of the trace's iteration history is (ContactHeader::iteration).
    static constexpr const char* kIteration =
        "one substep of the soft step: the velocities take h_s F/M, the warm start, one solve "
        "with soft contacts over every manifold, the positions move, one relax pass without the bias";

    // Once per step, before the lanes run: the softness, each manifold's bodies (A =
    // m.a; B = m.b, or planeBody for a plane) and its points' place, and the lanes:
    // the manifolds split into `lanes` lanes of whole islands that share no moving body
    // (solver_islands.h), each with its own static body: a manifold's fixed, sleeping or
    // plane side becomes bodies[count + lane] (appended; zero velocity, mass and inertia,
    // as the body it stands for), so that no two lanes write to one body. With one lane:
    // every manifold in order, every moving body.
    void begin(const std::vector<Manifold>& manifolds, std::vector<SolverBody>& bodies, int planeBody,
               const std::vector<char>& moving, const ManifoldSettings& settings, double h_s, int lanes);
    // For the lane's manifolds: lever arms, s_base, m_n, m_t1, m_t2, v_n0, the softness
    // (static when B cannot move), the warm-start impulses from the cache (lambda_n,
    // warm_t_W). Writes r_A, r_B, m_n, m_t1, m_t2, normalVelocity into the manifolds' points.
    void prepare(std::vector<Manifold>& manifolds, const std::vector<SolverBody>& bodies,
                 const std::vector<BodyState>& start, int lane);
    int laneCount() const { return static_cast<int>(lanes_.size()); }
    const SolverLane& lane(int l) const { return lanes_[static_cast<std::size_t>(l)]; }

    // One substep of one lane: integrateVelocities, warmStart, solve, integratePositions, relax.
    void substep(std::vector<SolverBody>& bodies, std::vector<SubstepMotion>& motion, double h_s, int lane);

    // v += h_s F / M, omega += h_s I^-1 q for the lane's bodies.
    static void integrateVelocities(std::vector<SolverBody>& bodies, const std::vector<SubstepMotion>& motion,
                                    double h_s, const SolverLane& lane);
    // Applies the accumulated impulses to the bodies (and counts them into the step's P).
    void warmStart(std::vector<SolverBody>& bodies, const SolverLane& lane);
    // The soft rows with the push-out bias.
    void solve(std::vector<SolverBody>& bodies, const std::vector<SubstepMotion>& motion, const SolverLane& lane)
    {
        solveRows(bodies, motion, true, lane);
    }
    // dx += h_s v, dtheta += h_s omega, dq <- normalise(dq + h_s/2 (0, omega) dq).
    static void integratePositions(const std::vector<SolverBody>& bodies, std::vector<SubstepMotion>& motion,
                                   double h_s, const SolverLane& lane);
    // The rigid rows without the bias: takes back the push-out velocity.
    void relax(std::vector<SolverBody>& bodies, const std::vector<SubstepMotion>& motion, const SolverLane& lane)
    {
        solveRows(bodies, motion, false, lane);
    }
    // After the substeps: the bounce v_n -> -e v_n0 at points approaching faster than
    // `threshold` at the start that got an impulse.
    void applyRestitution(std::vector<SolverBody>& bodies, double threshold, int lane);
    // Appends every point's accumulated impulses to history() (after a substep).
    void recordSubstep();
    // lambda_n, lambda_t1, lambda_t2 (the last substep's, what the next step warm-starts
    // from) into the manifolds' points, the step's impulses P_n, P_t into stepImpulse_*,
    // and the step's sums P, L_c into the bodies (the contact loads).
    void store(std::vector<Manifold>& manifolds, std::vector<SolverBody>& bodies, int lane) const;

    // Points of all manifolds, in order; history()[i * pointCount() + g]: point g after substep i+1.
    int pointCount() const { return static_cast<int>(points_.size()); }
    const std::vector<PointImpulses>& history() const { return history_; }
    const Softness& contactSoftness() const { return contact_; }
    const Softness& staticSoftness() const { return static_; }

private:
    void solveRows(std::vector<SolverBody>& bodies, const std::vector<SubstepMotion>& motion, bool useBias,
                   const SolverLane& lane);

    struct Point {
        Vec3 r_A_W, r_B_W;
        // The normal row's angular parts, fixed for the step (the anchors and I^-1 are):
        // rn_A = r_A x n, rn_B = r_B x n and their I^-1 images (as Bullet's btSolverConstraint)
        Vec3 rn_A_W, rn_B_W, Irn_A_W, Irn_B_W;
        // the friction rows' I^-1 (r x t1), I^-1 (r x t2), for A and B
        Vec3 It1_A_W, It1_B_W, It2_A_W, It2_B_W;
        double s_base;
        double m_n, m_t1, m_t2;
        double v_n0;
        double lambda_n, lambda_t1, lambda_t2;   // accumulated in the current substep [N s]
        double P_n, P_t1, P_t2;                  // applied over the step so far      [N s]
    };
    struct Constraint {
        Vec3 n_W, t1_W, t2_W;
        double mu, restitution;
        int a, b;   // solver bodies; a static side may be its lane's (splitLanes)
        int first, count;
        double invM_A, invM_B;   // [1/kg]
        Softness softness;
    };
    std::vector<Constraint> constraints_;
    std::vector<Point> points_;
    std::vector<PointImpulses> history_;
    std::vector<SolverLane> lanes_;
    IslandScratch islandScratch_;
    std::vector<std::array<int, 2>> ends_;   // splitLanes' input: each constraint's bodies
    std::vector<int> weights_;               // and points
    Softness contact_;
    Softness static_;
    double h_s_ = 0.0;
    double maxPushOut_ = 0.0;
};

} // namespace rbw
