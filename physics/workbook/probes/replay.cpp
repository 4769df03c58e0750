#include "physics/workbook/probes/replay.h"

#include "physics/engine/inertia.h"
#include "physics/engine/scene.h"
#include "physics/engine/world.h"
#include "physics/workbook/probes/simulator_state.h"

#include <string>
#include <utility>

namespace rbw::probes {

bool operator==(const ReplayModel& a, const ReplayModel& b)
{
    return a.mistake == b.mistake && a.variant == b.variant && a.second == b.second;
}

namespace {

std::string idOf(Mistake mistake)
{
    for (const MistakeInfo& m : mistakeCatalogue()) {
        if (m.mistake == mistake) return m.id;
    }
    return "unknown-mistake";
}

std::string labelOf(Mistake mistake, int variant)
{
    std::string label = idOf(mistake);
    if (mistake == Mistake::InertiaAxesSwapped) {
        static const char* const axes[3] = {"x-y", "y-z", "x-z"};   // mistakes.cpp's variants
        label += std::string(" (") + axes[variant % 3] + ")";
    }
    return label;
}

} // namespace

std::vector<std::string> modelIds(const ReplayModel& model)
{
    std::vector<std::string> ids;
    for (Mistake m : {model.mistake, model.second}) {
        if (m != Mistake::None) ids.push_back(idOf(m));
    }
    return ids;
}

std::string modelId(const ReplayModel& model)
{
    std::string id;
    for (const std::string& one : modelIds(model)) id += (id.empty() ? "" : " + ") + one;
    return id;
}

std::string modelLabel(const ReplayModel& model)
{
    if (model.mistake == Mistake::None && model.second == Mistake::None) return "the right algorithm";
    std::string label;
    for (Mistake m : {model.mistake, model.second}) {
        if (m != Mistake::None) label += (label.empty() ? "" : " + ") + labelOf(m, model.variant);
    }
    return label;
}

std::vector<AnswerSlot> answerSlots(const Probe& probe)
{
    std::vector<AnswerSlot> slots;
    int steps = 0;
    for (const Command& c : probe.commands) {
        if (c.kind == CommandKind::Step) ++steps;
        if (c.kind == CommandKind::State) slots.push_back({steps, c.body});
    }
    return slots;
}

namespace {

Answer answerOf(const Vec3& x, const Vec3& v, const Vec3& omega, const Quat& r)
{
    return {x.x(), x.y(), x.z(), v.x(), v.y(), v.z(), omega.x(), omega.y(), omega.z(), r.w(), r.x(), r.y(), r.z()};
}

} // namespace

Answers replay(const Probe& probe, const ReplayModel& model)
{
    std::vector<SimBody> bodies;
    Answers answers;
    for (const Command& c : probe.commands) {
        switch (c.kind) {
        case CommandKind::AddBody:
            bodies.push_back(addSimBody(c.a, c.b, c.mass, model));
            break;
        case CommandKind::SetOrientation:
            bodies[c.body].r_WB = c.q.normalized();   // the protocol's r = q/|q|; omega untouched
            bodies[c.body].kept.orientationSet = true;
            break;
        case CommandKind::SetVelocity:
            bodies[c.body].v_W = c.a;
            break;
        case CommandKind::ApplyForce:
            bodies[c.body].forces.push_back({c.a, c.b});
            break;
        case CommandKind::Step:
            for (SimBody& b : bodies) stepSimBody(b, c.h, model);
            break;
        case CommandKind::State: {
            const SimBody& b = bodies[c.body];
            answers.push_back(answerOf(b.x_W, b.v_W, b.omega_W, b.r_WB));
            break;
        }
        }
    }
    return answers;
}

SceneDef probeScene(const Probe& probe, InertiaConvention convention)
{
    SceneDef scene;
    scene.name = probe.name;
    scene.integrator = "explicit-euler";
    scene.inertiaConvention = convention;
    scene.steps = 0;
    long steps = 0;
    for (const Command& c : probe.commands) {
        switch (c.kind) {
        case CommandKind::AddBody: {
            BodyDef b;
            b.name = "body " + std::to_string(scene.bodies.size());   // validate(): a body has a name
            b.x0_W = c.a;
            b.size = c.b;
            b.mass = c.mass;
            scene.bodies.push_back(b);
            break;
        }
        case CommandKind::SetOrientation:
            scene.bodies[c.body].q0_WB = c.q.normalized();
            break;
        case CommandKind::SetVelocity:
            scene.bodies[c.body].v0_W = c.a;
            break;
        case CommandKind::ApplyForce: {
            ForceDef f;
            f.body = c.body;
            f.p_W = c.a;
            f.f_W = c.b;
            f.fromStep = steps;
            f.toStep = steps + 1;
            scene.forces.push_back(f);
            break;
        }
        case CommandKind::Step:
            scene.dt = c.h;
            ++steps;
            break;
        case CommandKind::State:
            break;
        }
    }
    scene.steps = steps;
    return scene;
}

Answers replayWithEngine(const Probe& probe, InertiaConvention convention)
{
    World world(probeScene(probe, convention));
    Answers answers;
    for (const Command& c : probe.commands) {
        if (c.kind == CommandKind::Step) world.step();
        if (c.kind == CommandKind::State) {
            const BodyState& s = world.states()[c.body];
            answers.push_back(answerOf(s.x_W, s.v_W, s.omega_W, s.q_WB));
        }
    }
    return answers;
}

} // namespace rbw::probes
