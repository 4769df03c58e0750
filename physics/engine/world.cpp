#include "physics/engine/world.h"

#include "physics/engine/integrator_registry.h"
#include "physics/engine/stages/checks.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace rbw {

World::World(SceneDef scene, WorldOptions options)
    : scene_(std::move(scene))
    , integrator_(makeIntegrator(scene_.integrator))
{
    assert(validate(scene_).empty() && "World built from an invalid scene");
    assert(integrator_ != nullptr);
    const size_t n = scene_.bodies.size();
    mass_.reserve(n);
    states_.reserve(n);
    conventions_.reserve(n);
    movable_.reserve(n);
    for (size_t b = 0; b < n; ++b) {
        const BodyDef& def = scene_.bodies[b];
        conventions_.push_back(scene_.conventionOf(static_cast<int>(b)));
        mass_.push_back(rbw::massProperties(def));
        states_.push_back(initialState(def, mass_.back(), conventions_.back()));
        movable_.push_back(def.fixed ? 0 : 1);
    }
    loads_.assign(n, BodyLoad{});
    contacts_ = ContactState(static_cast<int>(n));
    scratch_.loaded.assign(n, 0);
    scratch_.kineticBefore.assign(n, 0.0);
    scratch_.kineticBound.assign(n, 0.0);

    const IntegratorGroups groups = integratorGroups(scene_);
    groupOf_ = groups.groupOf;
    for (const std::string& name : groups.names) {
        groupIntegrators_.push_back(makeIntegrator(name));
        assert(groupIntegrators_.back() != nullptr);
    }
    for (const TorqueDef& t : scene_.torques) {
        torqueEnabled_.push_back(!t.switchable || t.enabledAtStart ? 1 : 0);
    }
    for (const ProbeDef& p : scene_.probes) {
        const BodyState& s = states_[p.body];
        // p_B = R0^T (p0 - x0): the probe's fixed offset in the body frame
        probeOffsets_B_.push_back(s.R_WB.transpose() * (p.p0_W - s.x_W));
    }
    pipeline_ = buildPipeline(scene_, mass_, movable_, groups, options);
}

std::vector<std::string> World::pipelineLabels() const
{
    std::vector<std::string> out;
    out.reserve(pipeline_.size());
    for (const PipelineEntry& e : pipeline_) {
        out.push_back(e.label());
    }
    return out;
}

bool World::runsStage(PipelineStage stage) const
{
    return std::any_of(pipeline_.begin(), pipeline_.end(),
                       [stage](const PipelineEntry& e) { return e.stage == stage; });
}

void World::applyForceOnce(int body, const Vec3& p_W, const Vec3& f_W)
{
    ForceDef f;
    f.body = body;
    f.p_W = p_W;
    f.f_W = f_W;
    f.fromStep = stepIndex_;
    f.toStep = stepIndex_ + 1;
    onceForces_.push_back(f);
}

void World::setTorqueEnabled(int i, bool on)
{
    assert(i >= 0 && i < static_cast<int>(torqueEnabled_.size()));
    if (scene_.torques[i].switchable) {
        torqueEnabled_[i] = on ? 1 : 0;
    }
}

bool World::hasSwitchableTorque() const
{
    return std::any_of(scene_.torques.begin(), scene_.torques.end(),
                       [](const TorqueDef& t) { return t.switchable; });
}

Vec3 World::bodyToWorld(int body, const Vec3& p_B) const
{
    const BodyState& s = states_[body];
    // p_W = x + R p_B
    return s.x_W + s.R_WB * p_B;
}

Vec3 World::worldToBody(int body, const Vec3& p_W) const
{
    const BodyState& s = states_[body];
    // p_B = R^T (p_W - x)
    return s.R_WB.transpose() * (p_W - s.x_W);
}

StepContext World::context(StepTrace* trace)
{
    return StepContext{scene_,  mass_,  conventions_, movable_, probeOffsets_B_, onceForces_, torqueEnabled_,
                       states_, loads_, contacts_,    scratch_, trace,           stepIndex_,  status_};
}

const StepStatus& World::step(StepTrace* trace)
{
    if (!status_.ok) {
        return status_;
    }
    if (trace != nullptr) {
        trace->clear();
        trace->step = stepIndex_;
        // The state at t_k, which the step starts from (StepTrace::start).
        trace->start.bodies = states_;
        trace->start.probes.resize(scene_.probes.size());
        for (int i = 0; i < static_cast<int>(scene_.probes.size()); ++i) {
            const ProbeReading r = readProbe(scene_, states_, probeOffsets_B_, i);
            trace->start.probes[static_cast<size_t>(i)] = ProbeSample{r.body, r.p_W, r.v_W};
        }
    }
    // A new step's loads and scratch.
    std::fill(loads_.begin(), loads_.end(), BodyLoad{});
    if (trace != nullptr) std::fill(scratch_.loaded.begin(), scratch_.loaded.end(), 0);
    scratch_.corrections.clear();
    scratch_.contactCount = 0;
    scratch_.contactLanes = 0;

    // The pipeline the scene built, in order; a check that finds a blow-up stops it.
    StepContext ctx = context(trace);
    for (PipelineEntry& e : pipeline_) {
        e.step->run(ctx);
        if (!status_.ok) break;
    }

    // t_{k+1} = t_k + h; the one-step forces (drags, pushes) have acted.
    time_ += scene_.dt;
    ++stepIndex_;
    onceForces_.clear();
    const CheckPoint at{stepIndex_ - 1, false};
    // t_{k+1} overflows only with dt at the edge of the double range
    if (status_.ok && !std::isfinite(time_)) {
        status_ = checkTime(CheckScope{scene_, mass_, conventions_, probeOffsets_B_}, time_, at);
    }
    if (trace != nullptr) {
        trace->time = time_;
        if (status_.ok) {
            trace->diagnostics = diagnostics();
            // Every number the trace holds, then what is computed from the state for it.
            // (The state itself was checked by the pipeline's finite_check.)
            const CheckScope scope{scene_, mass_, conventions_, probeOffsets_B_};
            StepStatus st = checkTrace(scope, *trace, at);
            if (st.ok) st = checkDerivedOutputs(scope, states_, trace->diagnostics, at);
            if (!st.ok) status_ = std::move(st);
        }
    }
    return status_;
}

StepStatus World::checkOutputs(const Diagnostics& d)
{
    if (!status_.ok) return status_;
    const CheckScope scope{scene_, mass_, conventions_, probeOffsets_B_};
    const bool initial = stepIndex_ == 0;
    const CheckPoint at{initial ? 0 : stepIndex_ - 1, initial};
    StepStatus st = checkMassProperties(scope, at);
    if (st.ok) st = checkStates(scope, states_, at);
    if (st.ok) st = checkTime(scope, time_, at);
    if (st.ok) st = checkDerivedOutputs(scope, states_, d, at);
    if (!st.ok) status_ = st;
    return st;
}

ProbeReading World::probe(int i) const
{
    return readProbe(scene_, states_, probeOffsets_B_, i);
}

Diagnostics World::diagnostics() const
{
    return computeDiagnostics(mass_, states_, scene_.g_W);
}

WorldSnapshot World::snapshot() const
{
    return WorldSnapshot{states_, torqueEnabled_, stepIndex_, time_, status_, contacts_};
}

void World::restore(const WorldSnapshot& s)
{
    states_ = s.states;
    if (s.torqueEnabled.size() == torqueEnabled_.size()) {
        torqueEnabled_ = s.torqueEnabled;
    }
    stepIndex_ = s.stepIndex;
    time_ = s.time;
    status_ = s.status;
    // A snapshot of another scene, or a default-constructed one, has no contact state for
    // these bodies: the world's is then a fresh world's.
    if (s.contacts.sleep.bodyCount() == static_cast<int>(scene_.bodies.size())) {
        contacts_ = s.contacts;
    } else {
        contacts_ = ContactState(static_cast<int>(scene_.bodies.size()));
    }
    onceForces_.clear();
}

} // namespace rbw
