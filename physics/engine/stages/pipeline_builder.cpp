// The step pipeline: this file is the one place that states its order, because it is
// the code that builds it. World::step() runs the list buildPipeline() returns, in order
// and nothing else; tst_pipeline pins every lesson's list. A stage in [brackets] is in
// the list only when the scene needs it (the conditions are in buildPipeline() below).
//
// The course's contact model (contact_model "course", the default):
//   [gravity] -> loads -> [energy_bound] -> integration (one per integrator group with a
//   movable body) -> finite_check -> [energy_check] -> [box_box] -> [box_plane]
//   -> [correction] -> [finite_check] -> [probes]
// The contacts are answered after the integration, one impulse at a time; the second
// finite_check follows the contact stages whenever there is one.
//
// The manifold model (contact_model "manifold", when two bodies or a plane can touch):
//   [gravity] -> loads -> manifold_contacts -> [energy_bound] -> manifold_velocities
//   -> integration (one per group) -> finite_check -> [energy_check]
//   -> manifold_positions -> [sleep] -> finite_check -> [probes]
// Forces -> velocities -> contacts -> positions, whatever the integrator: the contacts
// are solved on the velocities the step will have, manifold_velocities gives every body
// the solved velocities and spends the loads, and the integration applies the
// integrator's own position and orientation formula with them (docs/collisions.md,
// "Every integrator"). The position fix and sleeping follow it.
//
// docs/architecture.md ("The step pipeline") describes each stage, its file and its
// trace ids.
#include "physics/engine/stages/pipeline_builder.h"

#include "physics/engine/integrator_registry.h"
#include "physics/engine/course/box_box_stage.h"
#include "physics/engine/course/box_plane_stage.h"
#include "physics/engine/stages/checks.h"
#include "physics/engine/stages/energy_jump_stage.h"
#include "physics/engine/course/correction_stage.h"
#include "physics/engine/stages/forces_stage.h"
#include "physics/engine/stages/integration_stage.h"
#include "physics/engine/manifold/manifold_contact_stage.h"
#include "physics/engine/manifold/manifold_position_stage.h"
#include "physics/engine/manifold/manifold_velocity_stage.h"
#include "physics/engine/stages/probes_stage.h"
#include "physics/engine/manifold/sleep_stage.h"

#include <algorithm>
#include <cassert>

namespace rbw {

const char* pipelineStageName(PipelineStage stage)
{
    switch (stage) {
    case PipelineStage::Gravity: return "gravity";
    case PipelineStage::Loads: return "loads";
    case PipelineStage::EnergyBound: return "energy_bound";
    case PipelineStage::Integration: return "integration";
    case PipelineStage::FiniteCheck: return "finite_check";
    case PipelineStage::EnergyCheck: return "energy_check";
    case PipelineStage::BoxBox: return "box_box";
    case PipelineStage::BoxPlane: return "box_plane";
    case PipelineStage::Correction: return "correction";
    case PipelineStage::ManifoldContacts: return "manifold_contacts";
    case PipelineStage::ManifoldVelocities: return "manifold_velocities";
    case PipelineStage::ManifoldPositions: return "manifold_positions";
    case PipelineStage::Sleep: return "sleep";
    case PipelineStage::Probes: return "probes";
    }
    return "?";
}

std::string PipelineStep::label() const
{
    if (kind() == PipelineStage::Integration) {
        return std::string("integration:") + integratorName();
    }
    return pipelineStageName(kind());
}

PipelineEntry::PipelineEntry(std::unique_ptr<PipelineStep> s)
    : stage(s->kind())
    , integrator(s->integratorName())
    , bodies(s->bodies() != nullptr ? *s->bodies() : std::vector<int>{})
    , step(std::move(s))
{
}

std::string PipelineEntry::label() const
{
    return step->label();
}

IntegratorGroups integratorGroups(const SceneDef& scene)
{
    IntegratorGroups g;
    const int n = static_cast<int>(scene.bodies.size());
    g.groupOf.assign(n, 0);
    for (int b = 0; b < n; ++b) {
        const std::string& name = scene.integratorOf(b);
        const auto it = std::find(g.names.begin(), g.names.end(), name);
        g.groupOf[b] = static_cast<int>(it - g.names.begin());
        if (it == g.names.end()) g.names.push_back(name);
    }
    return g;
}

std::vector<PipelineEntry> buildPipeline(const SceneDef& scene, const std::vector<MassProperties>& mass,
                                         const std::vector<char>& movable, const IntegratorGroups& groups,
                                         const WorldOptions& options)
{
    const int n = static_cast<int>(scene.bodies.size());
    const int movableCount = static_cast<int>(std::count(movable.begin(), movable.end(), 1));
    const bool gravity = (scene.hasGravity() && movableCount >= 1) || options.allStages;
    const bool energyCheck = scene.energyJumpFactor > 0.0;
    // Box-box contacts need two bodies, at least one of them movable.
    const bool boxPairs = (scene.boxCollisions || options.allStages) && n >= 2 && movableCount >= 1;
    // Plane tests need a plane and a movable body.
    const bool planeTests = !scene.planes.empty() && (movableCount >= 1 || options.allStages);

    // The manifold model (docs/collisions.md) solves its contacts before the integration,
    // as loads, and fixes positions after it; the course model answers contacts after
    // the integration, one impulse at a time.
    const bool manifold = scene.contactModel == ContactModel::Manifold && (boxPairs || planeTests);
    std::shared_ptr<ContactScratch> contactScratch;
    if (manifold) {
        contactScratch = std::make_shared<ContactScratch>();
        contactScratch->settings = manifoldSettings(scene);
        contactScratch->threads = options.contactThreads;
    }

    std::vector<PipelineEntry> out;
    auto add = [&out](std::unique_ptr<PipelineStep> s) { out.emplace_back(std::move(s)); };
    if (gravity) add(std::make_unique<GravityStage>());
    add(std::make_unique<LoadsStage>(gravity));
    // After the loads (the solver works on v + h F/M) and before the energy bound, which
    // then counts the contact loads among the step's loads.
    if (manifold) add(std::make_unique<ManifoldContactStage>(contactScratch, boxPairs, planeTests));
    if (energyCheck) add(std::make_unique<EnergyBoundStage>(mass));
    // After the bound (which counts the contact loads among the loads): the solved
    // velocities, so that the integration moves the bodies with them.
    if (manifold) add(std::make_unique<ManifoldVelocityStage>());
    // One integration per integrator group that has a movable body.
    for (int g = 0; g < static_cast<int>(groups.names.size()); ++g) {
        std::vector<int> bodies;
        std::vector<char> active(n, 0);
        for (int b = 0; b < n; ++b) {
            active[b] = groups.groupOf[b] == g ? 1 : 0;
            if (active[b] && movable[b]) bodies.push_back(b);
        }
        if (bodies.empty()) continue;
        std::unique_ptr<Integrator> integrator = makeIntegrator(groups.names[g]);
        assert(integrator != nullptr);
        add(std::make_unique<IntegrationStage>(std::move(integrator), std::move(bodies), std::move(active),
                                               groups.names.size() == 1));
    }
    // Before the contact stages: a NaN pose would pass every overlap test.
    add(std::make_unique<FiniteCheckStage>());
    if (energyCheck) add(std::make_unique<EnergyCheckStage>());
    if (manifold) {
        add(std::make_unique<ManifoldPositionStage>(contactScratch));
        if (contactScratch->settings.sleep) add(std::make_unique<SleepStage>(contactScratch));
        add(std::make_unique<FiniteCheckStage>());
    } else {
        if (boxPairs) add(std::make_unique<BoxBoxStage>());
        if (planeTests) add(std::make_unique<BoxPlaneStage>());
        if (boxPairs || planeTests) {
            if (scene.positionCorrection) add(std::make_unique<CorrectionStage>());
            // Anything the contact stages made non-finite.
            add(std::make_unique<FiniteCheckStage>());
        }
    }
    if (!scene.probes.empty()) add(std::make_unique<ProbesStage>());
    return out;
}

} // namespace rbw
