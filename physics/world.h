// The world: a scene definition plus the mutable state of its bodies, and the
// pipeline of stages that one step runs (forces -> integration -> probes).
//
// Data flows one way: SceneDef -> World -> step() -> StepTrace -> every view.
// No view reaches back into the world to recompute a quantity.
#pragma once

#include "physics/body.h"
#include "physics/diagnostics.h"
#include "physics/integrator.h"
#include "physics/scene.h"
#include "physics/step_status.h"
#include "physics/trace.h"

#include <memory>
#include <vector>

namespace rbw {

struct ProbeReading {
    int body = -1;
    Vec3 p_W = Vec3::Zero();   // current position of the probe point
    Vec3 v_W = Vec3::Zero();   // its velocity v + omega x (p - x)
};

// Everything needed to put a world back exactly as it was (history, step back).
struct WorldSnapshot {
    std::vector<BodyState> states;
    long stepIndex = 0;
    double time = 0.0;
    StepStatus status;
};

class World {
public:
    // The scene must be valid (validate(scene) empty); front ends check that first.
    explicit World(SceneDef scene);

    const SceneDef& scene() const { return scene_; }
    const std::vector<BodyState>& states() const { return states_; }
    const std::vector<MassProperties>& massProperties() const { return mass_; }
    const Integrator& integrator() const { return *integrator_; }
    long stepIndex() const { return stepIndex_; }   // the next step to take is k = stepIndex()
    double time() const { return time_; }
    const StepStatus& status() const { return status_; }

    // Adds a force that acts in the next step only (interaction: drag, key pushes).
    void applyForceOnce(int body, const Vec3& p_W, const Vec3& f_W);

    // Advances by one step of size dt. With a trace, records every intermediate
    // quantity and the diagnostics after the step. After a blow-up the world refuses
    // to step again and keeps returning the same status.
    StepStatus step(StepTrace* trace = nullptr);

    Diagnostics diagnostics() const;
    ProbeReading probe(int i) const;

    WorldSnapshot snapshot() const;
    void restore(const WorldSnapshot& s);

private:
    void forcesStage(StepTrace* trace);
    void probesStage(StepTrace* trace) const;
    bool allStatesFinite() const;
    // The first non-finite quantity, as a status that names step, body and quantity.
    StepStatus describeBlowUp() const;

    SceneDef scene_;
    std::vector<MassProperties> mass_;
    std::vector<Vec3> probeOffsets_B_;   // p0 in the body frame: R0^T (p0 - x0)
    std::unique_ptr<Integrator> integrator_;

    std::vector<BodyState> states_;
    std::vector<BodyLoad> loads_;
    std::vector<ForceDef> onceForces_;
    std::vector<char> loaded_;           // forces stage scratch: which bodies carry a load
    long stepIndex_ = 0;
    double time_ = 0.0;
    StepStatus status_;
};

} // namespace rbw
