#include "app/core/scene_loader.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>

#include <cmath>
#include <limits>
#include <numbers>

namespace rbw {
namespace {

// Thrown inside the loader only; loadSceneFile() turns it into an error line.
struct FieldError {
    QString path;
    QString reason;
};

QString join(const QString& path, const QString& key)
{
    return path.isEmpty() ? key : path + '.' + key;
}

QString typeName(const QJsonValue& v)
{
    switch (v.type()) {
    case QJsonValue::Null: return QStringLiteral("null");
    case QJsonValue::Bool: return QStringLiteral("a boolean");
    case QJsonValue::Double: return QStringLiteral("a number");
    case QJsonValue::String: return QStringLiteral("a string");
    case QJsonValue::Array: return QStringLiteral("an array");
    case QJsonValue::Object: return QStringLiteral("an object");
    case QJsonValue::Undefined: return QStringLiteral("nothing");
    }
    return QStringLiteral("?");
}

// Levenshtein distance, for "did you mean" on unknown keys.
int editDistance(const QString& a, const QString& b)
{
    std::vector<int> prev(b.size() + 1), cur(b.size() + 1);
    for (int j = 0; j <= b.size(); ++j) prev[j] = j;
    for (int i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (int j = 1; j <= b.size(); ++j) {
            const int subst = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, subst});
        }
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

// Unknown keys are refused, so a typo is caught instead of silently ignored.
void checkKeys(const QJsonObject& o, const QString& path, const QStringList& allowed)
{
    for (auto it = o.begin(); it != o.end(); ++it) {
        if (allowed.contains(it.key())) {
            continue;
        }
        QString best;
        int bestDistance = 3;
        for (const QString& k : allowed) {
            const int d = editDistance(it.key(), k);
            if (d < bestDistance) {
                bestDistance = d;
                best = k;
            }
        }
        QString reason = QStringLiteral("unknown key");
        if (!best.isEmpty()) {
            reason += QStringLiteral(" (did you mean \"%1\"?)").arg(best);
        } else {
            reason += QStringLiteral(" (allowed: %1)").arg(allowed.join(QStringLiteral(", ")));
        }
        throw FieldError{join(path, it.key()), reason};
    }
}

QJsonValue require(const QJsonObject& o, const QString& path, const QString& key)
{
    if (!o.contains(key)) {
        throw FieldError{join(path, key), QStringLiteral("required field is missing")};
    }
    return o.value(key);
}

// A number JSON cannot hold (NaN, Infinity, 1e999) is swapped for a string with this
// prefix before a second parse, so the error can name the field it stands in.
const QString kNonFinitePrefix = QStringLiteral("\u0001nonfinite:");

double toNumber(const QJsonValue& v, const QString& path)
{
    if (v.isString() && v.toString().startsWith(kNonFinitePrefix)) {
        throw FieldError{path, QStringLiteral("must be a finite number, got %1 (JSON has no NaN or Infinity, "
                                              "and every number must fit in a double)")
                                   .arg(v.toString().mid(kNonFinitePrefix.size()))};
    }
    if (!v.isDouble()) {
        throw FieldError{path, QStringLiteral("must be a number, got %1").arg(typeName(v))};
    }
    const double x = v.toDouble();
    if (!std::isfinite(x)) {
        throw FieldError{path, QStringLiteral("must be finite, got %1").arg(x)};
    }
    return x;
}

long toInteger(const QJsonValue& v, const QString& path)
{
    const double x = toNumber(v, path);
    if (x != std::floor(x) || std::abs(x) > 9.0e15) {
        throw FieldError{path, QStringLiteral("must be a whole number, got %1").arg(x)};
    }
    return static_cast<long>(x);
}

Vec3 toVec3(const QJsonValue& v, const QString& path)
{
    if (!v.isArray() || v.toArray().size() != 3) {
        throw FieldError{path, QStringLiteral("must be an array of 3 numbers, got %1")
                                   .arg(v.isArray() ? QStringLiteral("%1 elements").arg(v.toArray().size())
                                                    : typeName(v))};
    }
    const QJsonArray a = v.toArray();
    return Vec3(toNumber(a[0], path + "[0]"), toNumber(a[1], path + "[1]"),
                toNumber(a[2], path + "[2]"));
}

Vec3 vec3Or(const QJsonObject& o, const QString& path, const QString& key, const Vec3& fallback)
{
    return o.contains(key) ? toVec3(o.value(key), join(path, key)) : fallback;
}

QString toString(const QJsonValue& v, const QString& path)
{
    if (!v.isString()) {
        throw FieldError{path, QStringLiteral("must be a string, got %1").arg(typeName(v))};
    }
    return v.toString();
}

bool toBool(const QJsonValue& v, const QString& path)
{
    if (!v.isBool()) {
        throw FieldError{path, QStringLiteral("must be true or false, got %1").arg(typeName(v))};
    }
    return v.toBool();
}

QJsonObject toObject(const QJsonValue& v, const QString& path)
{
    if (!v.isObject()) {
        throw FieldError{path, QStringLiteral("must be an object, got %1").arg(typeName(v))};
    }
    return v.toObject();
}

QJsonArray toArray(const QJsonValue& v, const QString& path)
{
    if (!v.isArray()) {
        throw FieldError{path, QStringLiteral("must be an array, got %1").arg(typeName(v))};
    }
    return v.toArray();
}

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
        // Scene files write quaternions scalar first: [w, x, y, z] (physics/math_types.h).
        const Quat q(toNumber(a[0], qp + "[0]"), toNumber(a[1], qp + "[1]"),
                     toNumber(a[2], qp + "[2]"), toNumber(a[3], qp + "[3]"));
        if (q.norm() == 0.0) {
            throw FieldError{qp, QStringLiteral("must not be the zero quaternion")};
        }
        return q.normalized();
    }
    const Vec3 axis = toVec3(require(o, path, "axis"), join(path, "axis"));
    if (axis.norm() == 0.0) {
        throw FieldError{join(path, "axis"), QStringLiteral("rotation axis must not be zero")};
    }
    if (o.contains("degrees") == o.contains("radians")) {
        throw FieldError{path, QStringLiteral("give the angle as exactly one of \"degrees\" or \"radians\"")};
    }
    const double angle = o.contains("degrees")
                             ? toNumber(o.value("degrees"), join(path, "degrees")) * std::numbers::pi / 180.0
                             : toNumber(o.value("radians"), join(path, "radians"));
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
    throw FieldError{path, QStringLiteral("must be \"standard\" or \"course-template\", got \"%1\"").arg(c)};
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
int bodyByName(const SceneDef& scene, const QJsonObject& o, const QString& path, std::string& name)
{
    name = toString(require(o, path, "body"), join(path, "body")).toStdString();
    return scene.bodyIndex(name);
}

ForceDef toForce(const SceneDef& scene, const QJsonValue& v, const QString& path)
{
    const QJsonObject o = toObject(v, path);
    checkKeys(o, path, {"body", "point", "force", "from_step", "to_step"});
    ForceDef f;
    f.body = bodyByName(scene, o, path, f.bodyName);
    f.p_W = toVec3(require(o, path, "point"), join(path, "point"));
    f.f_W = toVec3(require(o, path, "force"), join(path, "force"));
    // Lifetime: steps k with from_step <= k < to_step. Neither key: step 0 only.
    // Only from_step: that one step. Only to_step: from step 0.
    f.fromStep = o.contains("from_step") ? toInteger(o.value("from_step"), join(path, "from_step")) : 0;
    f.toStep = o.contains("to_step") ? toInteger(o.value("to_step"), join(path, "to_step")) : f.fromStep + 1;
    return f;
}

TorqueDef toTorque(const SceneDef& scene, const QJsonValue& v, const QString& path)
{
    const QJsonObject o = toObject(v, path);
    checkKeys(o, path, {"body", "torque", "from_step", "to_step", "switchable", "enabled"});
    TorqueDef t;
    t.body = bodyByName(scene, o, path, t.bodyName);
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

PushDef toPush(const SceneDef& scene, const QJsonValue& v, const QString& path)
{
    const QJsonObject o = toObject(v, path);
    checkKeys(o, path, {"body", "point", "force"});
    PushDef p;
    p.body = bodyByName(scene, o, path, p.bodyName);
    p.p_B = o.contains("point") ? toVec3(o.value("point"), join(path, "point")) : Vec3::Zero();
    p.magnitude = o.contains("force") ? toNumber(o.value("force"), join(path, "force")) : 1.0;
    return p;
}

ProbeDef toProbe(const SceneDef& scene, const QJsonValue& v, const QString& path)
{
    const QJsonObject o = toObject(v, path);
    checkKeys(o, path, {"body", "point"});
    ProbeDef p;
    p.body = bodyByName(scene, o, path, p.bodyName);
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
    p.n_W = n == Vec3::Zero() ? n : n.normalized();
    return p;
}

PairOverride toPair(const SceneDef& scene, const QJsonValue& v, const QString& path)
{
    const QJsonObject o = toObject(v, path);
    checkKeys(o, path, {"bodies", "restitution", "friction"});
    const QString bp = join(path, "bodies");
    const QJsonArray names = toArray(require(o, path, "bodies"), bp);
    if (names.size() != 2) {
        throw FieldError{bp, QStringLiteral("must name exactly two: [\"bodyA\", \"bodyB or plane\"]")};
    }
    // Names are resolved to indices (-1: none) and kept; validate() checks that they
    // exist, differ and are not listed twice.
    PairOverride pair;
    pair.nameA = toString(names[0], bp + "[0]").toStdString();
    pair.nameB = toString(names[1], bp + "[1]").toStdString();
    pair.bodyA = scene.bodyIndex(pair.nameA);
    pair.bodyB = scene.bodyIndex(pair.nameB);
    pair.planeB = pair.bodyB < 0 ? scene.planeIndex(pair.nameB) : -1;
    if (o.contains("restitution")) pair.restitution = toNumber(o.value("restitution"), join(path, "restitution"));
    if (o.contains("friction")) pair.friction = toNumber(o.value("friction"), join(path, "friction"));
    return pair;
}

SceneDef toScene(const QJsonObject& o, const QString& fileLabel)
{
    checkKeys(o, QString(), {"name", "description", "dt", "steps", "integrator", "inertia_convention",
                             "gravity", "bodies", "forces", "torques", "push", "probes", "planes", "box_collisions",
                             "restitution", "restitution_threshold", "friction", "pairs", "position_correction",
                             "plane_contacts", "energy_jump"});
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
    if (o.contains("forces")) {
        const QJsonArray forces = toArray(o.value("forces"), "forces");
        for (int i = 0; i < forces.size(); ++i) {
            s.forces.push_back(toForce(s, forces[i], QStringLiteral("forces[%1]").arg(i)));
        }
    }
    if (o.contains("torques")) {
        const QJsonArray torques = toArray(o.value("torques"), "torques");
        for (int i = 0; i < torques.size(); ++i) {
            s.torques.push_back(toTorque(s, torques[i], QStringLiteral("torques[%1]").arg(i)));
        }
    }
    if (o.contains("push")) {
        s.push = toPush(s, o.value("push"), "push");
    }
    if (o.contains("probes")) {
        const QJsonArray probes = toArray(o.value("probes"), "probes");
        for (int i = 0; i < probes.size(); ++i) {
            s.probes.push_back(toProbe(s, probes[i], QStringLiteral("probes[%1]").arg(i)));
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
            s.pairs.push_back(toPair(s, pairs[i], QStringLiteral("pairs[%1]").arg(i)));
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
                             QStringLiteral("must be \"per-point\" or \"average\", got \"%1\"").arg(mode)};
        }
    }
    return s;
}

// 1-based line and column of a byte offset.
std::pair<int, int> lineColumn(const QByteArray& text, int offset)
{
    int line = 1;
    int column = 1;
    for (int i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return {line, column};
}

// For an illegal number at `offset`, the same text with that token replaced by a
// marker string; empty if there is no such token.
QByteArray markNonFiniteNumber(const QByteArray& json, int offset)
{
    static const QByteArray chars("+-.0123456789eEINaNnfinity");
    auto inToken = [&](int i) { return i >= 0 && i < json.size() && chars.contains(json[i]); };
    int start = inToken(offset) ? offset : offset - 1;
    if (!inToken(start)) return {};
    int end = start;
    while (inToken(start - 1)) --start;
    while (inToken(end + 1)) ++end;
    const QByteArray token = json.mid(start, end - start + 1);
    return json.left(start) + '"' + kNonFinitePrefix.toUtf8() + token + '"' + json.mid(end + 1);
}

} // namespace

SceneLoadResult parseScene(const QByteArray& json, const QString& fileLabel)
{
    SceneLoadResult result;
    QJsonParseError parseError;
    QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error == QJsonParseError::IllegalNumber) {
        QJsonParseError second;
        const QJsonDocument marked = QJsonDocument::fromJson(markNonFiniteNumber(json, parseError.offset), &second);
        if (second.error == QJsonParseError::NoError) {
            doc = marked;   // the structural pass below names the field
            parseError = second;
        }
    }
    if (parseError.error != QJsonParseError::NoError) {
        // QJsonParseError::offset points at (or just after) the offending token.
        const auto [line, column] = lineColumn(json, parseError.offset);
        QString reason = QStringLiteral("malformed JSON at line %1, column %2: %3")
                             .arg(line).arg(column).arg(parseError.errorString());
        result.errors << QStringLiteral("%1: %2").arg(fileLabel, reason);
        return result;
    }
    if (!doc.isObject()) {
        result.errors << QStringLiteral("%1: the top level must be a JSON object").arg(fileLabel);
        return result;
    }
    try {
        // Structure first (stops at the first problem), then every rule of the physics
        // (all problems at once), the same validate() a scene built in code goes through.
        SceneDef scene = toScene(doc.object(), fileLabel);
        for (const SceneIssue& issue : validate(scene)) {
            result.errors << QStringLiteral("%1: %2: %3")
                                 .arg(fileLabel, QString::fromStdString(issue.path),
                                      QString::fromStdString(issue.reason));
        }
        if (result.errors.isEmpty()) {
            result.scene = std::move(scene);
        }
    } catch (const FieldError& e) {
        result.errors << QStringLiteral("%1: %2: %3").arg(fileLabel, e.path, e.reason);
    }
    return result;
}

SceneLoadResult loadSceneFile(const QString& filePath)
{
    QFile file(filePath);
    if (!file.open(QIODevice::ReadOnly)) {
        SceneLoadResult result;
        result.errors << QStringLiteral("%1: cannot open: %2").arg(filePath, file.errorString());
        return result;
    }
    return parseScene(file.readAll(), filePath);
}

} // namespace rbw
