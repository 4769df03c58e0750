#include "app/gui/panels/editor/scene_editor_model.h"

#include "app/gui/panels/editor/scene_editor_fields.h"

#include <QBrush>
#include <QColor>
#include <QFont>

namespace rbw {

using namespace editorfields;

namespace {

using K = sceneformat::Key;

// The scene-file key of each group's list, and its title in the tree.
const K kGroupKeys[] = {K::Name, K::Bodies, K::Forces, K::Torques, K::Probes, K::Planes, K::Pairs};   // Settings: none
const char* const kGroupTitles[] = {"Settings", "Bodies", "Forces", "Torques", "Probes", "Planes", "Pairs"};

// Row identity: SceneEditorModel::pack() stores group, element + 1 and property + 1.
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

QString SceneEditorModel::pathOf(int group, int element, int property) const
{
    if (group == Settings) return property < 0 ? QString() : fieldName(fieldsOf(group).value(property));
    QString path = sceneformat::key(kGroupKeys[group]);
    if (element < 0) return path;
    path += QStringLiteral("[%1]").arg(element);
    if (property < 0) return path;
    return path + '.' + fieldName(fieldsOf(group).value(property));
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
        return row < fieldsOf(Settings).size() ? createIndex(row, column, pack(Settings, -1, row)) : QModelIndex();
    }
    if (element < 0) return row < elementCount(group) ? createIndex(row, column, pack(group, row, -1)) : QModelIndex();
    return row < fieldsOf(group).size() ? createIndex(row, column, pack(group, element, row)) : QModelIndex();
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
    if (group == Settings) return static_cast<int>(fieldsOf(Settings).size());
    return element < 0 ? elementCount(group) : static_cast<int>(fieldsOf(group).size());
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
    const Field field = fieldsOf(group).value(property);
    if (isCheckBox(field)) return f | Qt::ItemIsUserCheckable;
    if (field.key == K::BodyMass && scene_.bodies[decodeElement(index.internalId())].fixed) return f;
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
    const Field field = fieldsOf(group).value(property);
    const QString key = fieldName(field);
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
        if (index.column() == ValueColumn) lines << valueOf(group, element, field, Qt::DisplayRole).toString();
        lines << QStringLiteral("%1: %2").arg(path, fieldMeaning(field));
        for (auto it = issues_.begin(); it != issues_.end(); ++it) {
            if (it.key() == path || it.key().startsWith(path + '[') || it.key().startsWith(path + '.')) {
                lines << QStringLiteral("⚠ %1: %2").arg(it.key(), it.value());
            }
        }
        return lines.join('\n');
    }
    if (index.column() == KeyColumn) {
        if (role != Qt::DisplayRole) return {};
        const QString unit = fieldUnit(field);
        return unit.isEmpty() ? key : QStringLiteral("%1 [%2]").arg(key, unit);
    }
    if (role == OptionsRole) return optionsOf(group, field);
    return valueOf(group, element, field, role);
}

bool SceneEditorModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    if (!index.isValid() || index.column() != ValueColumn) return false;
    const quintptr id = index.internalId();
    const int group = decodeGroup(id);
    const int element = decodeElement(id);
    const int property = decodeProperty(id);
    if (property < 0) return false;
    const Field field = fieldsOf(group).value(property);
    QVariant v = value;
    if (isCheckBox(field)) {
        if (role != Qt::CheckStateRole && role != Qt::EditRole) return false;
        v = role == Qt::CheckStateRole ? value.toInt() == Qt::Checked : value.toBool();
    } else if (role != Qt::EditRole) {
        return false;
    }
    QString error;
    if (!setValue(group, element, field, v, &error)) {
        emit editRefused(QStringLiteral("%1: %2").arg(pathOf(group, element, property), error));
        return false;
    }
    // A name or a reference changes the titles of other rows too: refresh the whole tree's text.
    const sceneformat::KeyRow& row = sceneformat::row(field.key);
    if (field.key == K::Name || field.key == K::BodyName || field.key == K::PlaneName || field.key == K::BodyFixed ||
        row.type == sceneformat::Type::BodyRef || row.type == sceneformat::Type::NamePair) {
        refreshAll();
    } else {
        emit dataChanged(index.siblingAtColumn(KeyColumn), index.siblingAtColumn(ValueColumn));
    }
    emit sceneEdited();
    return true;
}

QModelIndex SceneEditorModel::addElement(Group group)
{
    if (group == Settings || group >= GroupCount) return {};
    SceneDef& s = scene_;
    const std::string firstBody = s.bodies.empty() ? std::string() : s.bodies.front().name;
    const Vec3 firstPosition = s.bodies.empty() ? Vec3::Zero() : s.bodies.front().x0_W;
    auto unique = [&](const QString& pattern) {   // "body%1" -> body2, body3, ...
        for (int i = 2;; ++i) {
            const std::string name = QString(pattern).arg(i).toStdString();
            if (s.bodyIndex(name) < 0 && s.planeIndex(name) < 0) return name;
        }
    };
    beginResetModel();
    switch (group) {
    case Bodies: {
        BodyDef b;
        b.name = unique(QStringLiteral("body%1"));
        b.x0_W = Vec3(2.0 * static_cast<double>(s.bodies.size()), 0, 0);   // beside the others
        s.bodies.push_back(b);
        break;
    }
    case Forces: s.forces.push_back(ForceDef{s.bodies.empty() ? -1 : 0, firstPosition, Vec3(1, 0, 0), 0, 1, firstBody}); break;
    case Torques: s.torques.push_back(TorqueDef{s.bodies.empty() ? -1 : 0, Vec3(0, 0, 1), 0, kForever, false, true, firstBody}); break;
    case Probes: s.probes.push_back(ProbeDef{s.bodies.empty() ? -1 : 0, firstPosition, firstBody}); break;
    case Planes: s.planes.push_back(PlaneDef{unique(QStringLiteral("plane%1")), Vec3::Zero(), Vec3::UnitY()}); break;
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
