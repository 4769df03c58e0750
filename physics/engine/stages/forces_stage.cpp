#include "physics/engine/stages/forces_stage.h"

#include "physics/engine/quantities.h"

namespace rbw {

void GravityStage::run(StepContext& ctx)
{
    const int n = static_cast<int>(ctx.states.size());
    for (int b = 0; b < n; ++b) {
        if (!ctx.movable[b]) continue;
        // f_g = M g at the centre of mass, so it adds no torque.
        const Vec3 fg_W = ctx.mass[b].M * ctx.scene.g_W;
        ctx.loads[b].F_W += fg_W;
        if (ctx.trace != nullptr) {
            record(ctx.trace, q::gravity_force, b, fg_W);
            ctx.scratch.loaded[b] = 1;
        }
    }
}

namespace {

// One applied force f_i at the world point p_i on its body.
void applyForce(StepContext& ctx, const ForceDef& f, int index)
{
    const BodyState& s = ctx.states[f.body];
    record(ctx.trace, q::applied_force, f.body, f.f_W, index);
    record(ctx.trace, q::application_point, f.body, f.p_W, index);
    // x_i = p_i - x   (the lever arm)
    const Vec3 x_i = f.p_W - s.x_W;
    record(ctx.trace, q::lever_arm, f.body, x_i, index);
    // F += f_i,  q += x_i x f_i
    ctx.loads[f.body].F_W += f.f_W;
    ctx.loads[f.body].q_W += x_i.cross(f.f_W);
    if (ctx.trace != nullptr) ctx.scratch.loaded[f.body] = 1;
}

} // namespace

void LoadsStage::run(StepContext& ctx)
{
    // External forces f_i at world points p_i (TUM algorithm step 1), then the
    // interaction's one-step forces, numbered after them.
    int index = 0;
    for (const ForceDef& f : ctx.scene.forces) {
        if (f.activeIn(ctx.k)) applyForce(ctx, f, index);
        ++index;
    }
    for (const ForceDef& f : ctx.onceForces) {
        applyForce(ctx, f, index++);
    }

    // Pure couples q_j add to the torque and not to the force: q = sum x_i x f_i + sum q_j.
    for (int j = 0; j < static_cast<int>(ctx.scene.torques.size()); ++j) {
        const TorqueDef& t = ctx.scene.torques[j];
        if (!t.activeIn(ctx.k) || !ctx.torqueEnabled[j]) continue;
        ctx.loads[t.body].q_W += t.q_W;
        if (ctx.trace != nullptr) {
            record(ctx.trace, q::applied_torque, t.body, t.q_W, j);
            ctx.scratch.loaded[t.body] = 1;
        }
    }

    if (ctx.trace == nullptr) return;
    // The totals, for the bodies that carry a load (summed above, term by term).
    const QuantityInfo& F = afterGravity_ ? q::force_with_gravity : q::force;
    const QuantityInfo& torque = ctx.scene.torques.empty() ? q::torque : q::torque_with_couples;
    for (int b = 0; b < static_cast<int>(ctx.states.size()); ++b) {
        if (!ctx.scratch.loaded[b]) continue;
        record(ctx.trace, F, b, ctx.loads[b].F_W);
        record(ctx.trace, torque, b, ctx.loads[b].q_W);
    }
}

} // namespace rbw
