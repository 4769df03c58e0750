// validate(): every rule a scene definition must obey (scene.h), whoever built it,
// with the path of the field in the scene file's terms and the reason.
#include "physics/engine/scene.h"
#include "physics/engine/manifold/settings.h"
#include "physics/engine/integrator_registry.h"
#include "physics/engine/scene_words.h"
#include "physics/engine/validation_detail.h"
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <tuple>

namespace rbw {

namespace {

using namespace validation;

void requireFinite(std::vector<SceneIssue>& out, const std::string& path, const Vec3& v)
{
    if (!v.allFinite()) {
        out.push_back({path, "must be finite (no NaN or infinity)"});
    }
}

bool knownConvention(InertiaConvention c)
{
    return isSceneWordValue(c);
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
        return "no body named " + quoted(name) + " (bodies: " + nameList(scene.bodies) + ")";
    }
    return "names no body of the scene (index " + std::to_string(index) + "; bodies: " + nameList(scene.bodies) +
           ")";
}

// A force, torque or push needs a body that exists and can move; a probe any body.
// `onFixed` is the reason given for a fixed body; empty: a fixed body is fine. A scene
// without bodies gets one message for that ("bodies"), not one per reference.
void checkBodyRef(std::vector<SceneIssue>& out, const SceneDef& scene, const std::string& path, int index,
                  const std::string& name, const std::string& onFixed)
{
    if (scene.bodies.empty()) {
        return;
    }
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

// The orientation initialState() normalises: q / |q| needs a finite |q|^2 > 0.
void checkOrientation(std::vector<SceneIssue>& out, const std::string& at, const Quat& q)
{
    const double n2 = q.coeffs().squaredNorm();
    if (!q.coeffs().allFinite() || q.coeffs().isZero(0.0)) {
        out.push_back({at + ".orientation", "must be a finite, non-zero quaternion"});
    } else if (!std::isfinite(n2)) {
        out.push_back({at + ".orientation", "the quaternion's length overflows (|q|^2 exceeds the largest double), "
                                            "so it cannot be normalised; give it a length near 1"});
    } else if (n2 == 0.0) {
        out.push_back({at + ".orientation", "the quaternion's length underflows (|q|^2 rounds to 0), so it cannot "
                                            "be normalised; give it a length near 1"});
    }
}

void checkPairs(std::vector<SceneIssue>& out, const SceneDef& scene, const SceneNames& names)
{
    const int nPlanes = static_cast<int>(scene.planes.size());
    // The first entry of each resolved pair: (lower body, higher body, -1) for two
    // bodies in either order, (body, -1, plane) for a body and a plane.
    std::map<std::tuple<int, int, int>, std::size_t> listed;
    for (size_t i = 0; i < scene.pairs.size(); ++i) {
        const PairOverride& o = scene.pairs[i];
        const std::string at = "pairs[" + std::to_string(i) + "]";
        bool ok = !scene.bodies.empty();   // no bodies: one message, at "bodies"
        if (ok && !isBody(scene, o.bodyA)) {
            ok = false;
            std::string reason = missingBody(scene, o.bodyA, o.nameA);
            if (!o.nameA.empty() && names.plane(o.nameA) >= 0) {
                reason += "; " + quoted(o.nameA) + " is a plane, and a plane comes second: [\"body\", " +
                          quoted(o.nameA) + "]";
            }
            out.push_back({at + ".bodies[0]", reason});
        }
        if (scene.bodies.empty()) {
            // nothing to say about the second name either
        } else if (o.planeB >= 0) {
            if (o.planeB >= nPlanes) {
                ok = false;
                out.push_back({at + ".bodies[1]", "names no plane of the scene (index " + std::to_string(o.planeB) +
                                                      "; planes: " + nameList(scene.planes) + ")"});
            }
        } else if (!isBody(scene, o.bodyB)) {
            ok = false;
            out.push_back({at + ".bodies[1]",
                           o.nameB.empty() ? missingBody(scene, o.bodyB, o.nameB)
                                           : "no body or plane named " + quoted(o.nameB) + " (bodies: " +
                                                 nameList(scene.bodies) + "; planes: " + nameList(scene.planes) + ")"});
        } else if (ok && o.bodyA == o.bodyB) {
            ok = false;
            out.push_back({at + ".bodies", "names " + quoted(scene.bodies[o.bodyA].name) +
                                               " twice; a pair needs two different bodies"});
        }
        if (ok) {
            const auto key = o.planeB >= 0 ? std::make_tuple(o.bodyA, -1, o.planeB)
                                           : std::make_tuple(std::min(o.bodyA, o.bodyB), std::max(o.bodyA, o.bodyB), -1);
            const auto [first, isNew] = listed.emplace(key, i);
            if (!isNew) {
                out.push_back({at + ".bodies", "this pair is already listed as pairs[" +
                                                   std::to_string(first->second) + "]; give each pair once"});
            }
        }
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
    const bool dtOk = std::isfinite(scene.dt) && scene.dt > 0.0;
    if (!dtOk) {
        out.push_back({"dt", "must be a finite number > 0, got " + num(scene.dt)});
    }
    if (scene.steps < 0) {
        out.push_back({"steps", "must be >= 0, got " + std::to_string(scene.steps)});
    } else if (scene.steps > kMaxSceneSteps) {
        out.push_back({"steps", "must be at most " + std::to_string(kMaxSceneSteps) + " (10^9), got " +
                                    std::to_string(scene.steps)});
    } else if (dtOk && !std::isfinite(scene.dt * static_cast<double>(scene.steps))) {
        // t = k h after step k: the end time steps * h must be a finite double
        // (half the largest, for the rounding of t += h over the steps).
        out.push_back({"dt", num(scene.dt) + " s makes the end time steps \u00b7 h overflow; for " +
                                 std::to_string(scene.steps) + " steps h must be at most " +
                                 limit(kMaxDouble / 2.0 / static_cast<double>(scene.steps), false) + " s"});
    }
    if (!makeIntegrator(scene.integrator)) {
        out.push_back({"integrator", "unknown integrator " + quoted(scene.integrator) +
                                         "; known: " + integratorNames()});
    }
    if (!knownConvention(scene.inertiaConvention)) {
        out.push_back({"inertia_convention", "must be " + sceneWordChoices<InertiaConvention>()});
    }
    requireFinite(out, "gravity", scene.g_W);
    if (scene.bodies.empty()) {
        out.push_back({"bodies", "must list at least one body; a scene without a body has nothing to simulate"});
    }

    // Bodies and planes share one set of names, so that a pair can name either. A name
    // is a duplicate where SceneNames (which keeps the first) resolves it elsewhere.
    const SceneNames names(scene);
    for (size_t i = 0; i < scene.bodies.size(); ++i) {
        const BodyDef& b = scene.bodies[i];
        const std::string at = "bodies[" + std::to_string(i) + "]";
        if (b.name.empty()) {
            out.push_back({at + ".name", "must not be empty"});
        } else if (names.body(b.name) != static_cast<int>(i)) {
            out.push_back({at + ".name", "duplicate body name " + quoted(b.name)});
        }
        const bool massOk = b.fixed || (std::isfinite(b.mass) && b.mass > 0.0);
        if (!massOk) {
            out.push_back({at + ".mass", "must be a finite number > 0, got " + num(b.mass)});
        }
        bool sizeOk = true;
        for (int k = 0; k < 3; ++k) {
            if (!(std::isfinite(b.size[k]) && b.size[k] > 0.0)) {
                out.push_back({at + ".size", "every edge length must be a finite number > 0, got " +
                                                 num(b.size[k]) + " at index " + std::to_string(k)});
                sizeOk = false;
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
        const std::size_t before = out.size();
        checkOrientation(out, at, b.q0_WB);
        const bool orientationOk = out.size() == before;
        if (!b.integrator.empty() && !makeIntegrator(b.integrator)) {
            out.push_back({at + ".integrator", "unknown integrator " + quoted(b.integrator) +
                                                   "; known: " + integratorNames()});
        }
        const bool conventionOk = !b.inertiaConvention || knownConvention(*b.inertiaConvention);
        if (!conventionOk) {
            out.push_back({at + ".inertia_convention", "must be " + sceneWordChoices<InertiaConvention>()});
        }
        if (!b.fixed && massOk && sizeOk && orientationOk && conventionOk && b.omega0_W.allFinite() &&
            knownConvention(scene.inertiaConvention)) {
            checkDerived(out, at, b, scene.conventionOf(static_cast<int>(i)));
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
        if (isBody(scene, p.body) && p.p0_W.allFinite()) {
            const BodyDef& b = scene.bodies[p.body];
            const double n2 = b.q0_WB.coeffs().squaredNorm();
            if (b.x0_W.allFinite() && b.q0_WB.coeffs().allFinite() && std::isfinite(n2) && n2 > 0.0) {
                // The world keeps p_B = R0^T (p0 - x0), with R0 as initialState() builds it.
                const Mat3 R0 = b.q0_WB.normalized().toRotationMatrix();
                const Vec3 offset_B = R0.transpose() * (p.p0_W - b.x0_W);
                if (!offset_B.allFinite()) {
                    out.push_back({at + ".point", "its offset p0 \u2212 x0 from the centre of body " + quoted(b.name) +
                                                      " overflows (p0 = " + vec(p.p0_W) + ", x0 = " + vec(b.x0_W) +
                                                      "); give a point nearer the body"});
                }
            }
        }
    }

    for (size_t i = 0; i < scene.planes.size(); ++i) {
        const PlaneDef& p = scene.planes[i];
        const std::string at = "planes[" + std::to_string(i) + "]";
        if (p.name.empty()) {
            out.push_back({at + ".name", "must not be empty"});
        } else if (names.body(p.name) >= 0 || names.plane(p.name) != static_cast<int>(i)) {
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
    checkPairs(out, scene, names);
    if (!isSceneWordValue(scene.planeContacts)) {
        out.push_back({"plane_contacts", "must be " + sceneWordChoices<PlaneContactMode>()});
    }
    if (!(std::isfinite(scene.energyJumpFactor) && (scene.energyJumpFactor == 0.0 || scene.energyJumpFactor >= 1.0))) {
        out.push_back({"energy_jump.factor", "must be 0 (off) or a finite number >= 1, got " +
                                                 num(scene.energyJumpFactor)});
    }
    checkCoefficient(out, "energy_jump.floor", scene.energyJumpFloor, kNoLimit);
    checkContactModel(out, scene);
    return out;
}

} // namespace rbw
