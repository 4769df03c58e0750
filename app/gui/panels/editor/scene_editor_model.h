// The scene editor's model: a tree over one SceneDef for a QTreeView.
//
//   Settings                  dt, steps, integrator, gravity, restitution, friction, ...
//   Bodies / box              name, size, mass, fixed, position, orientation, v, ω, ...
//   Forces / forces[0]        body, point, force, from_step, to_step
//   Torques, Probes, Planes, Pairs   likewise
//
// Column 0 names a property by its scene-file key, column 1 holds its value: a number
// or a word as text, a vector as "x, y, z", a true/false key as a check box, a choice
// (integrator, convention, the body a force acts on) as one of optionsFor(). An edit
// that cannot be read (a word where a number belongs) is refused with a message in
// the loader's terms ("bodies[0].mass: must be a number, got \"abc\""); an edit that
// can be read changes the scene, even if the scene then breaks a rule: the rules are
// physics' validate(), which the editor runs on the whole scene (setIssues() marks the
// rows the issues name). Nothing here applies the scene to the running world.
#pragma once

#include "physics/engine/scene.h"

#include <QAbstractItemModel>
#include <QHash>
#include <QStringList>
#include <QVector>

namespace rbw {

namespace editorfields {
struct Field;
}

class SceneEditorModel : public QAbstractItemModel {
    Q_OBJECT
public:
    enum Column { KeyColumn, ValueColumn, ColumnCount };
    enum Role {
        PathRole = Qt::UserRole + 1,   // "bodies[0].mass": the field's path in the scene file
        OptionsRole,                   // QStringList: the values a choice may take; empty for free text
    };
    enum Group { Settings, Bodies, Forces, Torques, Probes, Planes, Pairs, GroupCount };

    explicit SceneEditorModel(QObject* parent = nullptr);

    void setScene(const SceneDef& scene);
    const SceneDef& scene() const { return scene_; }

    // Issues from validate() (path, reason); rows whose path is named are marked.
    void setIssues(const QHash<QString, QString>& issues);

    // Adds a new element to a group (a body named "body2", a force on the first
    // body, ...) or removes one; references to a removed body keep its name, so that
    // validate() says which force names it. Return the new element's row, or false.
    QModelIndex addElement(Group group);
    bool removeElement(const QModelIndex& index);

    // The index of the value cell of a field, by path ("bodies[0].mass"); invalid if none.
    QModelIndex indexOfPath(const QString& path) const;
    // The group and element a row belongs to (element -1 for a group row or a setting).
    static Group groupOf(const QModelIndex& index);
    static int elementOf(const QModelIndex& index);

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

signals:
    // The scene changed through an edit, an addition or a removal.
    void sceneEdited();
    // An edit could not be read; the message names the field and the reason.
    void editRefused(const QString& message);

private:
    // Row identity packed into the internal id: group, element + 1, property + 1.
    static quintptr pack(int group, int element, int property);
    int elementCount(int group) const;
    QString pathOf(int group, int element, int property) const;
    QString elementTitle(int group, int element) const;
    // The values (scene_editor_values.cpp): a field as text, read back, its choices.
    QVariant valueOf(int group, int element, const editorfields::Field& field, int role) const;
    QStringList optionsOf(int group, const editorfields::Field& field) const;
    bool setValue(int group, int element, const editorfields::Field& field, const QVariant& value, QString* error);
    QStringList bodyNames() const;
    void refreshAll();

    SceneDef scene_;
    QHash<QString, QString> issues_;
};

} // namespace rbw
