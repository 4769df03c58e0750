#include "app/scene/scene_writer.h"

#include "app/output/atomic_file.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QLocale>

#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace rbw {
namespace {

struct Member {
    QString key;
    QJsonValue value;
};
using Members = QList<Member>;

QJsonObject toObject(const Members& members)
{
    QJsonObject o;
    for (const Member& m : members) o.insert(m.key, m.value);
    return o;
}

QJsonArray vec(const Vec3& v) { return QJsonArray{v.x(), v.y(), v.z()}; }

// Whole numbers as JSON integers ("steps": 1000000000, not 1e+09).
QJsonValue whole(long n) { return QJsonValue(static_cast<qint64>(n)); }

QString convention(InertiaConvention c)
{
    return c == InertiaConvention::CourseTemplate ? QStringLiteral("course-template") : QStringLiteral("standard");
}

QString contactModel(ContactModel m)
{
    return m == ContactModel::Manifold ? QStringLiteral("manifold") : QStringLiteral("course");
}

QString positionFix(PositionFix f)
{
    switch (f) {
    case PositionFix::Ngs: return QStringLiteral("ngs");
    case PositionFix::Baumgarte: return QStringLiteral("baumgarte");
    case PositionFix::None: return QStringLiteral("none");
    }
    return {};
}

// The name a reference is written with: the body's (plane's) own name when the index
// names one, else the name the file gave (a scene that would not validate).
QString bodyRef(const SceneDef& s, int index, const std::string& given)
{
    if (index >= 0 && index < static_cast<int>(s.bodies.size())) return QString::fromStdString(s.bodies[index].name);
    return QString::fromStdString(given);
}

QString pairSecond(const SceneDef& s, const PairOverride& p)
{
    if (p.bodyB >= 0) return bodyRef(s, p.bodyB, p.nameB);
    if (p.planeB >= 0 && p.planeB < static_cast<int>(s.planes.size())) {
        return QString::fromStdString(s.planes[p.planeB].name);
    }
    return QString::fromStdString(p.nameB);
}

Members bodyMembers(const BodyDef& b)
{
    Members m{{"name", QString::fromStdString(b.name)}, {"size", vec(b.size)}};
    if (!b.fixed) m.append({"mass", b.mass});
    if (b.fixed) m.append({"fixed", true});
    m.append({"position", vec(b.x0_W)});
    const Quat& q = b.q0_WB;
    m.append({"orientation", QJsonObject{{"quaternion", QJsonArray{q.w(), q.x(), q.y(), q.z()}}}});
    m.append({"linear_velocity", vec(b.v0_W)});
    m.append({"angular_velocity", vec(b.omega0_W)});
    if (!b.angularResponse) m.append({"angular_response", false});
    if (!b.integrator.empty()) m.append({"integrator", QString::fromStdString(b.integrator)});
    if (b.inertiaConvention) m.append({"inertia_convention", convention(*b.inertiaConvention)});
    return m;
}

Members forceMembers(const SceneDef& s, const ForceDef& f)
{
    return {{"body", bodyRef(s, f.body, f.bodyName)},
            {"point", vec(f.p_W)},
            {"force", vec(f.f_W)},
            {"from_step", whole(f.fromStep)},
            {"to_step", whole(f.toStep)}};
}

Members torqueMembers(const SceneDef& s, const TorqueDef& t)
{
    Members m{{"body", bodyRef(s, t.body, t.bodyName)}, {"torque", vec(t.q_W)}, {"from_step", whole(t.fromStep)}};
    // Left out, a torque lasts for ever (the loader's default), which no number says.
    if (t.toStep != std::numeric_limits<long>::max()) m.append({"to_step", whole(t.toStep)});
    if (t.switchable) m.append({"switchable", true});
    if (!t.enabledAtStart) m.append({"enabled", false});
    return m;
}

Members planeMembers(const PlaneDef& p)
{
    return {{"name", QString::fromStdString(p.name)}, {"point", vec(p.point_W)}, {"normal", vec(p.n_W)}};
}

Members pairMembers(const SceneDef& s, const PairOverride& p)
{
    Members m{{"bodies", QJsonArray{bodyRef(s, p.bodyA, p.nameA), pairSecond(s, p)}}};
    if (p.restitution) m.append({"restitution", *p.restitution});
    if (p.friction) m.append({"friction", *p.friction});
    return m;
}

// The top level, in the order of docs/scene-format.md; each list as a list of Members.
struct Layout {
    Members settings;
    QList<QPair<QString, QList<Members>>> lists;
    std::optional<Members> push;
};

Layout layout(const SceneDef& s)
{
    Layout l;
    l.settings = {{"name", QString::fromStdString(s.name)},
                  {"description", QString::fromStdString(s.description)},
                  {"dt", s.dt},
                  {"steps", whole(s.steps)},
                  {"integrator", QString::fromStdString(s.integrator)},
                  {"inertia_convention", convention(s.inertiaConvention)},
                  {"gravity", vec(s.g_W)},
                  {"box_collisions", s.boxCollisions},
                  {"restitution", s.restitution},
                  {"restitution_threshold", s.restitutionThreshold},
                  {"friction", s.friction},
                  {"position_correction", s.positionCorrection},
                  {"plane_contacts", s.planeContacts == PlaneContactMode::Average ? QStringLiteral("average")
                                                                                  : QStringLiteral("per-point")},
                  {"energy_jump", QJsonObject{{"factor", s.energyJumpFactor}, {"floor", s.energyJumpFloor}}},
                  {"contact_model", contactModel(s.contactModel)}};
    // The manifold model's keys, only when given (left out, the model's defaults).
    if (s.solverIterations) l.settings.append({"solver_iterations", whole(*s.solverIterations)});
    if (s.sleep) l.settings.append({"sleep", *s.sleep});
    if (s.positionFix) l.settings.append({"position_fix", positionFix(*s.positionFix)});
    QList<Members> bodies, planes, forces, torques, probes, pairs;
    for (const BodyDef& b : s.bodies) bodies << bodyMembers(b);
    for (const PlaneDef& p : s.planes) planes << planeMembers(p);
    for (const ForceDef& f : s.forces) forces << forceMembers(s, f);
    for (const TorqueDef& t : s.torques) torques << torqueMembers(s, t);
    for (const ProbeDef& p : s.probes) probes << Members{{"body", bodyRef(s, p.body, p.bodyName)}, {"point", vec(p.p0_W)}};
    for (const PairOverride& p : s.pairs) pairs << pairMembers(s, p);
    l.lists = {{"bodies", bodies}, {"planes", planes}, {"forces", forces},
               {"torques", torques}, {"probes", probes}, {"pairs", pairs}};
    if (s.push.body >= 0 || !s.push.bodyName.empty()) {
        l.push = Members{{"body", bodyRef(s, s.push.body, s.push.bodyName)},
                         {"point", vec(s.push.p_B)},
                         {"force", s.push.magnitude}};
    }
    return l;
}

// One JSON value on one line, through QJsonDocument (its escaping, its shortest
// round-trip numbers), with a space after each comma.
QByteArray oneLine(const QJsonValue& v)
{
    if (v.isArray()) {
        QByteArrayList parts;
        for (const QJsonValue& e : v.toArray()) parts << oneLine(e);
        return '[' + parts.join(", ") + ']';
    }
    if (v.isObject()) {
        const QJsonObject o = v.toObject();
        QByteArrayList parts;
        for (auto it = o.begin(); it != o.end(); ++it) parts << oneLine(it.key()) + ": " + oneLine(it.value());
        return "{ " + parts.join(", ") + " }";
    }
    const QByteArray wrapped = QJsonDocument(QJsonArray{v}).toJson(QJsonDocument::Compact);
    return wrapped.mid(1, wrapped.size() - 2);
}

QByteArray oneLine(const Members& members)
{
    QByteArrayList parts;
    for (const Member& m : members) parts << oneLine(m.key) + ": " + oneLine(m.value);
    return "{ " + parts.join(", ") + " }";
}

} // namespace

QJsonObject sceneToJson(const SceneDef& scene)
{
    const Layout l = layout(scene);
    QJsonObject o = toObject(l.settings);
    for (const auto& [key, list] : l.lists) {
        if (key != QLatin1String("bodies") && list.isEmpty()) continue;
        QJsonArray a;
        for (const Members& m : list) a.append(toObject(m));
        o.insert(key, a);
    }
    if (l.push) o.insert("push", toObject(*l.push));
    return o;
}

QByteArray writeScene(const SceneDef& scene)
{
    const Layout l = layout(scene);
    QByteArrayList lines;
    for (const Member& m : l.settings) lines << "  " + oneLine(m.key) + ": " + oneLine(m.value);
    for (const auto& [key, list] : l.lists) {
        if (key != QLatin1String("bodies") && list.isEmpty()) continue;
        QByteArrayList items;
        for (const Members& m : list) items << "    " + oneLine(m);
        lines << "  " + oneLine(key) + ": [\n" + items.join(",\n") + "\n  ]";
    }
    if (l.push) lines << "  \"push\": " + oneLine(*l.push);
    return "{\n" + lines.join(",\n") + "\n}\n";
}

bool saveSceneFile(const SceneDef& scene, const QString& path, QString* error)
{
    return writeFileAtomically(path, writeScene(scene), error);
}

namespace {

QString num(double x) { return QString::number(x, 'g', QLocale::FloatingPointShortest); }

class Differ {
public:
    QStringList out;

    void value(const QString& path, double a, double b)
    {
        if (a != b) out << QStringLiteral("%1: %2 != %3").arg(path, num(a), num(b));
    }
    void value(const QString& path, long a, long b)
    {
        if (a != b) out << QStringLiteral("%1: %2 != %3").arg(path).arg(a).arg(b);
    }
    void value(const QString& path, bool a, bool b)
    {
        if (a != b) out << QStringLiteral("%1: %2 != %3").arg(path, a ? QStringLiteral("true") : QStringLiteral("false"), b ? QStringLiteral("true") : QStringLiteral("false"));
    }
    void value(const QString& path, const QString& a, const QString& b)
    {
        if (a != b) out << QStringLiteral("%1: \"%2\" != \"%3\"").arg(path, a, b);
    }
    void value(const QString& path, const std::string& a, const std::string& b)
    {
        value(path, QString::fromStdString(a), QString::fromStdString(b));
    }
    void value(const QString& path, const Vec3& a, const Vec3& b)
    {
        for (int i = 0; i < 3; ++i) value(QStringLiteral("%1[%2]").arg(path).arg(i), a[i], b[i]);
    }
    void value(const QString& path, const Quat& a, const Quat& b)
    {
        const std::array<double, 4> x{a.w(), a.x(), a.y(), a.z()}, y{b.w(), b.x(), b.y(), b.z()};
        for (int i = 0; i < 4; ++i) value(QStringLiteral("%1[%2]").arg(path).arg(i), x[i], y[i]);
    }
    void value(const QString& path, const std::optional<double>& a, const std::optional<double>& b)
    {
        if (a.has_value() != b.has_value()) {
            out << QStringLiteral("%1: %2 != %3").arg(path, a ? num(*a) : QStringLiteral("(none)"), b ? num(*b) : QStringLiteral("(none)"));
        } else if (a) {
            value(path, *a, *b);
        }
    }
    bool sizes(const QString& path, std::size_t a, std::size_t b)
    {
        if (a != b) out << QStringLiteral("%1: %2 entries != %3").arg(path).arg(a).arg(b);
        return a == b;
    }
};

QString at(const char* list, std::size_t i) { return QStringLiteral("%1[%2]").arg(QLatin1String(list)).arg(i); }

} // namespace

QStringList sceneDifferences(const SceneDef& a, const SceneDef& b)
{
    Differ d;
    d.value("name", a.name, b.name);
    d.value("description", a.description, b.description);
    d.value("dt", a.dt, b.dt);
    d.value("steps", a.steps, b.steps);
    d.value("integrator", a.integrator, b.integrator);
    d.value("inertia_convention", convention(a.inertiaConvention), convention(b.inertiaConvention));
    d.value("gravity", a.g_W, b.g_W);
    if (d.sizes("bodies", a.bodies.size(), b.bodies.size())) {
        for (std::size_t i = 0; i < a.bodies.size(); ++i) {
            const BodyDef& x = a.bodies[i];
            const BodyDef& y = b.bodies[i];
            const QString p = at("bodies", i);
            d.value(p + ".name", x.name, y.name);
            d.value(p + ".size", x.size, y.size);
            d.value(p + ".fixed", x.fixed, y.fixed);
            if (!x.fixed && !y.fixed) d.value(p + ".mass", x.mass, y.mass);
            d.value(p + ".angular_response", x.angularResponse, y.angularResponse);
            d.value(p + ".position", x.x0_W, y.x0_W);
            d.value(p + ".orientation", x.q0_WB, y.q0_WB);
            d.value(p + ".linear_velocity", x.v0_W, y.v0_W);
            d.value(p + ".angular_velocity", x.omega0_W, y.omega0_W);
            d.value(p + ".integrator", x.integrator, y.integrator);
            d.value(p + ".inertia_convention", x.inertiaConvention ? convention(*x.inertiaConvention) : QStringLiteral("(scene's)"),
                    y.inertiaConvention ? convention(*y.inertiaConvention) : QStringLiteral("(scene's)"));
        }
    }
    if (d.sizes("forces", a.forces.size(), b.forces.size())) {
        for (std::size_t i = 0; i < a.forces.size(); ++i) {
            const ForceDef& x = a.forces[i];
            const ForceDef& y = b.forces[i];
            const QString p = at("forces", i);
            d.value(p + ".body", bodyRef(a, x.body, x.bodyName), bodyRef(b, y.body, y.bodyName));
            d.value(p + ".body (index)", static_cast<long>(x.body), static_cast<long>(y.body));
            d.value(p + ".point", x.p_W, y.p_W);
            d.value(p + ".force", x.f_W, y.f_W);
            d.value(p + ".from_step", x.fromStep, y.fromStep);
            d.value(p + ".to_step", x.toStep, y.toStep);
        }
    }
    if (d.sizes("torques", a.torques.size(), b.torques.size())) {
        for (std::size_t i = 0; i < a.torques.size(); ++i) {
            const TorqueDef& x = a.torques[i];
            const TorqueDef& y = b.torques[i];
            const QString p = at("torques", i);
            d.value(p + ".body", bodyRef(a, x.body, x.bodyName), bodyRef(b, y.body, y.bodyName));
            d.value(p + ".body (index)", static_cast<long>(x.body), static_cast<long>(y.body));
            d.value(p + ".torque", x.q_W, y.q_W);
            d.value(p + ".from_step", x.fromStep, y.fromStep);
            d.value(p + ".to_step", x.toStep, y.toStep);
            d.value(p + ".switchable", x.switchable, y.switchable);
            d.value(p + ".enabled", x.enabledAtStart, y.enabledAtStart);
        }
    }
    d.value("push.body", bodyRef(a, a.push.body, a.push.bodyName), bodyRef(b, b.push.body, b.push.bodyName));
    d.value("push.body (index)", static_cast<long>(a.push.body), static_cast<long>(b.push.body));
    d.value("push.point", a.push.p_B, b.push.p_B);
    d.value("push.force", a.push.magnitude, b.push.magnitude);
    if (d.sizes("probes", a.probes.size(), b.probes.size())) {
        for (std::size_t i = 0; i < a.probes.size(); ++i) {
            const QString p = at("probes", i);
            d.value(p + ".body", bodyRef(a, a.probes[i].body, a.probes[i].bodyName),
                    bodyRef(b, b.probes[i].body, b.probes[i].bodyName));
            d.value(p + ".body (index)", static_cast<long>(a.probes[i].body), static_cast<long>(b.probes[i].body));
            d.value(p + ".point", a.probes[i].p0_W, b.probes[i].p0_W);
        }
    }
    if (d.sizes("planes", a.planes.size(), b.planes.size())) {
        for (std::size_t i = 0; i < a.planes.size(); ++i) {
            const QString p = at("planes", i);
            d.value(p + ".name", a.planes[i].name, b.planes[i].name);
            d.value(p + ".point", a.planes[i].point_W, b.planes[i].point_W);
            d.value(p + ".normal", a.planes[i].n_W, b.planes[i].n_W);
        }
    }
    d.value("box_collisions", a.boxCollisions, b.boxCollisions);
    d.value("restitution", a.restitution, b.restitution);
    d.value("friction", a.friction, b.friction);
    d.value("restitution_threshold", a.restitutionThreshold, b.restitutionThreshold);
    if (d.sizes("pairs", a.pairs.size(), b.pairs.size())) {
        for (std::size_t i = 0; i < a.pairs.size(); ++i) {
            const PairOverride& x = a.pairs[i];
            const PairOverride& y = b.pairs[i];
            const QString p = at("pairs", i);
            d.value(p + ".bodies[0]", bodyRef(a, x.bodyA, x.nameA), bodyRef(b, y.bodyA, y.nameA));
            d.value(p + ".bodies[1]", pairSecond(a, x), pairSecond(b, y));
            d.value(p + ".bodies (indices)", QStringLiteral("%1/%2/%3").arg(x.bodyA).arg(x.bodyB).arg(x.planeB),
                    QStringLiteral("%1/%2/%3").arg(y.bodyA).arg(y.bodyB).arg(y.planeB));
            d.value(p + ".restitution", x.restitution, y.restitution);
            d.value(p + ".friction", x.friction, y.friction);
        }
    }
    d.value("position_correction", a.positionCorrection, b.positionCorrection);
    d.value("plane_contacts", a.planeContacts == PlaneContactMode::Average, b.planeContacts == PlaneContactMode::Average);
    d.value("energy_jump.factor", a.energyJumpFactor, b.energyJumpFactor);
    d.value("energy_jump.floor", a.energyJumpFloor, b.energyJumpFloor);
    d.value("contact_model", contactModel(a.contactModel), contactModel(b.contactModel));
    d.value("solver_iterations", a.solverIterations ? QString::number(*a.solverIterations) : QStringLiteral("(none)"),
            b.solverIterations ? QString::number(*b.solverIterations) : QStringLiteral("(none)"));
    d.value("sleep", a.sleep ? QString::number(*a.sleep) : QStringLiteral("(none)"),
            b.sleep ? QString::number(*b.sleep) : QStringLiteral("(none)"));
    d.value("position_fix", a.positionFix ? positionFix(*a.positionFix) : QStringLiteral("(none)"),
            b.positionFix ? positionFix(*b.positionFix) : QStringLiteral("(none)"));
    return d.out;
}

} // namespace rbw
