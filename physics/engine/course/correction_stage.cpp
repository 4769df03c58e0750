#include "physics/engine/course/correction_stage.h"

#include "physics/engine/collision/contact.h"
#include "physics/engine/quantities.h"
#include "physics/engine/course/contact_response.h"

#include <algorithm>

namespace rbw {

void CorrectionStage::run(StepContext& ctx)
{
    int index = 0;
    for (const PendingCorrection& c : ctx.scratch.corrections) {
        const double invMA = ctx.mass[c.a].invM;
        const double invMB = ctx.mass[c.b].invM;
        const double sum = invMA + invMB;
        if (sum == 0.0) continue;
        // What the shares are made of, for the derivation: d, n, 1/M_A, 1/M_B
        record(ctx.trace, q::correction_depth, c.a, c.depth, index);
        record(ctx.trace, q::correction_normal, c.a, c.n_W, index);
        record(ctx.trace, q::correction_inv_mass_a, c.a, invMA, index);
        record(ctx.trace, q::correction_inv_mass_b, c.a, invMB, index);
        // dx_A = d n (1/M_A) / (1/M_A + 1/M_B)
        const Vec3 dx_A = c.depth * (invMA / sum) * c.n_W;
        if (invMA != 0.0) record(ctx.trace, q::correction_a, c.a, dx_A, index);
        // dx_B = -d n (1/M_B) / (1/M_A + 1/M_B)
        const Vec3 dx_B = -c.depth * (invMB / sum) * c.n_W;
        if (invMB != 0.0) record(ctx.trace, q::correction_b, c.b, dx_B, index);
        ctx.states[c.a].x_W += dx_A;
        ctx.states[c.b].x_W += dx_B;
        ++index;
    }
    // Fixed planes have the last word: every movable body is lifted out of every plane
    // by its deepest corner's depth measured now, d = max(0, max_corners -n.(corner - point)),
    // since a box-box correction may have pushed it in. A plane takes no share: dx = d n.
    for (int p = 0; p < static_cast<int>(ctx.scene.planes.size()); ++p) {
        const PlaneDef& plane = ctx.scene.planes[p];
        for (int b = 0; b < static_cast<int>(ctx.states.size()); ++b) {
            if (!ctx.movable[b]) continue;
            double depth = 0.0;
            for (const Vec3& corner : boxCorners(poseOf(ctx, b))) {
                depth = std::max(depth, -plane.n_W.dot(corner - plane.point_W));
            }
            if (depth == 0.0) continue;
            // dx_A = d n (the plane takes no share: 1/M_B = 0)
            record(ctx.trace, q::correction_depth, b, depth, index);
            record(ctx.trace, q::correction_normal, b, plane.n_W, index);
            record(ctx.trace, q::correction_inv_mass_a, b, ctx.mass[b].invM, index);
            record(ctx.trace, q::correction_inv_mass_b, b, 0.0, index);
            const Vec3 dx_A = depth * plane.n_W;
            record(ctx.trace, q::correction_a, b, dx_A, index++);
            ctx.states[b].x_W += dx_A;
        }
    }
}

} // namespace rbw
