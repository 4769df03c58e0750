#include "app/gui/shell/main_window.h"

#include "app/exercise/exercise.h"
#include "app/core/focus_filter.h"
#include "app/scene/scene_loader.h"
#include "app/gui/panels/accuracy/accuracy_panel.h"
#include "app/gui/panels/accuracy/contact_study_panel.h"
#include "app/gui/panels/quantities/body_colour_delegate.h"
#include "app/gui/panels/check/check_panel.h"
#include "app/gui/panels/quantities/code_view.h"
#include "app/gui/panels/quantities/formula_pane.h"
#include "app/gui/shell/worksheet_export.h"
#include "app/derivation/derivation_builder.h"
#include "app/gui/panels/derivation/derivation_view.h"
#include "app/gui/shell/history_scrubber.h"
#include "app/gui/shell/parameter_bar.h"
#include "app/gui/panels/plots/body_plot_panel.h"
#include "app/gui/panels/plots/quantity_plot_panel.h"
#include "app/gui/panels/plots/plot_panel.h"
#include "app/gui/panels/quantities/trace_model.h"
#include "app/gui/panels/view/scene_view.h"
#include "app/gui/panels/view/view_snapshot.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QClipboard>
#include <QCloseEvent>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QSplitter>
#include <QTabWidget>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QInputDialog>
#include <QKeySequence>
#include <QLabel>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QRandomGenerator>
#include <QScrollArea>
#include <QSettings>
#include <QSignalBlocker>
#include <QStatusBar>
#include <QTableWidget>
#include <QTextBrowser>
#include <QTimer>
#include <QToolBar>
#include <QTreeView>
#include <QVBoxLayout>

#include <algorithm>
#include <cstring>

namespace rbw {

namespace {

QString plainText(const QAction* a)
{
    QString t = a->text();
    t.remove('&');
    return t;
}

// The page shown before the first step: nothing is computed yet.
QString introPage(const Lesson& lesson)
{
    return QStringLiteral(
               "<!DOCTYPE html><html><head><meta charset=\"utf-8\"><style>"
               "body{font-family:sans-serif;margin:1.5em;color:#222;background:#fcfcfa}"
               "h1{font-size:1.2em}p{line-height:1.5}</style></head><body>"
               "<h1>%1</h1><p>%2</p><p><b>Press Step (S or →)</b> to take the first step. This page then "
               "writes it out line by line: each formula, the formula with this step's numbers, "
               "and the result.</p></body></html>")
        .arg(lesson.title.toHtmlEscaped(), lesson.description.toHtmlEscaped());
}

} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent)
    , traceModel_(new TraceModel(this))
    , playTimer_(new QTimer(this))
{
    setWindowTitle(tr("Rigid Body Workbook"));
    lessons_ = lessonCatalogue();

    sceneView_ = new SceneView;
    sceneView_->setObjectName("sceneView");
    alertLabel_ = new QLabel;
    alertLabel_->setObjectName("alertLabel");
    alertLabel_->setWordWrap(true);
    alertLabel_->setStyleSheet("QLabel{background:#b3261e;color:white;padding:6px;font-weight:bold}");
    alertLabel_->hide();
    auto* centre = new QWidget;
    auto* centreLayout = new QVBoxLayout(centre);
    centreLayout->setContentsMargins(0, 0, 0, 0);
    centreLayout->setSpacing(0);
    centreLayout->addWidget(alertLabel_);
    centreLayout->addWidget(sceneView_, 1);
    scrubber_ = new HistoryScrubber(&session_);
    centreLayout->addWidget(scrubber_);
    connect(scrubber_, &HistoryScrubber::stepRequested, this, &MainWindow::goToStep);
    connect(scrubber_, &HistoryScrubber::focusReturnRequested, this,
            [this] { sceneView_->setFocus(Qt::OtherFocusReason); });
    setCentralWidget(centre);

    parameterBar_ = new ParameterBar(&session_, this);
    parameterBar_->setFocusReturnTarget(sceneView_);   // Enter/Escape in a box: S, Space, arrows work again
    connect(parameterBar_, &ParameterBar::speedChanged, this, [this](double speed) { clock_.setSpeed(speed); });
    connect(parameterBar_, &ParameterBar::messageRequested, statusBar(), &QStatusBar::showMessage);
    clock_.setSpeed(parameterBar_->speed());
    createDocks();
    createEditorDock();   // before the menus: the View menu lists every dock
    createActions();
    addToolBar(parameterBar_);   // after the simulation bar

    statusLabel_ = new QLabel;
    statusLabel_->setObjectName("statusLabel");
    statusBar()->addPermanentWidget(statusLabel_, 1);

    playTimer_->setInterval(PlaybackClock::kTickIntervalMs);   // each tick takes bounded time
    connect(playTimer_, &QTimer::timeout, this, &MainWindow::onPlayTick);

    connect(&session_, &Session::sessionReset, this, &MainWindow::onSessionReset);
    connect(&session_, &Session::stepRecorded, this, &MainWindow::onStepRecorded);
    connect(&session_, &Session::rewound, this, [this](long stepIndex) {
        plotPanel_->truncate(static_cast<int>(stepIndex) + 1);   // sample 0 is t = 0
        bodyPlotPanel_->truncate(static_cast<int>(stepIndex) + 1);
        quantityPlots_->truncateAfter(stepIndex - 1);   // the trace of step k leads to state k + 1
        derivationDirty_ = true;
        traceDirty_ = true;
        checkDirty_ = true;
    });
    connect(&session_, &Session::stateChanged, this, &MainWindow::onStateChanged);
    connect(&session_, &Session::blownUp, this, &MainWindow::onBlownUp);

    connect(sceneView_, &SceneView::grabStarted, this, [this](int body, QVector3D hit) {
        if (focusBody_ != body) {
            focusBody_ = body;   // the derivation of a many-body scene follows this box
            derivationDirty_ = true;
        }
        session_.beginGrab(body, Vec3(hit.x(), hit.y(), hit.z()));
    });
    connect(sceneView_, &SceneView::grabMoved, this, [this](QVector3D target) {
        session_.moveGrab(Vec3(target.x(), target.y(), target.z()));
    });
    connect(sceneView_, &SceneView::grabEnded, &session_, &Session::endGrab);

    resize(1360, 740);
    restoreLayout();
    clock_.panelsRefreshed();
}

MainWindow::~MainWindow() = default;

QAction* MainWindow::addShortcutAction(const QString& text, const QString& objectName,
                                       const QList<QKeySequence>& keys)
{
    auto* a = new QAction(text, this);
    a->setObjectName(objectName);
    a->setShortcuts(keys);
    if (!keys.isEmpty()) {
        a->setToolTip(QStringLiteral("%1 (%2)").arg(plainText(a), keys.first().toString(QKeySequence::NativeText)));
    }
    addAction(a);   // shortcuts work wherever the focus is in the window
    shortcutActions_ << a;
    return a;
}

void MainWindow::createActions()
{
    stepBackAction_ = addShortcutAction(tr("Step &back"), "actionStepBack",
                                        {QKeySequence(Qt::Key_B), QKeySequence(Qt::Key_Left)});
    connect(stepBackAction_, &QAction::triggered, this, &MainWindow::stepBack);
    stepAction_ = addShortcutAction(tr("&Step"), "actionStep", {QKeySequence(Qt::Key_S), QKeySequence(Qt::Key_Right)});
    connect(stepAction_, &QAction::triggered, this, &MainWindow::stepOnce);
    playAction_ = addShortcutAction(tr("&Play"), "actionPlay", {QKeySequence(Qt::Key_Space)});
    playAction_->setCheckable(true);
    connect(playAction_, &QAction::toggled, this, &MainWindow::setPlaying);
    resetAction_ = addShortcutAction(tr("&Reset"), "actionReset", {QKeySequence(Qt::Key_R)});
    connect(resetAction_, &QAction::triggered, this, &MainWindow::resetLesson);
    auto* slower = addShortcutAction(tr("Play s&lower"), "actionSlower", {QKeySequence(Qt::Key_BracketLeft)});
    connect(slower, &QAction::triggered, parameterBar_, &ParameterBar::slower);
    auto* faster = addShortcutAction(tr("Play &faster"), "actionFaster", {QKeySequence(Qt::Key_BracketRight)});
    connect(faster, &QAction::triggered, parameterBar_, &ParameterBar::faster);
    gravityAction_ = addShortcutAction(tr("&Gravity on/off"), "actionGravity", {QKeySequence(Qt::Key_G)});
    connect(gravityAction_, &QAction::triggered, this, [this] {
        if (session_.isLoaded()) session_.setGravityEnabled(!session_.gravityEnabled());
    });
    torqueAction_ = addShortcutAction(tr("Toggle the &torque (angular acceleration)"), "actionToggleTorque",
                                      {QKeySequence(Qt::Key_K)});
    connect(torqueAction_, &QAction::triggered, this, [this] { session_.toggleTorques(); });

    addPushAction(tr("Push −x"), QKeySequence(Qt::CTRL | Qt::Key_Left), Vec3(-1, 0, 0));
    addPushAction(tr("Push +x"), QKeySequence(Qt::CTRL | Qt::Key_Right), Vec3(1, 0, 0));
    addPushAction(tr("Push +y"), QKeySequence(Qt::CTRL | Qt::Key_Up), Vec3(0, 1, 0));
    addPushAction(tr("Push −y"), QKeySequence(Qt::CTRL | Qt::Key_Down), Vec3(0, -1, 0));
    addPushAction(tr("Push +z"), QKeySequence(Qt::CTRL | Qt::Key_PageUp), Vec3(0, 0, 1));
    addPushAction(tr("Push −z"), QKeySequence(Qt::CTRL | Qt::Key_PageDown), Vec3(0, 0, -1));

    // Keys for the parameter bar's controls.
    auto* halveDt = addShortcutAction(tr("Halve h"), "actionHalveDt", {QKeySequence(Qt::Key_H)});
    connect(halveDt, &QAction::triggered, parameterBar_, [this] { parameterBar_->scaleDt(0.5); });
    auto* doubleDt = addShortcutAction(tr("Double h"), "actionDoubleDt", {QKeySequence(Qt::SHIFT | Qt::Key_H)});
    connect(doubleDt, &QAction::triggered, parameterBar_, [this] { parameterBar_->scaleDt(2.0); });
    auto* nextIntegrator = addShortcutAction(tr("Next integrator"), "actionNextIntegrator", {QKeySequence(Qt::Key_I)});
    connect(nextIntegrator, &QAction::triggered, parameterBar_, [this] { parameterBar_->cycleIntegrator(+1); });
    auto* previousIntegrator = addShortcutAction(tr("Previous integrator"), "actionPreviousIntegrator",
                                                 {QKeySequence(Qt::SHIFT | Qt::Key_I)});
    connect(previousIntegrator, &QAction::triggered, parameterBar_, [this] { parameterBar_->cycleIntegrator(-1); });
    auto* moreC = addShortcutAction(tr("Restitution c + 0.05"), "actionMoreRestitution", {QKeySequence(Qt::Key_C)});
    connect(moreC, &QAction::triggered, parameterBar_, [this] { parameterBar_->stepRestitution(+1); });
    auto* lessC = addShortcutAction(tr("Restitution c − 0.05"), "actionLessRestitution",
                                    {QKeySequence(Qt::SHIFT | Qt::Key_C)});
    connect(lessC, &QAction::triggered, parameterBar_, [this] { parameterBar_->stepRestitution(-1); });
    auto* moreMu = addShortcutAction(tr("Friction μ + 0.05"), "actionMoreFriction", {QKeySequence(Qt::Key_U)});
    connect(moreMu, &QAction::triggered, parameterBar_, [this] { parameterBar_->stepFriction(+1); });
    auto* lessMu = addShortcutAction(tr("Friction μ − 0.05"), "actionLessFriction", {QKeySequence(Qt::SHIFT | Qt::Key_U)});
    connect(lessMu, &QAction::triggered, parameterBar_, [this] { parameterBar_->stepFriction(-1); });
    parameterActions_ = {halveDt, doubleDt, nextIntegrator, previousIntegrator, moreC, lessC, moreMu, lessMu};

    trailsAction_ = addShortcutAction(tr("Motion &trails"), "actionTrails", {QKeySequence(Qt::Key_T)});
    trailsAction_->setCheckable(true);
    trailsAction_->setChecked(true);
    connect(trailsAction_, &QAction::toggled, sceneView_, &SceneView::setTrailsVisible);
    auto* fit = addShortcutAction(tr("&Fit to scene"), "actionFit", {QKeySequence(Qt::Key_F)});
    connect(fit, &QAction::triggered, sceneView_, &SceneView::fitToScene);
    auto* resetView = addShortcutAction(tr("Reset &view"), "actionResetView", {QKeySequence(Qt::Key_Home)});
    connect(resetView, &QAction::triggered, sceneView_, &SceneView::resetView);

    auto* nextLesson = addShortcutAction(tr("&Next lesson"), "actionNextLesson", {QKeySequence(Qt::Key_PageDown)});
    connect(nextLesson, &QAction::triggered, this, [this] {
        lessonList_->setCurrentRow(std::min(lessonList_->count() - 1, lessonList_->currentRow() + 1));
    });
    auto* previousLesson =
        addShortcutAction(tr("P&revious lesson"), "actionPreviousLesson", {QKeySequence(Qt::Key_PageUp)});
    connect(previousLesson, &QAction::triggered, this, [this] {
        lessonList_->setCurrentRow(std::max(0, lessonList_->currentRow() - 1));
    });

    auto* copyAction = addShortcutAction(tr("&Copy row as text"), "actionCopy", {QKeySequence::Copy});
    connect(copyAction, &QAction::triggered, this, [this] { copySelection(false); });
    auto* copyLatexAction = addShortcutAction(tr("Copy row as &LaTeX"), "actionCopyLatex",
                                              {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_C)});
    connect(copyLatexAction, &QAction::triggered, this, [this] { copySelection(true); });
    auto* showCodeAction = addShortcutAction(tr("Show c&ode of row"), "actionShowCode", {QKeySequence(Qt::Key_F2)});
    connect(showCodeAction, &QAction::triggered, this, &MainWindow::showCodeOfCurrentRow);
    // The quantities table's context menu: the row's code and copies.
    traceView_->setContextMenuPolicy(Qt::ActionsContextMenu);
    traceView_->addActions({showCodeAction, copyAction, copyLatexAction});
    // Plot over time: any row of the table (a contact's too), from the recorded history.
    auto* plotRow = new QAction(tr("Plot over time"), this);
    plotRow->setObjectName("actionPlotOverTime");
    connect(plotRow, &QAction::triggered, this, [this] { plotRowOverTime(traceView_->currentIndex(), false); });
    auto* plotRowNorm = new QAction(tr("Plot length over time"), this);
    plotRowNorm->setObjectName("actionPlotNormOverTime");
    connect(plotRowNorm, &QAction::triggered, this, [this] { plotRowOverTime(traceView_->currentIndex(), true); });
    traceView_->addActions({plotRow, plotRowNorm});

    auto* exportHtml = addShortcutAction(tr("Export derivation as &HTML…"), "actionExportHtml",
                                         {QKeySequence(Qt::CTRL | Qt::Key_E)});
    connect(exportHtml, &QAction::triggered, this, &MainWindow::exportDerivationHtml);
    auto* exportPdf = addShortcutAction(tr("Export derivation as &PDF…"), "actionExportPdf",
                                        {QKeySequence(Qt::CTRL | Qt::Key_P)});
    connect(exportPdf, &QAction::triggered, this, &MainWindow::exportDerivationPdf);
    auto* exportPng = addShortcutAction(tr("Export plot as P&NG…"), "actionExportPlotPng", {});
    connect(exportPng, &QAction::triggered, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export plot"), "plot.png", tr("PNG (*.png)"));
        QString error;
        if (!path.isEmpty() && !plotPanel_->exportPng(path, &error)) QMessageBox::warning(this, tr("Export"), error);
    });
    auto* exportCsv = addShortcutAction(tr("Export plot data as CS&V…"), "actionExportPlotCsv", {});
    connect(exportCsv, &QAction::triggered, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export plot data"), "plot.csv", tr("CSV (*.csv)"));
        QString error;
        if (!path.isEmpty() && !plotPanel_->exportCsv(path, &error)) QMessageBox::warning(this, tr("Export"), error);
    });
    auto* quitAction = addShortcutAction(tr("&Quit"), "actionQuit", {QKeySequence::Quit});
    connect(quitAction, &QAction::triggered, this, &QWidget::close);
    auto* keysAction = addShortcutAction(tr("&Keys…"), "actionKeys", {QKeySequence(Qt::Key_F1)});
    connect(keysAction, &QAction::triggered, this, &MainWindow::showKeys);

    QMenu* fileMenu = menuBar()->addMenu(tr("&File"));
    createFileActions(fileMenu);   // open, recent, save (main_window_files.cpp)
    fileMenu->addActions({exportHtml, exportPdf, exportPng, exportCsv});
    fileMenu->addSeparator();
    fileMenu->addAction(quitAction);
    QMenu* editMenu = menuBar()->addMenu(tr("&Edit"));
    editMenu->addActions({copyAction, copyLatexAction});
    editMenu->addSeparator();
    editMenu->addAction(showCodeAction);
    QMenu* simMenu = menuBar()->addMenu(tr("&Simulation"));
    simMenu->addActions({stepBackAction_, stepAction_, playAction_, resetAction_, slower, faster});
    simMenu->addSeparator();
    simMenu->addActions({gravityAction_, torqueAction_});
    QMenu* parameterMenu = simMenu->addMenu(tr("P&arameters"));
    parameterMenu->addActions(parameterActions_);
    QMenu* pushMenu = simMenu->addMenu(tr("&Push (single-body lesson)"));
    pushMenu->addActions(pushActions_);
    simMenu->addSeparator();
    simMenu->addActions({previousLesson, nextLesson});
    // New numbers for practice (docs/exercises.md): the lesson's exercise for a seed.
    auto* newNumbers = new QAction(tr("&New numbers…"), this);
    newNumbers->setObjectName("actionNewNumbers");
    connect(newNumbers, &QAction::triggered, this, [this] {
        bool ok = false;
        const QString text = QInputDialog::getText(this, tr("New numbers"), tr("Seed (the same seed gives the same numbers):"),
                                                   QLineEdit::Normal,
                                                   QString::number(QRandomGenerator::global()->bounded(1000000)), &ok);
        if (!ok) return;
        const quint64 seed = text.trimmed().toULongLong(&ok);
        QString error;
        if (!ok) error = tr("The seed must be a whole number, got \"%1\".").arg(text);
        if (ok) openNewNumbers(seed, &error);
        if (!error.isEmpty()) QMessageBox::warning(this, tr("New numbers"), error);
    });
    simMenu->addAction(newNumbers);
    // The worksheet and answer key for a seed, as PDF or HTML (docs/exercises.md).
    auto* exportWorksheetAction = new QAction(tr("Export &worksheet and answer key…"), this);
    exportWorksheetAction->setObjectName("actionExportWorksheet");
    connect(exportWorksheetAction, &QAction::triggered, this, [this] {
        const ExerciseLoadResult spec = loadExercise(QFileInfo(currentLesson_.scenePath).absolutePath());
        if (!spec.ok()) {
            QMessageBox::information(this, tr("Worksheet"), tr("This lesson has no exercise.\n\n%1").arg(spec.errors.join('\n')));
            return;
        }
        bool ok = false;
        const QString text = QInputDialog::getText(this, tr("Worksheet"), tr("Seed (the same seed gives the same numbers):"),
                                                   QLineEdit::Normal,
                                                   QString::number(QRandomGenerator::global()->bounded(1000000)), &ok);
        if (!ok) return;
        const quint64 seed = text.trimmed().toULongLong(&ok);
        if (!ok) {
            QMessageBox::warning(this, tr("Worksheet"), tr("The seed must be a whole number, got \"%1\".").arg(text));
            return;
        }
        const QString path = QFileDialog::getSaveFileName(this, tr("Export worksheet"),
                                                          QStringLiteral("worksheet-%1.pdf").arg(seed),
                                                          tr("PDF (*.pdf);;HTML (*.html)"));
        if (path.isEmpty()) return;
        const GeneratedExercise generated = generateExercise(*spec.spec, seed);
        WorksheetFiles written;
        QString error;
        if (!generated.ok()) error = generated.errors.join('\n');
        if (error.isEmpty() && !exportWorksheet(*spec.spec, generated, path, &written, &error)) {
            QMessageBox::warning(this, tr("Worksheet"), error);
            return;
        }
        if (!error.isEmpty()) {
            QMessageBox::warning(this, tr("Worksheet"), error);
            return;
        }
        statusBar()->showMessage(tr("Wrote %1 and %2").arg(written.worksheet, written.answerKey), 6000);
    });
    simMenu->addAction(exportWorksheetAction);
    QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
    viewMenu->addActions({trailsAction_, fit, resetView});
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
        QAction* action = addShortcutAction(a.text, QString::fromLatin1(a.name), {QKeySequence(a.key)});
        action->setCheckable(true);
        connect(action, &QAction::toggled, sceneView_, a.set);
        stateArrowActions_ << action;
        viewMenu->addAction(action);
    }
    followMenu_ = viewMenu->addMenu(tr("Camera &follows"));
    followMenu_->setObjectName("followMenu");
    viewMenu->addSeparator();
    for (QDockWidget* dock : findChildren<QDockWidget*>()) {
        viewMenu->addAction(dock->toggleViewAction());
    }
    QMenu* helpMenu = menuBar()->addMenu(tr("&Help"));
    helpMenu->addAction(keysAction);

    QToolBar* bar = addToolBar(tr("Simulation"));
    bar->setObjectName("simulationToolBar");
    bar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    bar->addActions({stepBackAction_, stepAction_, playAction_, resetAction_});
}

void MainWindow::addPushAction(const QString& text, const QKeySequence& key, const Vec3& direction)
{
    QAction* a = addShortcutAction(text, QStringLiteral("actionPush%1").arg(pushActions_.size()), {key});
    connect(a, &QAction::triggered, this, [this, direction] {
        if (session_.push(direction)) statusBar()->showMessage(tr("Push queued for the next step"), 1500);
    });
    pushActions_ << a;
}

void MainWindow::createDocks()
{
    setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    setDockNestingEnabled(true);

    lessonList_ = new QListWidget;
    lessonList_->setObjectName("lessonList");
    for (const Lesson& l : lessons_) {
        auto* item = new QListWidgetItem(l.variant ? QStringLiteral("      ↳ %1").arg(l.title)
                                                   : QStringLiteral("%1  %2").arg(l.id.left(2), l.title));
        item->setToolTip(l.description);
        item->setData(Qt::UserRole, l.id);
        lessonList_->addItem(item);
    }
    lessonList_->setWordWrap(true);
    connect(lessonList_, &QListWidget::currentRowChanged, this, &MainWindow::onLessonRowChanged);
    auto* lessonsDock = new QDockWidget(tr("Lessons"), this);
    lessonsDock->setObjectName("lessonsDock");
    lessonsDock->setWidget(lessonList_);
    addDockWidget(Qt::LeftDockWidgetArea, lessonsDock);

    lessonText_ = new QTextBrowser;
    lessonText_->setObjectName("lessonText");
    lessonText_->setOpenExternalLinks(true);
    auto* textDock = new QDockWidget(tr("Lesson"), this);
    textDock->setObjectName("lessonTextDock");
    textDock->setWidget(lessonText_);
    addDockWidget(Qt::LeftDockWidgetArea, textDock);
    splitDockWidget(lessonsDock, textDock, Qt::Vertical);

    traceView_ = new QTreeView;
    traceView_->setObjectName("traceView");
    traceView_->setModel(traceModel_);
    bodySwatches_ = new BodyColourDelegate(traceView_);
    traceView_->setItemDelegateForColumn(0, bodySwatches_);
    traceView_->setAlternatingRowColors(true);
    traceView_->setSelectionBehavior(QAbstractItemView::SelectRows);
    traceView_->setSelectionMode(QAbstractItemView::ExtendedSelection);
    // Matrices take three lines (one row each), so rows differ in height.
    traceView_->setUniformRowHeights(false);
    traceView_->setWordWrap(false);
    traceView_->setIndentation(12);   // three levels (stage, body, row) without losing the values' room
    traceView_->header()->setStretchLastSection(true);
    // The formula is typeset in the pane below the table, not shown as raw LaTeX.
    traceView_->setColumnHidden(TraceModel::FormulaColumn, true);
    connect(traceModel_, &QAbstractItemModel::modelReset, traceView_, [this] {
        traceView_->expandAll();
        for (int c = 0; c < TraceModel::FormulaColumn; ++c) {
            traceView_->resizeColumnToContents(c);
            // Long symbols (the J denominator terms) must not push the values off screen.
            if (c == TraceModel::SymbolColumn) traceView_->setColumnWidth(c, std::min(traceView_->columnWidth(c), 48));
            // Nor long names (a manifold point's group: pair, feature, point k of n): at most
            // a third of the table, elided, the whole name in the tooltip.
            if (c == TraceModel::QuantityColumn) {
                const int most = std::max(170, traceView_->viewport()->width() / 3);
                traceView_->setColumnWidth(c, std::min(traceView_->columnWidth(c), most));
            }
        }
    });
    formulaPane_ = new FormulaPane;
    formulaPane_->setObjectName("formulaPane");
    connect(traceView_->selectionModel(), &QItemSelectionModel::currentRowChanged, formulaPane_,
            [this](const QModelIndex& current) { formulaPane_->showRow(current); });
    // A new step (or a scrub) changes the values under the same selection.
    connect(traceModel_, &QAbstractItemModel::dataChanged, formulaPane_,
            [this] { formulaPane_->showRow(traceView_->currentIndex()); });
    connect(traceModel_, &QAbstractItemModel::modelReset, formulaPane_,
            [this] { formulaPane_->showRow(traceView_->currentIndex()); });
    auto* traceSplit = new QSplitter(Qt::Vertical);
    traceSplit->addWidget(traceView_);
    traceSplit->addWidget(formulaPane_);
    traceSplit->setStretchFactor(0, 4);
    traceSplit->setStretchFactor(1, 1);
    traceSplit->setSizes({600, 150});
    auto* traceDock = new QDockWidget(tr("Quantities of this step"), this);
    traceDock->setObjectName("traceDock");
    traceDock->setWidget(traceSplit);
    addDockWidget(Qt::RightDockWidgetArea, traceDock);

    derivationView_ = new DerivationView;
    derivationView_->setObjectName("derivationView");
    derivationDock_ = new QDockWidget(tr("Derivation"), this);
    derivationDock_->setObjectName("derivationDock");
    derivationDock_->setWidget(derivationView_);
    addDockWidget(Qt::RightDockWidgetArea, derivationDock_);
    tabifyDockWidget(traceDock, derivationDock_);
    connect(derivationDock_, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible && derivationDirty_) refreshDerivation();
    });
    // The PDF is printed asynchronously: report the result when it is written.
    connect(derivationView_, &DerivationView::pdfExported, this,
            [this](const QString& path, bool ok, const QString& error) {
                if (ok) {
                    statusBar()->showMessage(tr("Derivation exported to %1").arg(path), 3000);
                } else {
                    QMessageBox::warning(this, tr("Export"), error);
                }
            });

    plotPanel_ = new PlotPanel;
    plotPanel_->setObjectName("plotPanel");
    auto* plotDock = new QDockWidget(tr("Energy and momentum"), this);
    plotDock->setObjectName("plotDock");
    plotDock->setWidget(plotPanel_);
    addDockWidget(Qt::BottomDockWidgetArea, plotDock);

    bodyPlotPanel_ = new BodyPlotPanel;
    bodyPlotPanel_->setObjectName("bodyPlotPanel");
    auto* bodyPlotDock = new QDockWidget(tr("Per body"), this);
    bodyPlotDock->setObjectName("bodyPlotDock");
    bodyPlotDock->setWidget(bodyPlotPanel_);
    addDockWidget(Qt::BottomDockWidgetArea, bodyPlotDock);
    tabifyDockWidget(plotDock, bodyPlotDock);
    // A dock that is a tab behind another stays "visible" as a widget; its plots are
    // redrawn only while it can be seen (visibilityChanged), not behind the other tab.
    connect(plotDock, &QDockWidget::visibilityChanged, plotPanel_, &PlotPanel::setOnScreen);
    connect(bodyPlotDock, &QDockWidget::visibilityChanged, bodyPlotPanel_, &BodyPlotPanel::setOnScreen);

    // The physics statement behind a row of the table (Show code), beside the plots so
    // that the table and the code are on screen together.
    codeView_ = new CodeView;
    codeView_->setObjectName("codeView");
    codeDock_ = new QDockWidget(tr("Code"), this);
    codeDock_->setObjectName("codeDock");
    codeDock_->setWidget(codeView_);
    addDockWidget(Qt::BottomDockWidgetArea, codeDock_);
    tabifyDockWidget(bodyPlotDock, codeDock_);

    quantityPlots_ = new QuantityPlotPanel;
    quantityPlots_->setObjectName("quantityPlotPanel");
    quantityPlotDock_ = new QDockWidget(tr("Plot over time"), this);
    quantityPlotDock_->setObjectName("quantityPlotDock");
    quantityPlotDock_->setWidget(quantityPlots_);
    addDockWidget(Qt::BottomDockWidgetArea, quantityPlotDock_);
    tabifyDockWidget(codeDock_, quantityPlotDock_);
    plotDock->raise();

    accuracyPanel_ = new AccuracyPanel;
    accuracyPanel_->setObjectName("accuracyPanel");
    auto* accuracyDock = new QDockWidget(tr("Accuracy"), this);
    accuracyDock->setObjectName("accuracyDock");
    // The panel (chart, table, settings) needs more room than the bottom strip has at
    // 1366x768: it scrolls there, and fills the screen when the dock is floated.
    auto* accuracyScroll = new QScrollArea;
    accuracyScroll->setWidgetResizable(true);
    accuracyScroll->setWidget(accuracyPanel_);
    accuracyScroll->setMinimumSize(200, 120);
    // Its second tab: the contact problems (issue 11), error against cost per model.
    auto* contactStudy = new ContactStudyPanel;
    contactStudy->setObjectName("contactStudyPanel");
    auto* contactScroll = new QScrollArea;
    contactScroll->setWidgetResizable(true);
    contactScroll->setWidget(contactStudy);
    auto* accuracyTabs = new QTabWidget;
    accuracyTabs->setObjectName("accuracyTabs");
    accuracyTabs->addTab(accuracyScroll, tr("Integrators"));
    accuracyTabs->addTab(contactScroll, tr("Contacts"));
    accuracyDock->setWidget(accuracyTabs);
    addDockWidget(Qt::RightDockWidgetArea, accuracyDock);
    tabifyDockWidget(derivationDock_, accuracyDock);

    // Check my numbers: the student's own numbers for this step, beside the workbook's.
    checkPanel_ = new CheckPanel;
    checkPanel_->setObjectName("checkPanel");
    checkDock_ = new QDockWidget(tr("Check my numbers"), this);
    checkDock_->setObjectName("checkDock");
    checkDock_->setWidget(checkPanel_);
    addDockWidget(Qt::RightDockWidgetArea, checkDock_);
    tabifyDockWidget(traceDock, checkDock_);
    traceDock->raise();

    resizeDocks({lessonsDock, traceDock}, {250, 540}, Qt::Horizontal);
    resizeDocks({lessonsDock, textDock}, {190, 420}, Qt::Vertical);
    resizeDocks({plotDock}, {230}, Qt::Vertical);
}

void MainWindow::restoreLayout()
{
    QSettings settings;
    restoreGeometry(settings.value("window/geometry").toByteArray());
    if (settings.contains("window/state")) {
        restoreState(settings.value("window/state").toByteArray());
        return;
    }
    // The first start: once the window has its size, give the quantities table room
    // for all its columns (before, after, frame, unit, source) and the lessons theirs.
    // (resizeDocks before the window is laid out is overridden by the layout.)
    QTimer::singleShot(0, this, [this] {
        auto* lessons = findChild<QDockWidget*>(QStringLiteral("lessonsDock"));
        auto* trace = findChild<QDockWidget*>(QStringLiteral("traceDock"));
        if (lessons == nullptr || trace == nullptr) return;
        resizeDocks({lessons, trace}, {std::max(220, width() * 15 / 100), std::max(560, width() * 45 / 100)},
                    Qt::Horizontal);
    });
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/state", saveState());
    if (!currentLesson_.id.isEmpty()) settings.setValue("lesson/last", currentLesson_.id);
    QMainWindow::closeEvent(event);
}

QList<QAction*> MainWindow::shortcutActions() const { return shortcutActions_; }

bool MainWindow::openLesson(const QString& id)
{
    for (int row = 0; row < lessons_.size(); ++row) {
        if (lessons_[row].id == id) {
            if (lessonList_->currentRow() != row) {
                lessonList_->setCurrentRow(row);   // loads through onLessonRowChanged
            } else {
                onLessonRowChanged(row);
            }
            return session_.isLoaded() && currentLesson_.id == id;
        }
    }
    return false;
}

void MainWindow::onLessonRowChanged(int row)
{
    if (row < 0 || row >= lessons_.size()) return;
    const Lesson& lesson = lessons_[row];
    const SceneLoadResult loaded = loadSceneFile(lesson.scenePath);
    if (!loaded.ok()) {
        // The running scene stays, under its own name, and so does its row.
        showSceneErrors(tr("Lesson \"%1\"").arg(lesson.title), loaded.errors);
        const QSignalBlocker block(lessonList_);
        int running = -1;
        for (int r = 0; r < lessons_.size(); ++r) {
            if (!currentLesson_.id.isEmpty() && lessons_[r].id == currentLesson_.id) running = r;
        }
        lessonList_->setCurrentRow(running);
        if (running < 0) lessonList_->clearSelection();
        return;
    }
    setPlaying(false);
    alertLabel_->hide();
    focusBody_ = -1;
    currentLesson_ = lesson;

    QFile text(currentLesson_.textPath);
    if (text.open(QIODevice::ReadOnly)) {
        lessonText_->setMarkdown(QString::fromUtf8(text.readAll()));
    } else {
        lessonText_->setPlainText(currentLesson_.description);
    }
    QSettings().setValue("lesson/last", currentLesson_.id);
    session_.load(*loaded.scene);   // -> onSessionReset, onStateChanged
    accuracyPanel_->setScene(*loaded.scene, currentLesson_.id);
    sceneView_->resetView();
    setWindowTitle(tr("%1 — Rigid Body Workbook").arg(currentLesson_.title));
    sceneStarted(*loaded.scene, QString());
}

bool MainWindow::openNewNumbers(quint64 seed, QString* error)
{
    const QString lessonId = currentLesson_.variant ? currentLesson_.id.section('/', 0, 0) : currentLesson_.id;
    const ExerciseLoadResult spec = loadExercise(QFileInfo(currentLesson_.scenePath).absolutePath());
    GeneratedExercise generated;
    if (spec.ok()) generated = generateExercise(*spec.spec, seed);
    if (!spec.ok() || !generated.ok()) {
        if (error != nullptr) {
            *error = spec.ok() ? generated.errors.join('\n')
                               : tr("This lesson has no new numbers.\n\n%1").arg(spec.errors.join('\n'));
        }
        return false;
    }
    setPlaying(false);
    alertLabel_->hide();
    focusBody_ = -1;
    currentLesson_.title = tr("Lesson %1, new numbers (seed %2)").arg(lessonId.section('-', 0, 0).toInt()).arg(seed);
    session_.load(*generated.scene);   // -> onSessionReset, onStateChanged
    accuracyPanel_->setScene(*generated.scene, currentLesson_.id);
    sceneStarted(*generated.scene, QString());
    sceneView_->resetView();
    setWindowTitle(tr("%1 — Rigid Body Workbook").arg(currentLesson_.title));
    statusBar()->showMessage(tr("New numbers: seed %1").arg(seed));
    return true;
}

void MainWindow::resetLesson()
{
    setPlaying(false);
    alertLabel_->hide();
    if (session_.isLoaded()) session_.reset();
}

void MainWindow::onSessionReset()
{
    traceModel_->clear();
    plotPanel_->clear();
    QStringList names;
    for (const BodyDef& b : session_.world()->scene().bodies) names << QString::fromStdString(b.name);
    QList<bool> fixed;
    for (const BodyDef& b : session_.world()->scene().bodies) fixed << b.fixed;
    bodyPlotPanel_->setBodies(names, fixed);
    quantityPlots_->setScene(names, fixed);   // another scene's plots go
    bodySwatches_->setBodies(names, fixed);
    updateFollowMenu();
    quantityPlots_->clearSamples();
    sceneView_->clearTrails();
    // Sample 0: the initial state's diagnostics, computed by the physics.
    plotPanel_->appendStep(session_.world()->time(), session_.world()->diagnostics());
    bodyPlotPanel_->appendStep(session_.world()->time(), session_.world()->diagnostics());
    derivationDirty_ = true;
    traceDirty_ = true;
    checkDirty_ = true;
}

void MainWindow::onStepRecorded(const StepTrace& trace)
{
    plotPanel_->appendStep(trace.time, trace.diagnostics);
    bodyPlotPanel_->appendStep(trace.time, trace.diagnostics);
    quantityPlots_->appendStep(trace);
    derivationDirty_ = true;
    traceDirty_ = true;
    checkDirty_ = true;
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
    if (traceDirty_ && panelsDue) {
        // A new step (or step back, or reset): the table shows its trace.
        if (trace != nullptr) traceModel_->setTrace(*trace, world->scene());
        else traceModel_->clear();
        traceDirty_ = false;
    }
    // The check table rebuilds a world for the step's start: only when paused.
    if (checkDirty_ && !playing) updateCheckPanel();
    // The typeset page follows when the run pauses: typesetting at every frame would
    // cost more than the step itself.
    if (derivationDirty_ && PlaybackClock::derivationDue(playing)) refreshDerivation();
    // While playing, the actions and the status line change only at the table's
    // pace: every repainted widget is re-uploaded for the GL composition of the window.
    // (The parameter bar follows the session's parametersChanged, which a step never emits.)
    if (panelsDue || !playing) scrubber_->sync();
    if (panelsDue) {
        updateActions();
        updateStatus();
        clock_.panelsRefreshed();
    }
}

void MainWindow::updateCheckPanel()
{
    if (!session_.isLoaded()) return;
    checkPanel_->setStep(currentLesson_.id, session_.worldBeforeCurrentStep(), session_.currentTrace(),
                         session_.world()->scene());
    checkDirty_ = false;
}

void MainWindow::refreshDerivation()
{
    if (!session_.isLoaded()) return;
    const StepTrace* trace = session_.currentTrace();
    const SceneDef& scene = session_.world()->scene();
    if (trace == nullptr) {
        derivationHtml_ = introPage(currentLesson_);
    } else {
        const QString lessonDir = QFileInfo(currentLesson_.scenePath).absolutePath();
        // Many bodies: the page writes out one, the one last grabbed (else the first movable).
        DerivationOptions options;
        options.focusBody = derivationFocusBody(scene, focusBody_);
        derivationHtml_ = buildLessonDerivation(*trace, scene, lessonDir, options).html;
    }
    derivationView_->showStep(derivationHtml_);
    derivationDirty_ = false;
}

void MainWindow::onBlownUp(const QString& message)
{
    setPlaying(false);
    alertLabel_->setText(tr("The run stopped: %1").arg(message));
    alertLabel_->show();
}

void MainWindow::stepOnce()
{
    setPlaying(false);
    session_.step();
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

void MainWindow::updateFollowMenu()
{
    if (followMenu_ == nullptr || !session_.isLoaded()) return;
    followMenu_->clear();
    qDeleteAll(followMenu_->findChildren<QActionGroup*>(Qt::FindDirectChildrenOnly));
    auto* group = new QActionGroup(followMenu_);
    auto add = [&](const QString& text, int body) {
        QAction* a = followMenu_->addAction(text);
        a->setCheckable(true);
        a->setChecked(body == sceneView_->followBody());
        a->setData(body);
        group->addAction(a);
        connect(a, &QAction::triggered, sceneView_, [this, body] { sceneView_->setFollowBody(body); });
    };
    add(tr("No body (free camera)"), -1);
    const std::vector<BodyDef>& bodies = session_.world()->scene().bodies;
    for (int b = 0; b < static_cast<int>(bodies.size()); ++b) {
        if (!bodies[static_cast<std::size_t>(b)].fixed) add(QString::fromStdString(bodies[static_cast<std::size_t>(b)].name), b);
    }
}

bool MainWindow::plotRowOverTime(const QModelIndex& row, bool norm)
{
    const TraceEntry* e = traceModel_->entryAt(row);
    if (e == nullptr || !session_.isLoaded()) {
        statusBar()->showMessage(tr("Right-click a quantity's row (not a group) to plot it over time"), 3000);
        return false;
    }
    const SceneDef& scene = session_.world()->scene();
    QString label = QString::fromUtf8(e->info->text);
    if (e->index >= 0 && std::strcmp(indexKindName(e->info->indexKind), "") != 0) {
        label += QStringLiteral(" %1 %2").arg(QString::fromLatin1(indexKindName(e->info->indexKind))).arg(e->index);
    }
    if (e->body >= 0 && e->body < static_cast<int>(scene.bodies.size())) {
        label += QStringLiteral(" (%1)").arg(QString::fromStdString(scene.bodies[static_cast<std::size_t>(e->body)].name));
    }
    quantityPlots_->addQuantity(QuantityKey{QString::fromLatin1(e->info->id), e->body, e->index}, label,
                                QString::fromUtf8(e->info->unit), session_.history(), norm,
                                QString::fromUtf8(e->info->text));
    quantityPlotDock_->show();
    quantityPlotDock_->raise();
    return true;
}

bool MainWindow::goToStep(long k)
{
    setPlaying(false);
    if (!session_.isLoaded()) return false;
    if (k == session_.world()->stepIndex()) return true;
    QApplication::setOverrideCursor(Qt::WaitCursor);
    const bool reached = session_.goToStep(k);
    QApplication::restoreOverrideCursor();
    if (reached) {
        alertLabel_->setVisible(!session_.status().ok);
    } else if (k < session_.history().firstStep()) {
        statusBar()->showMessage(tr("Step %1 is no longer recorded: the history keeps the last %2 steps (up to 1000, fewer for many bodies)")
                                     .arg(k)
                                     .arg(session_.history().size() - 1), 4000);
    } else {
        statusBar()->showMessage(tr("Step %1 not reached: stopped at step %2").arg(k).arg(session_.world()->stepIndex()), 4000);
    }
    scrubber_->sync();
    // After Go (or Enter in the step box) the keys step and play again.
    if (scrubber_->isAncestorOf(QApplication::focusWidget())) sceneView_->setFocus(Qt::OtherFocusReason);
    return reached;
}

void MainWindow::setPlaying(bool playing)
{
    if (playing && (!session_.isLoaded() || !session_.status().ok)) playing = false;
    if (playing == playTimer_->isActive()) {
        if (playAction_->isChecked() != playing) playAction_->setChecked(playing);
        return;
    }
    if (playing) {
        clock_.start();
        playTimer_->start();
    } else {
        playTimer_->stop();
        onStateChanged();   // the table, page and status catch up with the last step
    }
    if (playAction_->isChecked() != playing) playAction_->setChecked(playing);
    playAction_->setText(playing ? tr("&Pause") : tr("&Play"));
}

void MainWindow::onPlayTick()
{
    const World* world = session_.world();
    if (world == nullptr) return;
    const double h = world->scene().dt;
    const int due = clock_.stepsDue(h);
    if (due == 0) return;   // less than one step owed to real time yet
    const int taken = session_.advance(due, clock_.budgetMs());
    clock_.stepsTaken(due, taken, h);
}

void MainWindow::copySelection(bool asLatex)
{
    QStringList lines;
    for (const QModelIndex& index : traceView_->selectionModel()->selectedRows()) {
        if (traceModel_->entryAt(index) == nullptr) continue;
        lines << (asLatex ? traceModel_->data(index, TraceModel::LatexRole).toString() : traceModel_->rowText(index));
    }
    if (!lines.isEmpty()) QApplication::clipboard()->setText(lines.join('\n'));
}

bool MainWindow::showCodeOfCurrentRow()
{
    QModelIndex index = traceView_->currentIndex();
    if (traceModel_->entryAt(index) == nullptr) {
        const QModelIndexList selected = traceView_->selectionModel()->selectedRows();
        index = selected.isEmpty() ? QModelIndex() : selected.first();
    }
    const QString file = index.data(TraceModel::SourceFileRole).toString();
    if (traceModel_->entryAt(index) == nullptr || file.isEmpty()) {
        statusBar()->showMessage(tr("Select a quantity in the table to see the code that computed it"), 3000);
        return false;
    }
    const int line = index.data(TraceModel::SourceLineRole).toInt();
    const bool shown = codeView_->showSource(file, line);
    codeDock_->show();
    codeDock_->raise();
    if (!shown) statusBar()->showMessage(codeView_->headerText(), 5000);
    return shown;
}

void MainWindow::showKeys()
{
    auto* dialog = new QDialog(this);
    dialog->setObjectName("keysDialog");
    dialog->setWindowTitle(tr("Keys"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    auto* table = new QTableWidget(dialog);
    table->setObjectName("keysTable");
    table->setColumnCount(2);
    table->setHorizontalHeaderLabels({tr("Action"), tr("Keys")});
    table->verticalHeader()->hide();
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    QList<QPair<QString, QString>> rows;
    for (const QAction* a : shortcutActions_) {
        QStringList keys;
        for (const QKeySequence& k : a->shortcuts()) keys << k.toString(QKeySequence::NativeText);
        if (!keys.isEmpty()) rows.append({plainText(a), keys.join(tr(" or "))});
    }
    rows.append({tr("Orbit the camera"), tr("Left-drag on empty space, or Alt+left-drag")});
    rows.append({tr("Pan"), tr("Right- or middle-drag")});
    rows.append({tr("Zoom"), tr("Mouse wheel")});
    rows.append({tr("Pull a box with a spring"), tr("Left-drag on the box")});
    table->setRowCount(rows.size());
    for (int r = 0; r < rows.size(); ++r) {
        table->setItem(r, 0, new QTableWidgetItem(rows[r].first));
        table->setItem(r, 1, new QTableWidgetItem(rows[r].second));
    }
    table->resizeColumnsToContents();
    table->horizontalHeader()->setStretchLastSection(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);
    auto* layout = new QVBoxLayout(dialog);
    layout->addWidget(table);
    layout->addWidget(buttons);
    dialog->resize(520, 600);
    dialog->show();
}

void MainWindow::exportDerivationHtml()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Export derivation"), "derivation.html", tr("HTML (*.html)"));
    if (path.isEmpty()) return;
    QString error;
    if (!derivationView_->exportHtml(path, &error)) QMessageBox::warning(this, tr("Export"), error);
}

void MainWindow::exportDerivationPdf()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Export derivation"), "derivation.pdf", tr("PDF (*.pdf)"));
    if (!path.isEmpty()) derivationView_->exportPdf(path);
}

void MainWindow::updateActions()
{
    const World* world = session_.world();
    if (world == nullptr) return;
    torqueAction_->setEnabled(world->hasSwitchableTorque());
    for (QAction* a : pushActions_) a->setEnabled(world->scene().push.body >= 0);
    stepBackAction_->setEnabled(session_.history().stepsBackAvailable() > 0);
}

void MainWindow::updateStatus()
{
    const World* world = session_.world();
    if (world == nullptr) {
        statusLabel_->setText(tr("No lesson loaded"));
        return;
    }
    QString text = tr("%1 · step %2 · t = %3 s · h = %4 s · %5 · %6 steps back")
                       .arg(currentLesson_.title)
                       .arg(world->stepIndex())
                       .arg(world->time(), 0, 'g', 6)
                       .arg(world->scene().dt, 0, 'g', 6)
                       .arg(QString::fromLatin1(world->integrator().name()))
                       .arg(session_.history().stepsBackAvailable());
    if (world->hasSwitchableTorque()) text += session_.torquesOn() ? tr(" · torque on (K)") : tr(" · torque off (K)");
    if (world->stepIndex() == 0) text += tr("  —  press Step (S) to take the first step");
    statusLabel_->setText(text);
}

} // namespace rbw
