#include "physics/integrators/symplectic_euler.h"

#include "physics/integrators/integrator_quantities.h"
#include "physics/integrators/rigid_ode.h"
#include "physics/quantities.h"

namespace rbw {

void SymplecticEuler::integrate(const IntegrationInput& in, std::vector<BodyState>& states,
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

        // v_{n+1} = v_n + h F/M
        s.v_W += (h * mp.invM) * load.F_W;
        record(trace, q::se_linear_velocity, b, s.v_W);

        // x_{n+1} = x_n + h v_{n+1}   (the NEW v)
        s.x_W += h * s.v_W;
        record(trace, q::se_position, b, s.x_W);

        // L_{n+1} = L_n + h q
        s.L_W += h * load.q_W;
        record(trace, q::se_angular_momentum, b, s.L_W);

        // omega' = I^-1(r_n) L_{n+1}: the new momentum seen through the old inertia
        const Vec3 omega1_W = s.Iinv_W * s.L_W;
        record(trace, q::update_angular_velocity, b, omega1_W);

        // r_{n+1} = normalise(r_n + h/2 (0, omega') r_n)
        const Quat rDot = orientationRate(omega1_W, s.q_WB);
        s.q_WB.coeffs() += h * rDot.coeffs();
        s.q_WB = normalisedOrientation(s.q_WB);
        record(trace, q::se_orientation, b, s.q_WB);

        // R = R(r), I^-1 = R I0^-1 R^T, omega = I^-1 L
        updateDerived(mp, s, in.conventionOf(b));
        recordDerived(trace, b, mp, s, in.conventionOf(b));
    }
}

} // namespace rbw
