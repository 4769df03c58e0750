// The workbook's main window. The 3D view sits in the middle; docks around it hold
// the lesson list and text, the quantities of the current step (a TraceModel over
// the trace), the typeset derivation and the energy and momentum plots. A Session
// owns the world, its history and the interaction; this window only wires the
// controls to the session and the session's signals to the views. What is not wiring
// lives elsewhere: the pacing of Play in PlaybackClock (app/core), the derivation's
// focus on one body of many in focus_filter (app/core), the parameter controls in
// ParameterBar, the code behind a quantity in CodeView.
#pragma once

#include "app/core/lesson_catalogue.h"
#include "app/core/playback_clock.h"
#include "app/core/session.h"

#include <QList>
#include <QMainWindow>

class QAction;
class QDockWidget;
class QLabel;
class QListWidget;
class QTextBrowser;
class QTimer;
class QTreeView;

namespace rbw {

class AccuracyPanel;
class BodyPlotPanel;
class CheckPanel;
class CodeView;
class DerivationView;
class ParameterBar;
class PlotPanel;
class SceneView;
class TraceModel;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Opens a lesson by folder id ("01-one-step"); false if it cannot be loaded.
    bool openLesson(const QString& id);
    // The current lesson's scene with new numbers for a seed (exercise.json,
    // docs/exercises.md), loaded in memory; false with the reason if it has none.
    bool openNewNumbers(quint64 seed, QString* error = nullptr);
    QString currentLessonId() const { return currentLesson_.id; }
    const QList<Lesson>& lessons() const { return lessons_; }
    TraceModel* traceModel() const { return traceModel_; }
    const World* world() const { return session_.world(); }
    Session* session() { return &session_; }
    SceneView* sceneView() const { return sceneView_; }
    DerivationView* derivationView() const { return derivationView_; }
    PlotPanel* plotPanel() const { return plotPanel_; }
    AccuracyPanel* accuracyPanel() const { return accuracyPanel_; }
    BodyPlotPanel* bodyPlotPanel() const { return bodyPlotPanel_; }
    // The HTML last handed to the derivation view (tests, export).
    QString derivationHtml() const { return derivationHtml_; }
    // Every action that has a keyboard shortcut, in menu order (the Help → Keys table).
    QList<QAction*> shortcutActions() const;
    // Steps per second of wall time while playing: 0 means one step per frame.
    double playbackSpeed() const { return clock_.speed(); }
    ParameterBar* parameterBar() const { return parameterBar_; }
    CodeView* codeView() const { return codeView_; }
    CheckPanel* checkPanel() const { return checkPanel_; }

public slots:
    void stepOnce();
    void stepBack();
    void setPlaying(bool playing);
    void resetLesson();
    void copySelection(bool asLatex);
    // Opens the code view at the physics statement that computed the current row of
    // the quantities table. False (with a note in the status bar) for a group row.
    bool showCodeOfCurrentRow();
    void showKeys();
    // Refreshes the derivation page now, even while playing.
    void refreshDerivation();

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void createActions();
    void createDocks();
    void restoreLayout();
    void onLessonRowChanged(int row);
    void onSessionReset();
    void onStepRecorded(const StepTrace& trace);
    void onStateChanged();
    void onBlownUp(const QString& message);
    void onPlayTick();
    void updateStatus();
    void updateActions();
    void updateCheckPanel();
    void exportDerivationHtml();
    void exportDerivationPdf();
    void addPushAction(const QString& text, const QKeySequence& key, const Vec3& direction);
    QAction* addShortcutAction(const QString& text, const QString& objectName, const QList<QKeySequence>& keys);

    QList<Lesson> lessons_;
    Lesson currentLesson_;
    Session session_;

    SceneView* sceneView_ = nullptr;
    QListWidget* lessonList_ = nullptr;
    QTextBrowser* lessonText_ = nullptr;
    QTreeView* traceView_ = nullptr;
    TraceModel* traceModel_ = nullptr;
    DerivationView* derivationView_ = nullptr;
    PlotPanel* plotPanel_ = nullptr;
    AccuracyPanel* accuracyPanel_ = nullptr;
    BodyPlotPanel* bodyPlotPanel_ = nullptr;
    QLabel* statusLabel_ = nullptr;
    QLabel* alertLabel_ = nullptr;
    QDockWidget* derivationDock_ = nullptr;
    CodeView* codeView_ = nullptr;
    QDockWidget* codeDock_ = nullptr;
    ParameterBar* parameterBar_ = nullptr;
    CheckPanel* checkPanel_ = nullptr;   // Check my numbers
    QDockWidget* checkDock_ = nullptr;

    QTimer* playTimer_ = nullptr;
    PlaybackClock clock_;            // steps per tick, and when the panels are due
    int focusBody_ = -1;             // the body last grabbed: a many-body derivation follows it
    bool derivationDirty_ = false;   // the page does not show the current step yet
    bool traceDirty_ = false;        // nor does the quantities table
    bool checkDirty_ = false;        // nor does Check my numbers (it follows when paused)
    QString derivationHtml_;

    QList<QAction*> shortcutActions_;
    QAction* stepAction_ = nullptr;
    QAction* stepBackAction_ = nullptr;
    QAction* playAction_ = nullptr;
    QAction* resetAction_ = nullptr;
    QAction* torqueAction_ = nullptr;
    QAction* gravityAction_ = nullptr;
    QAction* trailsAction_ = nullptr;
    QList<QAction*> pushActions_;
    QList<QAction*> parameterActions_;
};

} // namespace rbw
