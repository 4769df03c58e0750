#include "physics/engine/manifold/manifold_velocity_stage.h"

#include "physics/engine/quantities.h"

namespace rbw {

void ManifoldVelocityStage::run(StepContext& ctx)
{
    const double h = ctx.scene.dt;
    for (int b = 0; b < static_cast<int>(ctx.states.size()); ++b) {
        if (!ctx.movable[static_cast<std::size_t>(b)]) continue;
        BodyState& s = ctx.states[static_cast<std::size_t>(b)];
        BodyLoad& load = ctx.loads[static_cast<std::size_t>(b)];
        // v_{n+1} = v_n + h (F + F_c) / M   (the loads hold F + F_c: manifold_contact_stage)
        s.v_W += (h * ctx.mass[static_cast<std::size_t>(b)].invM) * load.F_W;
        record(ctx.trace, q::solved_linear_velocity, b, s.v_W);
        // L_{n+1} = L_n + h (q + q_c)
        s.L_W += h * load.q_W;
        record(ctx.trace, q::solved_angular_momentum, b, s.L_W);
        // omega_{n+1} = I^-1(r_n) L_{n+1}: what the orientation update turns with
        s.omega_W = s.Iinv_W * s.L_W;
        record(ctx.trace, q::solved_angular_velocity, b, s.omega_W);
        // The loads have acted: the integration applies no force or torque on top.
        load = BodyLoad{};
    }
}

} // namespace rbw
