#include "app/scene/scene_writer.h"

#include "app/output/atomic_file.h"
#include "app/output/json_text.h"
#include "app/scene/scene_format.h"

#include <QJsonArray>
#include <QLocale>

#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace rbw {
namespace {

using sceneformat::key;
using sceneformat::word;
using K = sceneformat::Key;

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

QString convention(InertiaConvention c) { return word(c); }
QString contactModel(ContactModel m) { return word(m); }
QString positionFix(PositionFix f) { return word(f); }

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
    Members m{{key(K::BodyName), QString::fromStdString(b.name)}, {key(K::BodySize), vec(b.size)}};
    if (!b.fixed) m.append({key(K::BodyMass), b.mass});
    if (b.fixed) m.append({key(K::BodyFixed), true});
    m.append({key(K::BodyPosition), vec(b.x0_W)});
    const Quat& q = b.q0_WB;
    m.append({key(K::BodyOrientation), QJsonObject{{key(K::OrientationQuaternion), QJsonArray{q.w(), q.x(), q.y(), q.z()}}}});
    m.append({key(K::BodyLinearVelocity), vec(b.v0_W)});
    m.append({key(K::BodyAngularVelocity), vec(b.omega0_W)});
    if (!b.angularResponse) m.append({key(K::BodyAngularResponse), false});
    if (!b.integrator.empty()) m.append({key(K::BodyIntegrator), QString::fromStdString(b.integrator)});
    if (b.inertiaConvention) m.append({key(K::BodyInertiaConvention), convention(*b.inertiaConvention)});
    return m;
}

Members forceMembers(const SceneDef& s, const ForceDef& f)
{
    return {{key(K::ForceBody), bodyRef(s, f.body, f.bodyName)},
            {key(K::ForcePoint), vec(f.p_W)},
            {key(K::ForceForce), vec(f.f_W)},
            {key(K::ForceFromStep), whole(f.fromStep)},
            {key(K::ForceToStep), whole(f.toStep)}};
}

Members torqueMembers(const SceneDef& s, const TorqueDef& t)
{
    Members m{{key(K::TorqueBody), bodyRef(s, t.body, t.bodyName)}, {key(K::TorqueTorque), vec(t.q_W)}, {key(K::TorqueFromStep), whole(t.fromStep)}};
    // Left out, a torque lasts for ever (the loader's default), which no number says.
    if (t.toStep != std::numeric_limits<long>::max()) m.append({key(K::TorqueToStep), whole(t.toStep)});
    if (t.switchable) m.append({key(K::TorqueSwitchable), true});
    if (!t.enabledAtStart) m.append({key(K::TorqueEnabled), false});
    return m;
}

Members planeMembers(const PlaneDef& p)
{
    return {{key(K::PlaneName), QString::fromStdString(p.name)}, {key(K::PlanePoint), vec(p.point_W)}, {key(K::PlaneNormal), vec(p.n_W)}};
}

Members pairMembers(const SceneDef& s, const PairOverride& p)
{
    Members m{{key(K::PairBodies), QJsonArray{bodyRef(s, p.bodyA, p.nameA), pairSecond(s, p)}}};
    if (p.restitution) m.append({key(K::PairRestitution), *p.restitution});
    if (p.friction) m.append({key(K::PairFriction), *p.friction});
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
    l.settings = {{key(K::Name), QString::fromStdString(s.name)},
                  {key(K::Description), QString::fromStdString(s.description)},
                  {key(K::Dt), s.dt},
                  {key(K::Steps), whole(s.steps)},
                  {key(K::Integrator), QString::fromStdString(s.integrator)},
                  {key(K::InertiaConvention), convention(s.inertiaConvention)},
                  {key(K::Gravity), vec(s.g_W)},
                  {key(K::BoxCollisions), s.boxCollisions},
                  {key(K::Restitution), s.restitution},
                  {key(K::RestitutionThreshold), s.restitutionThreshold},
                  {key(K::Friction), s.friction},
                  {key(K::PositionCorrection), s.positionCorrection},
                  {key(K::PlaneContacts), word(s.planeContacts)},
                  {key(K::EnergyJump), QJsonObject{{key(K::EnergyJumpFactor), s.energyJumpFactor}, {key(K::EnergyJumpFloor), s.energyJumpFloor}}},
                  {key(K::ContactModel), contactModel(s.contactModel)}};
    // The manifold model's keys, only when given (left out, the model's defaults).
    if (s.solverIterations) l.settings.append({key(K::SolverIterations), whole(*s.solverIterations)});
    if (s.sleep) l.settings.append({key(K::Sleep), *s.sleep});
    if (s.positionFix) l.settings.append({key(K::PositionFix), positionFix(*s.positionFix)});
    if (s.solver) l.settings.append({key(K::Solver), word(*s.solver)});
    if (s.substeps) l.settings.append({key(K::Substeps), whole(*s.substeps)});
    QList<Members> bodies, planes, forces, torques, probes, pairs;
    for (const BodyDef& b : s.bodies) bodies << bodyMembers(b);
    for (const PlaneDef& p : s.planes) planes << planeMembers(p);
    for (const ForceDef& f : s.forces) forces << forceMembers(s, f);
    for (const TorqueDef& t : s.torques) torques << torqueMembers(s, t);
    for (const ProbeDef& p : s.probes) probes << Members{{key(K::ProbeBody), bodyRef(s, p.body, p.bodyName)}, {key(K::ProbePoint), vec(p.p0_W)}};
    for (const PairOverride& p : s.pairs) pairs << pairMembers(s, p);
    l.lists = {{key(K::Bodies), bodies}, {key(K::Planes), planes}, {key(K::Forces), forces},
               {key(K::Torques), torques}, {key(K::Probes), probes}, {key(K::Pairs), pairs}};
    if (s.push.body >= 0 || !s.push.bodyName.empty()) {
        l.push = Members{{key(K::PushBody), bodyRef(s, s.push.body, s.push.bodyName)},
                         {key(K::PushPoint), vec(s.push.p_B)},
                         {key(K::PushForce), s.push.magnitude}};
    }
    return l;
}

// One body (force, ...) on one line, its keys in the documented order (a QJsonObject
// would sort them); each key and value through the one JSON writer.
QByteArray oneLine(const Members& members)
{
    using jsontext::oneLine;
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
        if (key != sceneformat::key(K::Bodies) && list.isEmpty()) continue;
        QJsonArray a;
        for (const Members& m : list) a.append(toObject(m));
        o.insert(key, a);
    }
    if (l.push) o.insert(key(K::Push), toObject(*l.push));
    return o;
}

QByteArray writeScene(const SceneDef& scene)
{
    const Layout l = layout(scene);
    QByteArrayList lines;
    for (const Member& m : l.settings) lines << "  " + jsontext::oneLine(m.key) + ": " + jsontext::oneLine(m.value);
    for (const auto& [key, list] : l.lists) {
        if (key != sceneformat::key(K::Bodies) && list.isEmpty()) continue;
        QByteArrayList items;
        for (const Members& m : list) items << "    " + oneLine(m);
        lines << "  " + jsontext::scalar(key) + ": [\n" + items.join(",\n") + "\n  ]";
    }
    if (l.push) lines << "  " + jsontext::scalar(key(K::Push)) + ": " + oneLine(*l.push);
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

QString at(K list, std::size_t i) { return QStringLiteral("%1[%2]").arg(key(list)).arg(i); }

} // namespace

QStringList sceneDifferences(const SceneDef& a, const SceneDef& b)
{
    Differ d;
    const QString push = key(K::Push) + '.';
    const QString energyJump = key(K::EnergyJump) + '.';
    d.value(key(K::Name), a.name, b.name);
    d.value(key(K::Description), a.description, b.description);
    d.value(key(K::Dt), a.dt, b.dt);
    d.value(key(K::Steps), a.steps, b.steps);
    d.value(key(K::Integrator), a.integrator, b.integrator);
    d.value(key(K::InertiaConvention), convention(a.inertiaConvention), convention(b.inertiaConvention));
    d.value(key(K::Gravity), a.g_W, b.g_W);
    if (d.sizes(key(K::Bodies), a.bodies.size(), b.bodies.size())) {
        for (std::size_t i = 0; i < a.bodies.size(); ++i) {
            const BodyDef& x = a.bodies[i];
            const BodyDef& y = b.bodies[i];
            const QString p = at(K::Bodies, i);
            d.value(p + '.' + key(K::BodyName), x.name, y.name);
            d.value(p + '.' + key(K::BodySize), x.size, y.size);
            d.value(p + '.' + key(K::BodyFixed), x.fixed, y.fixed);
            if (!x.fixed && !y.fixed) d.value(p + '.' + key(K::BodyMass), x.mass, y.mass);
            d.value(p + '.' + key(K::BodyAngularResponse), x.angularResponse, y.angularResponse);
            d.value(p + '.' + key(K::BodyPosition), x.x0_W, y.x0_W);
            d.value(p + '.' + key(K::BodyOrientation), x.q0_WB, y.q0_WB);
            d.value(p + '.' + key(K::BodyLinearVelocity), x.v0_W, y.v0_W);
            d.value(p + '.' + key(K::BodyAngularVelocity), x.omega0_W, y.omega0_W);
            d.value(p + '.' + key(K::BodyIntegrator), x.integrator, y.integrator);
            d.value(p + '.' + key(K::BodyInertiaConvention), x.inertiaConvention ? convention(*x.inertiaConvention) : QStringLiteral("(scene's)"),
                    y.inertiaConvention ? convention(*y.inertiaConvention) : QStringLiteral("(scene's)"));
        }
    }
    if (d.sizes(key(K::Forces), a.forces.size(), b.forces.size())) {
        for (std::size_t i = 0; i < a.forces.size(); ++i) {
            const ForceDef& x = a.forces[i];
            const ForceDef& y = b.forces[i];
            const QString p = at(K::Forces, i);
            d.value(p + '.' + key(K::ForceBody), bodyRef(a, x.body, x.bodyName), bodyRef(b, y.body, y.bodyName));
            d.value(p + '.' + key(K::ForceBody) + " (index)", static_cast<long>(x.body), static_cast<long>(y.body));
            d.value(p + '.' + key(K::ForcePoint), x.p_W, y.p_W);
            d.value(p + '.' + key(K::ForceForce), x.f_W, y.f_W);
            d.value(p + '.' + key(K::ForceFromStep), x.fromStep, y.fromStep);
            d.value(p + '.' + key(K::ForceToStep), x.toStep, y.toStep);
        }
    }
    if (d.sizes(key(K::Torques), a.torques.size(), b.torques.size())) {
        for (std::size_t i = 0; i < a.torques.size(); ++i) {
            const TorqueDef& x = a.torques[i];
            const TorqueDef& y = b.torques[i];
            const QString p = at(K::Torques, i);
            d.value(p + '.' + key(K::TorqueBody), bodyRef(a, x.body, x.bodyName), bodyRef(b, y.body, y.bodyName));
            d.value(p + '.' + key(K::TorqueBody) + " (index)", static_cast<long>(x.body), static_cast<long>(y.body));
            d.value(p + '.' + key(K::TorqueTorque), x.q_W, y.q_W);
            d.value(p + '.' + key(K::TorqueFromStep), x.fromStep, y.fromStep);
            d.value(p + '.' + key(K::TorqueToStep), x.toStep, y.toStep);
            d.value(p + '.' + key(K::TorqueSwitchable), x.switchable, y.switchable);
            d.value(p + '.' + key(K::TorqueEnabled), x.enabledAtStart, y.enabledAtStart);
        }
    }
    d.value(push + key(K::PushBody), bodyRef(a, a.push.body, a.push.bodyName), bodyRef(b, b.push.body, b.push.bodyName));
    d.value(push + key(K::PushBody) + " (index)", static_cast<long>(a.push.body), static_cast<long>(b.push.body));
    d.value(push + key(K::PushPoint), a.push.p_B, b.push.p_B);
    d.value(push + key(K::PushForce), a.push.magnitude, b.push.magnitude);
    if (d.sizes(key(K::Probes), a.probes.size(), b.probes.size())) {
        for (std::size_t i = 0; i < a.probes.size(); ++i) {
            const QString p = at(K::Probes, i);
            d.value(p + '.' + key(K::ProbeBody), bodyRef(a, a.probes[i].body, a.probes[i].bodyName),
                    bodyRef(b, b.probes[i].body, b.probes[i].bodyName));
            d.value(p + '.' + key(K::ProbeBody) + " (index)", static_cast<long>(a.probes[i].body), static_cast<long>(b.probes[i].body));
            d.value(p + '.' + key(K::ProbePoint), a.probes[i].p0_W, b.probes[i].p0_W);
        }
    }
    if (d.sizes(key(K::Planes), a.planes.size(), b.planes.size())) {
        for (std::size_t i = 0; i < a.planes.size(); ++i) {
            const QString p = at(K::Planes, i);
            d.value(p + '.' + key(K::PlaneName), a.planes[i].name, b.planes[i].name);
            d.value(p + '.' + key(K::PlanePoint), a.planes[i].point_W, b.planes[i].point_W);
            d.value(p + '.' + key(K::PlaneNormal), a.planes[i].n_W, b.planes[i].n_W);
        }
    }
    d.value(key(K::BoxCollisions), a.boxCollisions, b.boxCollisions);
    d.value(key(K::Restitution), a.restitution, b.restitution);
    d.value(key(K::Friction), a.friction, b.friction);
    d.value(key(K::RestitutionThreshold), a.restitutionThreshold, b.restitutionThreshold);
    if (d.sizes(key(K::Pairs), a.pairs.size(), b.pairs.size())) {
        for (std::size_t i = 0; i < a.pairs.size(); ++i) {
            const PairOverride& x = a.pairs[i];
            const PairOverride& y = b.pairs[i];
            const QString p = at(K::Pairs, i);
            d.value(p + '.' + key(K::PairBodies) + "[0]", bodyRef(a, x.bodyA, x.nameA), bodyRef(b, y.bodyA, y.nameA));
            d.value(p + '.' + key(K::PairBodies) + "[1]", pairSecond(a, x), pairSecond(b, y));
            d.value(p + '.' + key(K::PairBodies) + " (indices)", QStringLiteral("%1/%2/%3").arg(x.bodyA).arg(x.bodyB).arg(x.planeB),
                    QStringLiteral("%1/%2/%3").arg(y.bodyA).arg(y.bodyB).arg(y.planeB));
            d.value(p + '.' + key(K::PairRestitution), x.restitution, y.restitution);
            d.value(p + '.' + key(K::PairFriction), x.friction, y.friction);
        }
    }
    d.value(key(K::PositionCorrection), a.positionCorrection, b.positionCorrection);
    d.value(key(K::PlaneContacts), a.planeContacts == PlaneContactMode::Average, b.planeContacts == PlaneContactMode::Average);
    d.value(energyJump + key(K::EnergyJumpFactor), a.energyJumpFactor, b.energyJumpFactor);
    d.value(energyJump + key(K::EnergyJumpFloor), a.energyJumpFloor, b.energyJumpFloor);
    d.value(key(K::ContactModel), contactModel(a.contactModel), contactModel(b.contactModel));
    d.value(key(K::SolverIterations), a.solverIterations ? QString::number(*a.solverIterations) : QStringLiteral("(none)"),
            b.solverIterations ? QString::number(*b.solverIterations) : QStringLiteral("(none)"));
    d.value(key(K::Sleep), a.sleep ? QString::number(*a.sleep) : QStringLiteral("(none)"),
            b.sleep ? QString::number(*b.sleep) : QStringLiteral("(none)"));
    d.value(key(K::PositionFix), a.positionFix ? positionFix(*a.positionFix) : QStringLiteral("(none)"),
            b.positionFix ? positionFix(*b.positionFix) : QStringLiteral("(none)"));
    d.value(key(K::Solver), a.solver ? word(*a.solver) : QStringLiteral("(none)"),
            b.solver ? word(*b.solver) : QStringLiteral("(none)"));
    d.value(key(K::Substeps), a.substeps ? QString::number(*a.substeps) : QStringLiteral("(none)"),
            b.substeps ? QString::number(*b.substeps) : QStringLiteral("(none)"));
    return d.out;
}

} // namespace rbw
