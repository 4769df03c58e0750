// What the 3D view draws, as plain data: the bodies' poses, the planes, and the
// arrows of one step (forces, probe velocities, contacts and their impulses), read
// from the world's public state and the step's trace. The view never steps or
// recomputes physics: every vector here is copied from the trace (or, before the
// first step, from World::probe()).
//
// Glossary
//   x_W      centre of mass of a body, world frame                      [m]
//   R_WB     rotation matrix body -> world (columns: body axes in W)    [-]
//   size     edge lengths (a, b, c) along body x, y, z                  [m]
//   f_W      applied force f_i (trace `applied_force`)                  [N]
//   p_W      its application point p_i (trace `application_point`)     [m]
//   fg_W     gravity M g at the centre of mass (trace `gravity_force`)  [N]
//   q_W      a pure torque (couple) q_j on a body (trace `applied_torque`) [N m]
//   v_W      velocity of a probe point (trace `point_velocity`)         [m/s]
//   n_W      contact normal, unit, from B to A (trace `normal`)         [-]
//   J        normal impulse magnitude (trace `impulse`)                  [N s]
//   Jt_W     friction impulse J_t t on A (trace `friction_impulse`)      [N s]
//   P_W      total impulse applied to A: J n + J_t t (the two trace rows
//            side by side; the physics applies exactly these two)      [N s]
//   v, ω, L  each body's state after the step (World::states())     [m/s, rad/s, N m s]
//
// Forces are drawn at the step they act in: before step k the scene's forces active
// in step k (their f_i and p_i as defined, ForceDef::activeIn) are "upcoming"; the
// forces of the step just taken come from its trace and are drawn faded when they do
// not act again.
#pragma once

#include "physics/engine/math_types.h"

#include <optional>
#include <string>
#include <vector>

namespace rbw {

class World;
struct StepTrace;

struct ViewSnapshot {
    struct Body {
        std::string name;
        Vec3 x_W = Vec3::Zero();
        Mat3 R_WB = Mat3::Identity();
        Vec3 size = Vec3::Ones();
        bool fixed = false;
        bool finite = true;   // false after a blow-up: not drawn, not pickable
        Vec3 v_W = Vec3::Zero();       // the state: linear velocity
        Vec3 omega_W = Vec3::Zero();   // angular velocity
        Vec3 L_W = Vec3::Zero();       // angular momentum about the centre of mass
    };
    // A fixed plane { p : n . (p - point) = 0 }, drawn as a large finite quad.
    struct Plane {
        std::string name;
        Vec3 point_W = Vec3::Zero();
        Vec3 n_W = Vec3::UnitY();
    };
    enum class ForceKind { Applied, Gravity };
    // An arrow of a force: drawn from origin_W along f_W (scaled for display).
    struct Force {
        ForceKind kind = ForceKind::Applied;
        int body = -1;
        int index = -1;            // the trace index i of f_i; -1 for gravity
        Vec3 origin_W = Vec3::Zero();   // p_i, or x for gravity
        Vec3 f_W = Vec3::Zero();
        bool upcoming = false;     // acts in the next step (from the scene), else acted in the last
    };
    // A pure torque q_j of the step just taken (a couple: it has no point), drawn at x.
    struct Torque {
        int body = -1;
        int index = -1;            // the trace index j of q_j
        Vec3 q_W = Vec3::Zero();
    };
    struct Probe {
        int body = -1;
        int index = -1;            // probe number in the scene
        Vec3 p_W = Vec3::Zero();
        Vec3 v_W = Vec3::Zero();
    };
    // A contact of the step (trace collision stage, index = contact number).
    struct Contact {
        int index = -1;
        int bodyA = -1;
        int bodyB = -1;            // -1 when B is a plane
        int plane = -1;
        Vec3 p_W = Vec3::Zero();
        Vec3 n_W = Vec3::Zero();
        double J = 0.0;            // 0 when separating (no impulse applied)
        Vec3 impulse_W = Vec3::Zero();   // J n, the normal impulse on A
        Vec3 friction_W = Vec3::Zero();  // J_t t (trace friction_impulse; zero without friction)
        Vec3 total_W = Vec3::Zero();     // J n + J_t t, the whole impulse applied to A
        bool hasFriction = false;        // the trace has a friction_impulse row for it
        bool separating = false;
    };
    // The drag spring the app applies while the student pulls a body.
    struct Spring {
        int body = -1;
        Vec3 from_W = Vec3::Zero();   // the picked point, moving with the body
        Vec3 to_W = Vec3::Zero();     // the target under the mouse
    };

    std::vector<Body> bodies;      // in the world's body order
    std::vector<Plane> planes;     // in SceneDef::planes order
    std::vector<Force> forces;     // applied forces, then gravity, in trace order
    std::vector<Torque> torques;   // from the trace, in trace order
    std::vector<Probe> probes;
    std::vector<Contact> contacts;
    std::optional<Spring> spring;

    bool hasTrace = false;
    long step = -1;                // the trace's step k (-1 without a trace)
    double time = 0.0;             // the world's time t
    long nextStep = 0;             // the world's stepIndex(): the step Step takes next
    double h = 0.0;                // the scene's dt
    std::string integrator;        // the scene's integrator, or "per body"
    double energy = 0.0;           // total energy E (the trace's diagnostics, else World::diagnostics())
    bool energyFinite = false;
};

// Builds a snapshot from the world's public state and, if given, the trace of the
// step that led to it (nullptr before the first step: then there are no force or
// contact arrows, and the probes come from World::probe()). Entries with an
// out-of-range body or index, or a non-finite value, are skipped: the view never
// shows NaN.
ViewSnapshot makeViewSnapshot(const World& world, const StepTrace* trace);

} // namespace rbw
