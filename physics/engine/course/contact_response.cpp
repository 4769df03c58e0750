#include "physics/engine/course/contact_response.h"

#include "physics/engine/course/impulse.h"
#include "physics/engine/quantities.h"

namespace rbw {

BoxPose poseOf(const StepContext& ctx, int body)
{
    const BodyState& s = ctx.states[body];
    return BoxPose{s.x_W, s.R_WB, 0.5 * ctx.scene.bodies[body].size};
}

namespace {

// Box-box: keep the deepest penetration per pair for the correction stage. (Planes
// re-measure in the correction stage itself.)
void queueCorrection(StepContext& ctx, const ContactGeometry& g, int a, int b)
{
    for (PendingCorrection& c : ctx.scratch.corrections) {
        if (c.a == a && c.b == b) {
            if (g.depth > c.depth) {
                c.depth = g.depth;
                c.n_W = g.n_W;
            }
            return;
        }
    }
    ctx.scratch.corrections.push_back(PendingCorrection{a, b, g.n_W, g.depth});
}

} // namespace

void resolveContact(StepContext& ctx, const ContactGeometry& g, int a, int b, int plane, const char* resolution,
                    int pointCount)
{
    const int k = ctx.scratch.contactCount++;
    const SceneDef& scene = ctx.scene;
    ResponseBody A{&ctx.states[a], &ctx.mass[a], scene.bodies[a].angularResponse, a, ctx.conventions[a]};
    ResponseBody B;
    if (b >= 0) {
        B = ResponseBody{&ctx.states[b], &ctx.mass[b], scene.bodies[b].angularResponse, b, ctx.conventions[b]};
    }
    double c = scene.restitutionFor(a, b, plane);
    if (scene.restitutionThreshold > 0.0) {
        // Resting contact: an approach slower than the threshold does not bounce.
        const Vec3 vA = pointVelocity(ctx.states[a], g.p_W);
        const Vec3 vB = b >= 0 ? pointVelocity(ctx.states[b], g.p_W) : Vec3::Zero();
        if (-(vA - vB).dot(g.n_W) < scene.restitutionThreshold) c = 0.0;
    }
    const double mu = scene.frictionFor(a, b, plane);

    if (ctx.trace != nullptr) {
        // What the contact is; its numbers follow as entries with index k.
        ctx.trace->contacts.push_back(
            ContactHeader{a, b, plane, featureName(g.feature), resolution, pointCount, false, {}});
        // p, n and d as the narrow phase computed them (g.where: its statement)
        ctx.trace->add(q::contact_point, a, g.p_W, k, g.where);
        ctx.trace->add(q::contact_normal, a, g.n_W, k, g.where);
        ctx.trace->add(q::contact_depth, a, g.depth, k, g.where);
    }
    const ImpulseResult r = applyContactImpulse(g, A, B, c, mu, ctx.trace, k);
    if (ctx.trace != nullptr) {
        ctx.trace->contacts.back().separating = r.separating;   // v_rel . n > 0: no impulse
    }

    if (scene.positionCorrection && g.depth > 0.0 && plane < 0) {
        queueCorrection(ctx, g, a, b);
    }
}

} // namespace rbw
