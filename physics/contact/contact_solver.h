// The sequential-impulse contact solver of the manifold model (Catto, "Iterative
// dynamics with temporal coherence", GDC 2005, and "Fast and simple physics using
// sequential impulses", GDC 2006; Box2D-lite Arbiter::PreStep/ApplyImpulse; Box2D
// b2ContactSolver for the position fix; docs/references.md §9, §17).
//
// Velocity solve, at every manifold point, with effective masses
//   m_n = 1 / (1/M_A + 1/M_B + [(I_A^-1 (r_A x n)) x r_A + (I_B^-1 (r_B x n)) x r_B] . n)
// (and m_t1, m_t2 the same along t1, t2), in every iteration, manifold by manifold:
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
// Position fix (non-linear Gauss-Seidel, Box2D b2ContactSolver::SolvePositionConstraints),
// after the integration, on positions only: with the separation s re-measured from the
// anchors on both bodies,
//   C = clamp(beta (s + slop), -maxCorrection, 0),  K = 1/m_n at the current pose,
//   P = -C / K,  x_A += P n / M_A,  r_A <- rotate(I_A^-1 (r_A x P n)),  B opposite.
// v and L are not touched, so the fix adds no kinetic energy.
#pragma once

#include "physics/body.h"
#include "physics/contact/manifold.h"
#include "physics/contact/settings.h"

#include <vector>

namespace rbw {

// A body as the velocity solver sees it. A fixed body, a plane and the angular part of a
// body without angular response have zero inverse mass / inertia.
struct SolverBody {
    Vec3 v_W = Vec3::Zero();
    Vec3 omega_W = Vec3::Zero();
    double invM = 0.0;
    Mat3 Iinv_W = Mat3::Zero();
    Vec3 P_W = Vec3::Zero();    // sum of the impulses on the body (accumulateImpulses) [N s]
    Vec3 Lc_W = Vec3::Zero();   // sum of their moments about the centre   [kg m^2/s]
};

// Lever arms, effective masses, the start-of-step normal velocity v_n and the target
// v_target of every point of m, then applies the warm-start impulses (the points'
// lambda_n, lambda_t1, lambda_t2 as warmStart() left them). `start` is the bodies'
// velocity at the start of the step (for the bounce), `A`/`B` their solver bodies (B the
// static body for a plane), xA, xB the centres.
void prepareManifold(Manifold& m, SolverBody& A, SolverBody& B, const Vec3& xA_W, const Vec3& xB_W,
                     const BodyState& startA, const BodyState* startB, const ManifoldSettings& settings, double h,
                     double restitutionThreshold);

// One velocity iteration over m: normalSweeps passes over the normal rows of all its
// points, then the friction rows of each point; returns the largest change of an
// accumulated impulse in it [N s].
double solveManifoldVelocities(Manifold& m, SolverBody& A, SolverBody& B, int normalSweeps);

// One position iteration of NGS over every point of m; moves x and q of A and B (nullptr
// for a plane) by the corrections and adds each body's displacement to dxA/dxB. Returns
// the smallest separation it measured before correcting [m].
double solveManifoldPositions(const Manifold& m, BodyState& A, const MassProperties& massA, bool angularA,
                              BodyState* B, const MassProperties* massB, bool angularB,
                              const ManifoldSettings& settings, Vec3& dxA_W, Vec3& dxB_W);

// Adds the manifold's final impulses to the bodies' sums P and L_c (the contact loads):
// P = lambda_n n + lambda_t1 t1 + lambda_t2 t2 on A and -P on B, with their moments.
void accumulateImpulses(const Manifold& m, SolverBody& A, SolverBody& B);

// The separation of point k of m at the bodies' current poses: s = n . (pA - pB).
double currentSeparation(const Manifold& m, int k, const BodyState& A, const BodyState* B);

} // namespace rbw
