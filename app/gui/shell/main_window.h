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
class QModelIndex;
class QMenu;
class QTextBrowser;
class QTimer;
class QTreeView;

namespace rbw {

class FormulaPane;

class AccuracyPanel;
class BodyColourDelegate;
class BodyPlotPanel;
class QuantityPlotPanel;
class CheckPanel;
class CodeView;
class DerivationView;
class SceneEditor;
class SceneFiles;
class HistoryScrubber;
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
    // Opens a scene file (File → Open, a drop, the command line); a lesson's own file
    // opens that lesson. A file that does not load leaves the running scene as it was
    // and shows why (file, JSON path, reason); false with the messages in *error.
    bool openSceneFile(const QString& path, QString* error = nullptr);
    // Writes the editor's scene (it must pass validate()) to a file through QSaveFile;
    // it then becomes the open, watched file. False with the reason.
    bool saveSceneTo(const QString& path, QString* error = nullptr);
    // The scene file shown: a lesson's or the student's own (absolute path).
    QString currentScenePath() const { return currentLesson_.scenePath; }
    QString currentSceneTitle() const { return currentLesson_.title; }
    SceneEditor* sceneEditor() const { return sceneEditor_; }
    SceneFiles* sceneFiles() const { return sceneFiles_; }
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
    // "Plot over time" (the quantities table's context menu): one plot per quantity.
    QuantityPlotPanel* quantityPlotPanel() const { return quantityPlots_; }
    // Plots the quantity of a row of the quantities table (its components, or the
    // length with norm); false (with a note in the status bar) for a group row.
    bool plotRowOverTime(const QModelIndex& row, bool norm = false);
    QTreeView* traceView() const { return traceView_; }
    // The HTML last handed to the derivation view (tests, export).
    QString derivationHtml() const { return derivationHtml_; }
    // Every action that has a keyboard shortcut, in menu order (the Help → Keys table).
    QList<QAction*> shortcutActions() const;
    // Steps per second of wall time while playing: 0 means one step per frame.
    double playbackSpeed() const { return clock_.speed(); }
    ParameterBar* parameterBar() const { return parameterBar_; }
    CodeView* codeView() const { return codeView_; }
    CheckPanel* checkPanel() const { return checkPanel_; }
    HistoryScrubber* historyScrubber() const { return scrubber_; }

public slots:
    void stepOnce();
    void stepBack();
    // The history scrubber's "go to step k" (stops playing first); false if k is not
    // recorded and cannot be reached (see Session::goToStep).
    bool goToStep(long k);
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
    // Scene files and the editor (main_window_files.cpp).
    void createEditorDock();
    void createFileActions(QMenu* fileMenu);
    void sceneStarted(const SceneDef& scene, const QString& userFile);
    void showSceneErrors(const QString& what, const QStringList& errors);
    void applyEditedScene(const SceneDef& scene);
    void reloadWatchedFile(const QString& path);
    bool saveScene();
    bool saveSceneAs();
    void newSceneFromLesson();
    void updateRecentMenu();
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
    FormulaPane* formulaPane_ = nullptr;
    TraceModel* traceModel_ = nullptr;
    DerivationView* derivationView_ = nullptr;
    PlotPanel* plotPanel_ = nullptr;
    AccuracyPanel* accuracyPanel_ = nullptr;
    BodyPlotPanel* bodyPlotPanel_ = nullptr;
    QuantityPlotPanel* quantityPlots_ = nullptr;
    BodyColourDelegate* bodySwatches_ = nullptr;   // the table's body rows in the bodies' colours
    QDockWidget* quantityPlotDock_ = nullptr;
    QLabel* statusLabel_ = nullptr;
    QLabel* alertLabel_ = nullptr;
    QDockWidget* derivationDock_ = nullptr;
    CodeView* codeView_ = nullptr;
    QDockWidget* codeDock_ = nullptr;
    ParameterBar* parameterBar_ = nullptr;
    HistoryScrubber* scrubber_ = nullptr;   // the slider over the recorded history
    CheckPanel* checkPanel_ = nullptr;   // Check my numbers
    QDockWidget* checkDock_ = nullptr;
    SceneFiles* sceneFiles_ = nullptr;     // File → Open, recent files, drops, the watch
    SceneEditor* sceneEditor_ = nullptr;   // the scene editor dock
    QDockWidget* editorDock_ = nullptr;
    QMenu* recentMenu_ = nullptr;

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
    QList<QAction*> stateArrowActions_;   // v, ω, L at the centres (View menu)
    QMenu* followMenu_ = nullptr;         // View → Camera follows: none or a body
    void updateFollowMenu();
    QList<QAction*> pushActions_;
    QList<QAction*> parameterActions_;
};

} // namespace rbw
