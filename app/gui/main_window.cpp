#include "app/gui/main_window.h"

#include "app/core/scene_loader.h"
#include "app/gui/accuracy/accuracy_panel.h"
#include "app/gui/derivation/derivation_builder.h"
#include "app/gui/derivation/derivation_view.h"
#include "app/gui/plots/body_plot_panel.h"
#include "app/gui/plots/plot_panel.h"
#include "app/gui/trace_model.h"
#include "app/gui/view/scene_view.h"
#include "app/gui/view/view_snapshot.h"
#include "physics/integrator_registry.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QClipboard>
#include <QCloseEvent>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QDoubleValidator>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QKeySequence>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QTableWidget>
#include <QTextBrowser>
#include <QTimer>
#include <QToolBar>
#include <QTreeView>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rbw {

namespace {

// Wall-clock budget of one play tick: the GUI stays responsive at any speed.
constexpr double kTickBudgetMs = 12.0;

QString plainText(const QAction* a)
{
    QString t = a->text();
    t.remove('&');
    return t;
}

// Scenes with more bodies than this write out one body (and its contacts) at a time.
constexpr int kDerivationAllBodiesMax = 6;
// While playing, the quantities table is refreshed at most this often.
constexpr qint64 kTableIntervalMs = 250;

// The part of a trace about one body: its own rows, the world-level rows, and the
// contacts it takes part in (renumbered 0, 1, ... in their order). A selection of
// the recorded entries, nothing recomputed.
StepTrace focusTrace(const StepTrace& trace, int body)
{
    StepTrace out;
    out.step = trace.step;
    out.time = trace.time;
    out.diagnostics = trace.diagnostics;
    std::vector<int> renumber(trace.contacts.size(), -1);
    for (size_t c = 0; c < trace.contacts.size(); ++c) {
        const ContactHeader& h = trace.contacts[c];
        if (h.bodyA == body || h.bodyB == body) {
            renumber[c] = static_cast<int>(out.contacts.size());
            out.contacts.push_back(h);
        }
    }
    for (const TraceEntry& e : trace.entries) {
        if (e.info->stage == Stage::Collision && e.index >= 0) {
            if (e.index < static_cast<int>(renumber.size()) && renumber[e.index] >= 0) {
                out.entries.push_back(TraceEntry{e.info, e.body, renumber[e.index], e.value});
            }
        } else if (e.body == body || e.body < 0) {
            out.entries.push_back(e);
        }
    }
    return out;
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
    setCentralWidget(centre);

    createDocks();
    createActions();
    createParameterBar();

    statusLabel_ = new QLabel;
    statusLabel_->setObjectName("statusLabel");
    statusBar()->addPermanentWidget(statusLabel_, 1);

    playTimer_->setInterval(16);   // ~60 Hz; each tick takes bounded time (kTickBudgetMs)
    connect(playTimer_, &QTimer::timeout, this, &MainWindow::onPlayTick);

    connect(&session_, &Session::sessionReset, this, &MainWindow::onSessionReset);
    connect(&session_, &Session::stepRecorded, this, &MainWindow::onStepRecorded);
    connect(&session_, &Session::rewound, this, [this](long stepIndex) {
        plotPanel_->truncate(static_cast<int>(stepIndex) + 1);   // sample 0 is t = 0
        bodyPlotPanel_->truncate(static_cast<int>(stepIndex) + 1);
        derivationDirty_ = true;
        traceDirty_ = true;
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
    tableClock_.start();
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
    connect(slower, &QAction::triggered, this, [this] {
        speedBox_->setCurrentIndex(std::max(0, speedBox_->currentIndex() - 1));
    });
    auto* faster = addShortcutAction(tr("Play &faster"), "actionFaster", {QKeySequence(Qt::Key_BracketRight)});
    connect(faster, &QAction::triggered, this, [this] {
        speedBox_->setCurrentIndex(std::min(speedBox_->count() - 1, speedBox_->currentIndex() + 1));
    });
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
    connect(halveDt, &QAction::triggered, this, [this] { scaleDt(0.5); });
    auto* doubleDt = addShortcutAction(tr("Double h"), "actionDoubleDt", {QKeySequence(Qt::SHIFT | Qt::Key_H)});
    connect(doubleDt, &QAction::triggered, this, [this] { scaleDt(2.0); });
    auto* nextIntegrator = addShortcutAction(tr("Next integrator"), "actionNextIntegrator", {QKeySequence(Qt::Key_I)});
    connect(nextIntegrator, &QAction::triggered, this, [this] { cycleIntegrator(+1); });
    auto* previousIntegrator = addShortcutAction(tr("Previous integrator"), "actionPreviousIntegrator",
                                                 {QKeySequence(Qt::SHIFT | Qt::Key_I)});
    connect(previousIntegrator, &QAction::triggered, this, [this] { cycleIntegrator(-1); });
    auto* moreC = addShortcutAction(tr("Restitution c + 0.05"), "actionMoreRestitution", {QKeySequence(Qt::Key_C)});
    connect(moreC, &QAction::triggered, this, [this] { restitutionBox_->stepUp(); });
    auto* lessC = addShortcutAction(tr("Restitution c − 0.05"), "actionLessRestitution",
                                    {QKeySequence(Qt::SHIFT | Qt::Key_C)});
    connect(lessC, &QAction::triggered, this, [this] { restitutionBox_->stepDown(); });
    auto* moreMu = addShortcutAction(tr("Friction μ + 0.05"), "actionMoreFriction", {QKeySequence(Qt::Key_U)});
    connect(moreMu, &QAction::triggered, this, [this] { frictionBox_->stepUp(); });
    auto* lessMu = addShortcutAction(tr("Friction μ − 0.05"), "actionLessFriction", {QKeySequence(Qt::SHIFT | Qt::Key_U)});
    connect(lessMu, &QAction::triggered, this, [this] { frictionBox_->stepDown(); });
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
    fileMenu->addActions({exportHtml, exportPdf, exportPng, exportCsv});
    fileMenu->addSeparator();
    fileMenu->addAction(quitAction);
    QMenu* editMenu = menuBar()->addMenu(tr("&Edit"));
    editMenu->addActions({copyAction, copyLatexAction});
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
    QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
    viewMenu->addActions({trailsAction_, fit, resetView});
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

void MainWindow::scaleDt(double factor)
{
    if (!session_.isLoaded()) return;
    QString error;
    if (!session_.setDt(session_.world()->scene().dt * factor, &error)) statusBar()->showMessage(error, 5000);
}

void MainWindow::cycleIntegrator(int direction)
{
    if (!integratorBox_->isEnabled() || integratorBox_->count() == 0) return;
    const int n = integratorBox_->count();
    const int next = (integratorBox_->currentIndex() + direction + n) % n;
    QString error;
    if (!session_.setIntegrator(integratorBox_->itemText(next), &error)) statusBar()->showMessage(error, 5000);
}

void MainWindow::addPushAction(const QString& text, const QKeySequence& key, const Vec3& direction)
{
    QAction* a = addShortcutAction(text, QStringLiteral("actionPush%1").arg(pushActions_.size()), {key});
    connect(a, &QAction::triggered, this, [this, direction] {
        if (session_.push(direction)) statusBar()->showMessage(tr("Push queued for the next step"), 1500);
    });
    pushActions_ << a;
}

void MainWindow::createParameterBar()
{
    QToolBar* bar = addToolBar(tr("Parameters"));
    bar->setObjectName("parameterToolBar");

    speedBox_ = new QComboBox;
    speedBox_->setObjectName("speedBox");
    speedBox_->setToolTip(tr("Playback speed ([ slower, ] faster)"));
    // Simulated seconds per wall-clock second; 0: one step per frame; -1: as fast as possible.
    const QList<QPair<QString, double>> speeds = {
        {tr("1 step/frame"), 0.0}, {tr("¼× real time"), 0.25}, {tr("½× real time"), 0.5}, {tr("1× real time"), 1.0},
        {tr("2× real time"), 2.0}, {tr("5× real time"), 5.0},  {tr("10× real time"), 10.0}, {tr("as fast as possible"), -1.0}};
    for (const auto& [label, value] : speeds) speedBox_->addItem(label, value);
    speedBox_->setCurrentIndex(3);
    speed_ = 1.0;
    connect(speedBox_, &QComboBox::currentIndexChanged, this, [this](int i) {
        speed_ = speedBox_->itemData(i).toDouble();
        simDebt_ = 0.0;
    });
    bar->addWidget(new QLabel(tr(" Speed ")));
    bar->addWidget(speedBox_);

    dtBox_ = new QComboBox;
    dtBox_->setObjectName("dtBox");
    dtBox_->setEditable(true);
    dtBox_->setToolTip(tr("Time step h in seconds (type a value and press Enter)"));
    for (const char* h : {"2", "1", "0.1", "0.05", "0.02", "0.01", "0.005", "0.001", "0.0001"}) dtBox_->addItem(h);
    auto* validator = new QDoubleValidator(1e-9, 1e3, 12, dtBox_);
    validator->setNotation(QDoubleValidator::ScientificNotation);
    dtBox_->setValidator(validator);
    dtBox_->setMinimumContentsLength(7);
    connect(dtBox_->lineEdit(), &QLineEdit::editingFinished, this, [this] {
        if (syncing_ || !session_.isLoaded()) return;
        bool ok = false;
        const double h = dtBox_->currentText().toDouble(&ok);
        QString error;
        if (!ok || !session_.setDt(h, &error)) {
            statusBar()->showMessage(tr("h not changed: %1").arg(ok ? error : tr("not a number")), 5000);
            syncParameterControls();
        }
    });
    connect(dtBox_, &QComboBox::activated, this, [this](int) { dtBox_->lineEdit()->editingFinished(); });
    bar->addWidget(new QLabel(tr("  h ")));
    bar->addWidget(dtBox_);

    integratorBox_ = new QComboBox;
    integratorBox_->setObjectName("integratorBox");
    for (const IntegratorInfo& info : integratorCatalogue()) {
        integratorBox_->addItem(QString::fromLatin1(info.name));
        integratorBox_->setItemData(integratorBox_->count() - 1, QString::fromUtf8(info.summary), Qt::ToolTipRole);
    }
    connect(integratorBox_, &QComboBox::activated, this, [this](int i) {
        QString error;
        if (!session_.setIntegrator(integratorBox_->itemText(i), &error)) {
            statusBar()->showMessage(error, 5000);
            syncParameterControls();
        }
    });
    bar->addWidget(new QLabel(tr("  Integrator ")));
    bar->addWidget(integratorBox_);

    gravityBox_ = new QCheckBox(tr("Gravity"));
    gravityBox_->setObjectName("gravityBox");
    gravityBox_->setToolTip(tr("Gravity on/off (G)"));
    connect(gravityBox_, &QCheckBox::toggled, this, [this](bool on) {
        if (!syncing_ && session_.isLoaded()) session_.setGravityEnabled(on);
    });
    bar->addWidget(new QLabel("  "));
    bar->addWidget(gravityBox_);

    auto coefficientBox = [&](const QString& name, const QString& label, const QString& tip, double max) {
        auto* box = new QDoubleSpinBox;
        box->setObjectName(name);
        box->setRange(0.0, max);
        box->setSingleStep(0.05);
        box->setDecimals(2);
        box->setToolTip(tip);
        box->setKeyboardTracking(false);
        bar->addWidget(new QLabel(label));
        bar->addWidget(box);
        return box;
    };
    restitutionBox_ = coefficientBox("restitutionBox", tr("  c "), tr("Coefficient of restitution c (0 plastic, 1 elastic)"), 1.0);
    connect(restitutionBox_, &QDoubleSpinBox::valueChanged, this, [this](double c) {
        QString error;
        if (!syncing_ && session_.isLoaded() && !session_.setRestitution(c, &error)) statusBar()->showMessage(error, 5000);
    });
    frictionBox_ = coefficientBox("frictionBox", tr("  μ "), tr("Coulomb friction coefficient μ"), 5.0);
    connect(frictionBox_, &QDoubleSpinBox::valueChanged, this, [this](double mu) {
        QString error;
        if (!syncing_ && session_.isLoaded() && !session_.setFriction(mu, &error)) statusBar()->showMessage(error, 5000);
    });
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
    traceView_->setAlternatingRowColors(true);
    traceView_->setSelectionBehavior(QAbstractItemView::SelectRows);
    traceView_->setSelectionMode(QAbstractItemView::ExtendedSelection);
    traceView_->setUniformRowHeights(true);
    traceView_->header()->setStretchLastSection(true);
    connect(traceModel_, &QAbstractItemModel::modelReset, traceView_, [this] {
        traceView_->expandAll();
        for (int c = 0; c < TraceModel::FormulaColumn; ++c) {
            traceView_->resizeColumnToContents(c);
            // Long symbols (the J denominator terms) must not push the values off screen.
            if (c == TraceModel::SymbolColumn || c == TraceModel::QuantityColumn) {
                traceView_->setColumnWidth(c, std::min(traceView_->columnWidth(c), c == TraceModel::SymbolColumn ? 70 : 190));
            }
        }
    });
    auto* traceDock = new QDockWidget(tr("Quantities of this step"), this);
    traceDock->setObjectName("traceDock");
    traceDock->setWidget(traceView_);
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
    accuracyDock->setWidget(accuracyScroll);
    addDockWidget(Qt::RightDockWidgetArea, accuracyDock);
    tabifyDockWidget(derivationDock_, accuracyDock);
    traceDock->raise();

    resizeDocks({lessonsDock, traceDock}, {250, 540}, Qt::Horizontal);
    resizeDocks({lessonsDock, textDock}, {190, 420}, Qt::Vertical);
    resizeDocks({plotDock}, {230}, Qt::Vertical);
}

void MainWindow::restoreLayout()
{
    QSettings settings;
    restoreGeometry(settings.value("window/geometry").toByteArray());
    restoreState(settings.value("window/state").toByteArray());
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
    setPlaying(false);
    alertLabel_->hide();
    if (row < 0 || row >= lessons_.size()) return;
    focusBody_ = -1;
    currentLesson_ = lessons_[row];

    QFile text(currentLesson_.textPath);
    if (text.open(QIODevice::ReadOnly)) {
        lessonText_->setMarkdown(QString::fromUtf8(text.readAll()));
    } else {
        lessonText_->setPlainText(currentLesson_.description);
    }
    const SceneLoadResult loaded = loadSceneFile(currentLesson_.scenePath);
    if (!loaded.ok()) {
        lessonText_->setPlainText(tr("This lesson's scene cannot be loaded:\n\n") + loaded.errors.join('\n'));
        alertLabel_->setText(tr("This lesson's scene cannot be loaded: %1").arg(loaded.errors.value(0)));
        alertLabel_->show();
        updateStatus();
        return;
    }
    QSettings().setValue("lesson/last", currentLesson_.id);
    session_.load(*loaded.scene);   // -> onSessionReset, onStateChanged
    accuracyPanel_->setScene(*loaded.scene, currentLesson_.id);
    sceneView_->resetView();
    setWindowTitle(tr("%1 — Rigid Body Workbook").arg(currentLesson_.title));
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
    bodyPlotPanel_->setBodies(names);
    sceneView_->clearTrails();
    // Sample 0: the initial state's diagnostics, computed by the physics.
    plotPanel_->appendStep(session_.world()->time(), session_.world()->diagnostics());
    bodyPlotPanel_->appendStep(session_.world()->time(), session_.world()->diagnostics());
    derivationDirty_ = true;
    traceDirty_ = true;
}

void MainWindow::onStepRecorded(const StepTrace& trace)
{
    plotPanel_->appendStep(trace.time, trace.diagnostics);
    bodyPlotPanel_->appendStep(trace.time, trace.diagnostics);
    derivationDirty_ = true;
    traceDirty_ = true;
}

void MainWindow::onStateChanged()
{
    const World* world = session_.world();
    if (world == nullptr) return;
    const StepTrace* trace = session_.currentTrace();
    sceneView_->setSnapshot(makeViewSnapshot(*world, trace));
    sceneView_->setSpring(session_.springSegment());
    const bool playing = playTimer_->isActive();
    const bool panelsDue = !playing || tableClock_.elapsed() >= kTableIntervalMs;
    if (traceDirty_ && panelsDue) {
        // A new step (or step back, or reset): the table shows its trace.
        if (trace != nullptr) traceModel_->setTrace(*trace, world->scene());
        else traceModel_->clear();
        traceDirty_ = false;
    }
    // The typeset page follows when the run pauses: typesetting at every frame would
    // cost more than the step itself.
    if (derivationDirty_ && !playing) refreshDerivation();
    // While playing, the controls and the status line change only at the table's
    // pace: every repainted widget is re-uploaded for the GL composition of the window.
    if (panelsDue) {
        syncParameterControls();
        updateStatus();
        tableClock_.restart();
    }
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
        const int n = static_cast<int>(scene.bodies.size());
        if (n <= kDerivationAllBodiesMax) {
            derivationHtml_ = buildLessonDerivation(*trace, scene, lessonDir).html;
        } else {
            // Many bodies: one at a time, the one last grabbed (else the first movable).
            int focus = focusBody_;
            if (focus < 0 || focus >= n) {
                focus = 0;
                while (focus < n - 1 && scene.bodies[focus].fixed) ++focus;
            }
            derivationHtml_ = buildLessonDerivation(focusTrace(*trace, focus), scene, lessonDir).html;
            const QString note =
                tr("<p class=\"focus-note\" style=\"background:#fff4d6;padding:6px 10px;border-radius:4px\">"
                   "This scene has %1 bodies: the page writes out <b>%2</b> and its contacts. "
                   "Press on another box in the 3D view to follow it.</p>")
                    .arg(n)
                    .arg(QString::fromStdString(scene.bodies[focus].name).toHtmlEscaped());
            derivationHtml_.replace(QLatin1String("<main class=\"derivation\">"),
                                    QLatin1String("<main class=\"derivation\">") + note);
        }
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

void MainWindow::setPlaying(bool playing)
{
    if (playing && (!session_.isLoaded() || !session_.status().ok)) playing = false;
    if (playing == playTimer_->isActive()) {
        if (playAction_->isChecked() != playing) playAction_->setChecked(playing);
        return;
    }
    if (playing) {
        simDebt_ = 0.0;
        playClock_.start();
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
    // Wall time since the last tick, capped so a stall does not trigger a burst.
    const double wall = std::min(0.1, static_cast<double>(playClock_.restart()) * 1e-3);
    const double h = world->scene().dt;
    int wanted = 1;
    if (speed_ < 0.0) {
        wanted = std::numeric_limits<int>::max();
    } else if (speed_ > 0.0) {
        simDebt_ += speed_ * wall;
        wanted = static_cast<int>(std::floor(simDebt_ / h));
        if (wanted == 0) return;
    }
    const int taken = session_.advance(wanted, kTickBudgetMs);
    if (speed_ > 0.0) {
        simDebt_ -= taken * h;
        if (taken < wanted) simDebt_ = std::min(simDebt_, h);   // cannot keep up: drop the backlog
    }
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

void MainWindow::syncParameterControls()
{
    const World* world = session_.world();
    if (world == nullptr) return;
    syncing_ = true;
    const SceneDef& scene = world->scene();
    if (!dtBox_->lineEdit()->hasFocus()) dtBox_->setEditText(QString::number(scene.dt, 'g', 10));
    integratorBox_->setCurrentText(QString::fromStdString(scene.integrator));
    // A lesson that compares integrators side by side sets one per body: the box
    // would change only the bodies without their own.
    const bool perBody = std::any_of(scene.bodies.begin(), scene.bodies.end(),
                                     [](const BodyDef& b) { return !b.integrator.empty(); });
    integratorBox_->setEnabled(!perBody);
    integratorBox_->setToolTip(perBody ? tr("This lesson sets an integrator for each body (see the lesson text)")
                                       : tr("The integrator of every body"));
    gravityBox_->setChecked(scene.hasGravity());
    const bool collides = world->runsCollisionStage();
    restitutionBox_->setEnabled(collides);
    frictionBox_->setEnabled(collides);
    restitutionBox_->setValue(scene.restitution);
    frictionBox_->setValue(scene.friction);
    torqueAction_->setEnabled(world->hasSwitchableTorque());
    for (QAction* a : pushActions_) a->setEnabled(scene.push.body >= 0);
    stepBackAction_->setEnabled(session_.history().stepsBackAvailable() > 0);
    syncing_ = false;
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
