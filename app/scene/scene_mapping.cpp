#include "app/scene/scene_mapping.h"

#include "app/scene/scene_fields.h"
#include "app/scene/scene_format.h"

#include <QFileInfo>

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace rbw::scenefile {
namespace {

using sceneformat::choiceText;
using sceneformat::fromWord;
using sceneformat::key;
using sceneformat::keysOf;
using sceneformat::words;
using K = sceneformat::Key;
using Section = sceneformat::Section;

// One JSON object of the file, read by the table's keys: unknown keys are refused
// when it is made (with "did you mean"), and each key's path is the object's path and
// the key ("bodies[0].mass").
class Fields {
public:
    Fields(const QJsonValue& v, const QString& path, Section section)
        : o_(toObject(v, path)), path_(path)
    {
        checkKeys(o_, path, keysOf(section));
    }
    bool has(K k) const { return o_.contains(key(k)); }
    QString at(K k) const { return join(path_, key(k)); }
    QJsonValue value(K k) const { return o_.value(key(k)); }
    QJsonValue need(K k) const { return require(o_, path_, key(k)); }
    const QString& path() const { return path_; }

private:
    QJsonObject o_;
    QString path_;
};

// A word of an enumeration, or a FieldError listing the words ("must be \"course\" or
// \"manifold\", got \"soft\"").
template <typename E>
E toWord(const QJsonValue& v, const QString& path, sceneformat::Choices choices)
{
    const QString w = toString(v, path);
    if (const std::optional<E> e = fromWord<E>(w)) {
        return *e;
    }
    throw FieldError{path, QStringLiteral("must be %1, got \"%2\"").arg(choiceText(words(choices)), shown(w))};
}

// An axis with degrees or radians, or a quaternion [w, x, y, z].
Quat toOrientation(const QJsonValue& v, const QString& path)
{
    const Fields o(v, path, Section::Orientation);
    const QString quaternion = key(K::OrientationQuaternion), axisKey = key(K::OrientationAxis);
    const QString degrees = key(K::OrientationDegrees), radians = key(K::OrientationRadians);
    if (o.has(K::OrientationQuaternion)) {
        if (o.has(K::OrientationAxis) || o.has(K::OrientationDegrees) || o.has(K::OrientationRadians)) {
            throw FieldError{path, QStringLiteral("give either \"%1\" or \"%2\" with an angle, not both").arg(quaternion, axisKey)};
        }
        const QString qp = o.at(K::OrientationQuaternion);
        const QJsonArray a = toArray(o.value(K::OrientationQuaternion), qp);
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
    const QString ap = o.at(K::OrientationAxis);
    const Vec3 axis = toVec3(o.need(K::OrientationAxis), ap);
    if (axis == Vec3::Zero()) {
        throw FieldError{ap, QStringLiteral("rotation axis must not be zero")};
    }
    requireNormalisable(axis.squaredNorm(), ap);
    if (o.has(K::OrientationDegrees) == o.has(K::OrientationRadians)) {
        throw FieldError{path, QStringLiteral("give the angle as exactly one of \"%1\" or \"%2\"").arg(degrees, radians)};
    }
    const double angle = o.has(K::OrientationDegrees)
                             ? toNumber(o.value(K::OrientationDegrees), o.at(K::OrientationDegrees)) * std::numbers::pi / 180.0
                             : toNumber(o.value(K::OrientationRadians), o.at(K::OrientationRadians));
    if (!std::isfinite(angle)) {
        // d pi overflows for |d| > DBL_MAX / pi = 5.7e307.
        throw FieldError{o.at(K::OrientationDegrees), QStringLiteral("overflows in the conversion to radians (d \u00b7 "
                                                                     "\u03c0 exceeds the largest double); must be at most "
                                                                     "5.7e307 in size")};
    }
    return Quat(Eigen::AngleAxisd(angle, axis.normalized()));
}

InertiaConvention toConvention(const QJsonValue& v, const QString& path)
{
    return toWord<InertiaConvention>(v, path, sceneformat::Choices::InertiaConvention);
}

Vec3 vectorOr(const Fields& o, K k, const Vec3& fallback)
{
    return o.has(k) ? toVec3(o.value(k), o.at(k)) : fallback;
}

BodyDef toBody(const QJsonValue& v, const QString& path)
{
    const Fields o(v, path, Section::Body);
    BodyDef b;
    b.name = toString(o.need(K::BodyName), o.at(K::BodyName)).toStdString();
    b.size = toVec3(o.need(K::BodySize), o.at(K::BodySize));
    b.fixed = o.has(K::BodyFixed) ? toBool(o.value(K::BodyFixed), o.at(K::BodyFixed)) : false;
    if (b.fixed) {
        if (o.has(K::BodyMass)) {
            throw FieldError{o.at(K::BodyMass),
                             QStringLiteral("a fixed body has infinite mass; leave \"%1\" out").arg(key(K::BodyMass))};
        }
    } else {
        b.mass = toNumber(o.need(K::BodyMass), o.at(K::BodyMass));
    }
    b.x0_W = vectorOr(o, K::BodyPosition, Vec3::Zero());
    b.q0_WB = o.has(K::BodyOrientation) ? toOrientation(o.value(K::BodyOrientation), o.at(K::BodyOrientation))
                                        : Quat::Identity();
    b.v0_W = vectorOr(o, K::BodyLinearVelocity, Vec3::Zero());
    b.omega0_W = vectorOr(o, K::BodyAngularVelocity, Vec3::Zero());
    b.angularResponse = o.has(K::BodyAngularResponse)
                            ? toBool(o.value(K::BodyAngularResponse), o.at(K::BodyAngularResponse))
                            : true;
    // Per-body variants of the scene's integrator and convention (compared side by side).
    // An empty string is BodyDef's "the scene's integrator", so the file may not write it.
    if (o.has(K::BodyIntegrator)) {
        b.integrator = toString(o.value(K::BodyIntegrator), o.at(K::BodyIntegrator)).toStdString();
        if (b.integrator.empty()) {
            throw FieldError{o.at(K::BodyIntegrator), QStringLiteral("must name an integrator (see `rbw integrators`)")};
        }
    }
    if (o.has(K::BodyInertiaConvention)) {
        b.inertiaConvention = toConvention(o.value(K::BodyInertiaConvention), o.at(K::BodyInertiaConvention));
    }
    return b;
}

// The body an object's body key names: its index, -1 if no body has the name. The
// name is kept too, so that validate() can report it.
int bodyByName(const SceneNames& names, const Fields& o, K bodyKey, std::string& name)
{
    name = toString(o.need(bodyKey), o.at(bodyKey)).toStdString();
    return names.body(name);
}

long integerOr(const Fields& o, K k, long fallback)
{
    return o.has(k) ? toInteger(o.value(k), o.at(k)) : fallback;
}

ForceDef toForce(const SceneNames& names, const QJsonValue& v, const QString& path)
{
    const Fields o(v, path, Section::Force);
    ForceDef f;
    f.body = bodyByName(names, o, K::ForceBody, f.bodyName);
    f.p_W = toVec3(o.need(K::ForcePoint), o.at(K::ForcePoint));
    f.f_W = toVec3(o.need(K::ForceForce), o.at(K::ForceForce));
    // Lifetime: steps k with from_step <= k < to_step. Neither key: step 0 only.
    // Only from_step: that one step. Only to_step: from step 0.
    f.fromStep = integerOr(o, K::ForceFromStep, 0);
    f.toStep = integerOr(o, K::ForceToStep, f.fromStep + 1);
    return f;
}

TorqueDef toTorque(const SceneNames& names, const QJsonValue& v, const QString& path)
{
    const Fields o(v, path, Section::Torque);
    TorqueDef t;
    t.body = bodyByName(names, o, K::TorqueBody, t.bodyName);
    t.q_W = toVec3(o.need(K::TorqueTorque), o.at(K::TorqueTorque));
    // Lifetime as for forces, except that a torque with neither key lasts for ever:
    // a couple is usually a motor, not a kick.
    t.fromStep = integerOr(o, K::TorqueFromStep, 0);
    t.toStep = integerOr(o, K::TorqueToStep, std::numeric_limits<long>::max());
    t.switchable = o.has(K::TorqueSwitchable) && toBool(o.value(K::TorqueSwitchable), o.at(K::TorqueSwitchable));
    t.enabledAtStart = !o.has(K::TorqueEnabled) || toBool(o.value(K::TorqueEnabled), o.at(K::TorqueEnabled));
    return t;
}

PushDef toPush(const SceneNames& names, const QJsonValue& v, const QString& path)
{
    const Fields o(v, path, Section::Push);
    PushDef p;
    p.body = bodyByName(names, o, K::PushBody, p.bodyName);
    p.p_B = vectorOr(o, K::PushPoint, Vec3::Zero());
    p.magnitude = o.has(K::PushForce) ? toNumber(o.value(K::PushForce), o.at(K::PushForce)) : 1.0;
    return p;
}

ProbeDef toProbe(const SceneNames& names, const QJsonValue& v, const QString& path)
{
    const Fields o(v, path, Section::Probe);
    ProbeDef p;
    p.body = bodyByName(names, o, K::ProbeBody, p.bodyName);
    p.p0_W = toVec3(o.need(K::ProbePoint), o.at(K::ProbePoint));
    return p;
}

PlaneDef toPlane(const QJsonValue& v, const QString& path)
{
    const Fields o(v, path, Section::Plane);
    PlaneDef p;
    p.name = toString(o.need(K::PlaneName), o.at(K::PlaneName)).toStdString();
    p.point_W = toVec3(o.need(K::PlanePoint), o.at(K::PlanePoint));
    // A file's normal may have any length: it is normalised here. The zero vector has
    // no direction and stays zero, for validate() to report.
    const Vec3 n = toVec3(o.need(K::PlaneNormal), o.at(K::PlaneNormal));
    if (n != Vec3::Zero()) {
        requireNormalisable(n.squaredNorm(), o.at(K::PlaneNormal));
    }
    p.n_W = n == Vec3::Zero() || isUnitToRounding(n.squaredNorm()) ? n : n.normalized();
    return p;
}

PairOverride toPair(const SceneNames& names, const QJsonValue& v, const QString& path)
{
    const Fields o(v, path, Section::Pair);
    const QString bp = o.at(K::PairBodies);
    const QJsonArray given = toArray(o.need(K::PairBodies), bp);
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
    if (o.has(K::PairRestitution)) pair.restitution = toNumber(o.value(K::PairRestitution), o.at(K::PairRestitution));
    if (o.has(K::PairFriction)) pair.friction = toNumber(o.value(K::PairFriction), o.at(K::PairFriction));
    return pair;
}

// Each element of a list key through `read` (its path "forces[2]"); none if the key is left out.
template <typename T, typename Read>
void readList(const Fields& o, K k, std::vector<T>& out, Read read)
{
    if (!o.has(k)) return;
    const QJsonArray list = toArray(o.value(k), o.at(k));
    for (int i = 0; i < list.size(); ++i) {
        out.push_back(read(list[i], QStringLiteral("%1[%2]").arg(o.at(k)).arg(i)));
    }
}

} // namespace

SceneDef toScene(const QJsonObject& top, const QString& fileLabel)
{
    // A scene without bodies has nothing to simulate, and everything that names a body
    // would fail for that one reason: said first, and alone.
    const QJsonValue bodies = top.value(key(K::Bodies));
    if (bodies.isArray() && bodies.toArray().isEmpty()) {
        throw FieldError{key(K::Bodies), QStringLiteral("must list at least one body; a scene without a body has "
                                                        "nothing to simulate")};
    }
    const Fields o(top, QString(), Section::Scene);
    SceneDef s;
    s.name = o.has(K::Name) ? toString(o.value(K::Name), o.at(K::Name)).toStdString()
                            : QFileInfo(fileLabel).completeBaseName().toStdString();
    s.description = o.has(K::Description) ? toString(o.value(K::Description), o.at(K::Description)).toStdString()
                                          : std::string();
    s.dt = toNumber(o.need(K::Dt), o.at(K::Dt));
    s.steps = integerOr(o, K::Steps, 1);
    // Left out, SceneDef's own default (as for every key below); the table's default is
    // tested to be the same (tst_scene_format, leftOutIsTheDefault).
    if (o.has(K::Integrator)) s.integrator = toString(o.value(K::Integrator), o.at(K::Integrator)).toStdString();
    if (o.has(K::InertiaConvention)) {
        s.inertiaConvention = toConvention(o.value(K::InertiaConvention), o.at(K::InertiaConvention));
    }
    s.g_W = vectorOr(o, K::Gravity, Vec3::Zero());

    // Bodies and planes come first, so that forces, probes and pairs can name them
    // wherever they appear in the file. A name is resolved to the first body (or
    // plane) that has it; validate() reports a name used twice.
    o.need(K::Bodies);   // required, even though readList() would skip it
    readList(o, K::Bodies, s.bodies, toBody);
    readList(o, K::Planes, s.planes, toPlane);
    // Every name below is resolved through one hash map, built once: O(1) a name.
    const SceneNames names(s);
    auto named = [&names](auto read) {
        return [&names, read](const QJsonValue& v, const QString& path) { return read(names, v, path); };
    };
    readList(o, K::Forces, s.forces, named(toForce));
    readList(o, K::Torques, s.torques, named(toTorque));
    if (o.has(K::Push)) {
        s.push = toPush(names, o.value(K::Push), o.at(K::Push));
    }
    readList(o, K::Probes, s.probes, named(toProbe));
    if (o.has(K::BoxCollisions)) s.boxCollisions = toBool(o.value(K::BoxCollisions), o.at(K::BoxCollisions));
    if (o.has(K::Restitution)) s.restitution = toNumber(o.value(K::Restitution), o.at(K::Restitution));
    if (o.has(K::Friction)) s.friction = toNumber(o.value(K::Friction), o.at(K::Friction));
    if (o.has(K::RestitutionThreshold)) {
        s.restitutionThreshold = toNumber(o.value(K::RestitutionThreshold), o.at(K::RestitutionThreshold));
    }
    readList(o, K::Pairs, s.pairs, named(toPair));
    if (o.has(K::PositionCorrection)) {
        s.positionCorrection = toBool(o.value(K::PositionCorrection), o.at(K::PositionCorrection));
    }
    if (o.has(K::EnergyJump)) {
        // The energy-jump blow-up bound (docs/stability.md).
        const Fields e(o.value(K::EnergyJump), o.at(K::EnergyJump), Section::EnergyJump);
        if (e.has(K::EnergyJumpFactor)) s.energyJumpFactor = toNumber(e.value(K::EnergyJumpFactor), e.at(K::EnergyJumpFactor));
        if (e.has(K::EnergyJumpFloor)) s.energyJumpFloor = toNumber(e.value(K::EnergyJumpFloor), e.at(K::EnergyJumpFloor));
    }
    if (o.has(K::PlaneContacts)) {
        s.planeContacts = toWord<PlaneContactMode>(o.value(K::PlaneContacts), o.at(K::PlaneContacts),
                                                   sceneformat::Choices::PlaneContacts);
    }
    // The contact model and its keys (issue 11); the rules (which keys belong to which
    // model, the iteration range) are validate()'s.
    if (o.has(K::ContactModel)) {
        s.contactModel = toWord<ContactModel>(o.value(K::ContactModel), o.at(K::ContactModel),
                                              sceneformat::Choices::ContactModel);
    }
    if (o.has(K::SolverIterations)) {
        s.solverIterations = toInteger(o.value(K::SolverIterations), o.at(K::SolverIterations));
    }
    if (o.has(K::Sleep)) s.sleep = toBool(o.value(K::Sleep), o.at(K::Sleep));
    if (o.has(K::PositionFix)) {
        s.positionFix = toWord<PositionFix>(o.value(K::PositionFix), o.at(K::PositionFix), sceneformat::Choices::PositionFix);
    }
    if (o.has(K::Solver)) {
        s.solver = toWord<ManifoldSolver>(o.value(K::Solver), o.at(K::Solver), sceneformat::Choices::ManifoldSolver);
    }
    if (o.has(K::Substeps)) s.substeps = toInteger(o.value(K::Substeps), o.at(K::Substeps));
    return s;
}

} // namespace rbw::scenefile
