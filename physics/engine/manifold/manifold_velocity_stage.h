// The manifold model's velocity update (contact_model "manifold", docs/collisions.md,
// "Every integrator"): after the contact solve and the energy bound, before the
// integration, every awake movable body takes the velocities the solve produced,
//   v_{n+1} = v_n + h (F + F_c) / M,   L_{n+1} = L_n + h (q + q_c),
//   omega_{n+1} = I^-1(r_n) L_{n+1},
// and its loads are spent: the integration that follows sees F = q = 0, so it applies
// the integrator's own position and orientation formula with these solved velocities.
// The order is the one contact solving needs, forces -> velocities -> contacts ->
// positions, whatever integrator the scene names. Without it explicit Euler moved each
// body with its velocity from before the solve (x + h v_n), undoing the solve's work in
// every step. A sleeping body's F_c = -F, q_c = -q leave it at v = L = 0.
#pragma once

#include "physics/engine/stages/stage.h"

namespace rbw {

class ManifoldVelocityStage final : public PipelineStep {
public:
    PipelineStage kind() const override { return PipelineStage::ManifoldVelocities; }
    void run(StepContext& ctx) override;
};

} // namespace rbw
