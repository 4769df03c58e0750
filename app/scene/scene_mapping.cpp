#include "app/scene/scene_mapping.h"

#include "app/scene/scene_fields.h"

#include <QFileInfo>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace rbw::scenefile {
namespace {

// { "axis": [x,y,z], "degrees": d } | { "axis": [...], "radians": a } | { "quaternion": [w,x,y,z] }
Quat toOrientation(const QJsonValue& v, const QString& path)
{
    const QJsonObject o = toObject(v, path);
    checkKeys(o, path, {"axis", "degrees", "radians", "quaternion"});
    if (o.contains("quaternion")) {
        if (o.contains("axis") || o.contains("degrees") || o.contains("radians")) {
            throw FieldError{path, QStringLiteral("give either \"quaternion\" or \"axis\" with an angle, not both")};
        }
        const QString qp = join(path, "quaternion");
        const QJsonArray a = toArray(o.value("quaternion"), qp);
        if (a.size() != 4) {
            throw FieldError{qp, QStringLiteral("must be [w, x, y, z], got %1 elements").arg(a.size())};
        }
        // Scene files write quaternions scalar first: [w, x, y, z] (physics/engine/math_types.h).
        const Quat q(toNumber(a[0], qp + "[0]"), toNumber(a[1], qp + "[1]"),
                     toNumber(a[2], qp + "[2]"), toNumber(a[3], qp + "[3]"));
        if (q.coeffs().isZero(0.0)) {
            throw FieldError{qp, QStringLiteral("must not be the zero quaternion")};
        }
        requireNormalisable(q.coeffs().squaredNorm(), qp);
        return isUnitToRounding(q.coeffs().squaredNorm()) ? q : q.normalized();
    }
    const QString ap = join(path, "axis");
    const Vec3 axis = toVec3(require(o, path, "axis"), ap);
    if (axis == Vec3::Zero()) {
        throw FieldError{ap, QStringLiteral("rotation axis must not be zero")};
    }
    requireNormalisable(axis.squaredNorm(), ap);
    if (o.contains("degrees") == o.contains("radians")) {
        throw FieldError{path, QStringLiteral("give the angle as exactly one of \"degrees\" or \"radians\"")};
    }
    const double angle = o.contains("degrees")
                             ? toNumber(o.value("degrees"), join(path, "degrees")) * std::numbers::pi / 180.0
                             : toNumber(o.value("radians"), join(path, "radians"));
    if (!std::isfinite(angle)) {
        // d pi overflows for |d| > DBL_MAX / pi = 5.7e307.
        throw FieldError{join(path, "degrees"), QStringLiteral("overflows in the conversion to radians (d \u00b7 "
                                                               "\u03c0 exceeds the largest double); must be at most "
                                                               "5.7e307 in size")};
    }
    return Quat(Eigen::AngleAxisd(angle, axis.normalized()));
}

InertiaConvention toConvention(const QJsonValue& v, const QString& path)
{
    const QString c = toString(v, path);
    if (c == "standard") {
        return InertiaConvention::Standard;
    }
    if (c == "course-template") {
        return InertiaConvention::CourseTemplate;
    }
    throw FieldError{path, QStringLiteral("must be \"standard\" or \"course-template\", got \"%1\"").arg(shown(c))};
}

BodyDef toBody(const QJsonValue& v, const QString& path)
{
    const QJsonObject o = toObject(v, path);
    checkKeys(o, path, {"name", "size", "mass", "fixed", "position", "orientation",
                        "linear_velocity", "angular_velocity", "angular_response", "integrator",
                        "inertia_convention"});
    BodyDef b;
    b.name = toString(require(o, path, "name"), join(path, "name")).toStdString();
    b.size = toVec3(require(o, path, "size"), join(path, "size"));
    b.fixed = o.contains("fixed") ? toBool(o.value("fixed"), join(path, "fixed")) : false;
    if (b.fixed) {
        if (o.contains("mass")) {
            throw FieldError{join(path, "mass"),
                             QStringLiteral("a fixed body has infinite mass; leave \"mass\" out")};
        }
    } else {
        b.mass = toNumber(require(o, path, "mass"), join(path, "mass"));
    }
    b.x0_W = vec3Or(o, path, "position", Vec3::Zero());
    b.q0_WB = o.contains("orientation") ? toOrientation(o.value("orientation"), join(path, "orientation"))
                                        : Quat::Identity();
    b.v0_W = vec3Or(o, path, "linear_velocity", Vec3::Zero());
    b.omega0_W = vec3Or(o, path, "angular_velocity", Vec3::Zero());
    b.angularResponse = o.contains("angular_response")
                            ? toBool(o.value("angular_response"), join(path, "angular_response"))
                            : true;
    // Per-body variants of the scene's integrator and convention (compared side by side).
    // An empty string is BodyDef's "the scene's integrator", so the file may not write it.
    if (o.contains("integrator")) {
        b.integrator = toString(o.value("integrator"), join(path, "integrator")).toStdString();
        if (b.integrator.empty()) {
            throw FieldError{join(path, "integrator"), QStringLiteral("must name an integrator (see `rbw integrators`)")};
        }
    }
    if (o.contains("inertia_convention")) {
        b.inertiaConvention = toConvention(o.value("inertia_convention"), join(path, "inertia_convention"));
    }
    return b;
}

// The body an object's "body" key names: its index, -1 if no body has the name. The
// name is kept too, so that validate() can report it.
int bodyByName(const SceneNames& names, const QJsonObject& o, const QString& path, std::string& name)
{
    name = toString(require(o, path, "body"), join(path, "body")).toStdString();
    return names.body(name);
}

ForceDef toForce(const SceneNames& names, const QJsonValue& v, const QString& path)
{
    const QJsonObject o = toObject(v, path);
    checkKeys(o, path, {"body", "point", "force", "from_step", "to_step"});
    ForceDef f;
    f.body = bodyByName(names, o, path, f.bodyName);
    f.p_W = toVec3(require(o, path, "point"), join(path, "point"));
    f.f_W = toVec3(require(o, path, "force"), join(path, "force"));
    // Lifetime: steps k with from_step <= k < to_step. Neither key: step 0 only.
    // Only from_step: that one step. Only to_step: from step 0.
    f.fromStep = o.contains("from_step") ? toInteger(o.value("from_step"), join(path, "from_step")) : 0;
    f.toStep = o.contains("to_step") ? toInteger(o.value("to_step"), join(path, "to_step")) : f.fromStep + 1;
    return f;
}

TorqueDef toTorque(const SceneNames& names, const QJsonValue& v, const QString& path)
{
    const QJsonObject o = toObject(v, path);
    checkKeys(o, path, {"body", "torque", "from_step", "to_step", "switchable", "enabled"});
    TorqueDef t;
    t.body = bodyByName(names, o, path, t.bodyName);
    t.q_W = toVec3(require(o, path, "torque"), join(path, "torque"));
    // Lifetime as for forces, except that a torque with neither key lasts for ever:
    // a couple is usually a motor, not a kick.
    t.fromStep = o.contains("from_step") ? toInteger(o.value("from_step"), join(path, "from_step")) : 0;
    t.toStep = o.contains("to_step") ? toInteger(o.value("to_step"), join(path, "to_step"))
                                     : std::numeric_limits<long>::max();
    t.switchable = o.contains("switchable") && toBool(o.value("switchable"), join(path, "switchable"));
    t.enabledAtStart = !o.contains("enabled") || toBool(o.value("enabled"), join(path, "enabled"));
    return t;
}

PushDef toPush(const SceneNames& names, const QJsonValue& v, const QString& path)
{
    const QJsonObject o = toObject(v, path);
    checkKeys(o, path, {"body", "point", "force"});
    PushDef p;
    p.body = bodyByName(names, o, path, p.bodyName);
    p.p_B = o.contains("point") ? toVec3(o.value("point"), join(path, "point")) : Vec3::Zero();
    p.magnitude = o.contains("force") ? toNumber(o.value("force"), join(path, "force")) : 1.0;
    return p;
}

ProbeDef toProbe(const SceneNames& names, const QJsonValue& v, const QString& path)
{
    const QJsonObject o = toObject(v, path);
    checkKeys(o, path, {"body", "point"});
    ProbeDef p;
    p.body = bodyByName(names, o, path, p.bodyName);
    p.p0_W = toVec3(require(o, path, "point"), join(path, "point"));
    return p;
}

PlaneDef toPlane(const QJsonValue& v, const QString& path)
{
    const QJsonObject o = toObject(v, path);
    checkKeys(o, path, {"name", "point", "normal"});
    PlaneDef p;
    p.name = toString(require(o, path, "name"), join(path, "name")).toStdString();
    p.point_W = toVec3(require(o, path, "point"), join(path, "point"));
    // A file's normal may have any length: it is normalised here. The zero vector has
    // no direction and stays zero, for validate() to report.
    const Vec3 n = toVec3(require(o, path, "normal"), join(path, "normal"));
    if (n != Vec3::Zero()) {
        requireNormalisable(n.squaredNorm(), join(path, "normal"));
    }
    p.n_W = n == Vec3::Zero() || isUnitToRounding(n.squaredNorm()) ? n : n.normalized();
    return p;
}

PairOverride toPair(const SceneNames& names, const QJsonValue& v, const QString& path)
{
    const QJsonObject o = toObject(v, path);
    checkKeys(o, path, {"bodies", "restitution", "friction"});
    const QString bp = join(path, "bodies");
    const QJsonArray given = toArray(require(o, path, "bodies"), bp);
    if (given.size() != 2) {
        throw FieldError{bp, QStringLiteral("must name exactly two: [\"bodyA\", \"bodyB or plane\"]")};
    }
    // Names are resolved to indices (-1: none) and kept; validate() checks that they
    // exist, differ and are not listed twice.
    PairOverride pair;
    pair.nameA = toString(given[0], bp + "[0]").toStdString();
    pair.nameB = toString(given[1], bp + "[1]").toStdString();
    pair.bodyA = names.body(pair.nameA);
    pair.bodyB = names.body(pair.nameB);
    pair.planeB = pair.bodyB < 0 ? names.plane(pair.nameB) : -1;
    if (o.contains("restitution")) pair.restitution = toNumber(o.value("restitution"), join(path, "restitution"));
    if (o.contains("friction")) pair.friction = toNumber(o.value("friction"), join(path, "friction"));
    return pair;
}

} // namespace

SceneDef toScene(const QJsonObject& o, const QString& fileLabel)
{
    // A scene without bodies has nothing to simulate, and everything that names a body
    // would fail for that one reason: said first, and alone.
    if (o.value("bodies").isArray() && o.value("bodies").toArray().isEmpty()) {
        throw FieldError{"bodies", QStringLiteral("must list at least one body; a scene without a body has nothing "
                                                  "to simulate")};
    }
    checkKeys(o, QString(), {"name", "description", "dt", "steps", "integrator", "inertia_convention",
                             "gravity", "bodies", "forces", "torques", "push", "probes", "planes", "box_collisions",
                             "restitution", "restitution_threshold", "friction", "pairs", "position_correction",
                             "plane_contacts", "energy_jump", "contact_model", "solver_iterations", "sleep",
                             "position_fix"});
    SceneDef s;
    s.name = o.contains("name") ? toString(o.value("name"), "name").toStdString()
                                : QFileInfo(fileLabel).completeBaseName().toStdString();
    s.description = o.contains("description") ? toString(o.value("description"), "description").toStdString()
                                              : std::string();
    s.dt = toNumber(require(o, QString(), "dt"), "dt");
    s.steps = o.contains("steps") ? toInteger(o.value("steps"), "steps") : 1;
    s.integrator = o.contains("integrator") ? toString(o.value("integrator"), "integrator").toStdString()
                                            : std::string("explicit-euler");
    if (o.contains("inertia_convention")) {
        s.inertiaConvention = toConvention(o.value("inertia_convention"), "inertia_convention");
    }
    s.g_W = vec3Or(o, QString(), "gravity", Vec3::Zero());

    // Bodies and planes come first, so that forces, probes and pairs can name them
    // wherever they appear in the file. A name is resolved to the first body (or
    // plane) that has it; validate() reports a name used twice.
    const QJsonArray bodies = toArray(require(o, QString(), "bodies"), "bodies");
    for (int i = 0; i < bodies.size(); ++i) {
        s.bodies.push_back(toBody(bodies[i], QStringLiteral("bodies[%1]").arg(i)));
    }
    if (o.contains("planes")) {
        const QJsonArray planes = toArray(o.value("planes"), "planes");
        for (int i = 0; i < planes.size(); ++i) {
            s.planes.push_back(toPlane(planes[i], QStringLiteral("planes[%1]").arg(i)));
        }
    }
    // Every name below is resolved through one hash map, built once: O(1) a name.
    const SceneNames names(s);
    if (o.contains("forces")) {
        const QJsonArray forces = toArray(o.value("forces"), "forces");
        for (int i = 0; i < forces.size(); ++i) {
            s.forces.push_back(toForce(names, forces[i], QStringLiteral("forces[%1]").arg(i)));
        }
    }
    if (o.contains("torques")) {
        const QJsonArray torques = toArray(o.value("torques"), "torques");
        for (int i = 0; i < torques.size(); ++i) {
            s.torques.push_back(toTorque(names, torques[i], QStringLiteral("torques[%1]").arg(i)));
        }
    }
    if (o.contains("push")) {
        s.push = toPush(names, o.value("push"), "push");
    }
    if (o.contains("probes")) {
        const QJsonArray probes = toArray(o.value("probes"), "probes");
        for (int i = 0; i < probes.size(); ++i) {
            s.probes.push_back(toProbe(names, probes[i], QStringLiteral("probes[%1]").arg(i)));
        }
    }
    if (o.contains("box_collisions")) s.boxCollisions = toBool(o.value("box_collisions"), "box_collisions");
    if (o.contains("restitution")) s.restitution = toNumber(o.value("restitution"), "restitution");
    if (o.contains("friction")) s.friction = toNumber(o.value("friction"), "friction");
    if (o.contains("restitution_threshold")) {
        s.restitutionThreshold = toNumber(o.value("restitution_threshold"), "restitution_threshold");
    }
    if (o.contains("pairs")) {
        const QJsonArray pairs = toArray(o.value("pairs"), "pairs");
        for (int i = 0; i < pairs.size(); ++i) {
            s.pairs.push_back(toPair(names, pairs[i], QStringLiteral("pairs[%1]").arg(i)));
        }
    }
    if (o.contains("position_correction")) {
        s.positionCorrection = toBool(o.value("position_correction"), "position_correction");
    }
    if (o.contains("energy_jump")) {
        // { "factor": 2, "floor": 1e-9 }: the energy-jump blow-up bound (docs/stability.md)
        const QJsonObject e = toObject(o.value("energy_jump"), "energy_jump");
        checkKeys(e, "energy_jump", {"factor", "floor"});
        if (e.contains("factor")) s.energyJumpFactor = toNumber(e.value("factor"), "energy_jump.factor");
        if (e.contains("floor")) s.energyJumpFloor = toNumber(e.value("floor"), "energy_jump.floor");
    }
    if (o.contains("plane_contacts")) {
        const QString mode = toString(o.value("plane_contacts"), "plane_contacts");
        if (mode == "per-point") {
            s.planeContacts = PlaneContactMode::PerPoint;
        } else if (mode == "average") {
            s.planeContacts = PlaneContactMode::Average;
        } else {
            throw FieldError{"plane_contacts",
                             QStringLiteral("must be \"per-point\" or \"average\", got \"%1\"").arg(shown(mode))};
        }
    }
    // The contact model and its keys (issue 11); the rules (which keys belong to which
    // model, the iteration range) are validate()'s.
    if (o.contains("contact_model")) {
        const QString model = toString(o.value("contact_model"), "contact_model");
        if (model == "course") {
            s.contactModel = ContactModel::Course;
        } else if (model == "manifold") {
            s.contactModel = ContactModel::Manifold;
        } else {
            throw FieldError{"contact_model",
                             QStringLiteral("must be \"course\" or \"manifold\", got \"%1\"").arg(shown(model))};
        }
    }
    if (o.contains("solver_iterations")) {
        s.solverIterations = toInteger(o.value("solver_iterations"), "solver_iterations");
    }
    if (o.contains("sleep")) s.sleep = toBool(o.value("sleep"), "sleep");
    if (o.contains("position_fix")) {
        const QString fix = toString(o.value("position_fix"), "position_fix");
        if (fix == "ngs") {
            s.positionFix = PositionFix::Ngs;
        } else if (fix == "baumgarte") {
            s.positionFix = PositionFix::Baumgarte;
        } else if (fix == "none") {
            s.positionFix = PositionFix::None;
        } else {
            throw FieldError{"position_fix", QStringLiteral("must be \"ngs\", \"baumgarte\" or \"none\", got \"%1\"")
                                                 .arg(shown(fix))};
        }
    }
    return s;
}

} // namespace rbw::scenefile
