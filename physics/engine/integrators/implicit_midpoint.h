// The implicit midpoint rule on the body-frame angular momentum (the Lie-Poisson
// form of Euler's equations), with the orientation advanced by the matching Cayley
// rotation. Second order, symmetric; conserves every quadratic invariant of the
// free body, |L|^2 and 2T = L_B . I0^-1 L_B, and the world-frame L.
// Hairer, Lubich & Wanner, "Geometric Numerical Integration", Thm IV.2.2 (implicit
// midpoint keeps quadratic invariants) and section VII.5.3 (rigid body); Austin,
// Krishnaprasad & Wang, J. Comput. Phys. 107 (1993) (the Cayley form of the step).
//
// One step, standard convention (I^-1 = R I0^-1 R^T), torque q and force F constant:
//   L   <- L + h/2 q,   v <- v + h/2 F/M,   x <- x + h v       (half kick, drift)
//   L_B  = R_n^T L
//   solve  L_B' = L_B - h omega_m x L_m,   L_m = (L_B + L_B')/2,  omega_m = I0^-1 L_m
//          by Newton on G(L_B') = L_B' - L_B + h omega_m x L_m,
//          dG/dL_B' = E + h/2 ([omega_m]x - [L_m]x I0^-1), to machine precision
//   c    = (1, h/2 omega_m) / |.|   = cay(h [omega_m]x), a rotation by 2 atan(h|omega_m|/2)
//   r_{n+1} = r_n c,   so R_{n+1}^T L = c^T L_B = L_B' exactly: L_W is not touched
//   L   <- L + h/2 q,   v <- v + h/2 F/M                        (half kick)
// Why c: L_B' = (E + A/2)^-1 (E - A/2) L_B with A = h[omega_m]x, and that matrix is
// cay(A)^T, cay(A) = (E - A/2)^-1 (E + A/2), whose quaternion is (1, a/2)/|.| for A = [a]x.
// The translation is velocity Verlet: exact for a constant force.
//
// Course-template convention (I^-1 = R^T I0^-1 R): there is no body frame in which
// the equations close (inertia.h), so the rule is applied to the world-frame
// orientation instead: r_{n+1} = r_n + h/2 (0, omega_m) (r_n + r_{n+1})/2 with
// omega_m = I^-1(r_m) L, i.e. r_{n+1} = p r_n, p = ((1 - |a|^2), 2a)/(1 + |a|^2),
// a = h omega_m/4, solved by fixed-point iteration on omega_m. This keeps |r| = 1 and
// L_W exactly and is second order, but conserves T only to O(h^2).
//
// When I0 = k E the Lie-Poisson right-hand side omega x L is zero, so L_B' = L_B
// and no Newton iteration runs (the trace says so).
#pragma once

#include "physics/engine/integrator.h"

namespace rbw {

class ImplicitMidpoint final : public Integrator {
public:
    static constexpr const char* kName = "implicit-midpoint";
    static constexpr int kMaxIterations = 50;
    explicit ImplicitMidpoint(bool skipIsotropic = true) : skipIsotropic_(skipIsotropic) {}
    const char* name() const override { return kName; }
    void advance(const BodyStep& step, BodyState& s) const override;

private:
    bool skipIsotropic_;
};

} // namespace rbw
