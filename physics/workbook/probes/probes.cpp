#include "physics/workbook/probes/probes.h"

#include <charconv>
#include <cmath>
#include <system_error>

namespace rbw::probes {

Command addBody(const Vec3& x_W, const Vec3& size, int mass)
{
    Command c;
    c.kind = CommandKind::AddBody;
    c.a = x_W;
    c.b = size;
    c.mass = mass;
    return c;
}

Command setOrientation(int body, const Quat& q_WB)
{
    Command c;
    c.kind = CommandKind::SetOrientation;
    c.body = body;
    c.q = q_WB;
    return c;
}

Command setVelocity(int body, const Vec3& v_W)
{
    Command c;
    c.kind = CommandKind::SetVelocity;
    c.body = body;
    c.a = v_W;
    return c;
}

Command applyForce(int body, const Vec3& p_W, const Vec3& f_W)
{
    Command c;
    c.kind = CommandKind::ApplyForce;
    c.body = body;
    c.a = p_W;
    c.b = f_W;
    return c;
}

Command step(double h)
{
    Command c;
    c.kind = CommandKind::Step;
    c.h = h;
    return c;
}

Command state(int body)
{
    Command c;
    c.kind = CommandKind::State;
    c.body = body;
    return c;
}

// r = (cos th/2, n sin th/2), n = axis/|axis|
Quat turn(double degrees, const Vec3& axis)
{
    const double half = 0.5 * degrees * std::acos(-1.0) / 180.0;
    const Vec3 n = axis.normalized();
    return Quat(std::cos(half), std::sin(half) * n.x(), std::sin(half) * n.y(), std::sin(half) * n.z());
}

namespace {

// The probes of the motion group. Each one is a whole scene; the comment says which
// mistakes it is there for (the distinguishability test, tests/physics/workbook/probes/,
// proves that together they separate every motion model).
std::vector<Probe> buildMotionProbes()
{
    std::vector<Probe> all;

    // 1. One box off the origin, turned 50 deg about the tilted axis (1, 2, 2): the world
    // inverse inertia is neither diagonal nor symmetric under R <-> R^T (transposed-inertia,
    // body-inverse-inertia), the lever arm from the origin is not the one from the centre
    // (lever-arm-from-origin). Two pushes at off-centre points, then two free steps in which
    // the box turns with the omega it has (the quaternion mistakes, omega-before-orientation).
    all.push_back({"motion-01", "one box off the origin, turned about a tilted axis, pushed off-centre twice, then free",
                   {addBody(Vec3(1.5, 0.5, -1.0), Vec3(1.0, 0.6, 0.4), 2),
                    setOrientation(0, turn(50.0, Vec3(1, 2, 2))),
                    applyForce(0, Vec3(1.8, 0.9, -0.8), Vec3(0.5, -1.0, 2.0)), step(0.1), state(0),
                    applyForce(0, Vec3(1.2, 0.2, -1.1), Vec3(-1.0, 0.5, 0.5)), step(0.1), state(0),
                    step(0.1), state(0),
                    step(0.1), state(0)}});

    // 2. A box whose orientation is never set (r = 1), given a velocity and asked before
    // any step (set_velocity itself), pushed once at an off-centre point with h = 0.25
    // (missing-time-step: h != 1; velocity-before-position: x moves with the new v).
    all.push_back({"motion-02", "a box never turned, with a velocity, pushed once off-centre, then free",
                   {addBody(Vec3(-1.0, 0.5, 2.0), Vec3(0.8, 0.5, 1.2), 3),
                    setVelocity(0, Vec3(0.5, -0.2, 0.3)), state(0),
                    applyForce(0, Vec3(-0.7, 0.8, 2.4), Vec3(1.0, 2.0, -1.0)), step(0.25), state(0),
                    step(0.25), state(0),
                    step(0.25), state(0)}});

    // 3. Two boxes far apart (8 m; neither moves more than a few cm), each turned about
    // its own tilted axis, one with a velocity; forces on different bodies in different
    // steps, and a step where every force has stopped. Bodies are updated separately
    // and the right body gets each force.
    all.push_back({"motion-03", "two boxes far apart, turned about tilted axes, forces on each in different steps",
                   {addBody(Vec3(4.0, 0.0, 0.0), Vec3(0.5, 1.0, 1.5), 1),
                    addBody(Vec3(-4.0, 2.0, 1.0), Vec3(2.0, 0.4, 0.8), 4),
                    setOrientation(0, turn(30.0, Vec3(1, -1, 1))),
                    setOrientation(1, turn(120.0, Vec3(-2, 1, 3))),
                    setVelocity(1, Vec3(0.3, 0.0, -0.4)),
                    applyForce(0, Vec3(4.2, 0.4, 0.6), Vec3(0.0, -2.0, 1.0)), step(0.1), state(0), state(1),
                    applyForce(1, Vec3(-3.2, 2.1, 1.3), Vec3(1.0, 3.0, -2.0)),
                    applyForce(0, Vec3(3.9, -0.3, 0.2), Vec3(1.0, 1.0, 1.0)), step(0.1), state(0), state(1),
                    step(0.1), state(0), state(1)}});

    // 4. A fast spin: one strong push at a corner-like point of a long, thin box turned
    // 70 deg about (-1, 1, 3), then four free steps. omega h / 2 is about 0.2, so a
    // missing 1/2 or a missing normalisation changes r (and with it R, I^-1 and omega)
    // far beyond float round-off; the box's three different moments bring out which two
    // axes were swapped.
    all.push_back({"motion-04", "a long box turned about a tilted axis, one strong off-centre push, then spinning freely",
                   {addBody(Vec3(0.5, -2.0, 1.5), Vec3(0.3, 1.0, 2.0), 5),
                    setOrientation(0, turn(70.0, Vec3(-1, 1, 3))),
                    applyForce(0, Vec3(0.65, -1.5, 2.3), Vec3(30.0, -8.0, 15.0)), step(0.1), state(0),
                    step(0.1), state(0),
                    step(0.1), state(0),
                    step(0.1), state(0),
                    step(0.1), state(0)}});
    return all;
}

void appendVec(std::string& line, const Vec3& v)
{
    for (int i = 0; i < 3; ++i) line += ' ' + plainDecimal(v[i]);
}

} // namespace

const std::vector<Probe>& motionProbes()
{
    static const std::vector<Probe> all = buildMotionProbes();
    return all;
}

std::optional<ProbeGroup> probeGroupNamed(std::string_view name)
{
    if (name == "motion") return ProbeGroup::Motion;
    if (name == "collision") return ProbeGroup::Collision;
    if (name == "all") return ProbeGroup::All;
    return std::nullopt;
}

const char* probeGroupName(ProbeGroup group)
{
    switch (group) {
    case ProbeGroup::Motion: return "motion";
    case ProbeGroup::Collision: return "collision";
    case ProbeGroup::All: return "all";
    }
    return "all";
}

std::vector<Probe> probesOf(ProbeGroup group)
{
    std::vector<Probe> out;
    if (group != ProbeGroup::Collision) out = motionProbes();
    if (group != ProbeGroup::Motion) out.insert(out.end(), collisionProbes().begin(), collisionProbes().end());
    return out;
}

const Probe* findProbe(std::string_view name)
{
    for (const std::vector<Probe>* group : {&motionProbes(), &collisionProbes()}) {
        for (const Probe& p : *group) {
            if (p.name == name) return &p;
        }
    }
    return nullptr;
}

std::string plainDecimal(double value)
{
    if (value == 0.0) return "0";   // also -0: the protocol's numbers have no "-0"
    char buffer[400];
    const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed);
    if (r.ec != std::errc()) return "0";   // unreachable for the finite values of a probe
    return std::string(buffer, r.ptr);
}

std::vector<std::string> protocolLines(const Probe& probe)
{
    std::vector<std::string> lines{"reset"};
    for (const Command& c : probe.commands) {
        std::string line;
        switch (c.kind) {
        case CommandKind::AddBody:
            line = "add_body";
            appendVec(line, c.a);
            appendVec(line, c.b);
            line += ' ' + std::to_string(c.mass);
            break;
        case CommandKind::SetOrientation:
            line = "set_orientation " + std::to_string(c.body);
            for (double d : {c.q.w(), c.q.x(), c.q.y(), c.q.z()}) line += ' ' + plainDecimal(d);
            break;
        case CommandKind::SetVelocity:
            line = "set_velocity " + std::to_string(c.body);
            appendVec(line, c.a);
            break;
        case CommandKind::ApplyForce:
            line = "apply_force " + std::to_string(c.body);
            appendVec(line, c.a);
            appendVec(line, c.b);
            break;
        case CommandKind::Step:
            line = "step " + plainDecimal(c.h);
            break;
        case CommandKind::State:
            line = "state " + std::to_string(c.body);
            break;
        }
        lines.push_back(line);
    }
    lines.push_back("quit");
    return lines;
}

std::vector<std::string> probesAreWellFormed(const std::vector<Probe>& probes)
{
    std::vector<std::string> issues;
    for (const Probe& p : probes) {
        auto issue = [&](const std::string& what) { issues.push_back(p.name + ": " + what); };
        int bodies = 0;
        int steps = 0;
        int states = 0;
        double h = 0.0;
        for (const Command& c : p.commands) {
            const bool needsBody = c.kind == CommandKind::SetOrientation || c.kind == CommandKind::SetVelocity ||
                                   c.kind == CommandKind::ApplyForce || c.kind == CommandKind::State;
            if (needsBody && (c.body < 0 || c.body >= bodies)) issue("a command names body " + std::to_string(c.body));
            switch (c.kind) {
            case CommandKind::AddBody:
                if (c.mass <= 0) issue("a mass is not a whole number > 0");
                if (!(c.b.minCoeff() > 0.0)) issue("a size is not > 0");
                if (steps > 0) issue("add_body after the first step");
                ++bodies;
                break;
            case CommandKind::SetOrientation:
                if (!(c.q.norm() > 0.0)) issue("a zero quaternion");
                if (steps > 0) issue("set_orientation after the first step");
                break;
            case CommandKind::SetVelocity:
                if (steps > 0) issue("set_velocity after the first step");
                break;
            case CommandKind::ApplyForce:
                break;
            case CommandKind::Step:
                if (!(c.h > 0.0)) issue("a step with h <= 0");
                if (steps > 0 && c.h != h) issue("steps of different h");
                h = c.h;
                ++steps;
                break;
            case CommandKind::State:
                ++states;
                break;
            }
        }
        if (steps == 0) issue("no step");
        if (states == 0) issue("no state question");
    }
    return issues;
}

} // namespace rbw::probes
