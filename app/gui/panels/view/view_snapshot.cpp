#include "app/gui/panels/view/view_snapshot.h"

#include "physics/engine/quantities.h"
#include "physics/engine/trace.h"
#include "physics/engine/world.h"

#include <cstring>

namespace rbw {

namespace {

// Trace entries are matched by their catalogue id (physics/engine/quantities.h), not by
// address, so that two QuantityInfo variants with one id (e.g. "force") both match.
bool is(const TraceEntry& e, const QuantityInfo& info) { return std::strcmp(e.info->id, info.id) == 0; }

const Vec3* vec3Of(const TraceEntry& e)
{
    const Vec3* v = std::get_if<Vec3>(&e.value);
    return (v != nullptr && isFinite(*v)) ? v : nullptr;
}

const double* scalarOf(const TraceEntry& e)
{
    const double* d = std::get_if<double>(&e.value);
    return (d != nullptr && std::isfinite(*d)) ? d : nullptr;
}

// A force arrow is complete once both f_i and p_i of the same (body, i) were read.
struct PendingForce {
    int body = -1;
    int index = -1;
    std::optional<Vec3> f_W;
    std::optional<Vec3> p_W;
};

PendingForce& pendingFor(std::vector<PendingForce>& pending, int body, int index)
{
    for (PendingForce& p : pending) {
        if (p.body == body && p.index == index) return p;
    }
    pending.push_back(PendingForce{body, index, std::nullopt, std::nullopt});
    return pending.back();
}

struct PendingContact {
    std::optional<Vec3> p_W;
    std::optional<Vec3> n_W;
    double J = 0.0;
    std::optional<Vec3> friction_W;
};

} // namespace

ViewSnapshot makeViewSnapshot(const World& world, const StepTrace* trace)
{
    ViewSnapshot snap;
    const SceneDef& scene = world.scene();
    const std::vector<BodyState>& states = world.states();
    const int bodyCount = static_cast<int>(states.size());

    snap.time = world.time();
    snap.nextStep = world.stepIndex();
    snap.h = scene.dt;
    bool perBody = false;
    for (const BodyDef& b : scene.bodies) perBody = perBody || !b.integrator.empty();
    snap.integrator = perBody ? std::string("per body") : scene.integrator;
    snap.bodies.reserve(states.size());
    for (int b = 0; b < bodyCount; ++b) {
        ViewSnapshot::Body body;
        body.name = scene.bodies[b].name;
        body.x_W = states[b].x_W;
        body.R_WB = states[b].R_WB;
        body.size = scene.bodies[b].size;
        body.fixed = scene.bodies[b].fixed;
        body.finite = isFinite(body.x_W) && isFinite(body.R_WB);
        body.v_W = isFinite(states[b].v_W) ? states[b].v_W : Vec3::Zero();
        body.omega_W = isFinite(states[b].omega_W) ? states[b].omega_W : Vec3::Zero();
        body.L_W = isFinite(states[b].L_W) ? states[b].L_W : Vec3::Zero();
        snap.bodies.push_back(body);
    }
    for (const PlaneDef& p : scene.planes) {
        snap.planes.push_back(ViewSnapshot::Plane{p.name, p.point_W, p.n_W});
    }

    const int probeCount = static_cast<int>(scene.probes.size());
    std::vector<ViewSnapshot::Probe> probes(static_cast<size_t>(probeCount));
    std::vector<char> probeSeen(static_cast<size_t>(probeCount), 0);
    bool probesFromTrace = false;

    if (trace != nullptr) {
        snap.hasTrace = true;
        snap.step = trace->step;
        const int contactCount = static_cast<int>(trace->contacts.size());
        std::vector<PendingContact> contacts(static_cast<size_t>(contactCount));
        std::vector<PendingForce> pendingForces;
        std::vector<ViewSnapshot::Force> gravity;

        for (const TraceEntry& e : trace->entries) {
            const bool bodyOk = e.body >= 0 && e.body < bodyCount;
            switch (e.info->stage) {
            case Stage::Forces:
                if (!bodyOk) break;
                if (is(e, q::applied_force) || is(e, q::application_point)) {
                    // f_i and p_i: the same body and force index i (World::forcesStage).
                    const Vec3* v = vec3Of(e);
                    if (v == nullptr) break;
                    PendingForce& pf = pendingFor(pendingForces, e.body, e.index);
                    (is(e, q::applied_force) ? pf.f_W : pf.p_W) = *v;
                } else if (is(e, q::applied_torque)) {
                    // q_j, a couple: drawn at the centre of mass x.
                    const Vec3* v = vec3Of(e);
                    if (v == nullptr || !snap.bodies[e.body].finite) break;
                    snap.torques.push_back(ViewSnapshot::Torque{e.body, e.index, *v});
                } else if (is(e, q::gravity_force)) {
                    // M g acts at the centre of mass x (no torque).
                    const Vec3* v = vec3Of(e);
                    if (v == nullptr || !snap.bodies[e.body].finite) break;
                    // Gravity acts in every step: it is also the next step's.
                    gravity.push_back(ViewSnapshot::Force{ViewSnapshot::ForceKind::Gravity, e.body, -1,
                                                          snap.bodies[e.body].x_W, *v, true});
                }
                break;
            case Stage::Collision:
                if (e.index < 0 || e.index >= contactCount) break;
                // The course model's rows, or a manifold point's (contact_model "manifold":
                // the clipped point, n, the accumulated lambda_n and lambda_t after the
                // solver's iterations, both applied to A as P = lambda_n n + lambda_t).
                if (is(e, q::contact_point) || is(e, q::manifold_point)) {
                    if (const Vec3* v = vec3Of(e)) contacts[e.index].p_W = *v;
                } else if (is(e, q::contact_normal) || is(e, q::manifold_normal)) {
                    if (const Vec3* v = vec3Of(e)) contacts[e.index].n_W = *v;
                } else if (is(e, q::impulse) || is(e, q::normal_impulse)) {
                    if (const double* d = scalarOf(e)) contacts[e.index].J = *d;
                } else if (is(e, q::friction_impulse) || is(e, q::tangent_impulse)) {
                    if (const Vec3* v = vec3Of(e)) contacts[e.index].friction_W = *v;
                }
                break;
            case Stage::Probes:
                if (e.index < 0 || e.index >= probeCount) break;
                if (is(e, q::probe_position)) {
                    if (const Vec3* v = vec3Of(e)) {
                        probes[e.index].p_W = *v;
                        probeSeen[e.index] |= 1;
                    }
                } else if (is(e, q::point_velocity)) {
                    if (const Vec3* v = vec3Of(e)) {
                        probes[e.index].v_W = *v;
                        probeSeen[e.index] |= 2;
                    }
                }
                probes[e.index].body = e.body;
                probes[e.index].index = e.index;
                probesFromTrace = true;
                break;
            default:
                break;
            }
        }

        // The forces of the step just taken, unless they act again in the next one (then
        // they are drawn once, as upcoming, below).
        for (const PendingForce& pf : pendingForces) {
            if (pf.f_W && pf.p_W) {
                bool again = false;
                for (const ForceDef& f : scene.forces) {
                    again = again || (f.body == pf.body && f.activeIn(snap.nextStep) && f.p_W == *pf.p_W && f.f_W == *pf.f_W);
                }
                if (again) continue;
                snap.forces.push_back(
                    ViewSnapshot::Force{ViewSnapshot::ForceKind::Applied, pf.body, pf.index, *pf.p_W, *pf.f_W});
            }
        }
        snap.forces.insert(snap.forces.end(), gravity.begin(), gravity.end());

        for (int k = 0; k < contactCount; ++k) {
            const PendingContact& pc = contacts[k];
            if (!pc.p_W || !pc.n_W) continue;
            const ContactHeader& h = trace->contacts[k];
            ViewSnapshot::Contact c;
            c.index = k;
            c.bodyA = h.bodyA;
            c.bodyB = h.bodyB;
            c.plane = h.plane;
            c.p_W = *pc.p_W;
            c.n_W = *pc.n_W;
            c.separating = h.separating;
            c.J = h.separating ? 0.0 : pc.J;
            // The impulse on A along the normal: J n (docs/references.md §3).
            c.impulse_W = c.J * c.n_W;
            c.hasFriction = pc.friction_W.has_value();
            c.friction_W = (pc.friction_W && !h.separating) ? *pc.friction_W : Vec3::Zero();
            // What the physics applies to A (impulse.cpp: applyImpulse(J n), then applyImpulse(J_t t)).
            c.total_W = c.impulse_W + c.friction_W;
            snap.contacts.push_back(c);
        }
    }

    // The forces that act in the next step, as the scene defines them (f_i at p_i).
    {
        std::vector<ViewSnapshot::Force> upcoming;
        for (int i = 0; i < static_cast<int>(scene.forces.size()); ++i) {
            const ForceDef& f = scene.forces[static_cast<size_t>(i)];
            if (!f.activeIn(snap.nextStep) || f.body < 0 || f.body >= bodyCount) continue;
            if (!isFinite(f.p_W) || !isFinite(f.f_W)) continue;
            ViewSnapshot::Force force{ViewSnapshot::ForceKind::Applied, f.body, i, f.p_W, f.f_W};
            force.upcoming = true;
            upcoming.push_back(force);
        }
        snap.forces.insert(snap.forces.begin(), upcoming.begin(), upcoming.end());
    }
    // E: the trace's diagnostics after the step, or the world's before the first step.
    const double E = trace != nullptr ? trace->diagnostics.total : world.diagnostics().total;
    snap.energyFinite = std::isfinite(E);
    snap.energy = snap.energyFinite ? E : 0.0;

    if (probesFromTrace) {
        for (int i = 0; i < probeCount; ++i) {
            if (probeSeen[i] == 3) snap.probes.push_back(probes[i]);
        }
    } else {
        // No trace (before the first step, or a step without probes): the world's own
        // reading p = x + R p_B, v_p = v + omega x (p - x).
        for (int i = 0; i < probeCount; ++i) {
            const ProbeReading r = world.probe(i);
            if (isFinite(r.p_W) && isFinite(r.v_W)) {
                snap.probes.push_back(ViewSnapshot::Probe{r.body, i, r.p_W, r.v_W});
            }
        }
    }
    return snap;
}

} // namespace rbw
