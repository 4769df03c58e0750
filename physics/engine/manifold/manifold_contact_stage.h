// The manifold model's contact stage (contact_model "manifold", docs/collisions.md),
// before the integration: sleeping islands that are touched or loaded wake; the AABB
// tree finds the pairs; each pair with an awake movable body gets its manifold (box-box
// face clipping, box-plane corners), warm-started from last step's impulses; the
// sequential-impulse solver runs up to solver_iterations iterations on the free
// velocities v + h F/M (or the soft step runs its substeps from v, soft_step_solver.h); the impulses it found go to the integrator as contact loads
// F_c = P/h, q_c = L_c/h, and a sleeping body gets F_c = -F, q_c = -q, so it stays put.
#pragma once

#include "physics/engine/manifold/contact_scratch.h"
#include "physics/engine/stages/stage.h"

#include <memory>

namespace rbw {

class ManifoldContactStage final : public PipelineStep {
public:
    // boxPairs: box-box manifolds (box_collisions); planes: box-plane manifolds.
    ManifoldContactStage(std::shared_ptr<ContactScratch> world, bool boxPairs, bool planes)
        : world_(std::move(world)), boxPairs_(boxPairs), planes_(planes)
    {
    }
    PipelineStage kind() const override { return PipelineStage::ManifoldContacts; }
    void run(StepContext& ctx) override;

private:
    void wakeLoadedBodies(StepContext& ctx);
    void findManifolds(StepContext& ctx);
    bool findPairs(StepContext& ctx, long& tested);
    bool wakeTouched(StepContext& ctx);
    bool collidePair(StepContext& ctx, int a, int b);
    void solve(StepContext& ctx);
    void solveSequentialImpulses(StepContext& ctx);
    void solveSoftStep(StepContext& ctx);
    void recordPoints(StepContext& ctx) const;

    std::shared_ptr<ContactScratch> world_;
    bool boxPairs_;
    bool planes_;
};

} // namespace rbw
