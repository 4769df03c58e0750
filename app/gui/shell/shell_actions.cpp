#include "app/gui/shell/shell_actions.h"

#include "app/gui/panels/derivation/derivation_view.h"
#include "app/gui/panels/editor/scene_editor.h"
#include "app/gui/panels/plots/plot_panel.h"
#include "app/gui/panels/simulator/simulator_dialog.h"
#include "app/gui/panels/view/scene_view.h"
#include "app/gui/shell/exercise_actions.h"
#include "app/gui/shell/help_dialogs.h"
#include "app/gui/shell/keys_dialog.h"
#include "app/gui/shell/main_window.h"
#include "app/gui/shell/parameter_bar.h"
#include "app/gui/shell/probe_in_window.h"
#include "app/gui/shell/scene_files.h"

#include <QAction>
#include <QActionGroup>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QToolBar>
#include <QTreeView>

#include <functional>

namespace rbw {

namespace {

// File → Export …: a save dialog, then the panel's own atomic export; a refusal is shown.
void exportWith(QWidget* parent, const QString& title, const QString& suggested, const QString& filter,
                const std::function<bool(const QString&, QString*)>& write)
{
    const QString path = QFileDialog::getSaveFileName(parent, title, suggested, filter);
    QString error;
    if (!path.isEmpty() && !write(path, &error)) QMessageBox::warning(parent, QObject::tr("Export"), error);
}

} // namespace

QAction* ShellActions::add(const QString& text, const QString& objectName, const QList<QKeySequence>& keys)
{
    auto* a = new QAction(text, w_);
    a->setObjectName(objectName);
    a->setShortcuts(keys);
    if (!keys.isEmpty()) {
        a->setToolTip(QStringLiteral("%1 (%2)").arg(plainActionText(a), keys.first().toString(QKeySequence::NativeText)));
    }
    w_->addAction(a);   // shortcuts work wherever the focus is in the window
    shortcutActions_ << a;
    return a;
}

void ShellActions::addPush(const QString& text, const QKeySequence& key, const Vec3& direction)
{
    QAction* a = add(text, QStringLiteral("actionPush%1").arg(pushActions_.size()), {key});
    connect(a, &QAction::triggered, w_, [w = w_, direction] {
        if (w->session()->push(direction)) w->statusBar()->showMessage(tr("Push queued for the next step"), 1500);
    });
    pushActions_ << a;
}

ShellActions::ShellActions(MainWindow* window, ExerciseActions* exercise)
    : QObject(window)
    , w_(window)
{
    MainWindow* w = w_;
    ParameterBar* bar = w->parameterBar();
    SceneView* view = w->sceneView();
    stepBackAction_ = add(tr("Step &back"), "actionStepBack", {QKeySequence(Qt::Key_B), QKeySequence(Qt::Key_Left)});
    connect(stepBackAction_, &QAction::triggered, w, &MainWindow::stepBack);
    stepAction_ = add(tr("&Step"), "actionStep", {QKeySequence(Qt::Key_S), QKeySequence(Qt::Key_Right)});
    connect(stepAction_, &QAction::triggered, w, &MainWindow::stepOnce);
    playAction_ = add(tr("&Play"), "actionPlay", {QKeySequence(Qt::Key_Space)});
    playAction_->setCheckable(true);
    connect(playAction_, &QAction::toggled, w, &MainWindow::setPlaying);
    resetAction_ = add(tr("&Reset"), "actionReset", {QKeySequence(Qt::Key_R)});
    connect(resetAction_, &QAction::triggered, w, &MainWindow::resetLesson);
    auto* slower = add(tr("Play s&lower"), "actionSlower", {QKeySequence(Qt::Key_BracketLeft)});
    connect(slower, &QAction::triggered, bar, &ParameterBar::slower);
    auto* faster = add(tr("Play &faster"), "actionFaster", {QKeySequence(Qt::Key_BracketRight)});
    connect(faster, &QAction::triggered, bar, &ParameterBar::faster);
    auto* gravity = add(tr("&Gravity on/off"), "actionGravity", {QKeySequence(Qt::Key_G)});
    connect(gravity, &QAction::triggered, w, [w] {
        if (w->session()->isLoaded()) w->session()->setGravityEnabled(!w->session()->gravityEnabled());
    });
    torqueAction_ = add(tr("Toggle the &torque (angular acceleration)"), "actionToggleTorque", {QKeySequence(Qt::Key_K)});
    connect(torqueAction_, &QAction::triggered, w, [w] { w->session()->toggleTorques(); });

    addPush(tr("Push −x"), QKeySequence(Qt::CTRL | Qt::Key_Left), Vec3(-1, 0, 0));
    addPush(tr("Push +x"), QKeySequence(Qt::CTRL | Qt::Key_Right), Vec3(1, 0, 0));
    addPush(tr("Push +y"), QKeySequence(Qt::CTRL | Qt::Key_Up), Vec3(0, 1, 0));
    addPush(tr("Push −y"), QKeySequence(Qt::CTRL | Qt::Key_Down), Vec3(0, -1, 0));
    addPush(tr("Push +z"), QKeySequence(Qt::CTRL | Qt::Key_PageUp), Vec3(0, 0, 1));
    addPush(tr("Push −z"), QKeySequence(Qt::CTRL | Qt::Key_PageDown), Vec3(0, 0, -1));

    // Keys for the parameter bar's controls.
    auto* halveDt = add(tr("Halve h"), "actionHalveDt", {QKeySequence(Qt::Key_H)});
    connect(halveDt, &QAction::triggered, bar, [bar] { bar->scaleDt(0.5); });
    auto* doubleDt = add(tr("Double h"), "actionDoubleDt", {QKeySequence(Qt::SHIFT | Qt::Key_H)});
    connect(doubleDt, &QAction::triggered, bar, [bar] { bar->scaleDt(2.0); });
    auto* nextIntegrator = add(tr("Next integrator"), "actionNextIntegrator", {QKeySequence(Qt::Key_I)});
    connect(nextIntegrator, &QAction::triggered, bar, [bar] { bar->cycleIntegrator(+1); });
    auto* previousIntegrator = add(tr("Previous integrator"), "actionPreviousIntegrator", {QKeySequence(Qt::SHIFT | Qt::Key_I)});
    connect(previousIntegrator, &QAction::triggered, bar, [bar] { bar->cycleIntegrator(-1); });
    auto* moreC = add(tr("Restitution c + 0.05"), "actionMoreRestitution", {QKeySequence(Qt::Key_C)});
    connect(moreC, &QAction::triggered, bar, [bar] { bar->stepRestitution(+1); });
    auto* lessC = add(tr("Restitution c − 0.05"), "actionLessRestitution", {QKeySequence(Qt::SHIFT | Qt::Key_C)});
    connect(lessC, &QAction::triggered, bar, [bar] { bar->stepRestitution(-1); });
    auto* moreMu = add(tr("Friction μ + 0.05"), "actionMoreFriction", {QKeySequence(Qt::Key_U)});
    connect(moreMu, &QAction::triggered, bar, [bar] { bar->stepFriction(+1); });
    auto* lessMu = add(tr("Friction μ − 0.05"), "actionLessFriction", {QKeySequence(Qt::SHIFT | Qt::Key_U)});
    connect(lessMu, &QAction::triggered, bar, [bar] { bar->stepFriction(-1); });
    const QList<QAction*> parameterActions{halveDt, doubleDt, nextIntegrator, previousIntegrator, moreC, lessC, moreMu, lessMu};

    auto* trails = add(tr("Motion &trails"), "actionTrails", {QKeySequence(Qt::Key_T)});
    trails->setCheckable(true);
    trails->setChecked(true);
    connect(trails, &QAction::toggled, view, &SceneView::setTrailsVisible);
    connect(view, &SceneView::trailsVisibleChanged, trails, &QAction::setChecked);   // each scene's default (issue 20)
    auto* fit = add(tr("&Fit to scene"), "actionFit", {QKeySequence(Qt::Key_F)});
    connect(fit, &QAction::triggered, view, &SceneView::fitToScene);
    auto* resetView = add(tr("Reset &view"), "actionResetView", {QKeySequence(Qt::Key_Home)});
    connect(resetView, &QAction::triggered, view, &SceneView::resetView);

    auto* nextLesson = add(tr("&Next lesson"), "actionNextLesson", {QKeySequence(Qt::Key_PageDown)});
    connect(nextLesson, &QAction::triggered, w, [w] { w->stepLesson(+1); });
    auto* previousLesson = add(tr("P&revious lesson"), "actionPreviousLesson", {QKeySequence(Qt::Key_PageUp)});
    connect(previousLesson, &QAction::triggered, w, [w] { w->stepLesson(-1); });

    auto* copy = add(tr("&Copy row as text"), "actionCopy", {QKeySequence::Copy});
    connect(copy, &QAction::triggered, w, [w] { w->copySelection(false); });
    auto* copyLatex = add(tr("Copy row as &LaTeX"), "actionCopyLatex", {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_C)});
    connect(copyLatex, &QAction::triggered, w, [w] { w->copySelection(true); });
    auto* showCode = add(tr("Show c&ode of row"), "actionShowCode", {QKeySequence(Qt::Key_F2)});
    connect(showCode, &QAction::triggered, w, &MainWindow::showCodeOfCurrentRow);
    // The quantities table's context menu: the row's code, copies, and Plot over time
    // (any row, a contact's too, from the recorded history).
    QTreeView* table = w->traceView();
    table->setContextMenuPolicy(Qt::ActionsContextMenu);
    table->addActions({showCode, copy, copyLatex});
    auto* plotRow = new QAction(tr("Plot over time"), w);
    plotRow->setObjectName("actionPlotOverTime");
    connect(plotRow, &QAction::triggered, w, [w, table] { w->plotRowOverTime(table->currentIndex(), false); });
    auto* plotRowNorm = new QAction(tr("Plot length over time"), w);
    plotRowNorm->setObjectName("actionPlotNormOverTime");
    connect(plotRowNorm, &QAction::triggered, w, [w, table] { w->plotRowOverTime(table->currentIndex(), true); });
    table->addActions({plotRow, plotRowNorm});

    auto* exportHtml = add(tr("Export derivation as &HTML…"), "actionExportHtml", {QKeySequence(Qt::CTRL | Qt::Key_E)});
    connect(exportHtml, &QAction::triggered, w, [w] {
        exportWith(w, tr("Export derivation"), "derivation.html", tr("HTML (*.html)"),
                   [w](const QString& path, QString* error) { return w->derivationView()->exportHtml(path, error); });
    });
    auto* exportPdf = add(tr("Export derivation as &PDF…"), "actionExportPdf", {QKeySequence(Qt::CTRL | Qt::Key_P)});
    connect(exportPdf, &QAction::triggered, w, [w] {
        // Printed asynchronously: the window reports the result (DerivationView::pdfExported).
        const QString path = QFileDialog::getSaveFileName(w, tr("Export derivation"), "derivation.pdf", tr("PDF (*.pdf)"));
        if (!path.isEmpty()) w->derivationView()->exportPdf(path);
    });
    auto* exportPng = add(tr("Export plot as P&NG…"), "actionExportPlotPng", {});
    connect(exportPng, &QAction::triggered, w, [w] {
        exportWith(w, tr("Export plot"), "plot.png", tr("PNG (*.png)"),
                   [w](const QString& path, QString* error) { return w->plotPanel()->exportPng(path, error); });
    });
    auto* exportCsv = add(tr("Export plot data as CS&V…"), "actionExportPlotCsv", {});
    connect(exportCsv, &QAction::triggered, w, [w] {
        exportWith(w, tr("Export plot data"), "plot.csv", tr("CSV (*.csv)"),
                   [w](const QString& path, QString* error) { return w->plotPanel()->exportCsv(path, error); });
    });
    auto* quit = add(tr("&Quit"), "actionQuit", {QKeySequence::Quit});
    connect(quit, &QAction::triggered, w, &QWidget::close);
    auto* keys = add(tr("&Keys…"), "actionKeys", {QKeySequence(Qt::Key_F1)});
    connect(keys, &QAction::triggered, w, &MainWindow::showKeys);
    auto* guide = add(tr("&User guide"), "actionUserGuide", {});
    guide->setToolTip(tr("The user guide (docs/user-guide.md), with screenshots"));
    connect(guide, &QAction::triggered, w, [w] { showUserGuide(w); });
    // Tools → Compare with my simulator: one dialog per window, keeping its inputs (docs/simulator-protocol.md).
    auto* compare = add(tr("&Compare with my simulator…"), "actionCompareSimulator", {});
    compare->setToolTip(tr("Run your own simulator through the probes and name its mistakes"));
    connect(compare, &QAction::triggered, w, [w] {
        auto* dialog = w->findChild<SimulatorDialog*>(QString(), Qt::FindDirectChildrenOnly);
        if (dialog == nullptr) {
            dialog = new SimulatorDialog(w);
            // Open in the main window: the probe as the scene, the student's numbers in the table.
            // The dialog steps aside (it stays on top of its window otherwise); Tools → Compare
            // brings it back with its inputs and result.
            connect(dialog, &SimulatorDialog::openInMainWindowRequested, w, [w, dialog](int probe) {
                if (!w->probeInWindow()->open(dialog->outcome().run, dialog->outcome().right, probe)) return;
                dialog->hide();
                w->activateWindow();
            });
        }
        dialog->show();
        dialog->raise();
        dialog->activateWindow();
    });
    auto* about = add(tr("&About Rigid Body Workbook"), "actionAbout", {});
    connect(about, &QAction::triggered, w, [w] { showAbout(w); });

    QMenu* fileMenu = w->menuBar()->addMenu(tr("&File"));
    createFileActions(fileMenu);   // open, recent, save
    fileMenu->addActions({exportHtml, exportPdf, exportPng, exportCsv});
    fileMenu->addSeparator();
    fileMenu->addAction(quit);
    QMenu* editMenu = w->menuBar()->addMenu(tr("&Edit"));
    editMenu->addActions({copy, copyLatex});
    editMenu->addSeparator();
    editMenu->addAction(showCode);
    QMenu* simMenu = w->menuBar()->addMenu(tr("&Simulation"));
    simMenu->addActions({stepBackAction_, stepAction_, playAction_, resetAction_, slower, faster});
    simMenu->addSeparator();
    simMenu->addActions({gravity, torqueAction_});
    simMenu->addMenu(tr("P&arameters"))->addActions(parameterActions);
    simMenu->addMenu(tr("&Push (single-body lesson)"))->addActions(pushActions_);
    simMenu->addSeparator();
    simMenu->addActions({previousLesson, nextLesson});
    // New numbers for practice, and the worksheet for a seed (docs/exercises.md).
    simMenu->addActions({exercise->newNumbersAction(), exercise->exportWorksheetAction()});
    QMenu* viewMenu = w->menuBar()->addMenu(tr("&View"));
    viewMenu->addActions({trails, fit, resetView});
    viewMenu->addActions(view->viewActions());   // front/top/side views (1-3), body names (N)
    shortcutActions_ << view->viewActions();     // listed in Help → Keys
    // The state at each body's centre: v, ω and L arrows.
    const struct {
        QString text;
        const char* name;
        Qt::Key key;
        void (SceneView::*set)(bool);
    } stateArrows[] = {{tr("Show &velocity v"), "actionShowVelocity", Qt::Key_V, &SceneView::setShowVelocity},
                       {tr("Show angular velocity &ω"), "actionShowOmega", Qt::Key_W, &SceneView::setShowAngularVelocity},
                       {tr("Show angular &momentum L"), "actionShowL", Qt::Key_L, &SceneView::setShowAngularMomentum}};
    viewMenu->addSeparator();
    for (const auto& a : stateArrows) {
        QAction* action = add(a.text, QString::fromLatin1(a.name), {QKeySequence(a.key)});
        action->setCheckable(true);
        connect(action, &QAction::toggled, view, a.set);
        viewMenu->addAction(action);
    }
    followMenu_ = viewMenu->addMenu(tr("Camera &follows"));
    followMenu_->setObjectName("followMenu");
    viewMenu->addSeparator();
    for (QDockWidget* dock : w->findChildren<QDockWidget*>()) viewMenu->addAction(dock->toggleViewAction());
    w->menuBar()->addMenu(tr("&Tools"))->addAction(compare);
    QMenu* helpMenu = w->menuBar()->addMenu(tr("&Help"));
    helpMenu->addActions({guide, keys});
    helpMenu->addSeparator();
    helpMenu->addAction(about);

    QToolBar* toolBar = w->addToolBar(tr("Simulation"));
    toolBar->setObjectName("simulationToolBar");
    toolBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    toolBar->addActions({stepBackAction_, stepAction_, playAction_, resetAction_});
}

void ShellActions::createFileActions(QMenu* fileMenu)
{
    MainWindow* w = w_;
    auto* open = add(tr("&Open scene…"), "actionOpenScene", {QKeySequence::Open});
    connect(open, &QAction::triggered, w, [w] {
        const QString current = w->currentScenePath();
        w->sceneFiles()->showOpenDialog(current.isEmpty() ? QDir::homePath() : QFileInfo(current).absolutePath());
    });
    recentMenu_ = new QMenu(tr("Open &recent"), w);
    recentMenu_->setObjectName("recentMenu");
    connect(w->sceneFiles(), &SceneFiles::recentChanged, this, &ShellActions::updateRecentMenu);
    auto* save = add(tr("&Save scene"), "actionSaveScene", {QKeySequence::Save});
    connect(save, &QAction::triggered, w, &MainWindow::saveScene);
    // QKeySequence::SaveAs is empty on a desktop without a key theme (Xvfb, a bare
    // window manager): Ctrl+Shift+S, as the user guide says, in any case.
    QList<QKeySequence> saveAsKeys = QKeySequence::keyBindings(QKeySequence::SaveAs);
    const QKeySequence ctrlShiftS(Qt::CTRL | Qt::SHIFT | Qt::Key_S);
    if (!saveAsKeys.contains(ctrlShiftS)) saveAsKeys.prepend(ctrlShiftS);
    auto* saveAs = add(tr("Save scene &as…"), "actionSaveSceneAs", saveAsKeys);
    connect(saveAs, &QAction::triggered, w, &MainWindow::saveSceneAs);
    auto* fromLesson = add(tr("&New scene from this lesson"), "actionNewSceneFromLesson", {QKeySequence::New});
    connect(fromLesson, &QAction::triggered, w, &MainWindow::newSceneFromLesson);
    auto* editor = add(tr("&Edit the scene"), "actionEditScene", {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E)});
    connect(editor, &QAction::triggered, w, &MainWindow::showSceneEditor);

    fileMenu->addAction(open);
    fileMenu->addMenu(recentMenu_);
    fileMenu->addSeparator();
    fileMenu->addActions({fromLesson, editor, save, saveAs});
    fileMenu->addSeparator();
    w->sceneEditor()->toolBar()->addActions({save, saveAs});
    updateRecentMenu();
}

void ShellActions::updateRecentMenu()
{
    recentMenu_->clear();
    const QStringList files = w_->sceneFiles()->recentFiles();
    for (int i = 0; i < files.size(); ++i) {
        auto* a = recentMenu_->addAction(QStringLiteral("&%1  %2").arg(i + 1).arg(QDir::toNativeSeparators(files[i])));
        const QString path = files[i];
        connect(a, &QAction::triggered, w_, [w = w_, path] { w->requestOpen(path); });
    }
    if (files.isEmpty()) recentMenu_->addAction(tr("(none yet)"))->setEnabled(false);
    recentMenu_->addSeparator();
    auto* clear = recentMenu_->addAction(tr("Clear the list"));
    clear->setEnabled(!files.isEmpty());
    connect(clear, &QAction::triggered, w_->sceneFiles(), &SceneFiles::clearRecent);
}

void ShellActions::update(const World& world, long stepsBack)
{
    torqueAction_->setEnabled(world.hasSwitchableTorque());
    for (QAction* a : pushActions_) a->setEnabled(world.scene().push.body >= 0);
    stepBackAction_->setEnabled(stepsBack > 0);
}

void ShellActions::updateFollowMenu(const SceneDef& scene)
{
    followMenu_->clear();
    qDeleteAll(followMenu_->findChildren<QActionGroup*>(Qt::FindDirectChildrenOnly));
    auto* group = new QActionGroup(followMenu_);
    SceneView* view = w_->sceneView();
    auto addBody = [&](const QString& text, int body) {
        QAction* a = followMenu_->addAction(text);
        a->setCheckable(true);
        a->setChecked(body == view->followBody());
        a->setData(body);
        group->addAction(a);
        connect(a, &QAction::triggered, view, [view, body] { view->setFollowBody(body); });
    };
    addBody(tr("No body (free camera)"), -1);
    for (int b = 0; b < static_cast<int>(scene.bodies.size()); ++b) {
        const BodyDef& body = scene.bodies[static_cast<std::size_t>(b)];
        if (!body.fixed) addBody(QString::fromStdString(body.name), b);
    }
}

} // namespace rbw
