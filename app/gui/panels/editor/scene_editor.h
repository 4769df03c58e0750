// The scene editor dock: a tree of the scene's settings, bodies, forces, torques,
// probes, planes and pairs (SceneEditorModel), edited in place. After every edit the
// whole scene goes through physics' validate(), the same rules and messages as a
// scene file gets from the loader: a valid scene is handed to the window to run
// (applyRequested), from t = 0; an invalid one is listed, problem by problem, and the
// running scene stays as it was until the problems are fixed. Saving is the window's
// (File → Save), through the scene writer.
#pragma once

#include "physics/engine/scene.h"

#include <QString>
#include <QStringList>
#include <QWidget>

class QLabel;
class QToolBar;
class QTreeView;

namespace rbw {

class SceneEditorModel;

class SceneEditor : public QWidget {
    Q_OBJECT
public:
    explicit SceneEditor(QWidget* parent = nullptr);

    // A scene the window loaded (a lesson, a file, a reload): shown unmodified.
    // filePath is where Save writes; empty for a lesson (Save asks for a file).
    void setScene(const SceneDef& scene, const QString& filePath);
    const SceneDef& scene() const;
    QString filePath() const { return filePath_; }
    void setFilePath(const QString& path) { filePath_ = path; }
    // Edited since it was loaded or saved.
    bool isModified() const { return modified_; }
    void setModified(bool modified);
    // validate()'s problems with the edited scene, as "path: reason".
    QStringList issues() const { return issues_; }

    SceneEditorModel* model() const { return model_; }
    QTreeView* view() const { return view_; }
    QToolBar* toolBar() const { return toolBar_; }

signals:
    // The edited scene passes validate(): run it.
    void applyRequested(const rbw::SceneDef& scene);
    void modifiedChanged(bool modified);
    // For the status bar.
    void message(const QString& text);

private:
    void onEdited();
    void addToSelectedGroup();
    void removeSelected();
    void expandDefault();

    SceneEditorModel* model_;
    QTreeView* view_;
    QToolBar* toolBar_;
    QLabel* state_;
    QString filePath_;
    QStringList issues_;
    bool modified_ = false;
};

} // namespace rbw
