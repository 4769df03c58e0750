#include "app/gui/main_window.h"

#include "app/core/scene_loader.h"
#include "app/gui/trace_model.h"

#include <QAction>

#include <algorithm>
#include <QApplication>
#include <QClipboard>
#include <QFile>
#include <QHeaderView>
#include <QKeySequence>
#include <QLabel>
#include <QListWidget>
#include <QMenuBar>
#include <QSplitter>
#include <QStatusBar>
#include <QTextBrowser>
#include <QTimer>
#include <QToolBar>
#include <QTreeView>

namespace rbw {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent)
    , traceModel_(new TraceModel(this))
    , playTimer_(new QTimer(this))
{
    setWindowTitle(tr("Rigid Body Workbook"));
    lessons_ = lessonCatalogue();
    createActions();
    createLayout();
    playTimer_->setInterval(16);   // ~60 Hz; one step per tick keeps every tick short
    connect(playTimer_, &QTimer::timeout, this, &MainWindow::stepOnce);
    resize(1280, 720);
}

MainWindow::~MainWindow() = default;

void MainWindow::createActions()
{
    stepAction_ = new QAction(tr("&Step"), this);
    stepAction_->setObjectName("actionStep");
    stepAction_->setShortcuts({QKeySequence(Qt::Key_S), QKeySequence(Qt::Key_Right)});
    stepAction_->setToolTip(tr("Take one step (S or →)"));
    connect(stepAction_, &QAction::triggered, this, &MainWindow::stepOnce);

    playAction_ = new QAction(tr("&Play"), this);
    playAction_->setObjectName("actionPlay");
    playAction_->setCheckable(true);
    playAction_->setShortcut(QKeySequence(Qt::Key_Space));
    playAction_->setToolTip(tr("Play / pause (Space)"));
    connect(playAction_, &QAction::toggled, this, &MainWindow::setPlaying);

    resetAction_ = new QAction(tr("&Reset"), this);
    resetAction_->setObjectName("actionReset");
    resetAction_->setShortcut(QKeySequence(Qt::Key_R));
    resetAction_->setToolTip(tr("Back to the lesson's initial state (R)"));
    connect(resetAction_, &QAction::triggered, this, &MainWindow::resetLesson);

    auto* copyAction = new QAction(tr("&Copy row as text"), this);
    copyAction->setShortcut(QKeySequence::Copy);
    connect(copyAction, &QAction::triggered, this, [this] { copySelection(false); });
    auto* copyLatexAction = new QAction(tr("Copy row as &LaTeX"), this);
    copyLatexAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_C));
    connect(copyLatexAction, &QAction::triggered, this, [this] { copySelection(true); });

    auto* quitAction = new QAction(tr("&Quit"), this);
    quitAction->setShortcut(QKeySequence::Quit);
    connect(quitAction, &QAction::triggered, this, &QWidget::close);

    QMenu* fileMenu = menuBar()->addMenu(tr("&File"));
    fileMenu->addAction(quitAction);
    QMenu* simMenu = menuBar()->addMenu(tr("&Simulation"));
    simMenu->addAction(stepAction_);
    simMenu->addAction(playAction_);
    simMenu->addAction(resetAction_);
    QMenu* editMenu = menuBar()->addMenu(tr("&Edit"));
    editMenu->addAction(copyAction);
    editMenu->addAction(copyLatexAction);

    QToolBar* bar = addToolBar(tr("Simulation"));
    bar->setObjectName("simulationToolBar");
    bar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    bar->addAction(stepAction_);
    bar->addAction(playAction_);
    bar->addAction(resetAction_);
}

void MainWindow::createLayout()
{
    lessonList_ = new QListWidget;
    lessonList_->setObjectName("lessonList");
    for (const Lesson& l : lessons_) {
        auto* item = new QListWidgetItem(QStringLiteral("%1\n%2").arg(l.id.left(2), l.title));
        item->setToolTip(l.description);
        item->setData(Qt::UserRole, l.id);
        lessonList_->addItem(item);
    }
    lessonList_->setMinimumWidth(180);
    lessonList_->setWordWrap(true);
    connect(lessonList_, &QListWidget::currentRowChanged, this, &MainWindow::onLessonRowChanged);

    traceView_ = new QTreeView;
    traceView_->setObjectName("traceView");
    traceView_->setModel(traceModel_);
    traceView_->setAlternatingRowColors(true);
    traceView_->setSelectionBehavior(QAbstractItemView::SelectRows);
    traceView_->setUniformRowHeights(true);
    traceView_->header()->setStretchLastSection(true);
    connect(traceModel_, &QAbstractItemModel::modelReset, traceView_, [this] {
        traceView_->expandAll();
        for (int c = 0; c < TraceModel::FormulaColumn; ++c) {
            traceView_->resizeColumnToContents(c);
            // Long symbols (the J denominator terms) must not push the values off screen.
            if (c == TraceModel::SymbolColumn) {
                traceView_->setColumnWidth(c, std::min(traceView_->columnWidth(c), 140));
            }
        }
    });

    lessonText_ = new QTextBrowser;
    lessonText_->setObjectName("lessonText");
    lessonText_->setOpenExternalLinks(true);

    auto* right = new QSplitter(Qt::Vertical);
    right->addWidget(traceView_);
    right->addWidget(lessonText_);
    right->setStretchFactor(0, 3);
    right->setStretchFactor(1, 2);

    auto* main = new QSplitter(Qt::Horizontal);
    main->addWidget(lessonList_);
    main->addWidget(right);
    main->setStretchFactor(1, 1);
    main->setSizes({220, 1060});
    setCentralWidget(main);

    statusLabel_ = new QLabel;
    statusLabel_->setObjectName("statusLabel");
    statusBar()->addPermanentWidget(statusLabel_, 1);
}

bool MainWindow::openLesson(const QString& id)
{
    for (int row = 0; row < lessons_.size(); ++row) {
        if (lessons_[row].id == id) {
            if (lessonList_->currentRow() != row) {
                lessonList_->setCurrentRow(row);   // loads through onLessonRowChanged
            } else {
                onLessonRowChanged(row);
            }
            return world_ != nullptr && currentLesson_.id == id;
        }
    }
    return false;
}

void MainWindow::onLessonRowChanged(int row)
{
    setPlaying(false);
    world_.reset();
    traceModel_->clear();
    if (row < 0 || row >= lessons_.size()) return;
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
        updateStatus();
        return;
    }
    world_ = std::make_unique<World>(*loaded.scene);
    setWindowTitle(tr("%1 — Rigid Body Workbook").arg(currentLesson_.title));
    updateStatus();
}

void MainWindow::resetLesson()
{
    onLessonRowChanged(lessonList_->currentRow());
}

void MainWindow::stepOnce()
{
    if (!world_) return;
    const StepStatus status = world_->step(&trace_);
    if (!status.ok) {
        setPlaying(false);
        traceModel_->clear();   // the blown-up step's numbers are not results
        statusLabel_->setText(QString::fromStdString(status.message));
        return;
    }
    traceModel_->setTrace(trace_, world_->scene());
    updateStatus();
}

void MainWindow::setPlaying(bool playing)
{
    if (playing && (!world_ || !world_->status().ok)) playing = false;
    if (playing) playTimer_->start();
    else playTimer_->stop();
    if (playAction_->isChecked() != playing) playAction_->setChecked(playing);
    playAction_->setText(playing ? tr("&Pause") : tr("&Play"));
}

void MainWindow::copySelection(bool asLatex)
{
    QStringList lines;
    for (const QModelIndex& index : traceView_->selectionModel()->selectedRows()) {
        if (traceModel_->entryAt(index) == nullptr) continue;
        lines << (asLatex ? traceModel_->data(index, TraceModel::LatexRole).toString()
                          : traceModel_->rowText(index));
    }
    if (!lines.isEmpty()) QApplication::clipboard()->setText(lines.join('\n'));
}

void MainWindow::updateStatus()
{
    if (!world_) {
        statusLabel_->setText(tr("No lesson loaded"));
        return;
    }
    statusLabel_->setText(tr("%1 · step %2 · t = %3 s · h = %4 s · %5")
                              .arg(currentLesson_.title)
                              .arg(world_->stepIndex())
                              .arg(world_->time(), 0, 'g', 6)
                              .arg(world_->scene().dt, 0, 'g', 6)
                              .arg(QString::fromLatin1(world_->integrator().name())));
    if (world_->stepIndex() == 0) {
        statusLabel_->setText(statusLabel_->text() + tr("  —  press Step (S) to take the first step"));
    }
}

} // namespace rbw
