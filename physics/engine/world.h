// The world: a scene definition plus the mutable state of its bodies, and the
// pipeline of stages that one step runs (stages/stage.h).
// The world decides once, in its constructor, which stages the scene needs
// (pipeline(), built by stages/pipeline_builder.cpp): no gravity work without
// gravity, no broad/narrow phase or response without a collidable pair, no plane
// tests without a plane, no correction unless asked for, no probes stage without
// probes. step() runs exactly that list. The order: stages/pipeline_builder.cpp;
// docs/architecture.md has the table of stages.
//
// Data flows one way: SceneDef -> World -> step() -> StepTrace -> every view.
// No view reaches back into the world to recompute a quantity.
#pragma once

#include "physics/engine/body.h"
#include "physics/engine/collision/broad_phase.h"
#include "physics/engine/collision/contact.h"
#include "physics/engine/diagnostics.h"
#include "physics/engine/integrator.h"
#include "physics/engine/manifold/contact_state.h"
#include "physics/engine/scene.h"
#include "physics/engine/stages/pipeline_builder.h"
#include "physics/engine/stages/probes_stage.h"
#include "physics/engine/step_status.h"
#include "physics/engine/trace.h"

#include <memory>
#include <string>
#include <vector>

namespace rbw {

// Everything needed to put a world back exactly as it was (history, step back): all
// that changes from step to step. A world restored from it, the same one or a fresh
// one of the same scene, steps on bit for bit (tst_snapshot). The stages keep nothing
// between steps themselves.
struct WorldSnapshot {
    std::vector<BodyState> states;
    std::vector<char> torqueEnabled;   // switchable torques' on/off state
    long stepIndex = 0;
    double time = 0.0;
    StepStatus status;
    ContactState contacts;             // the manifold model's warm-start impulses and sleep state

    // The heap bytes it holds beside sizeof(WorldSnapshot): what the history's memory
    // budget counts for a kept state.
    std::size_t bytes() const
    {
        return states.capacity() * sizeof(BodyState) + torqueEnabled.capacity() + contacts.bytes();
    }
};

class World {
public:
    // The scene must be valid (validate(scene) empty); front ends check that first.
    explicit World(SceneDef scene, WorldOptions options = {});

    const SceneDef& scene() const { return scene_; }
    const std::vector<BodyState>& states() const { return states_; }
    const std::vector<MassProperties>& massProperties() const { return mass_; }
    // The scene's integrator; a body may have its own (integratorOf).
    const Integrator& integrator() const { return *integrator_; }
    const Integrator& integratorOf(int body) const { return *groupIntegrators_[groupOf_[body]]; }
    InertiaConvention conventionOf(int body) const { return conventions_[body]; }
    long stepIndex() const { return stepIndex_; }   // the next step to take is k = stepIndex()
    double time() const { return time_; }
    const StepStatus& status() const { return status_; }

    // Adds a force that acts in the next step only (interaction: drag, key pushes).
    void applyForceOnce(int body, const Vec3& p_W, const Vec3& f_W);

    // Switchable torques (TorqueDef::switchable): on or off from the next step on.
    // Off, the body keeps its angular momentum, so it spins on at the same rate.
    void setTorqueEnabled(int i, bool on);
    bool torqueEnabled(int i) const { return torqueEnabled_[i] != 0; }
    bool hasSwitchableTorque() const;

    // A point fixed to a body: body frame -> world frame (p_W = x + R p_B) and back.
    Vec3 bodyToWorld(int body, const Vec3& p_B) const;
    Vec3 worldToBody(int body, const Vec3& p_W) const;

    // Advances by one step of size dt. With a trace, records every intermediate
    // quantity and the diagnostics after the step, and checks every number it recorded
    // (each entry, contacts included, and the diagnostics, P = M v per body, the probes):
    // a non-finite one is a blow-up. Without a trace the step checks the state (x, v, r,
    // R, L, I^-1, omega) and the time, and nothing else is computed. After a blow-up
    // the world refuses to step again and keeps returning the same status.
    // The status after the step (status()), by reference: a StepStatus holds strings,
    // and copying it every step was a tenth of a free body's step.
    const StepStatus& step(StepTrace* trace = nullptr);

    // Checks the current state and everything a view prints from it: I0 and I0^-1, x, v,
    // r, R, L, I^-1, omega, the time, each body's P = M v, the diagnostics d (as
    // diagnostics() computes them) and the probes. Before the first step it is the check
    // of the initial state (reported as such: a non-finite number there always comes
    // from inputs at the edge of the double range); after step k it names step k. A
    // front end calls it before it prints the initial state, and after each step it
    // takes without a trace (a traced step checks itself). On a blow-up it sets
    // status(), so the world refuses to step, and returns it; after an earlier blow-up
    // it returns that status.
    StepStatus checkOutputs(const Diagnostics& d);
    StepStatus checkOutputs() { return checkOutputs(diagnostics()); }

    Diagnostics diagnostics() const;
    ProbeReading probe(int i) const;

    WorldSnapshot snapshot() const;
    // Puts the world back as it was when `s` was taken (a snapshot of a world of the
    // same scene): the bodies, the switches, the step and time, the status and the
    // contact model's state. The one-step forces not yet applied are dropped.
    void restore(const WorldSnapshot& s);
    // The manifold model's state carried between steps (contact_state.h).
    const ContactState& contactState() const { return contacts_; }

    // The stages a step runs, decided once when the world is built (see the top).
    const std::vector<PipelineEntry>& pipeline() const { return pipeline_; }
    std::vector<std::string> pipelineLabels() const;
    bool runsStage(PipelineStage stage) const;

    bool runsCollisionStage() const
    {
        return runsStage(PipelineStage::BoxBox) || runsStage(PipelineStage::BoxPlane) ||
               runsStage(PipelineStage::ManifoldContacts);
    }
    // The broad phase's counts in the last step (zero when it did not run).
    const BroadPhaseStats& lastBroadPhaseStats() const { return scratch_.broadPhase; }
    // The lanes the soft step shared between two threads in the last step (1: one thread
    // solved them all; 0 when it did not run).
    int lastContactLanes() const { return scratch_.contactLanes; }

private:
    StepContext context(StepTrace* trace);

    SceneDef scene_;
    std::vector<MassProperties> mass_;
    std::vector<InertiaConvention> conventions_;   // per body: its own or the scene's
    std::vector<char> movable_;                    // per body: not fixed
    std::vector<Vec3> probeOffsets_B_;   // p0 in the body frame: R0^T (p0 - x0)
    std::unique_ptr<Integrator> integrator_;   // the scene's
    std::vector<std::unique_ptr<Integrator>> groupIntegrators_;   // per integrator group
    std::vector<int> groupOf_;                 // per body: its integrator group
    std::vector<PipelineEntry> pipeline_;

    std::vector<BodyState> states_;
    std::vector<BodyLoad> loads_;
    std::vector<ForceDef> onceForces_;
    std::vector<char> torqueEnabled_;
    ContactState contacts_;
    StepScratch scratch_;
    long stepIndex_ = 0;
    double time_ = 0.0;
    StepStatus status_;
};

} // namespace rbw
