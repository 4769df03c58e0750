#include "physics/world.h"

#include "physics/collision/box_box_sat.h"
#include "physics/collision/box_plane.h"
#include "physics/collision/impulse.h"
#include "physics/integrator_registry.h"
#include "physics/quantities.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>

namespace rbw {

const char* pipelineStageName(PipelineStage stage)
{
    switch (stage) {
    case PipelineStage::Gravity: return "gravity";
    case PipelineStage::Loads: return "loads";
    case PipelineStage::Integration: return "integration";
    case PipelineStage::FiniteCheck: return "finite_check";
    case PipelineStage::EnergyCheck: return "energy_check";
    case PipelineStage::BoxBox: return "box_box";
    case PipelineStage::BoxPlane: return "box_plane";
    case PipelineStage::Correction: return "correction";
    case PipelineStage::Probes: return "probes";
    }
    return "?";
}

std::string PipelineEntry::label() const
{
    if (stage == PipelineStage::Integration) {
        return std::string("integration:") + integrator;
    }
    return pipelineStageName(stage);
}

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
    maxInvInertia_.reserve(n);
    for (size_t b = 0; b < n; ++b) {
        const BodyDef& def = scene_.bodies[b];
        conventions_.push_back(scene_.conventionOf(static_cast<int>(b)));
        mass_.push_back(rbw::massProperties(def));
        states_.push_back(initialState(def, mass_.back(), conventions_.back()));
        // I0^-1 is diagonal: its largest entry is its largest eigenvalue
        maxInvInertia_.push_back(mass_.back().I0inv_B.diagonal().maxCoeff());
    }
    loads_.assign(n, BodyLoad{});
    kineticBefore_.assign(n, 0.0);
    kineticBound_.assign(n, 0.0);
    movable_.resize(n);
    int movableCount = 0;
    for (size_t b = 0; b < n; ++b) {
        movable_[b] = scene_.bodies[b].fixed ? 0 : 1;
        movableCount += movable_[b];
    }
    // Box-box contacts need two bodies, at least one of them movable.
    boxPairsPossible_ = (scene_.boxCollisions || options.allStages) && n >= 2 && movableCount >= 1;
    // Plane tests need a plane and a movable body.
    planeTestsPossible_ = !scene_.planes.empty() && (movableCount >= 1 || options.allStages);
    runGravity_ = (scene_.hasGravity() && movableCount >= 1) || options.allStages;
    runEnergyCheck_ = scene_.energyJumpFactor > 0.0;

    // Integrator groups: the bodies grouped by their integrator's name, in the order
    // the names first appear; one group of all bodies when no body has its own.
    groupOf_.assign(n, 0);
    std::vector<std::string> names;
    for (size_t b = 0; b < n; ++b) {
        const std::string& name = scene_.integratorOf(static_cast<int>(b));
        const auto it = std::find(names.begin(), names.end(), name);
        groupOf_[b] = static_cast<int>(it - names.begin());
        if (it == names.end()) {
            names.push_back(name);
        }
    }
    for (size_t g = 0; g < names.size(); ++g) {
        IntegratorGroup group;
        group.integrator = makeIntegrator(names[g]);
        assert(group.integrator != nullptr);
        group.all = names.size() == 1;
        group.active.assign(n, 0);
        for (size_t b = 0; b < n; ++b) {
            group.active[b] = groupOf_[b] == static_cast<int>(g) ? 1 : 0;
        }
        groups_.push_back(std::move(group));
    }

    for (const TorqueDef& t : scene_.torques) {
        torqueEnabled_.push_back(!t.switchable || t.enabledAtStart ? 1 : 0);
    }
    for (const ProbeDef& p : scene_.probes) {
        const BodyState& s = states_[p.body];
        // p_B = R0^T (p0 - x0): the probe's fixed offset in the body frame
        probeOffsets_B_.push_back(s.R_WB.transpose() * (p.p0_W - s.x_W));
    }
    buildPipeline(options);
}

void World::buildPipeline(const WorldOptions& /*options*/)
{
    pipeline_.clear();
    if (runGravity_) {
        pipeline_.push_back({PipelineStage::Gravity, {}, {}});
    }
    pipeline_.push_back({PipelineStage::Loads, {}, {}});
    for (const IntegratorGroup& g : groups_) {
        PipelineEntry e{PipelineStage::Integration, g.integrator->name(), {}};
        for (int b = 0; b < static_cast<int>(g.active.size()); ++b) {
            if (g.active[b] && movable_[b]) {
                e.bodies.push_back(b);
            }
        }
        if (!e.bodies.empty()) {
            pipeline_.push_back(std::move(e));
        }
    }
    pipeline_.push_back({PipelineStage::FiniteCheck, {}, {}});
    if (runEnergyCheck_) {
        pipeline_.push_back({PipelineStage::EnergyCheck, {}, {}});
    }
    if (boxPairsPossible_) {
        pipeline_.push_back({PipelineStage::BoxBox, {}, {}});
    }
    if (planeTestsPossible_) {
        pipeline_.push_back({PipelineStage::BoxPlane, {}, {}});
    }
    if (scene_.positionCorrection && runsCollisionStage()) {
        pipeline_.push_back({PipelineStage::Correction, {}, {}});
    }
    if (!scene_.probes.empty()) {
        pipeline_.push_back({PipelineStage::Probes, {}, {}});
    }
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
    if (runEnergyCheck_) {
        energyBounds();
    }

    // Integration: each group's integrator advances its own bodies, with each body's
    // own inertia convention.
    for (const IntegratorGroup& g : groups_) {
        const IntegrationInput in{scene_.dt,          scene_.bodies, mass_, loads_, scene_.inertiaConvention,
                                  &conventions_,      g.all ? nullptr : &g.active};
        g.integrator->integrate(in, states_, trace);
    }
    time_ += scene_.dt;
    ++stepIndex_;
    onceForces_.clear();

    // Check before the collision stage: a NaN pose makes every overlap test pass and
    // would spread the NaN into healthy bodies, and the report would blame them.
    if (!allStatesFinite()) {
        status_ = describeBlowUp();
    } else if (runEnergyCheck_ && !(status_ = checkEnergyJump()).ok) {
        // an energy jump: stop before the collision stage, like a non-finite value
    } else if (runsCollisionStage()) {
        collisionStage(trace);
        if (scene_.positionCorrection) {
            correctionStage(trace);
        }
        if (!allStatesFinite()) {
            status_ = describeBlowUp();
        }
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
    const bool gravity = runGravity_;
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

    // Pure couples q_j: they add to the torque and not to the force,
    //   q = sum x_i x f_i + sum q_j.
    for (int j = 0; j < static_cast<int>(scene_.torques.size()); ++j) {
        const TorqueDef& t = scene_.torques[j];
        if (!t.activeIn(k) || !torqueEnabled_[j]) {
            continue;
        }
        loads_[t.body].q_W += t.q_W;
        if (trace != nullptr) {
            trace->add(q::applied_torque, t.body, t.q_W, j);
            loaded[t.body] = 1;
        }
    }

    if (trace != nullptr) {
        for (int b = 0; b < n; ++b) {
            if (!loaded[b]) {
                continue;
            }
            trace->add(gravity ? q::force_with_gravity : q::force, b, loads_[b].F_W);
            trace->add(scene_.torques.empty() ? q::torque : q::torque_with_couples, b, loads_[b].q_W);
        }
    }
}

BoxPose World::poseOf(int body) const
{
    const BodyState& s = states_[body];
    return BoxPose{s.x_W, s.R_WB, 0.5 * scene_.bodies[body].size};
}

void World::collisionStage(StepTrace* trace)
{
    contactCount_ = 0;
    corrections_.clear();
    const int n = static_cast<int>(states_.size());

    // Box-box: sweep-and-prune on world AABBs, then the course's SAT on each
    // overlapping pair (reference.md section 2).
    if (boxPairsPossible_) {
        aabbs_.resize(n);
        for (int b = 0; b < n; ++b) {
            aabbs_[b] = boxAabb(poseOf(b));
        }
        lastBroadPhase_ = BroadPhaseStats{};
        broadPhase_.findPairs(aabbs_, movable_, pairs_, lastBroadPhase_);
        record(trace, q::pairs_tested, -1, double(lastBroadPhase_.pairsTested));
        record(trace, q::pairs_overlapping, -1, double(lastBroadPhase_.pairsOverlapping));
        for (const auto& [a, b] : pairs_) {
            const std::optional<ContactGeometry> hit = collideBoxBoxSAT(poseOf(a), poseOf(b));
            if (hit) {
                resolveContact(*hit, a, b, -1, "single-point", 1, trace);
            }
        }
    }

    // Box-plane: every corner below a plane is a contact (Napier practical 6).
    for (int p = 0; planeTestsPossible_ && p < static_cast<int>(scene_.planes.size()); ++p) {
        for (int b = 0; b < n; ++b) {
            if (!movable_[b]) {
                continue;
            }
            planeContacts_.clear();
            const int count = collideBoxPlane(poseOf(b), scene_.planes[p], planeContacts_);
            if (count == 0) {
                continue;
            }
            if (scene_.planeContacts == PlaneContactMode::Average) {
                // One impulse at the average of the corners (Napier assessment).
                resolveContact(averageContact(planeContacts_, 0, planeContacts_.size()), b, -1, p, "average",
                               count, trace);
            } else {
                // One impulse per corner, in turn, each seeing the velocities the
                // previous ones left.
                for (const ContactGeometry& g : planeContacts_) {
                    resolveContact(g, b, -1, p, "per-point", 1, trace);
                }
            }
        }
    }
}

void World::resolveContact(const ContactGeometry& g, int a, int b, int plane, const char* resolution,
                           int pointCount, StepTrace* trace)
{
    const int k = contactCount_++;
    ResponseBody A{&states_[a], &mass_[a], scene_.bodies[a].angularResponse};
    ResponseBody B;
    if (b >= 0) {
        B = ResponseBody{&states_[b], &mass_[b], scene_.bodies[b].angularResponse};
    }
    double c = scene_.restitutionFor(a, b, plane);
    if (scene_.restitutionThreshold > 0.0) {
        // Resting contact: an approach slower than the threshold does not bounce.
        const Vec3 vA = pointVelocity(states_[a], g.p_W);
        const Vec3 vB = b >= 0 ? pointVelocity(states_[b], g.p_W) : Vec3::Zero();
        if (-(vA - vB).dot(g.n_W) < scene_.restitutionThreshold) c = 0.0;
    }
    const double mu = scene_.frictionFor(a, b, plane);
    // The impulse re-derives omega with one convention (A's); a body B with another
    // convention is re-derived with its own right after.
    const ImpulseResult r = applyContactImpulse(g, A, B, c, mu, conventions_[a]);
    if (b >= 0 && conventions_[b] != conventions_[a] && mass_[b].invM != 0.0) {
        updateDerived(mass_[b], states_[b], conventions_[b]);
    }

    if (scene_.positionCorrection && g.depth > 0.0 && plane < 0) {
        // Box-box: keep the deepest penetration per pair. (Planes re-measure in the
        // correction stage itself.)
        bool merged = false;
        for (Correction& corr : corrections_) {
            if (corr.a == a && corr.b == b) {
                if (g.depth > corr.depth) {
                    corr.depth = g.depth;
                    corr.n_W = g.n_W;
                }
                merged = true;
                break;
            }
        }
        if (!merged) {
            corrections_.push_back(Correction{a, b, g.n_W, g.depth});
        }
    }

    if (trace == nullptr) {
        return;
    }
    trace->contacts.push_back(ContactHeader{a, b, plane, featureName(g.feature), resolution, pointCount, r.separating});
    trace->add(q::contact_point, a, g.p_W, k);
    trace->add(q::contact_normal, a, g.n_W, k);
    trace->add(q::contact_depth, a, g.depth, k);
    trace->add(q::x_a, a, r.x_a, k);
    if (b >= 0) trace->add(q::x_b, b, r.x_b, k);
    trace->add(q::velocity_a, a, r.velocity_a, k);
    trace->add(q::velocity_b, b, r.velocity_b, k);
    trace->add(q::relative_velocity, a, r.v_rel, k);
    trace->add(q::normal_velocity, a, r.v_rel_n, k);
    if (r.separating) {
        return;   // no impulse: the header says "separating"
    }
    trace->add(q::restitution, a, r.restitution, k);
    trace->add(q::numerator, a, r.numerator, k);
    trace->add(q::inv_mass_a, a, r.invMassA, k);
    trace->add(q::inv_mass_b, b, r.invMassB, k);
    trace->add(q::rotational_a, a, r.rotationalA, k);
    trace->add(q::rotational_b, b, r.rotationalB, k);
    trace->add(q::denominator, a, r.denominator, k);
    trace->add(q::impulse, a, r.J, k);
    if (r.mu > 0.0) {
        trace->add(q::friction_coefficient, a, r.mu, k);
        trace->add(q::friction_impulse, a, r.frictionImpulse_W, k);
        trace->add(q::sliding, a, r.frictionClamped ? 1.0 : 0.0, k);
    }
    trace->add(q::delta_v_a, a, r.dv_A, k);
    trace->add(q::delta_L_a, a, r.dL_A, k);
    trace->add(q::linear_velocity_a, a, states_[a].v_W, k);
    trace->add(q::angular_momentum_a, a, states_[a].L_W, k);
    trace->add(q::angular_velocity_a, a, states_[a].omega_W, k);
    if (b >= 0 && mass_[b].invM != 0.0) {
        trace->add(q::delta_v_b, b, r.dv_B, k);
        trace->add(q::delta_L_b, b, r.dL_B, k);
        trace->add(q::linear_velocity_b, b, states_[b].v_W, k);
        trace->add(q::angular_momentum_b, b, states_[b].L_W, k);
        trace->add(q::angular_velocity_b, b, states_[b].omega_W, k);
    }
    trace->add(q::kinetic_energy_before, a, r.kineticBefore, k);
    trace->add(q::kinetic_energy_after, a, r.kineticAfter, k);
}

void World::correctionStage(StepTrace* trace)
{
    // Projection: move penetrating bodies apart along n by the depth d, shared in
    // proportion to inverse mass. Not part of the impulse: it changes x only.
    int index = 0;
    for (const Correction& c : corrections_) {
        const double invMA = mass_[c.a].invM;
        const double invMB = mass_[c.b].invM;
        const double sum = invMA + invMB;
        if (sum == 0.0) continue;
        // dx_A = d n (1/M_A) / (1/M_A + 1/M_B),  dx_B = -d n (1/M_B) / (1/M_A + 1/M_B)
        const Vec3 dx_A = c.depth * (invMA / sum) * c.n_W;
        const Vec3 dx_B = -c.depth * (invMB / sum) * c.n_W;
        states_[c.a].x_W += dx_A;
        states_[c.b].x_W += dx_B;
        if (invMA != 0.0) record(trace, q::correction_a, c.a, dx_A, index);
        if (invMB != 0.0) record(trace, q::correction_b, c.b, dx_B, index);
        ++index;
    }
    // Fixed planes have the last word: every movable body is lifted out of every plane
    // by its deepest corner's depth measured now, d = max(0, max_corners -n.(corner - point)),
    // since a box-box correction may have pushed it in. A plane takes no share: dx = d n.
    for (int p = 0; p < static_cast<int>(scene_.planes.size()); ++p) {
        const PlaneDef& plane = scene_.planes[p];
        for (int b = 0; b < static_cast<int>(states_.size()); ++b) {
            if (!movable_[b]) continue;
            double depth = 0.0;
            for (const Vec3& corner : boxCorners(poseOf(b))) {
                depth = std::max(depth, -plane.n_W.dot(corner - plane.point_W));
            }
            if (depth == 0.0) continue;
            const Vec3 dx_A = depth * plane.n_W;
            states_[b].x_W += dx_A;
            record(trace, q::correction_a, b, dx_A, index++);
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
            st.kind = "non-finite";
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

void World::energyBounds()
{
    const double h = scene_.dt;
    const double factor = scene_.energyJumpFactor;
    for (int b = 0; b < static_cast<int>(states_.size()); ++b) {
        if (!movable_[b]) {
            continue;
        }
        const BodyState& s = states_[b];
        const MassProperties& mp = mass_[b];
        const BodyLoad& l = loads_[b];
        // T_n = 1/2 M |v|^2 + 1/2 omega . L
        const double T_n = kineticEnergy(mp, s);
        // W_n: the most work the step's loads can do, from v' = v + h F/M and
        // L' = L + h q with I^-1 unchanged (docs/stability.md):
        //   W_n = h |F.v| + h^2 |F|^2 / (2M) + h |q.omega| + h^2 |q|^2 max(I0^-1) / 2
        const double W_n = h * std::abs(l.F_W.dot(s.v_W)) + 0.5 * h * h * mp.invM * l.F_W.squaredNorm() +
                           h * std::abs(l.q_W.dot(s.omega_W)) +
                           0.5 * h * h * maxInvInertia_[b] * l.q_W.squaredNorm();
        // T_max = factor (T_n + W_n) + floor
        kineticBefore_[b] = T_n;
        kineticBound_[b] = factor * (T_n + W_n) + scene_.energyJumpFloor;
    }
}

namespace {

std::string joules(double x)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", x);
    return buf;
}

} // namespace

StepStatus World::checkEnergyJump() const
{
    for (int b = 0; b < static_cast<int>(states_.size()); ++b) {
        if (!movable_[b]) {
            continue;
        }
        const double T = kineticEnergy(mass_[b], states_[b]);
        // A bound that overflowed to infinity cannot be exceeded; T is finite here.
        if (!(T > kineticBound_[b])) {
            continue;
        }
        StepStatus st;
        st.ok = false;
        st.kind = "energy-jump";
        st.step = stepIndex_ - 1;
        st.body = b;
        st.bodyName = scene_.bodies[b].name;
        st.quantity = "kinetic_energy";
        st.kineticBefore = kineticBefore_[b];
        st.kineticAfter = T;
        st.kineticBound = kineticBound_[b];
        st.message = "simulation blew up in step " + std::to_string(st.step) + ": kinetic_energy of body \"" +
                     st.bodyName + "\" jumped from " + joules(st.kineticBefore) + " J to " + joules(T) +
                     " J in one step, above the bound " + joules(st.kineticBound) +
                     " J. Try a smaller dt or another integrator.";
        return st;
    }
    return StepStatus::success();
}

WorldSnapshot World::snapshot() const
{
    return WorldSnapshot{states_, torqueEnabled_, stepIndex_, time_, status_};
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
    onceForces_.clear();
}

} // namespace rbw
