#include "physics/engine/integrators/explicit_euler.h"

#include "physics/engine/quantities.h"

#include <cmath>

namespace rbw {

void ExplicitEuler::advance(const BodyStep& step, BodyState& s) const
{
    const double h = step.h;

    // Step 2: x <- x + h v   (old v)
    s.x_W += h * s.v_W;
    step.record(q::position, s.x_W);

    // Step 3: v <- v + h F / M
    s.v_W += (h * step.mp.invM) * step.load.F_W;
    step.record(q::linear_velocity, s.v_W);

    // Step 4: r <- r + (h/2) (0, omega) r, a quaternion product with the OLD omega
    // in the world frame, then renormalise r.
    const Quat omegaQuat(0.0, s.omega_W.x(), s.omega_W.y(), s.omega_W.z());
    const Quat rDot = omegaQuat * s.q_WB;
    s.q_WB.coeffs() += (0.5 * h) * rDot.coeffs();
    // |r|^2 overflows to infinity for (h/2)|omega| > ~1e154, and a plain normalize()
    // would then silently give the zero quaternion: fall back to the scaled norm.
    const double norm2 = s.q_WB.squaredNorm();
    if (std::isfinite(norm2)) {
        const double norm = std::sqrt(norm2);
        step.record(q::orientation_norm, norm);
        s.q_WB.coeffs() /= norm;
    } else {
        step.record(q::orientation_norm, s.q_WB.coeffs().stableNorm());
        s.q_WB.coeffs().stableNormalize();
    }
    step.record(q::orientation, s.q_WB);

    // Step 5: L <- L + h q
    s.L_W += h * step.load.q_W;
    step.record(q::angular_momentum, s.L_W);

    // Steps 6-7 (R = R(r), I^-1 = R I0^-1 R^T, omega = I^-1 L): the base, updateDerived()
}

} // namespace rbw
