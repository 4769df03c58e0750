// The sequential-impulse contact solver of the manifold model (Catto, "Iterative
// dynamics with temporal coherence", GDC 2005, and "Fast and simple physics using
// sequential impulses", GDC 2006; Box2D-lite Arbiter::PreStep/ApplyImpulse; Box2D v3
// b2ContactConstraint for the layout; docs/references.md §9, §17). The position fix
// that follows the integration is position_fix.h.
//
// Velocity solve, at every manifold point, with effective masses
//   m_n = 1 / (1/M_A + 1/M_B + (r_A x n) . I_A^-1 (r_A x n) + (r_B x n) . I_B^-1 (r_B x n))
// (and m_t1, m_t2 the same along t1, t2; contact_axis.h), in every iteration, manifold
// by manifold:
//   normal:    lambda_n <- max(0, lambda_n + m_n (v_target - v_n)), for all points of
//              the manifold, normal_sweeps times (ManifoldSettings::normalSweeps)
//   friction:  lambda_ti* = lambda_ti - m_ti v_ti; inside the Coulomb cone
//              |lambda_t| <= mu lambda_n it sticks, outside it slides and the 2-vector is
//              scaled back onto the cone
// with t1 along the sliding velocity when the pair slides (Bullet's choice).
// and each change of the accumulated impulse, dP, is applied at once:
//   v_A += dP / M_A, omega_A += I_A^-1 (r_A x dP), and the opposite for B.
// Accumulated impulses (not per-iteration ones) are clamped, so a later iteration may
// take back what an earlier one overdid; warm starting begins from last step's values.
//
// The velocities the solver works on are the free velocities after this step's loads,
//   v* = v + h F / M,  omega* = omega + h I^-1 q,
// and what it adds to them is handed to the integrator as a contact force and torque,
//   F_c = P / h,  q_c = L_c / h   (P, L_c the sums of the impulses and their moments),
// so every integrator integrates the constrained motion unchanged (Box2D-lite's order:
// forces, impulses, then positions with the new velocities).
//
// Layout (docs/performance.md, "Contacts: the box rain"): the iterations stream every
// row of every manifold ten times a step, so they read a compact copy of the rows, not
// the manifolds (whose points also hold the narrow phase's and the trace's numbers):
// per point the lever arms, the effective masses and the impulses (14 numbers) and the
// friction rows' angular responses I^-1 (r x t_i) (12), per manifold its basis, its
// bodies and the coupling K of its normal rows. The velocities along the rows use
// omega x r, and the normal rows' changes are applied once per manifold as a sum.
#pragma once

#include "physics/engine/body.h"
#include "physics/engine/manifold/manifold.h"
#include "physics/engine/manifold/settings.h"

#include <vector>

namespace rbw {

// A body as the velocity solver sees it. A fixed body, a plane and the angular part of a
// body without angular response have zero inverse mass / inertia.
struct SolverBody {
    Vec3 v_W = Vec3::Zero();
    Vec3 omega_W = Vec3::Zero();
    double invM = 0.0;
    Mat3 Iinv_W = Mat3::Zero();
    Vec3 P_W = Vec3::Zero();    // sum of the impulses on the body (ContactSolver::store) [N s]
    Vec3 Lc_W = Vec3::Zero();   // sum of their moments about the centre   [kg m^2/s]
};

// The step's impulse P at a point into the bodies' sums, the contact loads: P on A at
// r_A, -P on B at r_B, with their moments r_A x P and -r_B x P. Both solvers' store()
// (which differ in what the step's impulse is: the sequential impulses' accumulated
// lambda, the soft step's sum over its substeps P).
inline void addContactImpulse(SolverBody& A, SolverBody& B, const Vec3& r_A_W, const Vec3& r_B_W, const Vec3& P_W)
{
    A.P_W += P_W;
    A.Lc_W += r_A_W.cross(P_W);
    B.P_W -= P_W;
    B.Lc_W -= r_B_W.cross(P_W);
}

// One point's accumulated impulses after an iteration (the trace's iteration history).
struct PointImpulses {
    double lambda_n = 0.0;
    double lambda_t1 = 0.0;
    double lambda_t2 = 0.0;
};

// The sequential-impulse solver in Box2D v3's shape (contact_solver.c; the soft step,
// soft_step_solver.h, has the same functions and two more, relax and restitution, which
// this solver does not need: its bounce is in v_target and its position fix is the NGS
// pass after the integration). One step:
//   prepare(); warmStart(); solve() up to `iterations` times; store().
// One iteration (one call of solve(), one row of the derivation's @iterations table):
// every manifold in turn, its normal rows normalSweeps times, then its friction rows.
class ContactSolver {
public:
    // What one iteration is, for the trace (ContactHeader::iteration, the @iterations table).
    static constexpr const char* kIteration =
        "one sweep of the sequential impulses over every manifold in turn: its normal rows "
        "in 3 passes together, then each point's two friction rows";
    static_assert(ManifoldSettings{}.normalSweeps == 3, "kIteration names the passes over the normal rows");
    // For every manifold (A = bodies[m.a]; B = bodies[m.b], or bodies[planeBody] for a
    // plane): the tangents (along the sliding velocity when the pair slides), the lever
    // arms, the effective masses (contact_axis.h), the start-of-step normal velocity v_n,
    // the target v_target and the coupling of its normal rows, and the warm-start
    // impulses (the points' lambda_n and warm_t_W as ManifoldCache::warmStart left them,
    // applied by warmStart()). Writes t1, t2 and each point's r_A, r_B, m_n,
    // normalVelocity, v_target and lambda_t1, lambda_t2 into the manifolds. `start` is the
    // bodies' state at the start of the step (their centres, and their velocities for the
    // bounce). Reads of the bodies only their masses and inertias.
    void prepare(std::vector<Manifold>& manifolds, std::vector<SolverBody>& bodies, int planeBody,
                 const std::vector<BodyState>& start, const ManifoldSettings& settings, double h,
                 double restitutionThreshold);

    // Applies the warm-start impulses prepare() took from the cache to the bodies:
    // P = lambda_n n + lambda_t1 t1 + lambda_t2 t2 on A at r_A, -P on B at r_B.
    void warmStart(std::vector<SolverBody>& bodies) const;

    // One velocity iteration over every manifold in order: normalSweeps passes over the
    // normal rows of all its points, then the friction rows of each point. Returns the
    // largest change of an accumulated impulse in it [N s].
    double solve(std::vector<SolverBody>& bodies, int normalSweeps);

    // Appends every point's accumulated impulses to history() (call after an iteration).
    void recordIteration();

    // Copies the accumulated impulses lambda_n, lambda_t1, lambda_t2 into the manifolds'
    // points (the manifolds prepare() was given; the warm-start cache takes them from
    // there) and adds them to the bodies' sums P and L_c (the contact loads):
    // P = lambda_n n + lambda_t1 t1 + lambda_t2 t2 on A and -P on B, with their moments
    // r_A x P and -r_B x P.
    void store(std::vector<Manifold>& manifolds, std::vector<SolverBody>& bodies) const;

    // The points of all manifolds, in order (manifold by manifold, point by point).
    int pointCount() const { return static_cast<int>(points_.size()); }
    // history()[i * pointCount() + g]: point g's impulses after the (i+1)-th recorded
    // iteration; empty unless recordIteration() was called.
    const std::vector<PointImpulses>& history() const { return history_; }

private:
    // One manifold point as the iterations see it.
    struct Point {
        Vec3 r_A_W;           // lever arms p - x_A, p - x_B                      [m]
        Vec3 r_B_W;
        double m_n, m_t1, m_t2;   // effective masses                             [kg]
        // K_12 = (r_A x t1) . I_A^-1 (r_A x t2) + (r_B x t1) . I_B^-1 (r_B x t2): the
        // change of v_t2 per unit impulse along t1                               [1/kg]
        double K_t12;
        double v_target;      // [m/s]
        double lambda_n, lambda_t1, lambda_t2;   // accumulated                   [N s]
    };
    // The friction rows' angular responses of one point, I^-1 (r x t_i) for A and B
    // (the friction rows are solved point by point, each after the last one's change,
    // so applying them sits on the chain of dependent updates; computed once per step).
    struct FrictionRows {
        Vec3 IArAxt1_W, IArAxt2_W;
        Vec3 IBrBxt1_W, IBrBxt2_W;
    };
    // One manifold.
    struct Constraint {
        Vec3 n_W, t1_W, t2_W;
        double mu;
        int a, b;          // indices into the solver bodies (b: planeBody for a plane)
        int first, count;  // its points: points_[first, first + count)
        int firstW;        // its rows' coupling m_n,i K_ij = W_[firstW + j count + i]
        bool movesB;       // B has a mass or inertia to respond (not a plane, fixed, asleep)
    };
    std::vector<Constraint> constraints_;
    std::vector<Point> points_;
    std::vector<FrictionRows> friction_;   // indexed like points_
    std::vector<double> W_;
    std::vector<PointImpulses> history_;
};

} // namespace rbw
