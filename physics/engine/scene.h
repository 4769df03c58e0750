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
//
// Bodies are referred to by index. A scene file refers to them by name; the loader
// resolves the name and also keeps it (bodyName, PairOverride::nameA/nameB), so that
// validate() can say which name it was when it names no body (index -1). A scene
// built in code leaves the names empty.
#pragma once

#include "physics/engine/body.h"
#include "physics/engine/collision/contact.h"
#include "physics/engine/inertia.h"
#include "physics/engine/math_types.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace rbw {

struct ForceDef {
    int body = -1;                   // index into SceneDef::bodies
    Vec3 p_W = Vec3::Zero();         // application point, world frame (fixed in the world)
    Vec3 f_W = Vec3::Zero();         // force, world frame
    long fromStep = 0;
    long toStep = 1;                 // exclusive
    std::string bodyName = {};       // the name a scene file gave, or empty (see above)

    bool activeIn(long k) const { return fromStep <= k && k < toStep; }
};

// A pure couple: a torque q on a body, acting in steps fromStep <= k < toStep. It
// changes L (L <- L + h q) and nothing else; on a cube, whose I is a multiple of the
// identity, it is a constant angular acceleration alpha = I^-1 q (Napier practical 6,
// task 2). A switchable torque can be turned off and on while the scene runs (the
// app's K key); off, the body keeps the angular velocity it has.
struct TorqueDef {
    int body = -1;
    Vec3 q_W = Vec3::Zero();         // torque, world frame
    long fromStep = 0;
    long toStep = 1;                 // exclusive
    bool switchable = false;
    bool enabledAtStart = true;
    std::string bodyName = {};       // the name a scene file gave, or empty

    bool activeIn(long k) const { return fromStep <= k && k < toStep; }
};

// The keyboard push of an interactive lesson: a force of the given magnitude along a
// world axis, applied for one step at a point fixed to the body.
struct PushDef {
    int body = -1;                   // -1 (and no bodyName): the scene has no keyboard pushes
    Vec3 p_B = Vec3::Zero();         // point of application, body frame
    double magnitude = 1.0;          // [N]
    std::string bodyName = {};       // the name a scene file gave, or empty
};

struct ProbeDef {
    int body = -1;
    Vec3 p0_W = Vec3::Zero();        // world position at t = 0; moves with its body
    std::string bodyName = {};       // the name a scene file gave, or empty
};

// How the corners of a box below a plane are resolved: one impulse per corner, in
// turn, or one impulse at their average point (the Napier assessment's method).
enum class PlaneContactMode { PerPoint, Average };

// Which contact model a scene runs (docs/collisions.md):
//   Course    the course's single point per pair and one impulse per contact per step
//             (TUM SAT, Napier corners), resolved once in a fixed order;
//   Manifold  contact manifolds (box-box face clipping, every box corner at a plane)
//             and a sequential-impulse solver with accumulated, clamped impulses, warm
//             starting, a position fix that adds no energy and sleeping (physics/engine/manifold/).
enum class ContactModel { Course, Manifold };

// How the manifold model removes overlap (ManifoldSettings::positionFix):
//   Ngs        non-linear Gauss-Seidel on the positions after the integration (Box2D's
//              SolvePositionConstraints): changes x and r only, never v or L;
//   Baumgarte  a velocity bias beta/h * overlap in the velocity solve (Catto 2005): adds
//              kinetic energy, kept for comparison;
//   None       no position fix at all.
enum class PositionFix { Ngs, Baumgarte, None };
// The manifold model's velocity solver (docs/collisions.md): warm-started sequential
// impulses with the NGS position fix, or Box2D v3's soft step (substeps, soft contacts,
// relax, restitution at the end).
enum class ManifoldSolver { SequentialImpulses, SoftStep };

// Per-pair overrides of the scene-wide restitution and friction. B is a body, or a
// plane when planeB >= 0. A pair overrides at least one of the two, names two
// different bodies (or a body and a plane) and is listed once (validate()).
struct PairOverride {
    int bodyA = -1;
    int bodyB = -1;
    int planeB = -1;
    std::optional<double> restitution = std::nullopt;   // none: the scene's
    std::optional<double> friction = std::nullopt;      // none: the scene's
    // The names a scene file gave, [body, body or plane], or empty (see above).
    std::string nameA = {};
    std::string nameB = {};
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
    std::vector<TorqueDef> torques;
    std::vector<ProbeDef> probes;
    PushDef push;

    // Collisions (docs/references.md §2–§4).
    std::vector<PlaneDef> planes;          // fixed planes: ground and walls
    bool boxCollisions = true;             // box-box contacts between the bodies
    double restitution = 1.0;              // c, scene-wide
    double friction = 0.0;                 // mu, scene-wide
    // Approach speeds below this are resolved plastically (c = 0), so resting contact
    // stops micro-bouncing (Box2D's b2_velocityThreshold). 0: off, the course's model.
    double restitutionThreshold = 0.0;     // [m/s]
    std::vector<PairOverride> pairs;
    bool positionCorrection = false;       // push penetrating bodies apart after the impulses
    PlaneContactMode planeContacts = PlaneContactMode::PerPoint;

    // The contact model (docs/collisions.md). The keys below belong to the manifold
    // model; a course scene leaves them unset (validate() refuses them there).
    ContactModel contactModel = ContactModel::Course;
    // Unset: the default of ManifoldSettings (manifold/settings.h), the one set of the
    // model's defaults (manifoldSettings(scene) reads a scene's choices).
    std::optional<long> solverIterations = std::nullopt;  // velocity iterations
    std::optional<bool> sleep = std::nullopt;             // bodies at rest sleep
    std::optional<PositionFix> positionFix = std::nullopt;
    std::optional<ManifoldSolver> solver = std::nullopt;
    std::optional<long> substeps = std::nullopt;          // soft step: substeps per step

    // Energy-jump blow-up detection (World::step, docs/stability.md): a step stops the
    // run when a body's kinetic energy after the integration exceeds
    //   T_max = factor (T_n + W_n) + floor,
    // W_n the most work the step's loads can do on it. factor 0 switches it off.
    double energyJumpFactor = 10.0;         // [-], 0 or >= 1
    double energyJumpFloor = 1e-9;          // [J], >= 0

    // Body b's integrator and inertia convention: its own, or the scene's.
    const std::string& integratorOf(int b) const
    {
        return bodies[b].integrator.empty() ? integrator : bodies[b].integrator;
    }
    InertiaConvention conventionOf(int b) const
    {
        return bodies[b].inertiaConvention.value_or(inertiaConvention);
    }

    bool hasGravity() const { return g_W != Vec3::Zero(); }
    // One lookup by name, a linear search: the first plane (body) with that name, -1
    // if none. For many lookups build a SceneNames once.
    int planeIndex(const std::string& planeName) const;
    int bodyIndex(const std::string& bodyName) const;
    // c and mu for a pair (B a body, or the plane planeB when planeB >= 0).
    double restitutionFor(int a, int b, int planeB) const;
    double frictionFor(int a, int b, int planeB) const;
};

// The bodies and planes of a scene by name, built once in O(n) and looked up in O(1):
// the loader resolves every name a file gives through it, and validate() checks the
// names with it, so that a scene of 100 000 bodies loads in O(n) rather than O(n^2).
// Like bodyIndex(), a name used twice resolves to its first body (plane).
class SceneNames {
public:
    explicit SceneNames(const SceneDef& scene);
    int body(const std::string& name) const;    // -1 if none
    int plane(const std::string& name) const;   // -1 if none

private:
    std::unordered_map<std::string, int> bodies_;
    std::unordered_map<std::string, int> planes_;
};

// The most steps a scene may ask for: 10^9. A step of one free body takes about
// 0.1 µs, so the longest run of the smallest scene takes minutes, not years; a file
// with "steps": 9e15 is refused instead of running for ever.
inline constexpr long kMaxSceneSteps = 1'000'000'000;

// Text from the input (a name, a key, a word) as a message shows it: at most maxChars
// characters, then "…"; control characters (U+0000-U+001F, U+007F-U+009F), the line
// and paragraph separators and the bidirectional controls written as \u0000; `"` and
// `\` as \" and \\; a byte that is not UTF-8 as \xff. So a 50 MB key or a NUL in
// a name cannot flood or garble a message. The loader uses it for what it echoes too.
std::string messageText(std::string_view text, std::size_t maxChars = 40);

// A reason a scene definition cannot run, with the path of the offending field in
// the scene file's terms, e.g. {"bodies[0].mass", "must be > 0, got -1"}.
struct SceneIssue {
    std::string path;
    std::string reason;
};

// Every rule a definition must obey, whoever built it: finite numbers, dt > 0,
// 0 <= steps <= kMaxSceneSteps, masses and sizes > 0 and every quantity the world
// derives from them once representable (M, 1/M, I0, I0^-1, the initial L and omega,
// probe offsets, the end time; docs/scene-format.md), known integrators and
// conventions (scene and per body), unique non-empty names of bodies and planes, fixed bodies at rest and without
// forces, torques or pushes, forces, torques, pushes and probes on bodies that exist,
// coefficient ranges, energy-jump settings, unit plane normals, pairs that name two
// different bodies (or a body and a plane), override something and are listed once.
// All problems are returned at once, each with the path of the field in the scene
// file's terms ("bodies[0].mass", "pairs[2].bodies") and the reason. The scene
// loader only checks the file's structure (JSON, keys, types) and leaves every rule
// here, so a scene built in code and one read from a file get the same messages.
std::vector<SceneIssue> validate(const SceneDef& scene);

} // namespace rbw
