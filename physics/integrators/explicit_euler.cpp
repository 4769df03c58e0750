#include "physics/integrators/explicit_euler.h"

#include "physics/quantities.h"

#include <cmath>

namespace rbw {

void ExplicitEuler::integrate(const IntegrationInput& in, std::vector<BodyState>& states,
                              StepTrace* trace) const
{
    const double h = in.h;
    for (int b = 0; b < static_cast<int>(states.size()); ++b) {
        if (!in.advances(b)) {
            continue;
        }
        BodyState& s = states[b];
        const MassProperties& mp = in.mass[b];
        const BodyLoad& load = in.loads[b];

        // Step 2: x <- x + h v   (old v)
        s.x_W += h * s.v_W;
        record(trace, q::position, b, s.x_W);

        // Step 3: v <- v + h F / M
        s.v_W += (h * mp.invM) * load.F_W;
        record(trace, q::linear_velocity, b, s.v_W);

        // Step 4: r <- r + (h/2) (0, omega) r, a quaternion product with the OLD omega
        // in the world frame, then renormalise r.
        const Quat omegaQuat(0.0, s.omega_W.x(), s.omega_W.y(), s.omega_W.z());
        const Quat rDot = omegaQuat * s.q_WB;
        s.q_WB.coeffs() += (0.5 * h) * rDot.coeffs();
        // |r|^2 overflows to infinity for (h/2)|omega| > ~1e154, and a plain normalize()
        // would then silently give the zero quaternion: fall back to the scaled norm.
        const double norm2 = s.q_WB.squaredNorm();
        if (std::isfinite(norm2)) {
            s.q_WB.coeffs() /= std::sqrt(norm2);
        } else {
            s.q_WB.coeffs().stableNormalize();
        }
        record(trace, q::orientation, b, s.q_WB);

        // Step 5: L <- L + h q
        s.L_W += h * load.q_W;
        record(trace, q::angular_momentum, b, s.L_W);

        // Steps 6-7: R = R(r), I^-1 = R I0^-1 R^T, omega = I^-1 L
        updateDerived(mp, s, in.conventionOf(b));
        if (trace != nullptr) {
            trace->add(q::inertia_body, b, mp.I0_B);
            trace->add(q::inverse_inertia_body, b, mp.I0inv_B);
            trace->add(q::rotation_matrix, b, s.R_WB);
            trace->add(in.conventionOf(b) == InertiaConvention::CourseTemplate
                           ? q::inverse_inertia_world_template
                           : q::inverse_inertia_world,
                       b, s.Iinv_W);
            trace->add(q::angular_velocity, b, s.omega_W);
        }
    }
}

} // namespace rbw
