// A scene definition: everything a scene file says, as plain data. It is the
// creation-parameter side of a world (Jolt's "settings"); a World is built from it
// and never changes it.
//
// Glossary
//   h (dt)    time step                                     [s]
//   g_W       gravity acceleration, world frame               [m/s^2]
//   forces    external forces f at world points p, acting in steps k with
//             fromStep <= k < toStep (steps counted from 0)
//   probes    points fixed to a body, given in world coordinates at t = 0
#pragma once

#include "physics/body.h"
#include "physics/inertia.h"
#include "physics/math_types.h"

#include <string>
#include <vector>

namespace rbw {

struct ForceDef {
    int body = -1;                   // index into SceneDef::bodies
    Vec3 p_W = Vec3::Zero();         // application point, world frame (fixed in the world)
    Vec3 f_W = Vec3::Zero();         // force, world frame
    long fromStep = 0;
    long toStep = 1;                 // exclusive

    bool activeIn(long k) const { return fromStep <= k && k < toStep; }
};

struct ProbeDef {
    int body = -1;
    Vec3 p0_W = Vec3::Zero();        // world position at t = 0; moves with its body
};

struct SceneDef {
    std::string name;
    std::string description;
    double dt = 0.01;
    long steps = 1;
    std::string integrator = "explicit-euler";
    InertiaConvention inertiaConvention = InertiaConvention::Standard;
    Vec3 g_W = Vec3::Zero();
    std::vector<BodyDef> bodies;
    std::vector<ForceDef> forces;
    std::vector<ProbeDef> probes;

    bool hasGravity() const { return g_W != Vec3::Zero(); }
    int bodyIndex(const std::string& bodyName) const;   // -1 if none
};

// A reason a scene definition cannot run, with the path of the offending field in
// the scene file's terms, e.g. {"bodies[0].mass", "must be > 0, got -1"}.
struct SceneIssue {
    std::string path;
    std::string reason;
};

// Physical validity of a definition: masses and sizes > 0, finite numbers, dt > 0,
// a known integrator, force and probe bodies that exist, unique body names.
// Front ends check the file's structure; this checks what the physics requires.
std::vector<SceneIssue> validate(const SceneDef& scene);

} // namespace rbw
