#include "app/scene/scene_loader.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QLocale>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

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

// What a message echoes from the file (a key, a word): cut and escaped by physics'
// messageText(). It keeps 40 characters; 200 UTF-16 units hold at least 100, so a
// 50 MB key is never copied whole.
QString shown(const QString& text)
{
    return QString::fromStdString(messageText(text.left(200).toStdString()));
}

// The shortest text that reads back as the same double (2.0000001, not Qt's default 2).
QString numText(double x)
{
    return QString::number(x, 'g', QLocale::FloatingPointShortest);
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
            // The distance is at least the difference in length: a long key is never
            // compared letter by letter (a 50 MB key took 15 s).
            if (std::abs(it.key().size() - k.size()) >= bestDistance) {
                continue;
            }
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
        throw FieldError{join(path, shown(it.key())), reason};
    }
}

QJsonValue require(const QJsonObject& o, const QString& path, const QString& key)
{
    if (!o.contains(key)) {
        throw FieldError{join(path, key), QStringLiteral("required field is missing")};
    }
    return o.value(key);
}

// A number JSON cannot hold (NaN, Infinity, 1e999) is refused by QJsonDocument, and
// the raw scan in parseScene() names its field; the check below only guards that.
double toNumber(const QJsonValue& v, const QString& path)
{
    if (!v.isDouble()) {
        throw FieldError{path, QStringLiteral("must be a number, got %1").arg(typeName(v))};
    }
    const double x = v.toDouble();
    if (!std::isfinite(x)) {
        throw FieldError{path, QStringLiteral("must be a finite number, got %1").arg(numText(x))};
    }
    return x;
}

// Whole numbers are read into a long; beyond 9e15 a double no longer holds every
// whole number, so larger ones are refused here (steps has its own, lower limit).
long toInteger(const QJsonValue& v, const QString& path)
{
    const double x = toNumber(v, path);
    if (x != std::floor(x)) {
        throw FieldError{path, QStringLiteral("must be a whole number, got %1").arg(numText(x))};
    }
    if (std::abs(x) > 9.0e15) {
        throw FieldError{path, QStringLiteral("must be a whole number from -9e15 to 9e15, got %1").arg(numText(x))};
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

// A vector or quaternion is normalised by dividing by its length, sqrt of the sum of
// the squares: that sum must neither overflow ([1e308, 1e308, 0]) nor round to 0
// ([1e-200, 0, 0]), or the direction is lost (it used to become the identity).
void requireNormalisable(double squaredNorm, const QString& path)
{
    if (!std::isfinite(squaredNorm)) {
        throw FieldError{path, QStringLiteral("its length overflows (the sum of the squares exceeds the largest "
                                              "double), so it cannot be normalised; only its direction counts, so "
                                              "divide it by a large number")};
    }
    if (squaredNorm == 0.0) {
        throw FieldError{path, QStringLiteral("its length underflows (the sum of the squares rounds to 0), so it "
                                              "cannot be normalised; only its direction counts, so multiply it by "
                                              "a large number")};
    }
}

// A length that is 1 to rounding (|x.x - 1| <= 16 eps): normalising it again would only
// move the last bits, so it is kept as written and a scene the app saved (scene_writer.h)
// reads back bit for bit.
bool isUnitToRounding(double squaredNorm)
{
    return std::abs(squaredNorm - 1.0) <= 16 * std::numeric_limits<double>::epsilon();
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

// 1-based line and column of a byte offset.
std::pair<qsizetype, qsizetype> lineColumn(const QByteArray& text, qsizetype offset)
{
    qsizetype line = 1;
    qsizetype column = 1;
    for (qsizetype i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return {line, column};
}

QString at(const QByteArray& text, qsizetype offset)
{
    const auto [line, column] = lineColumn(text, offset);
    return QStringLiteral("line %1, column %2").arg(line).arg(column);
}

// A problem the raw scan finds: its JSON path and the reason.
struct RawFinding {
    QString path;
    QString reason;
};

bool isBareChar(char c)
{
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '+' || c == '-' ||
           c == '.';
}

// What a bare word that QJsonDocument refused stands for, as a reason; empty if it is
// something else (a typo such as `tru`), which QJsonDocument's own error describes.
QString nonFiniteReason(const QByteArray& token)
{
    const QByteArray word = token.toLower();
    if (word == "nan" || word == "-nan" || word == "+nan" || word == "infinity" || word == "-infinity" ||
        word == "+infinity" || word == "inf" || word == "-inf" || word == "+inf") {
        return QStringLiteral("must be a finite number, got %1 (not a JSON number: JSON has no literal for a "
                              "value that is not finite)")
            .arg(QString::fromLatin1(token));
    }
    bool ok = false;
    token.toDouble(&ok);   // as QJsonDocument reads a number
    if (ok || token.isEmpty()) {
        return {};
    }
    // A decimal number out of a double's range: read as a long double (locale-free),
    // whose range reaches 1e4932, it shows which side; beyond that, the exponent's sign.
    // libstdc++ 12's from_chars for long double runs strlen over its input for a word
    // that starts like "-Inf" (a fuzz finding, docs/reliability.md): give it its own
    // '\0'-terminated copy, whatever the token's buffer holds after its end.
    const std::string text(token.constData(), static_cast<std::size_t>(token.size()));
    long double x = 0.0L;
    const char* const last = text.data() + text.size();
    const std::from_chars_result r = std::from_chars(text.data(), last, x);
    if (r.ptr != last || (r.ec != std::errc() && r.ec != std::errc::result_out_of_range)) {
        return {};   // not a number at all: QJsonDocument's message
    }
    const bool tooLarge = r.ec == std::errc() ? std::abs(x) > std::numeric_limits<double>::max()
                                              : !word.contains("e-");
    if (tooLarge) {
        return QStringLiteral("must be a finite number, got %1 (too large for a double, whose largest value is "
                              "1.8e308)")
            .arg(QString::fromLatin1(token));
    }
    return QStringLiteral("must be a number a double can hold, got %1 (nearer to 0 than any double but 0; "
                          "write 0 if 0 is meant)")
        .arg(QString::fromLatin1(token));
}

// One pass over the raw bytes, for what QJsonDocument does not say: it keeps the last
// of two equal keys in an object silently, and reports NaN, Infinity or 1e999 only as
// "illegal number" at an offset. The scan follows the nesting of objects and arrays,
// so it names the JSON path of
//   - a key given twice in one object (compared after unescaping, as QJsonDocument
//     compares them), and
//   - with checkNumbers, a bare word that stands for a number a double cannot hold.
// It stops at the first finding, and looks only at tokens that start before `end`:
// the text QJsonDocument read without error, which is therefore JSON. Each open
// object keeps a hash set of its keys, so the scan is linear in the text.
std::optional<RawFinding> scanJson(const QByteArray& json, qsizetype end, bool checkNumbers)
{
    struct Frame {
        bool object = false;
        std::string key;                                      // object: the current member's key
        qsizetype index = 0;                                  // array: the current element
        bool expectKey = true;                                // object: the next string is a key
        std::unordered_map<std::string, qsizetype> keys = {}; // object: each key's first offset
    };
    std::vector<Frame> stack;
    auto path = [&stack] {
        QString p;
        for (const Frame& f : stack) {
            if (f.object) {
                p += (p.isEmpty() ? QString() : QStringLiteral(".")) + shown(QString::fromStdString(f.key));
            } else {
                p += QStringLiteral("[%1]").arg(f.index);
            }
        }
        return p;
    };
    const char* text = json.constData();
    const qsizetype size = json.size();
    qsizetype i = json.startsWith("\xef\xbb\xbf") ? 3 : 0;   // a UTF-8 byte order mark, which QJsonDocument skips
    while (i < end && i < size) {
        const char c = text[i];
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ':') {
            ++i;
        } else if (c == '{' || c == '[') {
            Frame frame;
            frame.object = c == '{';
            stack.push_back(std::move(frame));
            ++i;
        } else if (c == '}' || c == ']') {
            if (stack.empty()) return std::nullopt;
            stack.pop_back();
            ++i;
        } else if (c == ',') {
            if (stack.empty()) return std::nullopt;
            Frame& f = stack.back();
            if (f.object) {
                f.expectKey = true;
            } else {
                ++f.index;
            }
            ++i;
        } else if (c == '"') {
            qsizetype j = i + 1;
            bool escaped = false;
            while (j < size && text[j] != '"') {
                escaped = escaped || text[j] == '\\';
                j += text[j] == '\\' ? 2 : 1;
            }
            if (j >= size) return std::nullopt;
            if (!stack.empty() && stack.back().object && stack.back().expectKey) {
                Frame& f = stack.back();
                f.expectKey = false;
                // Unescaped by QJsonDocument itself, so "m\u0061ss" is "mass" here too.
                f.key = escaped ? QJsonDocument::fromJson("[" + json.mid(i, j + 1 - i) + "]")
                                      .array()
                                      .at(0)
                                      .toString()
                                      .toStdString()
                                : std::string(text + i + 1, text + j);
                const auto [first, isNew] = f.keys.emplace(f.key, i);
                if (!isNew) {
                    return RawFinding{path(),
                                      QStringLiteral("duplicate key \"%1\" (first at %2, again at %3); a key may "
                                                     "appear only once in an object")
                                          .arg(shown(QString::fromStdString(f.key)), at(json, first->second),
                                               at(json, i))};
                }
            }
            i = j + 1;
        } else if (isBareChar(c)) {
            qsizetype j = i;
            while (j < size && isBareChar(text[j])) ++j;
            if (checkNumbers) {
                const QString reason = nonFiniteReason(json.mid(i, j - i));
                if (!reason.isEmpty()) {
                    return RawFinding{path(), reason};
                }
            }
            i = j;
        } else {
            return std::nullopt;   // not JSON: QJsonDocument's error says where
        }
    }
    return std::nullopt;
}

} // namespace

SceneLoadResult parseScene(const QByteArray& json, const QString& fileLabel)
{
    SceneLoadResult result;
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    const bool parsed = parseError.error == QJsonParseError::NoError;
    const bool badWord = parseError.error == QJsonParseError::IllegalNumber ||
                         parseError.error == QJsonParseError::IllegalValue;
    if (parsed || badWord) {
        // Duplicate keys in a file that parsed; the field of a NaN or 1e999 where
        // QJsonDocument stopped (its error offset lies in or after that token).
        const qsizetype end = parsed ? json.size() : parseError.offset + 1;
        if (const std::optional<RawFinding> f = scanJson(json, end, badWord)) {
            result.errors << QStringLiteral("%1: %2: %3").arg(fileLabel, f->path, f->reason);
            return result;
        }
    }
    if (!parsed) {
        // QJsonParseError::offset points at (or just after) the offending token.
        result.errors << QStringLiteral("%1: malformed JSON at %2: %3")
                             .arg(fileLabel, at(json, parseError.offset), parseError.errorString());
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
        const std::vector<SceneIssue> issues = validate(scene);
        // Every problem, up to a screenful: 100 000 bad bodies need not print 100 000 lines.
        constexpr std::size_t kShown = 100;
        for (std::size_t i = 0; i < issues.size() && i < kShown; ++i) {
            result.errors << QStringLiteral("%1: %2: %3")
                                 .arg(fileLabel, QString::fromStdString(issues[i].path),
                                      QString::fromStdString(issues[i].reason));
        }
        if (issues.size() > kShown) {
            result.errors << QStringLiteral("%1: \u2026 and %2 more problems (the first %3 are listed)")
                                 .arg(fileLabel)
                                 .arg(issues.size() - kShown)
                                 .arg(kShown);
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
