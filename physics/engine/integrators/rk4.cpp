#include "physics/engine/integrators/rk4.h"

#include "physics/engine/quantities.h"

#include "physics/engine/integrators/rigid_ode.h"

namespace rbw {

void Rk4::advance(const BodyStep& step, BodyState& s) const
{
    const double h = step.h;
    const RigidOdeState y0{s.x_W, s.v_W, s.q_WB, s.L_W};

    // k1 = f(y_n)
    const RigidOdeRate k1 = rigidOdeRate(y0, step, 1);
    // k2 = f(y_n + h/2 k1)
    const RigidOdeRate k2 = rigidOdeRate(advanced(y0, 0.5 * h, k1), step, 2);
    // k3 = f(y_n + h/2 k2)
    const RigidOdeRate k3 = rigidOdeRate(advanced(y0, 0.5 * h, k2), step, 3);
    // k4 = f(y_n + h k3)
    const RigidOdeRate k4 = rigidOdeRate(advanced(y0, h, k3), step, 4);

    // y_{n+1} = y_n + h/6 (k1 + 2 k2 + 2 k3 + k4)
    const double w = h / 6.0;
    s.x_W += w * (k1.xDot + 2.0 * k2.xDot + 2.0 * k3.xDot + k4.xDot);
    step.record(q::rk4_position, s.x_W);
    s.v_W += w * (k1.vDot + 2.0 * k2.vDot + 2.0 * k3.vDot + k4.vDot);
    step.record(q::rk4_linear_velocity, s.v_W);
    s.q_WB.coeffs() += w * (k1.rDot.coeffs() + 2.0 * k2.rDot.coeffs() + 2.0 * k3.rDot.coeffs() +
                            k4.rDot.coeffs());
    // r /= |r|: the exact flow keeps |r| = 1, RK4 only to O(h^5) per step
    if (step.trace != nullptr) step.record(q::rk4_orientation_norm, orientationNorm(s.q_WB));
    s.q_WB = normalisedOrientation(s.q_WB);
    step.record(q::rk4_orientation, s.q_WB);
    s.L_W += w * (k1.LDot + 2.0 * k2.LDot + 2.0 * k3.LDot + k4.LDot);
    step.record(q::rk4_angular_momentum, s.L_W);
}

} // namespace rbw
