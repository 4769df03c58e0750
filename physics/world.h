// The world: a scene definition plus the mutable state of its bodies, and the
// pipeline of stages that one step runs:
//   [gravity] -> loads -> integration (one per integrator group) -> finite check
//   -> [energy check] -> [box-box] -> [box-plane] -> [correction] -> [probes].
// The world decides once, in its constructor, which stages the scene needs
// (pipeline()): no gravity work without gravity, no broad/narrow phase or response
// without a collidable pair, no plane tests without a plane, no correction unless
// asked for, no probes stage without probes. docs/architecture.md has the table.
//
// Data flows one way: SceneDef -> World -> step() -> StepTrace -> every view.
// No view reaches back into the world to recompute a quantity.
#pragma once

#include "physics/body.h"
#include "physics/collision/broad_phase.h"
#include "physics/collision/contact.h"
#include "physics/diagnostics.h"
#include "physics/integrator.h"
#include "physics/scene.h"
#include "physics/step_status.h"
#include "physics/trace.h"

#include <memory>
#include <string>
#include <vector>

namespace rbw {

// The stages a step can run, in this order. World::pipeline() lists those it runs.
enum class PipelineStage {
    Gravity,       // f_g = M g on every movable body (only with gravity)
    Loads,         // applied forces, couples and one-step forces (drags, pushes): always
    Integration,   // one entry per integrator group: x, v, r, L and the derived R, I^-1, omega
    FiniteCheck,   // the first non-finite value stops the run: always
    EnergyCheck,   // a body's kinetic-energy jump beyond the bound stops the run
    BoxBox,        // sweep-and-prune broad phase, SAT narrow phase, impulses
    BoxPlane,      // corners below each plane, impulses
    Correction,    // push penetrating bodies apart (position_correction)
    Probes,        // probe points, when a trace is recorded
};

const char* pipelineStageName(PipelineStage stage);   // e.g. "box_box"

struct PipelineEntry {
    PipelineStage stage;
    std::string integrator;    // Integration only: the integrator's name
    std::vector<int> bodies;   // Integration only: the bodies it advances (movable ones)

    // "integration:rk4" for an integration entry, else the stage name.
    std::string label() const;
};

// Creation options of a world that are not part of a scene.
struct WorldOptions {
    // Run every stage whether the scene needs it or not: gravity (also with g = 0), the
    // box-box broad and narrow phases for any two bodies (also with box_collisions off)
    // and the plane tests against the scene's planes. For benchmarks that measure what
    // the minimal pipeline saves; results equal the minimal pipeline's as long as no
    // two bodies touch when box_collisions is off.
    bool allStages = false;
};

struct ProbeReading {
    int body = -1;
    Vec3 p_W = Vec3::Zero();   // current position of the probe point
    Vec3 v_W = Vec3::Zero();   // its velocity v + omega x (p - x)
};

// Everything needed to put a world back exactly as it was (history, step back).
struct WorldSnapshot {
    std::vector<BodyState> states;
    std::vector<char> torqueEnabled;   // switchable torques' on/off state
    long stepIndex = 0;
    double time = 0.0;
    StepStatus status;
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
    const Integrator& integratorOf(int body) const { return *groups_[groupOf_[body]].integrator; }
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
    // quantity and the diagnostics after the step. After a blow-up the world refuses
    // to step again and keeps returning the same status.
    StepStatus step(StepTrace* trace = nullptr);

    Diagnostics diagnostics() const;
    ProbeReading probe(int i) const;

    WorldSnapshot snapshot() const;
    void restore(const WorldSnapshot& s);

    // The stages a step runs, decided once when the world is built (see the top).
    const std::vector<PipelineEntry>& pipeline() const { return pipeline_; }
    std::vector<std::string> pipelineLabels() const;
    bool runsStage(PipelineStage stage) const;

    bool runsCollisionStage() const { return boxPairsPossible_ || planeTestsPossible_; }
    // The broad phase's counts in the last step (zero when it did not run).
    const BroadPhaseStats& lastBroadPhaseStats() const { return lastBroadPhase_; }

private:
    void forcesStage(StepTrace* trace);
    void collisionStage(StepTrace* trace);
    void correctionStage(StepTrace* trace);
    // Resolves one contact between body a and body b (or plane when plane >= 0) and
    // records it; returns nothing, the state changes in place.
    void resolveContact(const ContactGeometry& g, int a, int b, int plane, const char* resolution,
                        int pointCount, StepTrace* trace);
    BoxPose poseOf(int body) const;
    void probesStage(StepTrace* trace) const;
    bool allStatesFinite() const;
    // The first non-finite quantity, as a status that names step, body and quantity.
    StepStatus describeBlowUp() const;
    // Before the integration: each movable body's T_n and its bound T_max.
    void energyBounds();
    // After it: the first body with T_{n+1} > T_max, as a blow-up status (or success).
    StepStatus checkEnergyJump() const;
    void buildPipeline(const WorldOptions& options);

    // The bodies one integrator advances.
    struct IntegratorGroup {
        std::unique_ptr<Integrator> integrator;
        std::vector<char> active;   // per body
        bool all = false;           // every body: pass no mask
    };

    SceneDef scene_;
    std::vector<MassProperties> mass_;
    std::vector<InertiaConvention> conventions_;   // per body: its own or the scene's
    std::vector<Vec3> probeOffsets_B_;   // p0 in the body frame: R0^T (p0 - x0)
    std::unique_ptr<Integrator> integrator_;   // the scene's
    std::vector<IntegratorGroup> groups_;
    std::vector<int> groupOf_;                 // per body: index into groups_
    std::vector<PipelineEntry> pipeline_;
    bool runGravity_ = false;
    bool runEnergyCheck_ = false;
    bool planeTestsPossible_ = false;
    std::vector<double> maxInvInertia_;   // per body: largest entry of I0^-1 (diagonal) [1/(kg m^2)]
    std::vector<double> kineticBefore_;   // energy check scratch: T_n per body [J]
    std::vector<double> kineticBound_;    // T_max per body [J]

    std::vector<BodyState> states_;
    std::vector<BodyLoad> loads_;
    std::vector<ForceDef> onceForces_;
    std::vector<char> torqueEnabled_;
    std::vector<char> loaded_;           // forces stage scratch: which bodies carry a load

    // Collision stage scratch, kept between steps to avoid allocations.
    bool boxPairsPossible_ = false;
    SweepAndPrune broadPhase_;
    BroadPhaseStats lastBroadPhase_;
    std::vector<Aabb> aabbs_;
    std::vector<char> movable_;
    std::vector<std::pair<int, int>> pairs_;
    std::vector<ContactGeometry> planeContacts_;
    struct Correction {   // a box-box pair to push apart
        int a, b;
        Vec3 n_W;
        double depth;
    };
    std::vector<Correction> corrections_;
    int contactCount_ = 0;
    long stepIndex_ = 0;
    double time_ = 0.0;
    StepStatus status_;
};

} // namespace rbw
