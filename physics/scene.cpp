#include "physics/scene.h"

#include "physics/integrator_registry.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <set>

namespace rbw {

int SceneDef::bodyIndex(const std::string& bodyName) const
{
    for (int i = 0; i < static_cast<int>(bodies.size()); ++i) {
        if (bodies[i].name == bodyName) {
            return i;
        }
    }
    return -1;
}

int SceneDef::planeIndex(const std::string& planeName) const
{
    for (int i = 0; i < static_cast<int>(planes.size()); ++i) {
        if (planes[i].name == planeName) {
            return i;
        }
    }
    return -1;
}

namespace {

bool samePair(const PairOverride& o, int a, int b, int planeB)
{
    return planeB >= 0 ? (o.planeB == planeB && o.bodyA == a)
                       : (o.planeB < 0 && ((o.bodyA == a && o.bodyB == b) || (o.bodyA == b && o.bodyB == a)));
}

const PairOverride* findOverride(const SceneDef& s, int a, int b, int planeB)
{
    for (const PairOverride& o : s.pairs) {
        if (samePair(o, a, b, planeB)) {
            return &o;
        }
    }
    return nullptr;
}

} // namespace

double SceneDef::restitutionFor(int a, int b, int planeB) const
{
    const PairOverride* o = findOverride(*this, a, b, planeB);
    return o != nullptr && o->restitution ? *o->restitution : restitution;
}

double SceneDef::frictionFor(int a, int b, int planeB) const
{
    const PairOverride* o = findOverride(*this, a, b, planeB);
    return o != nullptr && o->friction ? *o->friction : friction;
}

namespace {

// The shortest text that reads back as the same double: 0.1, not 0.10000000000000001.
std::string num(double x)
{
    char buffer[64];
    const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof buffer, x);
    return std::string(buffer, r.ptr);
}

void requireFinite(std::vector<SceneIssue>& out, const std::string& path, const Vec3& v)
{
    if (!v.allFinite()) {
        out.push_back({path, "must be finite (no NaN or infinity)"});
    }
}

bool knownConvention(InertiaConvention c)
{
    return c == InertiaConvention::Standard || c == InertiaConvention::CourseTemplate;
}

std::string quoted(const std::string& name)
{
    return "\"" + name + "\"";
}

// "a, b" for the message of a name that names no body.
std::string bodyList(const SceneDef& scene)
{
    if (scene.bodies.empty()) {
        return "none";
    }
    std::string list;
    for (const BodyDef& b : scene.bodies) {
        list += (list.empty() ? "" : ", ") + b.name;
    }
    return list;
}

std::string planeList(const SceneDef& scene)
{
    if (scene.planes.empty()) {
        return "none";
    }
    std::string list;
    for (const PlaneDef& p : scene.planes) {
        list += (list.empty() ? "" : ", ") + p.name;
    }
    return list;
}

bool isBody(const SceneDef& scene, int b)
{
    return b >= 0 && b < static_cast<int>(scene.bodies.size());
}

// A reference to a body, by index (a scene built in code) or by the name a file gave,
// which the loader resolved to -1 when no body has it.
std::string missingBody(const SceneDef& scene, int index, const std::string& name)
{
    if (!name.empty()) {
        return "no body named " + quoted(name) + " (bodies: " + bodyList(scene) + ")";
    }
    return "names no body of the scene (index " + std::to_string(index) + "; bodies: " + bodyList(scene) + ")";
}

// A force, torque or push needs a body that exists and can move; a probe any body.
// `onFixed` is the reason given for a fixed body; empty: a fixed body is fine.
void checkBodyRef(std::vector<SceneIssue>& out, const SceneDef& scene, const std::string& path, int index,
                  const std::string& name, const std::string& onFixed)
{
    if (!isBody(scene, index)) {
        out.push_back({path, missingBody(scene, index, name)});
    } else if (!onFixed.empty() && scene.bodies[index].fixed) {
        out.push_back({path, "body " + quoted(scene.bodies[index].name) + " is fixed; " + onFixed});
    }
}

void checkSteps(std::vector<SceneIssue>& out, const std::string& at, long fromStep, long toStep)
{
    if (fromStep < 0) {
        out.push_back({at + ".from_step", "must be >= 0, got " + std::to_string(fromStep)});
    }
    if (toStep <= fromStep) {
        out.push_back({at + ".to_step", "must be greater than from_step"});
    }
}

constexpr double kNoLimit = std::numeric_limits<double>::infinity();

void checkCoefficient(std::vector<SceneIssue>& out, const std::string& path, double x, double hi)
{
    if (!(std::isfinite(x) && x >= 0.0 && x <= hi)) {
        out.push_back({path, hi == 1.0 ? "must be a number from 0 to 1, got " + num(x)
                                       : "must be a finite number >= 0, got " + num(x)});
    }
}

void checkPairs(std::vector<SceneIssue>& out, const SceneDef& scene)
{
    const int nPlanes = static_cast<int>(scene.planes.size());
    // Whether pair i names existing bodies (and plane), so it can be compared.
    std::vector<bool> resolved(scene.pairs.size(), false);
    for (size_t i = 0; i < scene.pairs.size(); ++i) {
        const PairOverride& o = scene.pairs[i];
        const std::string at = "pairs[" + std::to_string(i) + "]";
        bool ok = true;
        if (!isBody(scene, o.bodyA)) {
            ok = false;
            std::string reason = missingBody(scene, o.bodyA, o.nameA);
            if (!o.nameA.empty() && scene.planeIndex(o.nameA) >= 0) {
                reason += "; " + quoted(o.nameA) + " is a plane, and a plane comes second: [\"body\", " +
                          quoted(o.nameA) + "]";
            }
            out.push_back({at + ".bodies[0]", reason});
        }
        if (o.planeB >= 0) {
            if (o.planeB >= nPlanes) {
                ok = false;
                out.push_back({at + ".bodies[1]", "names no plane of the scene (index " + std::to_string(o.planeB) +
                                                      "; planes: " + planeList(scene) + ")"});
            }
        } else if (!isBody(scene, o.bodyB)) {
            ok = false;
            out.push_back({at + ".bodies[1]",
                           o.nameB.empty() ? missingBody(scene, o.bodyB, o.nameB)
                                           : "no body or plane named " + quoted(o.nameB) + " (bodies: " +
                                                 bodyList(scene) + "; planes: " + planeList(scene) + ")"});
        } else if (ok && o.bodyA == o.bodyB) {
            ok = false;
            out.push_back({at + ".bodies", "names " + quoted(scene.bodies[o.bodyA].name) +
                                               " twice; a pair needs two different bodies"});
        }
        if (ok) {
            for (size_t j = 0; j < i; ++j) {
                if (resolved[j] && samePair(scene.pairs[j], o.bodyA, o.bodyB, o.planeB)) {
                    ok = false;
                    out.push_back({at + ".bodies", "this pair is already listed as pairs[" + std::to_string(j) +
                                                       "]; give each pair once"});
                    break;
                }
            }
        }
        resolved[i] = ok;
        if (!o.restitution && !o.friction) {
            out.push_back({at, "give \"restitution\", \"friction\" or both"});
        }
        if (o.restitution) {
            checkCoefficient(out, at + ".restitution", *o.restitution, 1.0);
        }
        if (o.friction) {
            checkCoefficient(out, at + ".friction", *o.friction, kNoLimit);
        }
    }
}

} // namespace

std::vector<SceneIssue> validate(const SceneDef& scene)
{
    std::vector<SceneIssue> out;
    if (!(std::isfinite(scene.dt) && scene.dt > 0.0)) {
        out.push_back({"dt", "must be a finite number > 0, got " + num(scene.dt)});
    }
    if (scene.steps < 0) {
        out.push_back({"steps", "must be >= 0, got " + std::to_string(scene.steps)});
    }
    if (!makeIntegrator(scene.integrator)) {
        out.push_back({"integrator", "unknown integrator " + quoted(scene.integrator) +
                                         "; known: " + integratorNames()});
    }
    if (!knownConvention(scene.inertiaConvention)) {
        out.push_back({"inertia_convention", "must be \"standard\" or \"course-template\""});
    }
    requireFinite(out, "gravity", scene.g_W);
    if (scene.bodies.empty()) {
        out.push_back({"bodies", "must list at least one body"});
    }

    // Bodies and planes share one set of names, so that a pair can name either.
    std::set<std::string> names;
    for (size_t i = 0; i < scene.bodies.size(); ++i) {
        const BodyDef& b = scene.bodies[i];
        const std::string at = "bodies[" + std::to_string(i) + "]";
        if (b.name.empty()) {
            out.push_back({at + ".name", "must not be empty"});
        } else if (!names.insert(b.name).second) {
            out.push_back({at + ".name", "duplicate body name " + quoted(b.name)});
        }
        if (!b.fixed && !(std::isfinite(b.mass) && b.mass > 0.0)) {
            out.push_back({at + ".mass", "must be a finite number > 0, got " + num(b.mass)});
        }
        for (int k = 0; k < 3; ++k) {
            if (!(std::isfinite(b.size[k]) && b.size[k] > 0.0)) {
                out.push_back({at + ".size", "every edge length must be a finite number > 0, got " +
                                                 num(b.size[k]) + " at index " + std::to_string(k)});
                break;
            }
        }
        requireFinite(out, at + ".position", b.x0_W);
        requireFinite(out, at + ".linear_velocity", b.v0_W);
        requireFinite(out, at + ".angular_velocity", b.omega0_W);
        if (b.fixed && b.v0_W.allFinite() && b.v0_W != Vec3::Zero()) {
            out.push_back({at + ".linear_velocity",
                           "a fixed body cannot have a velocity; leave it out or give [0, 0, 0]"});
        }
        if (b.fixed && b.omega0_W.allFinite() && b.omega0_W != Vec3::Zero()) {
            out.push_back({at + ".angular_velocity",
                           "a fixed body cannot have a velocity; leave it out or give [0, 0, 0]"});
        }
        if (!b.q0_WB.coeffs().allFinite() || b.q0_WB.norm() == 0.0) {
            out.push_back({at + ".orientation", "must be a finite, non-zero quaternion"});
        }
        if (!b.integrator.empty() && !makeIntegrator(b.integrator)) {
            out.push_back({at + ".integrator", "unknown integrator " + quoted(b.integrator) +
                                                   "; known: " + integratorNames()});
        }
        if (b.inertiaConvention && !knownConvention(*b.inertiaConvention)) {
            out.push_back({at + ".inertia_convention", "must be \"standard\" or \"course-template\""});
        }
    }

    for (size_t i = 0; i < scene.forces.size(); ++i) {
        const ForceDef& f = scene.forces[i];
        const std::string at = "forces[" + std::to_string(i) + "]";
        checkBodyRef(out, scene, at + ".body", f.body, f.bodyName, "a force on it has no effect");
        requireFinite(out, at + ".point", f.p_W);
        requireFinite(out, at + ".force", f.f_W);
        checkSteps(out, at, f.fromStep, f.toStep);
    }
    for (size_t i = 0; i < scene.torques.size(); ++i) {
        const TorqueDef& t = scene.torques[i];
        const std::string at = "torques[" + std::to_string(i) + "]";
        checkBodyRef(out, scene, at + ".body", t.body, t.bodyName, "a torque on it has no effect");
        requireFinite(out, at + ".torque", t.q_W);
        checkSteps(out, at, t.fromStep, t.toStep);
    }
    // No body and no name: the scene has no keyboard pushes.
    if (scene.push.body >= 0 || !scene.push.bodyName.empty()) {
        checkBodyRef(out, scene, "push.body", scene.push.body, scene.push.bodyName, "pushing it has no effect");
        requireFinite(out, "push.point", scene.push.p_B);
        if (!(std::isfinite(scene.push.magnitude) && scene.push.magnitude > 0.0)) {
            out.push_back({"push.force", "must be a finite number > 0, got " + num(scene.push.magnitude)});
        }
    }
    for (size_t i = 0; i < scene.probes.size(); ++i) {
        const ProbeDef& p = scene.probes[i];
        const std::string at = "probes[" + std::to_string(i) + "]";
        checkBodyRef(out, scene, at + ".body", p.body, p.bodyName, std::string());
        requireFinite(out, at + ".point", p.p0_W);
    }

    for (size_t i = 0; i < scene.planes.size(); ++i) {
        const PlaneDef& p = scene.planes[i];
        const std::string at = "planes[" + std::to_string(i) + "]";
        if (p.name.empty()) {
            out.push_back({at + ".name", "must not be empty"});
        } else if (!names.insert(p.name).second) {
            out.push_back({at + ".name", "duplicate name " + quoted(p.name) + " (bodies and planes share names)"});
        }
        requireFinite(out, at + ".point", p.point_W);
        if (!p.n_W.allFinite()) {
            out.push_back({at + ".normal", "must be finite (no NaN or infinity)"});
        } else if (p.n_W == Vec3::Zero()) {
            out.push_back({at + ".normal", "must not be the zero vector"});
        } else if (std::abs(p.n_W.norm() - 1.0) > 1e-12) {
            // The loader normalises a file's normal; a scene built in code must.
            out.push_back({at + ".normal", "must be a unit vector, got length " + num(p.n_W.norm())});
        }
    }
    checkCoefficient(out, "restitution", scene.restitution, 1.0);
    checkCoefficient(out, "friction", scene.friction, kNoLimit);
    checkCoefficient(out, "restitution_threshold", scene.restitutionThreshold, kNoLimit);
    checkPairs(out, scene);
    if (scene.planeContacts != PlaneContactMode::PerPoint && scene.planeContacts != PlaneContactMode::Average) {
        out.push_back({"plane_contacts", "must be \"per-point\" or \"average\""});
    }
    if (!(std::isfinite(scene.energyJumpFactor) && (scene.energyJumpFactor == 0.0 || scene.energyJumpFactor >= 1.0))) {
        out.push_back({"energy_jump.factor", "must be 0 (off) or a finite number >= 1, got " +
                                                 num(scene.energyJumpFactor)});
    }
    checkCoefficient(out, "energy_jump.floor", scene.energyJumpFloor, kNoLimit);
    return out;
}

} // namespace rbw
