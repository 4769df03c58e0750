#include "physics/engine/integrators/midpoint.h"

#include "physics/engine/quantities.h"

#include "physics/engine/integrators/rigid_ode.h"

namespace rbw {

void Midpoint::advance(const BodyStep& step, BodyState& s) const
{
    const double h = step.h;
    const RigidOdeState y0{s.x_W, s.v_W, s.q_WB, s.L_W};

    // k1 = f(y_n)
    const RigidOdeRate k1 = rigidOdeRate(y0, step, 1);
    // k2 = f(y_n + h/2 k1)
    const RigidOdeRate k2 = rigidOdeRate(advanced(y0, 0.5 * h, k1), step, 2);

    // y_{n+1} = y_n + h k2, then r /= |r|
    const RigidOdeState y1 = advanced(y0, h, k2);
    s.x_W = y1.x_W;
    step.record(q::midpoint_position, s.x_W);
    s.v_W = y1.v_W;
    step.record(q::midpoint_linear_velocity, s.v_W);
    if (step.trace != nullptr) step.record(q::midpoint_orientation_norm, orientationNorm(y1.r));
    s.q_WB = normalisedOrientation(y1.r);
    step.record(q::midpoint_orientation, s.q_WB);
    s.L_W = y1.L_W;
    step.record(q::midpoint_angular_momentum, s.L_W);
}

} // namespace rbw
