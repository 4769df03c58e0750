#include "physics/scene.h"

#include "physics/integrator_registry.h"

#include <cmath>
#include <limits>
#include <set>
#include <sstream>

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

const PairOverride* findOverride(const SceneDef& s, int a, int b, int planeB)
{
    for (const PairOverride& o : s.pairs) {
        const bool sameBodies = planeB >= 0 ? (o.planeB == planeB && o.bodyA == a)
                                            : (o.planeB < 0 && ((o.bodyA == a && o.bodyB == b) ||
                                                                (o.bodyA == b && o.bodyB == a)));
        if (sameBodies) {
            return &o;
        }
    }
    return nullptr;
}

} // namespace

double SceneDef::restitutionFor(int a, int b, int planeB) const
{
    const PairOverride* o = findOverride(*this, a, b, planeB);
    return o != nullptr && o->restitution >= 0.0 ? o->restitution : restitution;
}

double SceneDef::frictionFor(int a, int b, int planeB) const
{
    const PairOverride* o = findOverride(*this, a, b, planeB);
    return o != nullptr && o->friction >= 0.0 ? o->friction : friction;
}

namespace {

std::string num(double x)
{
    std::ostringstream os;
    os.precision(17);
    os << x;
    return os.str();
}

void requireFinite(std::vector<SceneIssue>& out, const std::string& path, const Vec3& v)
{
    if (!v.allFinite()) {
        out.push_back({path, "must be finite (no NaN or infinity)"});
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
        out.push_back({"integrator", "unknown integrator \"" + scene.integrator +
                                         "\"; known: " + integratorNames()});
    }
    requireFinite(out, "gravity", scene.g_W);
    if (scene.bodies.empty()) {
        out.push_back({"bodies", "must list at least one body"});
    }

    std::set<std::string> names;
    for (size_t i = 0; i < scene.bodies.size(); ++i) {
        const BodyDef& b = scene.bodies[i];
        const std::string at = "bodies[" + std::to_string(i) + "]";
        if (b.name.empty()) {
            out.push_back({at + ".name", "must not be empty"});
        } else if (!names.insert(b.name).second) {
            out.push_back({at + ".name", "duplicate body name \"" + b.name + "\""});
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
        if (!b.q0_WB.coeffs().allFinite() || b.q0_WB.norm() == 0.0) {
            out.push_back({at + ".orientation", "must be a finite, non-zero quaternion"});
        }
        if (!b.integrator.empty() && !makeIntegrator(b.integrator)) {
            out.push_back({at + ".integrator", "unknown integrator \"" + b.integrator +
                                                   "\"; known: " + integratorNames()});
        }
    }

    const int nBodies = static_cast<int>(scene.bodies.size());
    for (size_t i = 0; i < scene.forces.size(); ++i) {
        const ForceDef& f = scene.forces[i];
        const std::string at = "forces[" + std::to_string(i) + "]";
        if (f.body < 0 || f.body >= nBodies) {
            out.push_back({at + ".body", "names no body of the scene"});
        } else if (scene.bodies[f.body].fixed) {
            out.push_back({at + ".body", "body \"" + scene.bodies[f.body].name +
                                             "\" is fixed; a force on it has no effect"});
        }
        requireFinite(out, at + ".point", f.p_W);
        requireFinite(out, at + ".force", f.f_W);
        if (f.fromStep < 0) {
            out.push_back({at + ".from_step", "must be >= 0"});
        }
        if (f.toStep <= f.fromStep) {
            out.push_back({at + ".to_step", "must be greater than from_step"});
        }
    }
    for (size_t i = 0; i < scene.torques.size(); ++i) {
        const TorqueDef& t = scene.torques[i];
        const std::string at = "torques[" + std::to_string(i) + "]";
        if (t.body < 0 || t.body >= nBodies) {
            out.push_back({at + ".body", "names no body of the scene"});
        } else if (scene.bodies[t.body].fixed) {
            out.push_back({at + ".body", "body \"" + scene.bodies[t.body].name +
                                             "\" is fixed; a torque on it has no effect"});
        }
        requireFinite(out, at + ".torque", t.q_W);
        if (t.fromStep < 0) {
            out.push_back({at + ".from_step", "must be >= 0"});
        }
        if (t.toStep <= t.fromStep) {
            out.push_back({at + ".to_step", "must be greater than from_step"});
        }
    }
    if (scene.push.body >= nBodies) {
        out.push_back({"push.body", "names no body of the scene"});
    } else if (scene.push.body >= 0) {
        if (scene.bodies[scene.push.body].fixed) {
            out.push_back({"push.body", "body \"" + scene.bodies[scene.push.body].name +
                                            "\" is fixed; pushing it has no effect"});
        }
        requireFinite(out, "push.point", scene.push.p_B);
        if (!(std::isfinite(scene.push.magnitude) && scene.push.magnitude > 0.0)) {
            out.push_back({"push.force", "must be a finite number > 0, got " + num(scene.push.magnitude)});
        }
    }
    auto checkCoefficient = [&](const std::string& path, double x, double hi) {
        if (!(std::isfinite(x) && x >= 0.0 && x <= hi)) {
            out.push_back({path, hi == 1.0 ? "must be a number from 0 to 1, got " + num(x)
                                           : "must be a finite number >= 0, got " + num(x)});
        }
    };
    checkCoefficient("restitution", scene.restitution, 1.0);
    checkCoefficient("friction", scene.friction, std::numeric_limits<double>::infinity());
    checkCoefficient("restitution_threshold", scene.restitutionThreshold, std::numeric_limits<double>::infinity());
    if (!(std::isfinite(scene.energyJumpFactor) && (scene.energyJumpFactor == 0.0 || scene.energyJumpFactor >= 1.0))) {
        out.push_back({"energy_jump.factor", "must be 0 (off) or a finite number >= 1, got " +
                                                 num(scene.energyJumpFactor)});
    }
    checkCoefficient("energy_jump.floor", scene.energyJumpFloor, std::numeric_limits<double>::infinity());
    for (size_t i = 0; i < scene.planes.size(); ++i) {
        const PlaneDef& p = scene.planes[i];
        const std::string at = "planes[" + std::to_string(i) + "]";
        if (p.name.empty()) {
            out.push_back({at + ".name", "must not be empty"});
        } else if (!names.insert(p.name).second) {
            out.push_back({at + ".name", "duplicate name \"" + p.name + "\" (bodies and planes share names)"});
        }
        requireFinite(out, at + ".point", p.point_W);
        if (!p.n_W.allFinite() || std::abs(p.n_W.norm() - 1.0) > 1e-12) {
            out.push_back({at + ".normal", "must be a finite unit vector"});
        }
    }
    for (size_t i = 0; i < scene.pairs.size(); ++i) {
        const PairOverride& o = scene.pairs[i];
        const std::string at = "pairs[" + std::to_string(i) + "]";
        if (o.bodyA < 0 || o.bodyA >= nBodies || (o.planeB < 0 && (o.bodyB < 0 || o.bodyB >= nBodies))) {
            out.push_back({at + ".bodies", "must name two bodies, or a body and a plane"});
        }
        if (o.restitution != -1.0) {
            checkCoefficient(at + ".restitution", o.restitution, 1.0);
        }
        if (o.friction != -1.0) {
            checkCoefficient(at + ".friction", o.friction, std::numeric_limits<double>::infinity());
        }
    }
    for (size_t i = 0; i < scene.probes.size(); ++i) {
        const ProbeDef& p = scene.probes[i];
        const std::string at = "probes[" + std::to_string(i) + "]";
        if (p.body < 0 || p.body >= nBodies) {
            out.push_back({at + ".body", "names no body of the scene"});
        }
        requireFinite(out, at + ".point", p.p0_W);
    }
    return out;
}

} // namespace rbw
