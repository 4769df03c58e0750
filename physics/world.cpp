#include "physics/world.h"

#include "physics/integrator_registry.h"
#include "physics/quantities.h"

#include <cassert>
#include <cmath>

namespace rbw {

World::World(SceneDef scene)
    : scene_(std::move(scene))
    , integrator_(makeIntegrator(scene_.integrator))
{
    assert(validate(scene_).empty() && "World built from an invalid scene");
    assert(integrator_ != nullptr);
    const size_t n = scene_.bodies.size();
    mass_.reserve(n);
    states_.reserve(n);
    for (const BodyDef& def : scene_.bodies) {
        mass_.push_back(rbw::massProperties(def));
        states_.push_back(initialState(def, mass_.back(), scene_.inertiaConvention));
    }
    loads_.assign(n, BodyLoad{});
    for (const ProbeDef& p : scene_.probes) {
        const BodyState& s = states_[p.body];
        // p_B = R0^T (p0 - x0): the probe's fixed offset in the body frame
        probeOffsets_B_.push_back(s.R_WB.transpose() * (p.p0_W - s.x_W));
    }
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

StepStatus World::step(StepTrace* trace)
{
    if (!status_.ok) {
        return status_;
    }
    if (trace != nullptr) {
        trace->clear();
        trace->step = stepIndex_;
    }

    forcesStage(trace);

    const IntegrationInput in{scene_.dt, scene_.bodies, mass_, loads_, scene_.inertiaConvention};
    integrator_->integrate(in, states_, trace);

    time_ += scene_.dt;
    ++stepIndex_;
    onceForces_.clear();

    if (!allStatesFinite()) {
        status_ = describeBlowUp();
    }
    if (trace != nullptr) {
        trace->time = time_;
        if (status_.ok) {
            probesStage(trace);
            trace->diagnostics = diagnostics();
        }
    }
    return status_;
}

void World::forcesStage(StepTrace* trace)
{
    const long k = stepIndex_;
    const bool gravity = scene_.hasGravity();
    const int n = static_cast<int>(states_.size());
    for (BodyLoad& l : loads_) {
        l = BodyLoad{};
    }
    // Which bodies carry a load this step: only those get force/torque rows.
    std::vector<char>& loaded = loaded_;
    if (trace != nullptr) {
        loaded.assign(n, 0);
    }

    // Gravity: f_g = M g at the centre of mass, so it adds no torque.
    if (gravity) {
        for (int b = 0; b < n; ++b) {
            if (mass_[b].invM == 0.0) {
                continue;
            }
            const Vec3 fg_W = mass_[b].M * scene_.g_W;
            loads_[b].F_W += fg_W;
            if (trace != nullptr) {
                trace->add(q::gravity_force, b, fg_W);
                loaded[b] = 1;
            }
        }
    }

    // External forces f_i at world points p_i (TUM algorithm step 1):
    //   F = sum f_i,  q = sum x_i x f_i  with the lever arm x_i = p_i - x.
    auto applyOne = [&](const ForceDef& f, int index) {
        const BodyState& s = states_[f.body];
        const Vec3 x_i = f.p_W - s.x_W;
        loads_[f.body].F_W += f.f_W;
        loads_[f.body].q_W += x_i.cross(f.f_W);
        if (trace != nullptr) {
            trace->add(q::applied_force, f.body, f.f_W, index);
            trace->add(q::application_point, f.body, f.p_W, index);
            trace->add(q::lever_arm, f.body, x_i, index);
            loaded[f.body] = 1;
        }
    };
    int index = 0;
    for (const ForceDef& f : scene_.forces) {
        if (f.activeIn(k)) {
            applyOne(f, index);
        }
        ++index;
    }
    for (const ForceDef& f : onceForces_) {
        applyOne(f, index++);
    }

    if (trace != nullptr) {
        for (int b = 0; b < n; ++b) {
            if (!loaded[b]) {
                continue;
            }
            trace->add(gravity ? q::force_with_gravity : q::force, b, loads_[b].F_W);
            trace->add(q::torque, b, loads_[b].q_W);
        }
    }
}

void World::probesStage(StepTrace* trace) const
{
    for (int i = 0; i < static_cast<int>(scene_.probes.size()); ++i) {
        const ProbeReading r = probe(i);
        trace->add(q::probe_position, r.body, r.p_W, i);
        trace->add(q::point_velocity, r.body, r.v_W, i);
    }
}

ProbeReading World::probe(int i) const
{
    ProbeReading r;
    r.body = scene_.probes[i].body;
    const BodyState& s = states_[r.body];
    // p = x + R p_B
    r.p_W = s.x_W + s.R_WB * probeOffsets_B_[i];
    // v_p = v + omega x (p - x)
    r.v_W = pointVelocity(s, r.p_W);
    return r;
}

Diagnostics World::diagnostics() const
{
    return computeDiagnostics(mass_, states_, scene_.g_W);
}

bool World::allStatesFinite() const
{
    // NaN and infinity propagate through a sum, so a finite sum of every component
    // proves all are finite (a finite overflow only sends us to the detailed check).
    double sum = 0.0;
    for (const BodyState& s : states_) {
        sum += s.x_W.sum() + s.v_W.sum() + s.q_WB.coeffs().sum() + s.L_W.sum() + s.omega_W.sum();
    }
    return std::isfinite(sum);
}

StepStatus World::describeBlowUp() const
{
    struct Field {
        const char* id;
        bool finite;
    };
    for (int b = 0; b < static_cast<int>(states_.size()); ++b) {
        const BodyState& s = states_[b];
        const Field fields[] = {
            {"position", isFinite(s.x_W)},
            {"linear_velocity", isFinite(s.v_W)},
            {"orientation", isFinite(s.q_WB)},
            {"angular_momentum", isFinite(s.L_W)},
            {"angular_velocity", isFinite(s.omega_W)},
        };
        for (const Field& f : fields) {
            if (f.finite) {
                continue;
            }
            StepStatus st;
            st.ok = false;
            st.step = stepIndex_ - 1;
            st.body = b;
            st.bodyName = scene_.bodies[b].name;
            st.quantity = f.id;
            st.message = "simulation blew up in step " + std::to_string(st.step) + ": " + f.id +
                         " of body \"" + st.bodyName +
                         "\" is not finite. Try a smaller dt or another integrator.";
            return st;
        }
    }
    return StepStatus::success();
}

WorldSnapshot World::snapshot() const
{
    return WorldSnapshot{states_, stepIndex_, time_, status_};
}

void World::restore(const WorldSnapshot& s)
{
    states_ = s.states;
    stepIndex_ = s.stepIndex;
    time_ = s.time;
    status_ = s.status;
    onceForces_.clear();
}

} // namespace rbw
