// The world: a scene definition plus the mutable state of its bodies, and the
// pipeline of stages that one step runs:
//   forces -> integration -> collision -> correction -> probes.
// The collision stage runs only when the scene has something that can collide (two
// bodies with box collisions on, or a plane), and correction only when asked for.
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
    std::vector<char> torqueEnabled;   // switchable torques' on/off state
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

    bool runsCollisionStage() const { return boxPairsPossible_ || !scene_.planes.empty(); }
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

    SceneDef scene_;
    std::vector<MassProperties> mass_;
    std::vector<Vec3> probeOffsets_B_;   // p0 in the body frame: R0^T (p0 - x0)
    std::unique_ptr<Integrator> integrator_;

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
