#include "physics/engine/manifold/manifold_position_stage.h"

#include "physics/engine/manifold/position_fix.h"
#include "physics/engine/quantities.h"

#include <algorithm>

namespace rbw {

double deepestOverlap(const std::vector<Manifold>& manifolds, const std::vector<BodyState>& states)
{
    double deepest = 0.0;
    for (const Manifold& m : manifolds) {
        const BodyState& A = states[static_cast<std::size_t>(m.a)];
        const BodyState* B = m.b >= 0 ? &states[static_cast<std::size_t>(m.b)] : nullptr;
        for (int k = 0; k < m.count; ++k) {
            // d = -s = -n . (p_A - p_B)
            deepest = std::max(deepest, -currentSeparation(m, k, A, B));
        }
    }
    return deepest;
}

void ManifoldPositionStage::pushOut(StepContext& ctx)
{
    const ContactScratch& w = *world_;
    const double h = ctx.scene.dt;
    const int n = static_cast<int>(ctx.states.size());
    for (int b = 0; b < n && b < static_cast<int>(w.motion.size()); ++b) {
        if (!ctx.movable[static_cast<std::size_t>(b)]) continue;
        const SubstepMotion& m = w.motion[static_cast<std::size_t>(b)];
        if (m.dx_W == Vec3::Zero() && m.dtheta_W == Vec3::Zero()) continue;   // not moved by the soft step
        BodyState& s = ctx.states[static_cast<std::size_t>(b)];
        // The integration moved the body with v_{n+1}, omega_{n+1}; the substeps moved it
        // by dx, dtheta. The rest is the push-out: dx_s = dx - h v_{n+1}, dtheta_s = dtheta - h omega_{n+1}
        const Vec3 dx_s_W = m.dx_W - h * s.v_W;
        const Vec3 dtheta_s_W = m.dtheta_W - h * s.omega_W;
        s.x_W += dx_s_W;
        record(ctx.trace, q::soft_push_out, b, dx_s_W);
        if (ctx.scene.bodies[static_cast<std::size_t>(b)].angularResponse && dtheta_s_W != Vec3::Zero()) {
            rotateBy(s, dtheta_s_W);
        }
        // R, I^-1 and omega = I^-1 L from the corrected orientation (L unchanged)
        updateDerived(ctx.mass[static_cast<std::size_t>(b)], s, ctx.conventions[static_cast<std::size_t>(b)]);
    }
}

void ManifoldPositionStage::run(StepContext& ctx)
{
    ContactScratch& w = *world_;
    const int n = static_cast<int>(ctx.states.size());
    if (w.settings.solver == ManifoldSolver::SoftStep) {
        pushOut(ctx);
    } else if (w.settings.positionFix == PositionFix::Ngs && !w.manifolds.empty()) {
        dx_W_.assign(static_cast<std::size_t>(n), Vec3::Zero());
        moved_.assign(static_cast<std::size_t>(n), 0);
        angular_.resize(static_cast<std::size_t>(n));
        for (int b = 0; b < n; ++b) {
            angular_[static_cast<std::size_t>(b)] = ctx.scene.bodies[static_cast<std::size_t>(b)].angularResponse ? 1 : 0;
        }
        for (const Manifold& m : w.manifolds) {
            moved_[static_cast<std::size_t>(m.a)] = 1;
            if (m.b >= 0) moved_[static_cast<std::size_t>(m.b)] = 1;
        }
        ngs_.prepare(w.manifolds, ctx.mass, angular_);
        for (int it = 0; it < w.settings.positionIterations; ++it) {
            const double smallest = ngs_.iterate(ctx.states, w.settings, dx_W_);
            // Done when no point overlaps by more than the position tolerance (the slop
            // the fix leaves; Box2D stops at 3 slop, 1.5 cm, which left 1.4 cm overlaps
            // in a 1000-box pile: docs/performance.md, "Contacts: the box rain").
            if (smallest >= -w.settings.positionTolerance) break;
        }
        // R, I^-1 and omega = I^-1 L from the corrected orientations (L unchanged).
        int index = 0;
        for (int b = 0; b < n; ++b) {
            if (!moved_[static_cast<std::size_t>(b)] || !ctx.movable[static_cast<std::size_t>(b)]) continue;
            updateDerived(ctx.mass[static_cast<std::size_t>(b)], ctx.states[static_cast<std::size_t>(b)],
                          ctx.conventions[static_cast<std::size_t>(b)]);
            const Vec3& dx_W = dx_W_[static_cast<std::size_t>(b)];
            if (dx_W != Vec3::Zero()) record(ctx.trace, q::ngs_correction, b, dx_W, index++);
        }
    }
    if (ctx.trace != nullptr) {
        // d_max = max(0, max over points of -s) after the fix
        const double d_max = deepestOverlap(w.manifolds, ctx.states);
        record(ctx.trace, q::deepest_overlap, -1, d_max);
    }
}

} // namespace rbw
