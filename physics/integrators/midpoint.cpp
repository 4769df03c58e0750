#include "physics/integrators/midpoint.h"

#include "physics/integrators/integrator_quantities.h"
#include "physics/integrators/rigid_ode.h"

namespace rbw {

void Midpoint::integrate(const IntegrationInput& in, std::vector<BodyState>& states,
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
        const RigidOdeState y0{s.x_W, s.v_W, s.q_WB, s.L_W};

        // k1 = f(y_n)
        const RigidOdeRate k1 = rigidOdeRate(y0, mp, load, in.conventionOf(b));
        recordRkStage(trace, b, 1, k1);
        // k2 = f(y_n + h/2 k1)
        const RigidOdeRate k2 = rigidOdeRate(advanced(y0, 0.5 * h, k1), mp, load, in.conventionOf(b));
        recordRkStage(trace, b, 2, k2);

        // y_{n+1} = y_n + h k2, then r /= |r|
        const RigidOdeState y1 = advanced(y0, h, k2);
        s.x_W = y1.x_W;
        record(trace, q::midpoint_position, b, s.x_W);
        s.v_W = y1.v_W;
        record(trace, q::midpoint_linear_velocity, b, s.v_W);
        s.q_WB = normalisedOrientation(y1.r);
        record(trace, q::midpoint_orientation, b, s.q_WB);
        s.L_W = y1.L_W;
        record(trace, q::midpoint_angular_momentum, b, s.L_W);

        // R = R(r), I^-1 = R I0^-1 R^T, omega = I^-1 L
        updateDerived(mp, s, in.conventionOf(b));
        recordDerived(trace, b, mp, s, in.conventionOf(b));
    }
}

} // namespace rbw
