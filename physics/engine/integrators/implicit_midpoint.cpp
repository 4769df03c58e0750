#include "physics/engine/integrators/implicit_midpoint.h"

#include "physics/engine/integrators/rigid_ode.h"
#include "physics/engine/quantities.h"

#include <Eigen/LU>

#include <cmath>
#include <limits>

namespace rbw {

namespace {

constexpr double kUnitRoundoff = std::numeric_limits<double>::epsilon() / 2.0;

struct SolveResult {
    Vec3 value = Vec3::Zero();
    int iterations = 0;
    double residual = 0.0;
};

// Body frame: solve G(L1) = L1 - L0 + h omega_m x L_m = 0 by Newton's method.
// Stops when |G| is at rounding level, or when a Newton update no longer reduces it.
SolveResult solveLiePoisson(const Vec3& L0_B, const Mat3& I0inv_B, double h)
{
    auto residualOf = [&](const Vec3& L1_B) -> Vec3 {
        const Vec3 Lm_B = 0.5 * (L0_B + L1_B);
        const Vec3 omegam_B = I0inv_B * Lm_B;
        return Vec3(L1_B - L0_B + h * omegam_B.cross(Lm_B));
    };
    SolveResult r;
    // Predictor: one explicit Euler step, L1 = L0 - h omega_0 x L0
    r.value = L0_B - h * (I0inv_B * L0_B).cross(L0_B);
    Vec3 G = residualOf(r.value);
    double Gnorm = G.norm();
    const double tol = 4.0 * kUnitRoundoff * L0_B.norm();
    while (Gnorm > tol && r.iterations < ImplicitMidpoint::kMaxIterations) {
        // dG/dL1 = E + h/2 ([omega_m]x - [L_m]x I0^-1)
        const Vec3 Lm_B = 0.5 * (L0_B + r.value);
        const Vec3 omegam_B = I0inv_B * Lm_B;
        const Mat3 J = Mat3::Identity() + (0.5 * h) * (skew(omegam_B) - skew(Lm_B) * I0inv_B);
        const Vec3 candidate = r.value - J.partialPivLu().solve(G);
        const Vec3 Gc = residualOf(candidate);
        const double GcNorm = Gc.norm();
        ++r.iterations;
        if (!(GcNorm < Gnorm)) {
            break;   // rounding level reached: the update no longer helps
        }
        r.value = candidate;
        G = Gc;
        Gnorm = GcNorm;
    }
    r.residual = Gnorm;
    return r;
}

// p = ((1 - |a|^2), 2a) / (1 + |a|^2), a = h omega/4: the unit quaternion with
// p r = r + h/2 (0, omega) (r + p r)/2  (the midpoint rule for r' = 1/2 (0, omega) r).
Quat midpointRotation(const Vec3& omega_W, double h)
{
    const Vec3 a = (0.25 * h) * omega_W;
    const double a2 = a.squaredNorm();
    const double s = 1.0 / (1.0 + a2);
    return Quat((1.0 - a2) * s, 2.0 * s * a.x(), 2.0 * s * a.y(), 2.0 * s * a.z());
}

// World frame (course template): fixed point omega_m = I^-1(r_m(omega_m)) L.
SolveResult solveWorldMidpoint(const Quat& r0, const Vec3& L_W, const Vec3& omega0_W,
                               const MassProperties& mp, double h, InertiaConvention convention)
{
    SolveResult r;
    r.value = omega0_W;
    r.residual = std::numeric_limits<double>::infinity();
    const double tol = 4.0 * kUnitRoundoff * omega0_W.norm();
    while (r.iterations < ImplicitMidpoint::kMaxIterations) {
        const Quat r1 = midpointRotation(r.value, h) * r0;
        Quat rm;
        rm.coeffs() = 0.5 * (r0.coeffs() + r1.coeffs());
        const Vec3 next = angularVelocityAt(rm, L_W, mp, convention);
        const double change = (next - r.value).norm();
        ++r.iterations;
        const bool stalled = !(change < r.residual);
        r.residual = change;
        r.value = next;
        if (change <= tol || stalled) {
            break;
        }
    }
    return r;
}

} // namespace

void ImplicitMidpoint::advance(const BodyStep& step, BodyState& s) const
{
    const double h = step.h;

    // Half kick: v <- v + h/2 F/M,  L <- L + h/2 q;  drift: x <- x + h v
    const Vec3 halfDv_W = (0.5 * h * step.mp.invM) * step.load.F_W;
    const Vec3 halfDL_W = (0.5 * h) * step.load.q_W;
    s.v_W += halfDv_W;
    s.x_W += h * s.v_W;
    step.record(q::verlet_position, s.x_W);
    s.L_W += halfDL_W;

    if (step.convention == InertiaConvention::CourseTemplate) {
        // r_{n+1} = p r_n with omega_m = I^-1(r_m) L  (fixed point, see the header)
        const Vec3 omega0_W = s.Iinv_W * s.L_W;
        const SolveResult sol = solveWorldMidpoint(s.q_WB, s.L_W, omega0_W, step.mp, h, step.convention);
        step.record(q::midpoint_world_angular_velocity, sol.value);
        step.record(q::fixed_point_iterations, double(sol.iterations));
        step.record(q::fixed_point_residual, sol.residual);
        s.q_WB = normalisedOrientation(midpointRotation(sol.value, h) * s.q_WB);
        step.record(q::cayley_world_orientation, s.q_WB);
    } else {
        // L_B = R_n^T L
        const Vec3 L0_B = s.R_WB.transpose() * s.L_W;
        step.record(q::body_angular_momentum, L0_B);
        SolveResult sol;
        if (skipIsotropic_ && isIsotropic(step.mp.I0_B)) {
            // I0 = k E: omega_m x L_m = 0, so L_B' = L_B
            step.record(q::gyroscopic_skipped, 1.0);
            sol.value = L0_B;
        } else {
            // L_B' = L_B - h omega_m x L_m  (Newton to machine precision)
            sol = solveLiePoisson(L0_B, step.mp.I0inv_B, h);
            step.record(q::body_angular_momentum_new, sol.value);
            step.record(q::newton_iterations, double(sol.iterations));
            step.record(q::midpoint_newton_residual, sol.residual);
        }
        // omega_m = I0^-1 (L_B + L_B')/2
        const Vec3 omegam_B = step.mp.I0inv_B * (0.5 * (L0_B + sol.value));
        step.record(q::midpoint_body_angular_velocity, omegam_B);
        // c = (1, h/2 omega_m)/|.| = cay(h [omega_m]x);  r_{n+1} = r_n c
        const Vec3 half_B = (0.5 * h) * omegam_B;
        const Quat c0(1.0, half_B.x(), half_B.y(), half_B.z());
        step.record(q::cayley_norm, c0.norm());
        const Quat c = c0.normalized();
        step.record(q::cayley_rotation, c);
        s.q_WB = normalisedOrientation(s.q_WB * c);
        step.record(q::cayley_orientation, s.q_WB);
    }

    // Half kick: v <- v + h/2 F/M,  L <- L + h/2 q
    s.v_W += halfDv_W;
    step.record(q::verlet_linear_velocity, s.v_W);
    s.L_W += halfDL_W;
    step.record(q::half_kick_angular_momentum, s.L_W);
}

} // namespace rbw
