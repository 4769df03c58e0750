#include "app/gui/panels/editor/scene_editor_model.h"

#include "physics/engine/integrator_registry.h"

#include <QBrush>
#include <QColor>
#include <QFont>
#include <QLocale>
#include <QRegularExpression>

#include <cmath>
#include <limits>

namespace rbw {

namespace {

constexpr long kForever = std::numeric_limits<long>::max();
const QString kScenes = QStringLiteral("(scene's)");
const QString kNever = QStringLiteral("never");
const QString kDefault = QStringLiteral("(default)");

QString positionFixText(PositionFix f)
{
    return f == PositionFix::Ngs ? QStringLiteral("ngs") : f == PositionFix::Baumgarte ? QStringLiteral("baumgarte")
                                                                                        : QStringLiteral("none");
}

const char* const kGroupKeys[] = {"", "bodies", "forces", "torques", "probes", "planes", "pairs"};
const char* const kGroupTitles[] = {"Settings", "Bodies", "Forces", "Torques", "Probes", "Planes", "Pairs"};

// The unit shown beside a key, and a one-line meaning (docs/scene-format.md).
struct KeyInfo {
    const char* unit;
    const char* meaning;
};

const QHash<QString, KeyInfo>& keyInfo()
{
    static const QHash<QString, KeyInfo> info{
        {"name", {"", "title of the scene; unique name of a body or plane"}},
        {"description", {"", "one-line summary"}},
        {"dt", {"s", "time step h; > 0"}},
        {"steps", {"", "steps `rbw run` takes; 0 … 10^9"}},
        {"integrator", {"", "integration method (rbw integrators)"}},
        {"inertia_convention", {"", "standard: I⁻¹ = R I0⁻¹ Rᵀ; course-template: Rᵀ I0⁻¹ R"}},
        {"gravity", {"m/s²", "gravitational acceleration g, world frame"}},
        {"box_collisions", {"", "boxes collide with each other"}},
        {"restitution", {"", "coefficient of restitution c, 0 … 1"}},
        {"restitution_threshold", {"m/s", "approaches slower than this do not bounce; 0 is off"}},
        {"friction", {"", "Coulomb friction coefficient μ ≥ 0"}},
        {"position_correction", {"", "push penetrating bodies apart after the impulses"}},
        {"plane_contacts", {"", "per-point: one impulse per corner; average: one at their mean"}},
        {"energy_jump.factor", {"", "blow-up bound: 0 (off) or ≥ 1"}},
        {"energy_jump.floor", {"J", "blow-up bound floor, ≥ 0"}},
        {"size", {"m", "edge lengths a, b, c along body x, y, z"}},
        {"mass", {"kg", "M > 0 (a fixed body has none)"}},
        {"fixed", {"", "infinite mass: never moves"}},
        {"position", {"m", "centre of mass at t = 0"}},
        {"orientation", {"", "unit quaternion w, x, y, z (body → world) at t = 0; normalised"}},
        {"linear_velocity", {"m/s", "v at t = 0"}},
        {"angular_velocity", {"rad/s", "ω at t = 0, world frame"}},
        {"angular_response", {"", "off: in collisions a particle (L never changes)"}},
        {"body", {"", "the body it acts on"}},
        {"point", {"m", "world point at t = 0"}},
        {"force", {"N", "force f, world frame"}},
        {"torque", {"N m", "torque q, world frame"}},
        {"from_step", {"", "first step in which it acts"}},
        {"to_step", {"", "first step in which it no longer acts"}},
        {"switchable", {"", "the K key turns it off and on"}},
        {"enabled", {"", "on at the start"}},
        {"normal", {"", "towards the free side; normalised"}},
        {"bodies[0]", {"", "a body"}},
        {"contact_model", {"", "course: one impulse per contact point; manifold: manifolds and an iterative solver"}},
        {"solver_iterations", {"", "manifold model: velocity iterations (empty: the default)"}},
        {"sleep", {"", "manifold model: bodies at rest sleep"}},
        {"position_fix", {"", "manifold model: how overlap is removed"}},
        {"bodies[1]", {"", "a body or a plane"}},
    };
    return info;
}

QString num(double x) { return QString::number(x, 'g', QLocale::FloatingPointShortest); }

QString vecText(const Vec3& v) { return QStringLiteral("%1, %2, %3").arg(num(v.x()), num(v.y()), num(v.z())); }

QString convention(InertiaConvention c)
{
    return c == InertiaConvention::CourseTemplate ? QStringLiteral("course-template") : QStringLiteral("standard");
}

QString quoted(const QString& text) { return QStringLiteral("\"%1\"").arg(text.left(40)); }

// Numbers from "1, 2, 3", "[1 2 3]" or "1;2;3" (C locale: a point is the decimal sign).
bool parseNumbers(const QString& text, int count, QList<double>* out, QString* error)
{
    QString t = text.trimmed();
    if (t.startsWith('[') && t.endsWith(']')) t = t.mid(1, t.size() - 2);
    static const QRegularExpression separator(QStringLiteral("[,;\\s]+"));
    const QStringList parts = t.split(separator, Qt::SkipEmptyParts);
    if (parts.size() != count) {
        *error = QStringLiteral("must be %1 numbers separated by commas, got %2").arg(count).arg(quoted(text));
        return false;
    }
    for (const QString& p : parts) {
        bool ok = false;
        const double x = QLocale::c().toDouble(p, &ok);
        if (!ok || !std::isfinite(x)) {
            *error = QStringLiteral("must be %1 finite numbers, got %2").arg(count).arg(quoted(p));
            return false;
        }
        out->append(x);
    }
    return true;
}

bool parseNumber(const QString& text, double* x, QString* error)
{
    bool ok = false;
    *x = QLocale::c().toDouble(text.trimmed(), &ok);
    if (!ok || !std::isfinite(*x)) {
        *error = QStringLiteral("must be a finite number, got %1").arg(quoted(text));
        return false;
    }
    return true;
}

// As the loader reads a whole number: no fraction, at most 9e15 in size.
bool parseWhole(const QString& text, long* n, QString* error)
{
    double x = 0;
    if (!parseNumber(text, &x, error)) return false;
    if (x != std::floor(x) || std::abs(x) > 9.0e15) {
        *error = QStringLiteral("must be a whole number from -9e15 to 9e15, got %1").arg(num(x));
        return false;
    }
    *n = static_cast<long>(x);
    return true;
}

bool parseVec(const QString& text, Vec3* v, QString* error)
{
    QList<double> n;
    if (!parseNumbers(text, 3, &n, error)) return false;
    *v = Vec3(n[0], n[1], n[2]);
    return true;
}

// As the loader: a direction is normalised unless it is unit to rounding already.
template <typename V>
V normalisedAsLoaded(const V& v)
{
    return std::abs(v.squaredNorm() - 1.0) <= 16 * std::numeric_limits<double>::epsilon() ? v : v.normalized();
}

bool isBool(int group, const QString& key)
{
    if (group == SceneEditorModel::Settings) return key == "box_collisions" || key == "position_correction";
    if (group == SceneEditorModel::Bodies) return key == "fixed" || key == "angular_response";
    if (group == SceneEditorModel::Torques) return key == "switchable" || key == "enabled";
    return false;
}

int decodeGroup(quintptr id) { return static_cast<int>(id & 0xF); }
int decodeProperty(quintptr id) { return static_cast<int>((id >> 4) & 0xFF) - 1; }
int decodeElement(quintptr id) { return static_cast<int>(id >> 12) - 1; }

} // namespace

SceneEditorModel::SceneEditorModel(QObject* parent)
    : QAbstractItemModel(parent)
{
}

quintptr SceneEditorModel::pack(int group, int element, int property)
{
    return static_cast<quintptr>(group) | (static_cast<quintptr>(property + 1) << 4) |
           (static_cast<quintptr>(element + 1) << 12);
}

void SceneEditorModel::setScene(const SceneDef& scene)
{
    beginResetModel();
    scene_ = scene;
    issues_.clear();
    endResetModel();
}

void SceneEditorModel::setIssues(const QHash<QString, QString>& issues)
{
    issues_ = issues;
    refreshAll();
}

// Every row's text and colour may have changed (a name shows in other rows' titles).
void SceneEditorModel::refreshAll()
{
    for (int g = 0; g < GroupCount; ++g) {
        const QModelIndex group = index(g, 0);
        emit dataChanged(group, group.siblingAtColumn(ValueColumn));
        const int n = rowCount(group);
        if (n > 0) emit dataChanged(index(0, 0, group), index(n - 1, ColumnCount - 1, group));
        for (int e = 0; e < n; ++e) {
            const QModelIndex element = index(e, 0, group);
            const int m = rowCount(element);
            if (m > 0) emit dataChanged(index(0, 0, element), index(m - 1, ColumnCount - 1, element));
        }
    }
}

int SceneEditorModel::elementCount(int group) const
{
    switch (group) {
    case Bodies: return static_cast<int>(scene_.bodies.size());
    case Forces: return static_cast<int>(scene_.forces.size());
    case Torques: return static_cast<int>(scene_.torques.size());
    case Probes: return static_cast<int>(scene_.probes.size());
    case Planes: return static_cast<int>(scene_.planes.size());
    case Pairs: return static_cast<int>(scene_.pairs.size());
    default: return 0;
    }
}

QStringList SceneEditorModel::properties(int group) const
{
    switch (group) {
    case Settings:
        return {"name",        "description",           "dt",       "steps",
                "integrator",  "inertia_convention",    "gravity",  "box_collisions",
                "restitution", "restitution_threshold", "friction", "position_correction",
                "plane_contacts", "energy_jump.factor", "energy_jump.floor", "contact_model",
                "solver_iterations", "sleep", "position_fix"};
    case Bodies:
        return {"name",     "size",            "mass",             "fixed",           "position", "orientation",
                "linear_velocity", "angular_velocity", "angular_response", "integrator", "inertia_convention"};
    case Forces: return {"body", "point", "force", "from_step", "to_step"};
    case Torques: return {"body", "torque", "from_step", "to_step", "switchable", "enabled"};
    case Probes: return {"body", "point"};
    case Planes: return {"name", "point", "normal"};
    case Pairs: return {"bodies[0]", "bodies[1]", "restitution", "friction"};
    default: return {};
    }
}

QString SceneEditorModel::pathOf(int group, int element, int property) const
{
    if (group == Settings) return property < 0 ? QString() : properties(group).value(property);
    QString path = QString::fromLatin1(kGroupKeys[group]);
    if (element < 0) return path;
    path += QStringLiteral("[%1]").arg(element);
    if (property < 0) return path;
    return path + '.' + properties(group).value(property);
}

QStringList SceneEditorModel::bodyNames() const
{
    QStringList names;
    for (const BodyDef& b : scene_.bodies) names << QString::fromStdString(b.name);
    return names;
}

QString SceneEditorModel::elementTitle(int group, int element) const
{
    auto bodyName = [this](int i, const std::string& given) {
        return i >= 0 && i < static_cast<int>(scene_.bodies.size()) ? QString::fromStdString(scene_.bodies[i].name)
                                                                     : QString::fromStdString(given);
    };
    switch (group) {
    case Bodies: return QString::fromStdString(scene_.bodies[element].name);
    case Planes: return QString::fromStdString(scene_.planes[element].name);
    case Forces: {
        const ForceDef& f = scene_.forces[element];
        return QStringLiteral("force on %1").arg(bodyName(f.body, f.bodyName));
    }
    case Torques: {
        const TorqueDef& t = scene_.torques[element];
        return QStringLiteral("torque on %1").arg(bodyName(t.body, t.bodyName));
    }
    case Probes: {
        const ProbeDef& p = scene_.probes[element];
        return QStringLiteral("probe on %1").arg(bodyName(p.body, p.bodyName));
    }
    case Pairs: {
        const PairOverride& p = scene_.pairs[element];
        QString second = QString::fromStdString(p.nameB);
        if (p.bodyB >= 0) second = bodyName(p.bodyB, p.nameB);
        if (p.planeB >= 0 && p.planeB < static_cast<int>(scene_.planes.size())) {
            second = QString::fromStdString(scene_.planes[p.planeB].name);
        }
        return QStringLiteral("%1 – %2").arg(bodyName(p.bodyA, p.nameA), second);
    }
    default: return {};
    }
}

QModelIndex SceneEditorModel::index(int row, int column, const QModelIndex& parent) const
{
    if (row < 0 || column < 0 || column >= ColumnCount) return {};
    if (!parent.isValid()) {
        return row < GroupCount ? createIndex(row, column, pack(row, -1, -1)) : QModelIndex();
    }
    const quintptr id = parent.internalId();
    const int group = decodeGroup(id);
    const int element = decodeElement(id);
    const int property = decodeProperty(id);
    if (property >= 0) return {};   // a property has no children
    if (group == Settings) {
        return row < properties(Settings).size() ? createIndex(row, column, pack(Settings, -1, row)) : QModelIndex();
    }
    if (element < 0) return row < elementCount(group) ? createIndex(row, column, pack(group, row, -1)) : QModelIndex();
    return row < properties(group).size() ? createIndex(row, column, pack(group, element, row)) : QModelIndex();
}

QModelIndex SceneEditorModel::parent(const QModelIndex& child) const
{
    if (!child.isValid()) return {};
    const quintptr id = child.internalId();
    const int group = decodeGroup(id);
    const int element = decodeElement(id);
    const int property = decodeProperty(id);
    if (element < 0 && property < 0) return {};                                     // a group
    if (element < 0 || property < 0) return createIndex(group, 0, pack(group, -1, -1));   // a setting, an element
    return createIndex(element, 0, pack(group, element, -1));                       // an element's property
}

int SceneEditorModel::rowCount(const QModelIndex& parent) const
{
    if (!parent.isValid()) return GroupCount;
    if (parent.column() != 0) return 0;
    const quintptr id = parent.internalId();
    const int group = decodeGroup(id);
    const int element = decodeElement(id);
    if (decodeProperty(id) >= 0) return 0;
    if (group == Settings) return static_cast<int>(properties(Settings).size());
    return element < 0 ? elementCount(group) : static_cast<int>(properties(group).size());
}

int SceneEditorModel::columnCount(const QModelIndex&) const { return ColumnCount; }

SceneEditorModel::Group SceneEditorModel::groupOf(const QModelIndex& index)
{
    return index.isValid() ? static_cast<Group>(decodeGroup(index.internalId())) : GroupCount;
}

int SceneEditorModel::elementOf(const QModelIndex& index)
{
    return index.isValid() ? decodeElement(index.internalId()) : -1;
}

QVariant SceneEditorModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    return section == KeyColumn ? tr("Key") : tr("Value");
}

Qt::ItemFlags SceneEditorModel::flags(const QModelIndex& index) const
{
    if (!index.isValid()) return Qt::NoItemFlags;
    const int property = decodeProperty(index.internalId());
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (property < 0 || index.column() != ValueColumn) return f;
    const int group = decodeGroup(index.internalId());
    const QString key = properties(group).value(property);
    if (isBool(group, key)) return f | Qt::ItemIsUserCheckable;
    if (group == Bodies && key == "mass" && scene_.bodies[decodeElement(index.internalId())].fixed) return f;
    return f | Qt::ItemIsEditable;
}

QVariant SceneEditorModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid()) return {};
    const quintptr id = index.internalId();
    const int group = decodeGroup(id);
    const int element = decodeElement(id);
    const int property = decodeProperty(id);
    const QString path = pathOf(group, element, property);
    if (role == PathRole) return path;

    if (property < 0) {   // a group or an element
        if (role == Qt::DisplayRole && index.column() == KeyColumn) {
            return element < 0 ? tr(kGroupTitles[group]) : elementTitle(group, element);
        }
        if (role == Qt::DisplayRole && index.column() == ValueColumn && element < 0 && group != Settings) {
            const int n = elementCount(group);
            return n == 1 ? tr("1 item") : tr("%1 items").arg(n);
        }
        if (role == Qt::FontRole && element < 0) {
            QFont bold;
            bold.setBold(true);
            return bold;
        }
        if (role == Qt::ToolTipRole && issues_.contains(path)) return issues_.value(path);
        if (role == Qt::BackgroundRole && issues_.contains(path)) return QBrush(QColor(0xf9, 0xd6, 0xd5));
        return {};
    }
    const QString key = properties(group).value(property);
    if (role == Qt::BackgroundRole) {
        for (auto it = issues_.begin(); it != issues_.end(); ++it) {
            if (it.key() == path || it.key().startsWith(path + '[') || it.key().startsWith(path + '.')) {
                return QBrush(QColor(0xf9, 0xd6, 0xd5));
            }
        }
        return {};
    }
    if (role == Qt::ToolTipRole) {
        QStringList lines;
        const KeyInfo info = keyInfo().value(key, KeyInfo{"", ""});
        if (index.column() == ValueColumn) lines << valueOf(group, element, key, Qt::DisplayRole).toString();
        lines << QStringLiteral("%1: %2").arg(path, QString::fromUtf8(info.meaning));
        for (auto it = issues_.begin(); it != issues_.end(); ++it) {
            if (it.key() == path || it.key().startsWith(path + '[') || it.key().startsWith(path + '.')) {
                lines << QStringLiteral("⚠ %1: %2").arg(it.key(), it.value());
            }
        }
        return lines.join('\n');
    }
    if (index.column() == KeyColumn) {
        if (role != Qt::DisplayRole) return {};
        const KeyInfo info = keyInfo().value(key, KeyInfo{"", ""});
        return *info.unit ? QStringLiteral("%1 [%2]").arg(key, QString::fromUtf8(info.unit)) : key;
    }
    if (role == OptionsRole) {
        if (key == "integrator") {
            QStringList names;
            if (group == Bodies) names << kScenes;
            for (const IntegratorInfo& i : integratorCatalogue()) names << QString::fromLatin1(i.name);
            return names;
        }
        if (key == "inertia_convention") {
            return group == Bodies ? QStringList{kScenes, "standard", "course-template"}
                                   : QStringList{"standard", "course-template"};
        }
        if (key == "plane_contacts") return QStringList{"per-point", "average"};
        if (key == "contact_model") return QStringList{"course", "manifold"};
        if (key == "sleep") return QStringList{kDefault, "true", "false"};
        if (key == "position_fix") return QStringList{kDefault, "ngs", "baumgarte", "none"};
        if (key == "body" || key == "bodies[0]") return bodyNames();
        if (key == "bodies[1]") {
            QStringList names = bodyNames();
            for (const PlaneDef& p : scene_.planes) names << QString::fromStdString(p.name);
            return names;
        }
        return QStringList();
    }
    return valueOf(group, element, key, role);
}

QVariant SceneEditorModel::valueOf(int group, int element, const QString& key, int role) const
{
    if (isBool(group, key)) {
        bool on = false;
        if (group == Settings) on = key == "box_collisions" ? scene_.boxCollisions : scene_.positionCorrection;
        if (group == Bodies) on = key == "fixed" ? scene_.bodies[element].fixed : scene_.bodies[element].angularResponse;
        if (group == Torques) on = key == "switchable" ? scene_.torques[element].switchable
                                                       : scene_.torques[element].enabledAtStart;
        if (role == Qt::CheckStateRole) return on ? Qt::Checked : Qt::Unchecked;
        if (role == Qt::DisplayRole) return on ? tr("true") : tr("false");
        return {};
    }
    if (role != Qt::DisplayRole && role != Qt::EditRole) return {};
    const bool display = role == Qt::DisplayRole;
    auto bodyRef = [&](int i, const std::string& given) {
        return i >= 0 && i < static_cast<int>(scene_.bodies.size()) ? QString::fromStdString(scene_.bodies[i].name)
                                                                     : QString::fromStdString(given);
    };
    auto optional = [&](const std::optional<double>& x) { return x ? num(*x) : (display ? kScenes : QString()); };
    const SceneDef& s = scene_;
    switch (group) {
    case Settings:
        if (key == "name") return QString::fromStdString(s.name);
        if (key == "description") return QString::fromStdString(s.description);
        if (key == "dt") return num(s.dt);
        if (key == "steps") return QString::number(s.steps);
        if (key == "integrator") return QString::fromStdString(s.integrator);
        if (key == "inertia_convention") return convention(s.inertiaConvention);
        if (key == "gravity") return vecText(s.g_W);
        if (key == "restitution") return num(s.restitution);
        if (key == "restitution_threshold") return num(s.restitutionThreshold);
        if (key == "friction") return num(s.friction);
        if (key == "plane_contacts") return s.planeContacts == PlaneContactMode::Average ? QStringLiteral("average") : QStringLiteral("per-point");
        if (key == "energy_jump.factor") return num(s.energyJumpFactor);
        if (key == "energy_jump.floor") return num(s.energyJumpFloor);
        if (key == "contact_model") return s.contactModel == ContactModel::Manifold ? QStringLiteral("manifold") : QStringLiteral("course");
        if (key == "solver_iterations") return s.solverIterations ? QString::number(*s.solverIterations) : (display ? kDefault : QString());
        if (key == "sleep") return s.sleep ? (*s.sleep ? QStringLiteral("true") : QStringLiteral("false")) : kDefault;
        if (key == "position_fix") return s.positionFix ? positionFixText(*s.positionFix) : kDefault;
        break;
    case Bodies: {
        const BodyDef& b = s.bodies[element];
        if (key == "name") return QString::fromStdString(b.name);
        if (key == "size") return vecText(b.size);
        if (key == "mass") return b.fixed ? (display ? tr("(fixed: none)") : QString()) : num(b.mass);
        if (key == "position") return vecText(b.x0_W);
        if (key == "orientation") {
            const QString q = QStringLiteral("%1, %2, %3, %4").arg(num(b.q0_WB.w()), num(b.q0_WB.x()), num(b.q0_WB.y()), num(b.q0_WB.z()));
            if (!display) return q;
            // For reading: the same rotation as an angle about an axis.
            const Eigen::AngleAxisd aa(b.q0_WB);
            if (aa.angle() == 0.0) return tr("no rotation · q = %1").arg(q);
            const Vec3& n = aa.axis();
            return tr("%2° about (%3, %4, %5) · q = %1")
                .arg(q, QString::number(aa.angle() * 180.0 / 3.14159265358979323846, 'g', 4), QString::number(n.x(), 'g', 3),
                     QString::number(n.y(), 'g', 3), QString::number(n.z(), 'g', 3));
        }
        if (key == "linear_velocity") return vecText(b.v0_W);
        if (key == "angular_velocity") return vecText(b.omega0_W);
        if (key == "integrator") return b.integrator.empty() ? kScenes : QString::fromStdString(b.integrator);
        if (key == "inertia_convention") return b.inertiaConvention ? convention(*b.inertiaConvention) : kScenes;
        break;
    }
    case Forces: {
        const ForceDef& f = s.forces[element];
        if (key == "body") return bodyRef(f.body, f.bodyName);
        if (key == "point") return vecText(f.p_W);
        if (key == "force") return vecText(f.f_W);
        if (key == "from_step") return QString::number(f.fromStep);
        if (key == "to_step") return QString::number(f.toStep);
        break;
    }
    case Torques: {
        const TorqueDef& t = s.torques[element];
        if (key == "body") return bodyRef(t.body, t.bodyName);
        if (key == "torque") return vecText(t.q_W);
        if (key == "from_step") return QString::number(t.fromStep);
        if (key == "to_step") return t.toStep == kForever ? (display ? kNever : QString()) : QString::number(t.toStep);
        break;
    }
    case Probes: {
        const ProbeDef& p = s.probes[element];
        if (key == "body") return bodyRef(p.body, p.bodyName);
        if (key == "point") return vecText(p.p0_W);
        break;
    }
    case Planes: {
        const PlaneDef& p = s.planes[element];
        if (key == "name") return QString::fromStdString(p.name);
        if (key == "point") return vecText(p.point_W);
        if (key == "normal") return vecText(p.n_W);
        break;
    }
    case Pairs: {
        const PairOverride& p = s.pairs[element];
        if (key == "bodies[0]") return bodyRef(p.bodyA, p.nameA);
        if (key == "bodies[1]") {
            if (p.bodyB >= 0) return bodyRef(p.bodyB, p.nameB);
            if (p.planeB >= 0 && p.planeB < static_cast<int>(s.planes.size())) return QString::fromStdString(s.planes[p.planeB].name);
            return QString::fromStdString(p.nameB);
        }
        if (key == "restitution") return optional(p.restitution);
        if (key == "friction") return optional(p.friction);
        break;
    }
    default: break;
    }
    return {};
}

bool SceneEditorModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    if (!index.isValid() || index.column() != ValueColumn) return false;
    const quintptr id = index.internalId();
    const int group = decodeGroup(id);
    const int element = decodeElement(id);
    const int property = decodeProperty(id);
    if (property < 0) return false;
    const QString key = properties(group).value(property);
    QVariant v = value;
    if (isBool(group, key)) {
        if (role != Qt::CheckStateRole && role != Qt::EditRole) return false;
        v = role == Qt::CheckStateRole ? value.toInt() == Qt::Checked : value.toBool();
    } else if (role != Qt::EditRole) {
        return false;
    }
    QString error;
    if (!setValue(group, element, key, v, &error)) {
        emit editRefused(QStringLiteral("%1: %2").arg(pathOf(group, element, property), error));
        return false;
    }
    // A name or a reference changes the titles of other rows too: refresh the whole tree's text.
    if (key == "name" || key == "body" || key.startsWith("bodies[") || key == "fixed") {
        refreshAll();
    } else {
        emit dataChanged(index.siblingAtColumn(KeyColumn), index.siblingAtColumn(ValueColumn));
    }
    emit sceneEdited();
    return true;
}

bool SceneEditorModel::setValue(int group, int element, const QString& key, const QVariant& value, QString* error)
{
    SceneDef& s = scene_;
    const QString text = value.toString();
    double x = 0;
    long n = 0;
    Vec3 v;
    auto bodyIndex = [&](const QString& name) { return s.bodyIndex(name.toStdString()); };
    switch (group) {
    case Settings:
        if (key == "name") { s.name = text.toStdString(); return true; }
        if (key == "description") { s.description = text.toStdString(); return true; }
        if (key == "dt") { if (!parseNumber(text, &x, error)) return false; s.dt = x; return true; }
        if (key == "steps") { if (!parseWhole(text, &n, error)) return false; s.steps = n; return true; }
        if (key == "integrator") { s.integrator = text.trimmed().toStdString(); return true; }
        if (key == "inertia_convention") {
            if (text != "standard" && text != "course-template") {
                *error = QStringLiteral("must be \"standard\" or \"course-template\", got %1").arg(quoted(text));
                return false;
            }
            s.inertiaConvention = text == "standard" ? InertiaConvention::Standard : InertiaConvention::CourseTemplate;
            return true;
        }
        if (key == "gravity") { if (!parseVec(text, &v, error)) return false; s.g_W = v; return true; }
        if (key == "box_collisions") { s.boxCollisions = value.toBool(); return true; }
        if (key == "position_correction") { s.positionCorrection = value.toBool(); return true; }
        if (key == "restitution") { if (!parseNumber(text, &x, error)) return false; s.restitution = x; return true; }
        if (key == "restitution_threshold") {
            if (!parseNumber(text, &x, error)) return false;
            s.restitutionThreshold = x;
            return true;
        }
        if (key == "friction") { if (!parseNumber(text, &x, error)) return false; s.friction = x; return true; }
        if (key == "plane_contacts") {
            if (text != "per-point" && text != "average") {
                *error = QStringLiteral("must be \"per-point\" or \"average\", got %1").arg(quoted(text));
                return false;
            }
            s.planeContacts = text == "average" ? PlaneContactMode::Average : PlaneContactMode::PerPoint;
            return true;
        }
        if (key == "energy_jump.factor") { if (!parseNumber(text, &x, error)) return false; s.energyJumpFactor = x; return true; }
        if (key == "energy_jump.floor") { if (!parseNumber(text, &x, error)) return false; s.energyJumpFloor = x; return true; }
        if (key == "contact_model") {
            if (text != "course" && text != "manifold") {
                *error = QStringLiteral("must be \"course\" or \"manifold\", got %1").arg(quoted(text));
                return false;
            }
            s.contactModel = text == "manifold" ? ContactModel::Manifold : ContactModel::Course;
            return true;
        }
        if (key == "solver_iterations") {
            if (text.trimmed().isEmpty() || text.trimmed() == kDefault) { s.solverIterations.reset(); return true; }
            if (!parseWhole(text, &n, error)) return false;
            s.solverIterations = n;
            return true;
        }
        if (key == "sleep") {
            if (text == kDefault) s.sleep.reset();
            else if (text == "true" || text == "false") s.sleep = text == "true";
            else { *error = QStringLiteral("must be true, false or %1, got %2").arg(kDefault, quoted(text)); return false; }
            return true;
        }
        if (key == "position_fix") {
            if (text == kDefault) s.positionFix.reset();
            else if (text == "ngs") s.positionFix = PositionFix::Ngs;
            else if (text == "baumgarte") s.positionFix = PositionFix::Baumgarte;
            else if (text == "none") s.positionFix = PositionFix::None;
            else {
                *error = QStringLiteral("must be \"ngs\", \"baumgarte\", \"none\" or %1, got %2").arg(kDefault, quoted(text));
                return false;
            }
            return true;
        }
        break;
    case Bodies: {
        BodyDef& b = s.bodies[element];
        if (key == "name") { b.name = text.toStdString(); return true; }
        if (key == "size") { if (!parseVec(text, &v, error)) return false; b.size = v; return true; }
        if (key == "mass") { if (!parseNumber(text, &x, error)) return false; b.mass = x; return true; }
        if (key == "fixed") { b.fixed = value.toBool(); return true; }
        if (key == "angular_response") { b.angularResponse = value.toBool(); return true; }
        if (key == "position") { if (!parseVec(text, &v, error)) return false; b.x0_W = v; return true; }
        if (key == "linear_velocity") { if (!parseVec(text, &v, error)) return false; b.v0_W = v; return true; }
        if (key == "angular_velocity") { if (!parseVec(text, &v, error)) return false; b.omega0_W = v; return true; }
        if (key == "orientation") {
            QList<double> q;
            if (!parseNumbers(text, 4, &q, error)) return false;
            const Quat quat(q[0], q[1], q[2], q[3]);
            if (quat.coeffs().isZero(0.0)) { *error = QStringLiteral("must not be the zero quaternion"); return false; }
            if (!std::isfinite(quat.coeffs().squaredNorm())) {
                *error = QStringLiteral("its length overflows, so it cannot be normalised");
                return false;
            }
            b.q0_WB = Quat(normalisedAsLoaded(quat.coeffs()));
            return true;
        }
        if (key == "integrator") { b.integrator = text == kScenes ? std::string() : text.trimmed().toStdString(); return true; }
        if (key == "inertia_convention") {
            if (text == kScenes) b.inertiaConvention.reset();
            else if (text == "standard") b.inertiaConvention = InertiaConvention::Standard;
            else if (text == "course-template") b.inertiaConvention = InertiaConvention::CourseTemplate;
            else {
                *error = QStringLiteral("must be \"standard\", \"course-template\" or %1, got %2").arg(kScenes, quoted(text));
                return false;
            }
            return true;
        }
        break;
    }
    case Forces: {
        ForceDef& f = s.forces[element];
        if (key == "body") { f.bodyName = text.toStdString(); f.body = bodyIndex(text); return true; }
        if (key == "point") { if (!parseVec(text, &v, error)) return false; f.p_W = v; return true; }
        if (key == "force") { if (!parseVec(text, &v, error)) return false; f.f_W = v; return true; }
        if (key == "from_step") { if (!parseWhole(text, &n, error)) return false; f.fromStep = n; return true; }
        if (key == "to_step") { if (!parseWhole(text, &n, error)) return false; f.toStep = n; return true; }
        break;
    }
    case Torques: {
        TorqueDef& t = s.torques[element];
        if (key == "body") { t.bodyName = text.toStdString(); t.body = bodyIndex(text); return true; }
        if (key == "torque") { if (!parseVec(text, &v, error)) return false; t.q_W = v; return true; }
        if (key == "from_step") { if (!parseWhole(text, &n, error)) return false; t.fromStep = n; return true; }
        if (key == "to_step") {
            if (text.trimmed().isEmpty() || text.trimmed() == kNever) { t.toStep = kForever; return true; }
            if (!parseWhole(text, &n, error)) return false;
            t.toStep = n;
            return true;
        }
        if (key == "switchable") { t.switchable = value.toBool(); return true; }
        if (key == "enabled") { t.enabledAtStart = value.toBool(); return true; }
        break;
    }
    case Probes: {
        ProbeDef& p = s.probes[element];
        if (key == "body") { p.bodyName = text.toStdString(); p.body = bodyIndex(text); return true; }
        if (key == "point") { if (!parseVec(text, &v, error)) return false; p.p0_W = v; return true; }
        break;
    }
    case Planes: {
        PlaneDef& p = s.planes[element];
        if (key == "name") { p.name = text.toStdString(); return true; }
        if (key == "point") { if (!parseVec(text, &v, error)) return false; p.point_W = v; return true; }
        if (key == "normal") {
            if (!parseVec(text, &v, error)) return false;
            if (v == Vec3::Zero()) { *error = QStringLiteral("must not be the zero vector"); return false; }
            if (!std::isfinite(v.squaredNorm())) { *error = QStringLiteral("its length overflows"); return false; }
            p.n_W = normalisedAsLoaded(v);
            return true;
        }
        break;
    }
    case Pairs: {
        PairOverride& p = s.pairs[element];
        if (key == "bodies[0]") { p.nameA = text.toStdString(); p.bodyA = bodyIndex(text); return true; }
        if (key == "bodies[1]") {
            p.nameB = text.toStdString();
            p.bodyB = bodyIndex(text);
            p.planeB = p.bodyB < 0 ? s.planeIndex(text.toStdString()) : -1;
            return true;
        }
        if (key == "restitution" || key == "friction") {
            std::optional<double>& target = key == "restitution" ? p.restitution : p.friction;
            if (text.trimmed().isEmpty() || text.trimmed() == kScenes) { target.reset(); return true; }
            if (!parseNumber(text, &x, error)) return false;
            target = x;
            return true;
        }
        break;
    }
    default: break;
    }
    *error = QStringLiteral("cannot be edited");
    return false;
}

QModelIndex SceneEditorModel::addElement(Group group)
{
    if (group == Settings || group >= GroupCount) return {};
    SceneDef& s = scene_;
    const std::string firstBody = s.bodies.empty() ? std::string() : s.bodies.front().name;
    const Vec3 firstPosition = s.bodies.empty() ? Vec3::Zero() : s.bodies.front().x0_W;
    auto unique = [&](const QString& stem) {
        for (int i = 2;; ++i) {
            const std::string name = QStringLiteral("%1%2").arg(stem).arg(i).toStdString();
            if (s.bodyIndex(name) < 0 && s.planeIndex(name) < 0) return name;
        }
    };
    beginResetModel();
    switch (group) {
    case Bodies: {
        BodyDef b;
        b.name = unique(QStringLiteral("body"));
        b.x0_W = Vec3(2.0 * static_cast<double>(s.bodies.size()), 0, 0);   // beside the others
        s.bodies.push_back(b);
        break;
    }
    case Forces: s.forces.push_back(ForceDef{s.bodies.empty() ? -1 : 0, firstPosition, Vec3(1, 0, 0), 0, 1, firstBody}); break;
    case Torques: s.torques.push_back(TorqueDef{s.bodies.empty() ? -1 : 0, Vec3(0, 0, 1), 0, kForever, false, true, firstBody}); break;
    case Probes: s.probes.push_back(ProbeDef{s.bodies.empty() ? -1 : 0, firstPosition, firstBody}); break;
    case Planes: s.planes.push_back(PlaneDef{unique(QStringLiteral("plane")), Vec3::Zero(), Vec3::UnitY()}); break;
    case Pairs: {
        PairOverride p;
        p.bodyA = s.bodies.empty() ? -1 : 0;
        p.nameA = firstBody;
        if (!s.planes.empty()) {
            p.planeB = 0;
            p.nameB = s.planes.front().name;
        } else if (s.bodies.size() > 1) {
            p.bodyB = 1;
            p.nameB = s.bodies[1].name;
        }
        p.friction = s.friction;
        s.pairs.push_back(p);
        break;
    }
    default: break;
    }
    endResetModel();
    emit sceneEdited();
    const QModelIndex parentGroup = index(group, 0);
    return index(elementCount(group) - 1, 0, parentGroup);
}

bool SceneEditorModel::removeElement(const QModelIndex& idx)
{
    if (!idx.isValid()) return false;
    const int group = decodeGroup(idx.internalId());
    const int element = decodeElement(idx.internalId());
    if (group == Settings || element < 0 || element >= elementCount(group)) return false;
    SceneDef& s = scene_;
    // A reference to the removed element keeps its name (validate() then names it); a
    // later one moves down by one.
    auto fix = [element](int& ref, std::string& name, const std::string& removedName) {
        if (ref == element) {
            ref = -1;
            name = removedName;
        } else if (ref > element) {
            --ref;
        }
    };
    beginResetModel();
    if (group == Bodies) {
        const std::string gone = s.bodies[element].name;
        s.bodies.erase(s.bodies.begin() + element);
        for (ForceDef& f : s.forces) fix(f.body, f.bodyName, gone);
        for (TorqueDef& t : s.torques) fix(t.body, t.bodyName, gone);
        for (ProbeDef& p : s.probes) fix(p.body, p.bodyName, gone);
        fix(s.push.body, s.push.bodyName, gone);
        for (PairOverride& p : s.pairs) {
            fix(p.bodyA, p.nameA, gone);
            if (p.bodyB >= 0) fix(p.bodyB, p.nameB, gone);
        }
    } else if (group == Planes) {
        const std::string gone = s.planes[element].name;
        s.planes.erase(s.planes.begin() + element);
        for (PairOverride& p : s.pairs) {
            if (p.planeB >= 0) fix(p.planeB, p.nameB, gone);
        }
    } else if (group == Forces) {
        s.forces.erase(s.forces.begin() + element);
    } else if (group == Torques) {
        s.torques.erase(s.torques.begin() + element);
    } else if (group == Probes) {
        s.probes.erase(s.probes.begin() + element);
    } else if (group == Pairs) {
        s.pairs.erase(s.pairs.begin() + element);
    }
    endResetModel();
    emit sceneEdited();
    return true;
}

QModelIndex SceneEditorModel::indexOfPath(const QString& path) const
{
    for (int g = 0; g < GroupCount; ++g) {
        const QModelIndex group = index(g, 0);
        for (int r = 0; r < rowCount(group); ++r) {
            const QModelIndex row = index(r, 0, group);
            if (row.data(PathRole).toString() == path) return row.siblingAtColumn(ValueColumn);
            for (int p = 0; p < rowCount(row); ++p) {
                const QModelIndex prop = index(p, ValueColumn, row);
                if (prop.data(PathRole).toString() == path) return prop;
            }
        }
    }
    return {};
}

} // namespace rbw
