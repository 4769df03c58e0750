// The window's actions, menus and simulation toolbar: every control with its key
// (Help → Keys lists them, in menu order), connected to the window's public slots, the
// session, the parameter bar and the 3D view. The window builds the docks first (the
// View menu lists every dock), then this.
#pragma once

#include "app/core/session.h"

#include <QKeySequence>
#include <QList>
#include <QObject>

class QAction;
class QMenu;

namespace rbw {

class ExerciseActions;
class MainWindow;
class SceneFiles;

class ShellActions : public QObject {
    Q_OBJECT
public:
    ShellActions(MainWindow* window, ExerciseActions* exercise);

    // Every action with a keyboard shortcut, in menu order.
    QList<QAction*> shortcutActions() const { return shortcutActions_; }
    QAction* playAction() const { return playAction_; }

    // What the current world allows: K only with a switchable torque, the pushes only
    // in a lesson with a push body, Step back only with a recorded step.
    void update(const World& world, long stepsBack);
    // View → Camera follows: none, or one of the scene's movable bodies.
    void updateFollowMenu(const SceneDef& scene);
    void updateRecentMenu();

private:
    QAction* add(const QString& text, const QString& objectName, const QList<QKeySequence>& keys);
    void addPush(const QString& text, const QKeySequence& key, const Vec3& direction);
    void createFileActions(QMenu* fileMenu);
    void createViewMenu();

    MainWindow* w_;
    QList<QAction*> shortcutActions_;
    QAction* stepBackAction_ = nullptr;
    QAction* stepAction_ = nullptr;
    QAction* playAction_ = nullptr;
    QAction* resetAction_ = nullptr;
    QAction* torqueAction_ = nullptr;
    QList<QAction*> pushActions_;
    QMenu* followMenu_ = nullptr;
    QMenu* recentMenu_ = nullptr;
};

} // namespace rbw
