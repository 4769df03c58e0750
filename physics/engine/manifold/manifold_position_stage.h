// The manifold model's position fix, after the integration (contact/position_fix.h): with
// "position_fix": "ngs" (the default) up to 3 non-linear Gauss-Seidel sweeps over this
// step's manifold points (positionIterations, stopping once no point is deeper than the
// slop) move x and r of the overlapping bodies apart, leaving `slop`
// of overlap, and never touch v or L, so they add no kinetic energy (Box2D's
// SolvePositionConstraints). With "baumgarte" or "none" nothing moves here. With the
// soft step ("solver": "soft-step") the push-out its substeps made is added instead
// (soft_step_solver.h): dx_s = sum h_s v_i - h v_{n+1}, the same for the rotation. With a
// trace it records each moved body's total correction and the deepest overlap left.
#pragma once

#include "physics/engine/manifold/contact_scratch.h"
#include "physics/engine/manifold/position_fix.h"
#include "physics/engine/stages/stage.h"

#include <memory>

namespace rbw {

class ManifoldPositionStage final : public PipelineStep {
public:
    explicit ManifoldPositionStage(std::shared_ptr<ContactScratch> world) : world_(std::move(world)) {}
    PipelineStage kind() const override { return PipelineStage::ManifoldPositions; }
    void run(StepContext& ctx) override;

private:
    // The soft step's push-out: what its substeps moved beyond h v_{n+1}, h omega_{n+1}.
    void pushOut(StepContext& ctx);
    std::shared_ptr<ContactScratch> world_;
    NgsSolver ngs_;               // this step's manifolds as the iterations read them
    std::vector<Vec3> dx_W_;      // per body: its correction in this step
    std::vector<char> moved_;     // per body: corrected in this step
    std::vector<char> angular_;   // per body: contacts turn it (angular response)
};

// The deepest overlap among the manifold points at the bodies' current poses:
// d_max = max(0, max over points of -s) [m].
double deepestOverlap(const std::vector<Manifold>& manifolds, const std::vector<BodyState>& states);

} // namespace rbw
