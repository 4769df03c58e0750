#include "physics/integrators/rk4.h"

#include "physics/integrators/integrator_quantities.h"
#include "physics/integrators/rigid_ode.h"

namespace rbw {

void Rk4::integrate(const IntegrationInput& in, std::vector<BodyState>& states, StepTrace* trace) const
{
    const double h = in.h;
    for (int b = 0; b < static_cast<int>(states.size()); ++b) {
        if (!in.advances(b)) {
            continue;
        }
        BodyState& s = states[b];
        const MassProperties& mp = in.mass[b];
        const BodyLoad& load = in.loads[b];
        const RigidOdeState y0{s.x_W, s.v_W, s.q_WB, s.L_W};

        // k1 = f(y_n)
        const RigidOdeRate k1 = rigidOdeRate(y0, mp, load, in.conventionOf(b));
        recordRkStage(trace, b, 1, k1);
        // k2 = f(y_n + h/2 k1)
        const RigidOdeRate k2 = rigidOdeRate(advanced(y0, 0.5 * h, k1), mp, load, in.conventionOf(b));
        recordRkStage(trace, b, 2, k2);
        // k3 = f(y_n + h/2 k2)
        const RigidOdeRate k3 = rigidOdeRate(advanced(y0, 0.5 * h, k2), mp, load, in.conventionOf(b));
        recordRkStage(trace, b, 3, k3);
        // k4 = f(y_n + h k3)
        const RigidOdeRate k4 = rigidOdeRate(advanced(y0, h, k3), mp, load, in.conventionOf(b));
        recordRkStage(trace, b, 4, k4);

        // y_{n+1} = y_n + h/6 (k1 + 2 k2 + 2 k3 + k4)
        const double w = h / 6.0;
        s.x_W += w * (k1.xDot + 2.0 * k2.xDot + 2.0 * k3.xDot + k4.xDot);
        record(trace, q::rk4_position, b, s.x_W);
        s.v_W += w * (k1.vDot + 2.0 * k2.vDot + 2.0 * k3.vDot + k4.vDot);
        record(trace, q::rk4_linear_velocity, b, s.v_W);
        s.q_WB.coeffs() += w * (k1.rDot.coeffs() + 2.0 * k2.rDot.coeffs() + 2.0 * k3.rDot.coeffs() +
                                k4.rDot.coeffs());
        // r /= |r|: the exact flow keeps |r| = 1, RK4 only to O(h^5) per step
        s.q_WB = normalisedOrientation(s.q_WB);
        record(trace, q::rk4_orientation, b, s.q_WB);
        s.L_W += w * (k1.LDot + 2.0 * k2.LDot + 2.0 * k3.LDot + k4.LDot);
        record(trace, q::rk4_angular_momentum, b, s.L_W);

        // R = R(r), I^-1 = R I0^-1 R^T, omega = I^-1 L
        updateDerived(mp, s, in.conventionOf(b));
        recordDerived(trace, b, mp, s, in.conventionOf(b));
    }
}

} // namespace rbw
