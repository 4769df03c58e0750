// The workbook's main window: a shell. The 3D view sits in the middle; docks around
// it (ShellDocks, shell_docks.h) hold the lesson list and text, the quantities of the
// current step, the derivation, the plots and the studies. A Session (app/core) owns
// the world, its history and the interaction; a LessonController starts every scene
// (one sequence for lessons, files, new numbers and the editor); ShellActions builds
// the menus and keys; ExerciseActions the exercise flows; SceneFileFlows the
// student's files; QuantityTableActions what a table row offers; RefreshScheduler tells the
// panels that follow the run (SessionPanel) of each scene, step and rewind, in a loop,
// and which may catch up with the step; AppSettings keeps the settings. This class wires
// them: the controls to the session, the session's signals to the panels.
#pragma once

#include "app/core/playback_clock.h"
#include "app/core/session.h"
#include "app/core/session_panel.h"
#include "app/gui/shell/lesson_controller.h"
#include "app/gui/shell/refresh_scheduler.h"
#include "app/gui/shell/shell_docks.h"

#include <QList>
#include <QMainWindow>

#include <memory>

class QAction;
class QLabel;
class QModelIndex;
class QTimer;
class QTreeView;

namespace rbw {

class SceneEndBar;
class RunBusyBar;

class AccuracyPanel;
class BodyPlotPanel;
class CheckPanel;
class CheckSessionPanel;
class DerivationSessionPanel;
class QuantitiesSessionPanel;
class CodeView;
class DerivationView;
class ExerciseActions;
class HistoryScrubber;
class ParameterBar;
class PlotPanel;
class ProbeInWindow;
class QuantityTableActions;
class SceneFileFlows;
class QuantityPlotPanel;
class SceneEditor;
class SceneFiles;
class SceneView;
class ShellActions;
class TraceModel;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Opens a lesson by folder id ("01-one-step"); false if it cannot be loaded.
    bool openLesson(const QString& id);
    // Opens a scene file (File → Open, a drop, the command line); a lesson's own file
    // opens that lesson. A file that does not load leaves the running scene as it was
    // and shows why (file, JSON path, reason); false with the messages in *error.
    bool openSceneFile(const QString& path, QString* error = nullptr);
    // The same from the student's hand (a recent file): unsaved edits are asked about first.
    void requestOpen(const QString& path);
    // Writes the editor's scene (it must pass validate()) to a file through QSaveFile;
    // it then becomes the open, watched file. False with the reason.
    bool saveSceneTo(const QString& path, QString* error = nullptr);
    // The current lesson's scene with new numbers for a seed (exercise.json,
    // docs/exercises.md), loaded in memory; false with the reason if it has none.
    bool openNewNumbers(quint64 seed, QString* error = nullptr);
    // The scene file shown: a lesson's or the student's own (absolute path).
    QString currentScenePath() const { return lessons_->current().scenePath; }
    QString currentSceneTitle() const { return lessons_->current().title; }
    QString currentLessonId() const { return lessons_->current().id; }
    const QList<Lesson>& lessons() const { return lessons_->lessons(); }
    LessonController* lessonController() const { return lessons_; }

    // The session and the panels (for the shell's parts and the tests).
    const World* world() const { return session_.world(); }
    Session* session() { return &session_; }
    TraceModel* traceModel() const { return traceModel_; }
    SceneView* sceneView() const { return sceneView_; }
    SceneEditor* sceneEditor() const { return docks_.sceneEditor; }
    SceneFiles* sceneFiles() const { return sceneFiles_; }
    DerivationView* derivationView() const { return docks_.derivationView; }
    PlotPanel* plotPanel() const { return docks_.plotPanel; }
    AccuracyPanel* accuracyPanel() const { return docks_.accuracyPanel; }
    BodyPlotPanel* bodyPlotPanel() const { return docks_.bodyPlotPanel; }
    QuantityPlotPanel* quantityPlotPanel() const { return docks_.quantityPlots; }   // "Plot over time"
    QTreeView* traceView() const { return docks_.traceView; }
    CodeView* codeView() const { return docks_.codeView; }
    CheckPanel* checkPanel() const { return docks_.checkPanel; }
    ParameterBar* parameterBar() const { return parameterBar_; }
    HistoryScrubber* historyScrubber() const { return scrubber_; }
    ProbeInWindow* probeInWindow() const { return probe_; }   // Compare with my simulator's probe
    RunBusyBar* runBusyBar() const { return busyBar_; }
    // Plots the quantity of a row of the quantities table (its components, or the
    // length with norm); false (with a note in the status bar) for a group row.
    bool plotRowOverTime(const QModelIndex& row, bool norm = false);
    // The HTML last handed to the derivation view (tests, export).
    QString derivationHtml() const;
    // Every action that has a keyboard shortcut, in menu order (the Help → Keys table).
    QList<QAction*> shortcutActions() const;
    // Steps per second of wall time while playing: 0 means one step per frame.
    double playbackSpeed() const { return clock_.speed(); }

public slots:
    void stepOnce();
    void stepBack();
    // The history scrubber's "go to step k" (stops playing first). A recorded step is
    // restored at once; new steps beyond the recording are computed off the GUI thread
    // (Session::startGoToStep: the busy bar with Cancel once it takes longer than the
    // bar's wait). True if step k is current on return; false if it is not reached
    // (said beside the slider) or still being computed.
    bool goToStep(long k);
    void setPlaying(bool playing);
    void resetLesson();
    // The next (+1) or previous (-1) lesson of the list.
    void stepLesson(int delta);
    void copySelection(bool asLatex);
    // Opens the code view at the physics statement that computed the current row of
    // the quantities table. False (with a note in the status bar) for a group row.
    bool showCodeOfCurrentRow();
    void showKeys();
    // Refreshes the derivation page now, even while playing.
    void refreshDerivation();
    // The student's files (SceneFileFlows).
    bool saveScene();
    bool saveSceneAs();
    void newSceneFromLesson();
    void showSceneEditor();

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void restoreLayout();
    // Every started scene, whatever its origin (LessonController::started).
    void onSceneStarted(const SceneDef& scene, const StartedScene& info);
    void onSceneLoadFailed(const QString& what, const QStringList& errors);
    void onSessionReset();
    void onStateChanged();
    void onPlayTick();
    void onRunFinished(int taken);
    void onGoToFinished(long k, bool reached);
    void updateStatus();

    Session session_;
    LessonController* lessons_ = nullptr;
    SceneEndBar* sceneEnd_ = nullptr;
    RunBusyBar* busyBar_ = nullptr;   // a step computed off the GUI thread: busy, Cancel
    int playDue_ = 0;                 // the steps the running tick of Play asked for
    TraceModel* traceModel_ = nullptr;
    SceneView* sceneView_ = nullptr;
    ShellDocks docks_;
    // The panels that follow the run (SessionPanel): told of every reset, step and
    // rewind in turn, each refreshed at its pace. The three below adapt the table,
    // Check my numbers and the derivation, whose widgets know no session.
    RefreshScheduler panels_;
    std::unique_ptr<QuantitiesSessionPanel> tablePanel_;
    std::unique_ptr<CheckSessionPanel> checkPanel_;
    std::unique_ptr<DerivationSessionPanel> derivation_;
    QLabel* statusLabel_ = nullptr;
    QLabel* alertLabel_ = nullptr;
    ParameterBar* parameterBar_ = nullptr;
    HistoryScrubber* scrubber_ = nullptr;   // the slider over the recorded history
    SceneFiles* sceneFiles_ = nullptr;      // File → Open, recent files, drops, the watch
    ExerciseActions* exercise_ = nullptr;   // New numbers, worksheet
    ShellActions* actions_ = nullptr;       // menus, keys, toolbar
    SceneFileFlows* files_ = nullptr;       // save, save as, new scene, reload, the editor's Apply
    QuantityTableActions* table_ = nullptr; // copy, show code, plot over time
    ProbeInWindow* probe_ = nullptr;        // a probe with the student's numbers (Yours), the divergence mark

    QTimer* playTimer_ = nullptr;
    PlaybackClock clock_;          // steps per tick, and when the panels are due
};

} // namespace rbw
