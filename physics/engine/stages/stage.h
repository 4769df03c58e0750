// One stage of a step, and what the stages of a step share.
//
// A world builds its pipeline once, from what its scene declares (pipeline_builder.cpp):
// a list of stages, each an object of a class in this folder, one concept per file.
// World::step() runs that list in order and nothing else, so the pipeline a view
// describes (World::pipeline()) is what runs. A stage that finds a blow-up sets the
// step's status and the step stops there.
//
// The order: stages/pipeline_builder.cpp. docs/architecture.md has the table of stages,
// their files and their trace ids.
#pragma once

#include "physics/engine/body.h"
#include "physics/engine/collision/broad_phase.h"
#include "physics/engine/integrator.h"
#include "physics/engine/manifold/contact_state.h"
#include "physics/engine/scene.h"
#include "physics/engine/step_status.h"
#include "physics/engine/trace.h"

#include <string>
#include <vector>

namespace rbw {

// The stages a step can run (the order they run in: stages/pipeline_builder.cpp).
enum class PipelineStage {
    Gravity,       // f_g = M g on every movable body (only with gravity)
    Loads,         // applied forces, couples and one-step forces (drags, pushes): always
    EnergyBound,   // before the integration: each body's T_n and the bound T_max (energy_jump)
    Integration,   // one entry per integrator group: x, v, r, L and the derived R, I^-1, omega
    FiniteCheck,   // the first non-finite value stops the run: after the integration, and
                   // again after the contact stages
    EnergyCheck,   // a body's kinetic-energy jump beyond T_max stops the run
    BoxBox,        // sweep-and-prune broad phase, SAT narrow phase, impulses
    BoxPlane,      // corners below each plane, impulses
    Correction,    // push penetrating bodies apart (position_correction)
    // The manifold contact model (contact_model "manifold", physics/engine/manifold/):
    ManifoldContacts,    // before the integration: manifolds, sequential impulses -> contact loads
    ManifoldVelocities,  // v, L, omega from the loads and the contact loads; loads spent
    ManifoldPositions,   // after the integration: the position fix (NGS), no velocity change
    Sleep,               // bodies at rest go to sleep, touched ones wake
    Probes,        // probe points, when a trace is recorded
};

const char* pipelineStageName(PipelineStage stage);   // e.g. "box_box"

// A box-box pair whose penetration the correction stage removes.
struct PendingCorrection {
    int a, b;
    Vec3 n_W;
    double depth;
};

// What the stages of one step hand on to later stages; kept by the world between
// steps so that a step does not allocate it anew.
struct StepScratch {
    std::vector<char> loaded;            // forces: which bodies carry a load (trace rows)
    std::vector<double> kineticBefore;   // energy_bound: T_n per body [J]
    std::vector<double> kineticBound;    // energy_bound: T_max per body [J]
    std::vector<PendingCorrection> corrections;   // contacts -> correction
    int contactCount = 0;                // contacts resolved so far in this step
    BroadPhaseStats broadPhase;          // box_box: counts of the last step
    int contactLanes = 0;                // the soft step's lanes shared by two threads, or 1 (solver_islands.h)
};

// Everything a stage reads and writes in one step. The world owns all of it.
struct StepContext {
    const SceneDef& scene;
    const std::vector<MassProperties>& mass;
    const std::vector<InertiaConvention>& conventions;   // per body
    const std::vector<char>& movable;                    // per body: not fixed
    const std::vector<Vec3>& probeOffsets_B;             // per probe: p_B
    const std::vector<ForceDef>& onceForces;             // drags and pushes of this step
    const std::vector<char>& torqueEnabled;              // per couple
    std::vector<BodyState>& states;
    std::vector<BodyLoad>& loads;
    ContactState& contacts;   // the manifold model's state carried between steps (contact_state.h)
    StepScratch& scratch;
    StepTrace* trace;    // nullptr: record nothing
    long k;              // this step advances t_k = k h to t_{k+1}
    StepStatus& status;  // ok until a check finds a blow-up; then the pipeline stops
};

class PipelineStep {
public:
    virtual ~PipelineStep() = default;
    virtual PipelineStage kind() const = 0;
    // Runs the stage on this step; a stage that finds a blow-up sets ctx.status (and
    // only then: a successful step assigns no status, which keeps a step cheap).
    virtual void run(StepContext& ctx) = 0;
    // Integration only: the integrator's name and the bodies it advances.
    virtual const char* integratorName() const { return ""; }
    virtual const std::vector<int>* bodies() const { return nullptr; }
    // "integration:rk4" for an integration entry, else the stage name.
    std::string label() const;
};

} // namespace rbw
