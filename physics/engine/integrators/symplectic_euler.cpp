#include "physics/engine/integrators/symplectic_euler.h"

#include "physics/engine/integrators/rigid_ode.h"
#include "physics/engine/quantities.h"

namespace rbw {

void SymplecticEuler::advance(const BodyStep& step, BodyState& s) const
{
    const double h = step.h;

    // v_{n+1} = v_n + h F/M
    s.v_W += (h * step.mp.invM) * step.load.F_W;
    step.record(q::se_linear_velocity, s.v_W);

    // x_{n+1} = x_n + h v_{n+1}   (the NEW v)
    s.x_W += h * s.v_W;
    step.record(q::se_position, s.x_W);

    // L_{n+1} = L_n + h q
    s.L_W += h * step.load.q_W;
    step.record(q::se_angular_momentum, s.L_W);

    // omega' = I^-1(r_n) L_{n+1}: the new momentum seen through the old inertia
    const Vec3 omega1_W = s.Iinv_W * s.L_W;
    step.record(q::update_angular_velocity, omega1_W);

    // r_{n+1} = normalise(r_n + h/2 (0, omega') r_n)
    const Quat rDot = orientationRate(omega1_W, s.q_WB);
    s.q_WB.coeffs() += h * rDot.coeffs();
    if (step.trace != nullptr) step.record(q::se_orientation_norm, orientationNorm(s.q_WB));
    s.q_WB = normalisedOrientation(s.q_WB);
    step.record(q::se_orientation, s.q_WB);
}

} // namespace rbw
