// Probe scenes for "Check my simulator" (issue 23, docs/simulator-protocol.md): small
// scenes, written as the protocol's commands, that make each mistake of a student's
// simulator change some answer. A probe is data (the commands below, in order); the
// workbook sends it to the student's program line by line (protocolLines) and replays
// it itself (probes/replay.h).
//
// Glossary: as physics/engine/body.h. Every vector is in the world frame; a quaternion
// is (w, x, y, z), body -> world; a body's number is its place in the probe's add_body
// commands (0, 1, ...). A probe's "step k" is the state after its k-th `step` (step 0:
// before any step).
//
// The rules every probe keeps (probesAreWellFormed checks them):
//   masses are whole numbers (the TUM template's addRigidBody takes an int);
//   set_orientation and set_velocity come before the first step (the engine's scene
//   has initial values only, and replayWithEngine must be able to run every probe);
//   every step has the same h (one scene, one dt);
//   bodies never come close (collisions are the collision group's business), except in
//   a probe that `collides` (the collision group, collision_probes.cpp).
#pragma once

#include "physics/engine/math_types.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rbw::probes {

enum class CommandKind { AddBody, SetOrientation, SetVelocity, ApplyForce, Step, State };

// One protocol command. Which fields are used depends on the kind:
//   AddBody         a = centre x, b = size (a, b, c), mass
//   SetOrientation  body, q
//   SetVelocity     body, a = v
//   ApplyForce      body, a = world point p, b = force f
//   Step            h
//   State           body
struct Command {
    CommandKind kind = CommandKind::Step;
    int body = 0;
    Vec3 a = Vec3::Zero();
    Vec3 b = Vec3::Zero();
    int mass = 1;
    Quat q = Quat::Identity();
    double h = 0.0;
};

struct Probe {
    std::string name;      // e.g. "motion-01"
    std::string purpose;   // one sentence: what it brings out
    std::vector<Command> commands;
    bool collides = false;   // its bodies touch: replayed with the impulse (collision_replay.h)
};

// The motion group: no contacts, forces at off-centre points, tilted orientations,
// several steps (probes.cpp describes each one).
const std::vector<Probe>& motionProbes();

// The collision group: two boxes whose corner hits a face, off the origin, turned and
// spinning (collision_probes.cpp describes each one).
const std::vector<Probe>& collisionProbes();

// The groups `rbw diagnose --probes` and `rbw probes --probes` choose from.
enum class ProbeGroup { Motion, Collision, All };
std::optional<ProbeGroup> probeGroupNamed(std::string_view name);   // "motion", "collision", "all"
const char* probeGroupName(ProbeGroup group);
// The probes of a group, in the order they run (all: motion, then collision).
std::vector<Probe> probesOf(ProbeGroup group);
// The probe of any group with this name, or nullptr.
const Probe* findProbe(std::string_view name);

// The probe's commands as protocol lines, from "reset" to "quit"; numbers as plain
// decimals that read back to the same double (never an exponent, nan or inf), masses
// as whole numbers.
std::vector<std::string> protocolLines(const Probe& probe);

// One plain decimal that reads back to exactly `value` (shortest such), e.g. "0.1",
// "-2", "0.70710678118654757" is written as "0.7071067811865476".
std::string plainDecimal(double value);

// Empty when every probe keeps the rules above; otherwise one sentence per broken rule.
std::vector<std::string> probesAreWellFormed(const std::vector<Probe>& probes);

// Helpers to write probes as data.
Command addBody(const Vec3& x_W, const Vec3& size, int mass);
Command setOrientation(int body, const Quat& q_WB);
Command setVelocity(int body, const Vec3& v_W);
Command applyForce(int body, const Vec3& p_W, const Vec3& f_W);
Command step(double h);
Command state(int body);
// The unit quaternion of a turn by `degrees` about `axis` (any length > 0).
Quat turn(double degrees, const Vec3& axis);

} // namespace rbw::probes
