#include "app/gui/shell/main_window.h"

#include "app/core/step_numbering.h"
#include "app/gui/panels/accuracy/accuracy_panel.h"
#include "app/gui/panels/check/check_panel.h"
#include "app/gui/panels/check/check_session_panel.h"
#include "app/gui/panels/derivation/derivation_session_panel.h"
#include "app/gui/panels/derivation/derivation_view.h"
#include "app/gui/panels/editor/scene_editor.h"
#include "app/gui/panels/plots/body_plot_panel.h"
#include "app/gui/panels/plots/plot_panel.h"
#include "app/gui/panels/plots/quantity_plot_panel.h"
#include "app/gui/panels/quantities/body_colour_delegate.h"
#include "app/gui/panels/quantities/quantities_session_panel.h"
#include "app/gui/panels/quantities/trace_model.h"
#include "app/gui/panels/view/scene_view.h"
#include "app/gui/panels/view/view_snapshot.h"
#include "app/gui/shell/app_settings.h"
#include "app/gui/shell/exercise_actions.h"
#include "app/gui/shell/history_scrubber.h"
#include "app/gui/shell/keys_dialog.h"
#include "app/gui/shell/parameter_bar.h"
#include "app/gui/shell/probe_in_window.h"
#include "app/gui/shell/quantity_table_actions.h"
#include "app/gui/shell/run_busy_bar.h"
#include "app/gui/shell/scene_file_flows.h"
#include "app/gui/shell/scene_files.h"
#include "app/gui/shell/shell_actions.h"
#include "physics/engine/integrator_registry.h"

#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QLabel>
#include <QListWidget>
#include <QMessageBox>
#include <QSignalBlocker>
#include <QStatusBar>
#include <QTextBrowser>
#include <QTimer>
#include <QTreeView>
#include "app/gui/panels/view/scene_end_bar.h"
#include <QVBoxLayout>

#include <algorithm>

namespace rbw {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent)
    , lessons_(new LessonController(&session_, this))
    , traceModel_(new TraceModel(this))
    , playTimer_(new QTimer(this))
{
    setWindowTitle(tr("Rigid Body Workbook"));
    sceneView_ = new SceneView;
    sceneView_->setObjectName("sceneView");
    alertLabel_ = new QLabel;
    alertLabel_->setObjectName("alertLabel");
    alertLabel_->setWordWrap(true);
    alertLabel_->setStyleSheet("QLabel{background:#b3261e;color:white;padding:6px;font-weight:bold}");
    alertLabel_->hide();
    scrubber_ = new HistoryScrubber(&session_);
    auto* centre = new QWidget;
    auto* centreLayout = new QVBoxLayout(centre);
    centreLayout->setContentsMargins(0, 0, 0, 0);
    centreLayout->setSpacing(0);
    centreLayout->addWidget(alertLabel_);
    centreLayout->addWidget(sceneView_, 1);
    sceneEnd_ = new SceneEndBar(&session_);   // Play stops at the scene's steps
    centreLayout->addWidget(sceneEnd_);
    busyBar_ = new RunBusyBar(&session_);
    centreLayout->addWidget(busyBar_);
    centreLayout->addWidget(scrubber_);
    setCentralWidget(centre);
    connect(scrubber_, &HistoryScrubber::stepRequested, this, &MainWindow::goToStep);
    connect(sceneEnd_, &SceneEndBar::endReached, this, [this] { setPlaying(false); });
    connect(sceneEnd_, &SceneEndBar::resetRequested, this, &MainWindow::resetLesson);
    connect(sceneEnd_, &SceneEndBar::continueRequested, this, [this] { setPlaying(true); });
    connect(scrubber_, &HistoryScrubber::focusReturnRequested, this,
            [this] { sceneView_->setFocus(Qt::OtherFocusReason); });

    parameterBar_ = new ParameterBar(&session_, this);
    parameterBar_->setFocusReturnTarget(sceneView_);   // Enter/Escape in a box: S, Space, arrows work again
    connect(parameterBar_, &ParameterBar::speedChanged, this, [this](double speed) { clock_.setSpeed(speed); });
    connect(parameterBar_, &ParameterBar::messageRequested, statusBar(), &QStatusBar::showMessage);
    clock_.setSpeed(parameterBar_->speed());

    docks_ = buildDocks(this, lessons_->lessons(), traceModel_);   // before the menus: the View menu lists every dock
    // The panels that follow the run, told in turn of each scene, step and rewind; the
    // table, Check my numbers and the derivation catch up at their own pace.
    tablePanel_ = std::make_unique<QuantitiesSessionPanel>(traceModel_, &session_);
    checkPanel_ = std::make_unique<CheckSessionPanel>(docks_.checkPanel, &session_, [this] { return currentLessonId(); });
    derivation_ = std::make_unique<DerivationSessionPanel>(docks_.derivationView, &session_,
                                                           [this]() -> const Lesson& { return lessons_->current(); });
    for (SessionPanel* panel : std::initializer_list<SessionPanel*>{tablePanel_.get(), checkPanel_.get(), derivation_.get(),
                                                                   docks_.plotPanel, docks_.bodyPlotPanel, docks_.quantityPlots})
        panels_.add(panel);
    sceneFiles_ = new SceneFiles(this);
    files_ = new SceneFileFlows({this, docks_.sceneEditor, docks_.editorDock, sceneFiles_, lessons_, &session_});
    table_ = new QuantityTableActions({docks_.traceView, traceModel_, docks_.codeView, docks_.codeDock, docks_.quantityPlots,
                                       docks_.quantityPlotDock, statusBar()},
                                      &session_, this);
    exercise_ = new ExerciseActions(this, lessons_, statusBar());
    actions_ = new ShellActions(this, exercise_);
    addToolBar(parameterBar_);   // after the simulation bar
    statusLabel_ = new QLabel;
    statusLabel_->setObjectName("statusLabel");
    statusBar()->addPermanentWidget(statusLabel_, 1);

    connect(docks_.lessonList, &QListWidget::currentRowChanged, lessons_, [this](int row) {
        if (files_->confirmUnsavedEdits(tr("open another lesson"))) {
            lessons_->openLesson(row);
            return;
        }
        const QSignalBlocker block(docks_.lessonList);   // cancelled: the running lesson's row again
        docks_.lessonList->setCurrentRow(lessons_->lessonRow(currentLessonId()));
    });
    connect(lessons_, &LessonController::aboutToStart, this, [this] {
        setPlaying(false);
        alertLabel_->hide();
        derivation_->setFocusBody(-1);
    });
    connect(lessons_, &LessonController::started, this, &MainWindow::onSceneStarted);
    probe_ = new ProbeInWindow(lessons_, traceModel_, scrubber_, this);   // after: the scene shows first
    connect(lessons_, &LessonController::loadFailed, this, &MainWindow::onSceneLoadFailed);
    connect(docks_.derivationDock, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible) panels_.refreshIfDirty(derivation_.get());
    });
    // The PDF is printed asynchronously: report the result when it is written.
    connect(docks_.derivationView, &DerivationView::pdfExported, this,
            [this](const QString& path, bool ok, const QString& error) {
                if (ok) statusBar()->showMessage(tr("Derivation exported to %1").arg(path), 3000);
                else QMessageBox::warning(this, tr("Export"), error);
            });

    playTimer_->setInterval(PlaybackClock::kTickIntervalMs);   // each tick takes bounded time
    connect(playTimer_, &QTimer::timeout, this, &MainWindow::onPlayTick);
    connect(&session_, &Session::sessionReset, this, &MainWindow::onSessionReset);
    connect(&session_, &Session::stepRecorded, this, [this](const StepTrace& trace) { panels_.stepRecorded(trace); });
    connect(&session_, &Session::rewound, this, [this](long stepIndex) { panels_.rewound(stepIndex); });
    connect(&session_, &Session::stateChanged, this, &MainWindow::onStateChanged);
    connect(&session_, &Session::runFinished, this, &MainWindow::onRunFinished);
    connect(&session_, &Session::goToFinished, this, &MainWindow::onGoToFinished);
    connect(busyBar_, &RunBusyBar::cancelled, this, [this](long k) {
        setPlaying(false);
        statusBar()->showMessage(tr("Cancelled: the scene is at step %1, the last finished step").arg(k), 6000);
    });
    connect(&session_, &Session::blownUp, this, [this](const QString& message) {
        setPlaying(false);
        alertLabel_->setText(tr("The run stopped: %1").arg(message));
        alertLabel_->show();
    });

    connect(sceneView_, &SceneView::grabStarted, this, [this](int body, QVector3D hit) {
        if (derivation_->setFocusBody(body)) panels_.mark(derivation_.get());   // a many-body page follows this box
        session_.beginGrab(body, Vec3(hit.x(), hit.y(), hit.z()));
    });
    connect(sceneView_, &SceneView::grabMoved, this,
            [this](QVector3D target) { session_.moveGrab(Vec3(target.x(), target.y(), target.z())); });
    connect(sceneView_, &SceneView::grabEnded, &session_, &Session::endGrab);

    resize(1360, 740);
    restoreLayout();
    clock_.panelsRefreshed();
}

MainWindow::~MainWindow() = default;

QList<QAction*> MainWindow::shortcutActions() const { return actions_->shortcutActions(); }

void MainWindow::restoreLayout()
{
    const QByteArray geometry = AppSettings::windowGeometry();
    if (!geometry.isEmpty() && !restoreGeometry(geometry)) {
        AppSettings::dropWindowLayout(tr("QMainWindow::restoreGeometry refused the saved geometry"));
    }
    const QByteArray state = AppSettings::windowState();
    if (!state.isEmpty()) {
        if (restoreState(state, AppSettings::kLayoutVersion)) return;
        AppSettings::dropWindowLayout(tr("QMainWindow::restoreState refused the saved layout"));
    }
    fitDocksToWindow(this);   // the first start, or a layout dropped
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!files_->confirmUnsavedEdits(tr("quit"))) {
        event->ignore();
        return;
    }
    session_.cancelRun();   // a step being computed never holds Quit up (main() leaves without it)
    AppSettings::setWindowLayout(saveGeometry(), saveState(AppSettings::kLayoutVersion));
    if (!currentLessonId().isEmpty()) AppSettings::setLastLesson(currentLessonId());
    QMainWindow::closeEvent(event);
}

bool MainWindow::openLesson(const QString& id)
{
    const int row = lessons_->lessonRow(id);
    return row >= 0 && lessons_->openLesson(row) && session_.isLoaded();
}

bool MainWindow::openNewNumbers(quint64 seed, QString* error) { return lessons_->openNewNumbers(seed, error); }
bool MainWindow::openSceneFile(const QString& path, QString* error) { return lessons_->openSceneFile(path, error); }
void MainWindow::requestOpen(const QString& path) { files_->openAsked(path); }
bool MainWindow::saveSceneTo(const QString& path, QString* error) { return files_->saveSceneTo(path, error); }
bool MainWindow::saveScene() { return files_->saveScene(); }
bool MainWindow::saveSceneAs() { return files_->saveSceneAs(); }
void MainWindow::newSceneFromLesson() { files_->newSceneFromLesson(); }
void MainWindow::copySelection(bool asLatex) { table_->copySelection(asLatex); }
bool MainWindow::showCodeOfCurrentRow() { return table_->showCodeOfCurrentRow(); }
bool MainWindow::plotRowOverTime(const QModelIndex& row, bool norm) { return table_->plotRowOverTime(row, norm); }

void MainWindow::showSceneEditor()
{
    files_->showEditor();
    docks_.sceneEditor->view()->setFocus();
}

void MainWindow::stepLesson(int delta)
{
    QListWidget* list = docks_.lessonList;
    if (list->count() > 0) list->setCurrentRow(std::clamp(list->currentRow() + delta, 0, list->count() - 1));
}

void MainWindow::onSceneStarted(const SceneDef& scene, const StartedScene& info)
{
    // The lesson list shows the lesson running, or no row for the student's own scene.
    if (info.origin == SceneOrigin::Lesson || info.origin == SceneOrigin::File || info.origin == SceneOrigin::Probe) {
        const QSignalBlocker block(docks_.lessonList);
        docks_.lessonList->setCurrentRow(lessons_->lessonRow(currentLessonId()));
        if (currentLessonId().isEmpty()) docks_.lessonList->clearSelection();
    }
    if (!info.lessonMarkdown.isEmpty()) docks_.lessonText->setMarkdown(info.lessonMarkdown);
    docks_.accuracyPanel->setScene(scene, info.title);
    if (info.origin != SceneOrigin::Editor) {   // the editor's own Apply keeps its view and file
        docks_.sceneEditor->setScene(scene, info.userFile);
        sceneFiles_->watch(info.userFile);
        if (!info.userFile.isEmpty()) sceneFiles_->addRecent(info.userFile);
        sceneView_->resetView();
    }
    setWindowTitle(info.windowTitle);
    if (!info.statusMessage.isEmpty()) statusBar()->showMessage(info.statusMessage, 4000);
    updateStatus();
}

void MainWindow::onSceneLoadFailed(const QString& what, const QStringList& errors)
{
    // The running scene stays, under its own name, and so does its row in the list.
    const QString running = session_.isLoaded() ? currentSceneTitle() : tr("nothing");
    alertLabel_->setText(tr("%1 cannot be loaded; still running \"%2\".\n%3").arg(what, running, errors.mid(0, 6).join('\n')));
    alertLabel_->show();
    statusBar()->showMessage(errors.value(0), 10000);
    const QSignalBlocker block(docks_.lessonList);
    docks_.lessonList->setCurrentRow(lessons_->lessonRow(currentLessonId()));
    if (currentLessonId().isEmpty()) docks_.lessonList->clearSelection();
    updateStatus();
}

void MainWindow::resetLesson()
{
    setPlaying(false);
    alertLabel_->hide();
    if (session_.isLoaded()) session_.reset();
}

void MainWindow::onSessionReset()
{
    const SceneDef& scene = session_.world()->scene();
    panels_.sceneLoaded(*session_.world());
    QStringList names;
    QList<bool> fixed;
    for (const BodyDef& b : scene.bodies) {
        names << QString::fromStdString(b.name);
        fixed << b.fixed;
    }
    docks_.bodySwatches->setBodies(names, fixed);
    actions_->updateFollowMenu(scene);
    sceneView_->clearTrails();
}

void MainWindow::onStateChanged()
{
    const World* world = session_.world();
    if (world == nullptr) return;
    const StepTrace* trace = session_.currentTrace();
    ViewSnapshot snapshot = makeViewSnapshot(*world, trace);
    // A queued push acts in the next step: drawn now, like the scene's own forces.
    for (const auto& [p_W, f_W] : session_.pendingPushes()) {
        ViewSnapshot::Force push{ViewSnapshot::ForceKind::Applied, world->scene().push.body, -1, p_W, f_W};
        push.upcoming = true;
        if (isFinite(p_W) && isFinite(f_W)) snapshot.forces.push_back(push);
    }
    sceneView_->setSnapshot(snapshot);
    sceneView_->setSpring(session_.springSegment());
    const bool playing = playTimer_->isActive();
    const bool panelsDue = clock_.panelsDue(playing);
    panels_.refreshDue(playing, panelsDue);   // the table, Check my numbers, the derivation
    // While playing, the actions and the status line change only at the table's
    // pace: every repainted widget is re-uploaded for the GL composition of the window.
    // (The parameter bar follows the session's parametersChanged, which a step never emits.)
    if (panelsDue || !playing) scrubber_->sync();
    if (panelsDue) {
        actions_->update(*world, session_.history().stepsBackAvailable());
        updateStatus();
        clock_.panelsRefreshed();
    }
}

void MainWindow::refreshDerivation() { panels_.refreshNow(derivation_.get()); }
QString MainWindow::derivationHtml() const { return derivation_->html(); }

void MainWindow::stepOnce()
{
    setPlaying(false);
    if (session_.busy()) statusBar()->showMessage(tr("Still computing the step: wait, or Cancel it"), 3000);
    else session_.startRun(1, 0.0, busyBar_->stepWaitMs());   // off the GUI thread (RunBusyBar)
}

void MainWindow::stepBack()
{
    setPlaying(false);
    if (session_.stepBack()) {
        alertLabel_->hide();
    } else {
        statusBar()->showMessage(tr("No earlier step in the history"), 2000);
    }
}

bool MainWindow::goToStep(long k)
{
    setPlaying(false);
    if (!session_.isLoaded()) return false;
    if (k == session_.world()->stepIndex() && !session_.busy()) {
        // Already there: Enter in the step box still gives the keys back.
        if (scrubber_->isAncestorOf(QApplication::focusWidget())) sceneView_->setFocus(Qt::OtherFocusReason);
        return true;
    }
    // The newer request wins: a step still computing (Play's, an earlier Go) is dropped
    // first. Beyond the recording, off the GUI thread (goToFinished says how it ended).
    session_.startGoToStep(k, busyBar_->goWaitMs());
    // After Go (or Enter in the step box) the keys step and play again.
    if (scrubber_->isAncestorOf(QApplication::focusWidget())) sceneView_->setFocus(Qt::OtherFocusReason);
    return !session_.busy() && session_.world()->stepIndex() == k;
}

void MainWindow::onGoToFinished(long k, bool reached)
{
    if (reached) {
        alertLabel_->setVisible(!session_.status().ok);
    } else if (k < session_.history().firstStep()) {   // said beside the slider, where it was asked
        scrubber_->showNote(tr("n = %1 is no longer kept: the history keeps the last %2 steps (from n = %3)")
                                .arg(k).arg(session_.history().size() - 1).arg(session_.history().firstStep()));
    } else {
        scrubber_->showNote(tr("n = %1 not reached: the run stopped at n = %2").arg(k).arg(session_.history().current().state.stepIndex));
    }
    scrubber_->sync();
}

void MainWindow::setPlaying(bool playing)
{
    QAction* play = actions_->playAction();
    if (playing && (!session_.isLoaded() || !session_.status().ok)) playing = false;
    if (playing != playTimer_->isActive()) {
        if (playing) {
            sceneEnd_->playStarted();
            clock_.start();
            playTimer_->start();
        } else {
            playTimer_->stop();
            onStateChanged();   // the table, page and status catch up with the last step
        }
        play->setText(playing ? tr("&Pause") : tr("&Play"));
    }
    if (play->isChecked() != playing) play->setChecked(playing);
}

void MainWindow::onPlayTick()
{
    const World* world = session_.world();
    if (world == nullptr || session_.busy()) return;   // a tick's run still computes: this tick takes none
    // No step past the scene's end (SceneEndBar), then stop there if it was reached.
    playDue_ = sceneEnd_->stepsAllowed(clock_.stepsDue(world->scene().dt));
    if (playDue_ == 0 || session_.startRun(playDue_, clock_.budgetMs(), busyBar_->playWaitMs()) == Session::RunStart::Refused) {
        sceneEnd_->checkEnd();
    }
}

void MainWindow::onRunFinished(int taken)
{
    if (!playTimer_->isActive() || session_.world() == nullptr) return;
    clock_.stepsTaken(playDue_, taken, session_.world()->scene().dt);
    sceneEnd_->checkEnd();
}

void MainWindow::showKeys() { showKeysDialog(this, shortcutActions()); }

void MainWindow::updateStatus()
{
    const World* world = session_.world();
    if (world == nullptr) {
        statusLabel_->setText(tr("No lesson loaded"));
        return;
    }
    // Steps taken and the time they led to, t_n (app/core/step_numbering.h), the
    // integrator by its name.
    const IntegratorInfo* method = findIntegrator(world->integrator().name());
    const auto count = [this](long long n, const char* one, const char* many) { return n == 1 ? tr(one) : tr(many).arg(n); };
    QString text = tr("%1 · %2 · %3 = %4 s · h = %5 s · %6 · %7")
                       .arg(currentSceneTitle(), steps::stepsTaken(world->stepIndex()), steps::timeName(world->stepIndex()))
                       .arg(world->time(), 0, 'g', 6)
                       .arg(world->scene().dt, 0, 'g', 6)
                       .arg(method != nullptr && *method->title != '\0' ? QString::fromUtf8(method->title)
                                                                         : QString::fromLatin1(world->integrator().name()),
                            count(static_cast<long long>(session_.history().stepsBackAvailable()), "1 step back",
                                  "%1 steps back"));
    if (world->hasSwitchableTorque()) text += session_.torquesOn() ? tr(" · torque on (K)") : tr(" · torque off (K)");
    if (world->stepIndex() == 0) text += tr("  —  press Step (S) to take the first step");
    statusLabel_->setText(text);
}

} // namespace rbw
