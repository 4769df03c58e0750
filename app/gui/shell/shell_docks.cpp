#include "app/gui/shell/shell_docks.h"

#include "app/gui/panels/accuracy/accuracy_panel.h"
#include "app/gui/panels/accuracy/contact_study_panel.h"
#include "app/gui/panels/check/check_panel.h"
#include "app/gui/panels/derivation/derivation_view.h"
#include "app/gui/panels/editor/scene_editor.h"
#include "app/gui/panels/plots/body_plot_panel.h"
#include "app/gui/panels/plots/plot_panel.h"
#include "app/gui/panels/plots/quantity_plot_panel.h"
#include "app/gui/panels/quantities/body_colour_delegate.h"
#include "app/gui/panels/quantities/code_view.h"
#include "app/gui/panels/quantities/formula_pane.h"
#include "app/gui/panels/quantities/trace_model.h"

#include <QDockWidget>
#include <QHeaderView>
#include <QListWidget>
#include <QMainWindow>
#include <QScrollArea>
#include <QSplitter>
#include <QTabWidget>
#include <QTextBrowser>
#include <QTextDocument>
#include <QTimer>
#include <QTreeView>
#include "app/gui/panels/quantities/trace_view.h"

#include <algorithm>

namespace rbw {

ShellDocks buildDocks(QMainWindow* window, const QList<Lesson>& lessons, TraceModel* traceModel)
{
    ShellDocks d;
    window->setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
    window->setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    window->setDockNestingEnabled(true);

    d.lessonList = new QListWidget;
    d.lessonList->setObjectName("lessonList");
    for (const Lesson& l : lessons) {
        auto* item = new QListWidgetItem(l.variant ? QStringLiteral("      ↳ %1").arg(l.title)
                                                   : QStringLiteral("%1  %2").arg(l.id.left(2), l.title));
        item->setToolTip(l.description);
        item->setData(Qt::UserRole, l.id);
        d.lessonList->addItem(item);
    }
    d.lessonList->setWordWrap(true);
    auto* lessonsDock = new QDockWidget(QObject::tr("Lessons"), window);
    lessonsDock->setObjectName("lessonsDock");
    lessonsDock->setWidget(d.lessonList);
    window->addDockWidget(Qt::LeftDockWidgetArea, lessonsDock);

    d.lessonText = new QTextBrowser;
    d.lessonText->setObjectName("lessonText");
    d.lessonText->setOpenExternalLinks(true);
    // Headings sized for a side panel: Qt's default h1 (xx-large) broke a lesson's title
    // mid-word at 1366 px ("intermediat e-axis").
    d.lessonText->document()->setDefaultStyleSheet(
        QStringLiteral("h1{font-size:x-large} h2{font-size:large} h3{font-size:medium}"));
    auto* textDock = new QDockWidget(QObject::tr("Lesson"), window);
    textDock->setObjectName("lessonTextDock");
    textDock->setWidget(d.lessonText);
    window->addDockWidget(Qt::LeftDockWidgetArea, textDock);
    window->splitDockWidget(lessonsDock, textDock, Qt::Vertical);

    d.traceView = new TraceView(traceModel);   // columns sized to their values (issue 20)
    d.bodySwatches = new BodyColourDelegate(d.traceView);
    d.traceView->setItemDelegateForColumn(0, d.bodySwatches);
    d.formulaPane = new FormulaPane;
    d.formulaPane->setObjectName("formulaPane");
    QObject::connect(d.traceView->selectionModel(), &QItemSelectionModel::currentRowChanged, d.formulaPane,
                     [pane = d.formulaPane](const QModelIndex& current) { pane->showRow(current); });
    // A new step (or a scrub) changes the values under the same selection.
    QObject::connect(traceModel, &QAbstractItemModel::dataChanged, d.formulaPane,
                     [pane = d.formulaPane, view = d.traceView] { pane->showRow(view->currentIndex()); });
    QObject::connect(traceModel, &QAbstractItemModel::modelReset, d.formulaPane,
                     [pane = d.formulaPane, view = d.traceView] { pane->showRow(view->currentIndex()); });
    auto* traceSplit = new QSplitter(Qt::Vertical);
    traceSplit->addWidget(d.traceView);
    traceSplit->addWidget(d.formulaPane);
    traceSplit->setStretchFactor(0, 4);
    traceSplit->setStretchFactor(1, 1);
    traceSplit->setSizes({600, 150});
    auto* traceDock = new QDockWidget(QObject::tr("Quantities of this step"), window);
    traceDock->setObjectName("traceDock");
    traceDock->setWidget(traceSplit);
    window->addDockWidget(Qt::RightDockWidgetArea, traceDock);

    d.derivationView = new DerivationView;
    d.derivationView->setObjectName("derivationView");
    d.derivationDock = new QDockWidget(QObject::tr("Derivation"), window);
    d.derivationDock->setObjectName("derivationDock");
    d.derivationDock->setWidget(d.derivationView);
    window->addDockWidget(Qt::RightDockWidgetArea, d.derivationDock);
    window->tabifyDockWidget(traceDock, d.derivationDock);

    d.plotPanel = new PlotPanel;
    d.plotPanel->setObjectName("plotPanel");
    auto* plotDock = new QDockWidget(QObject::tr("Energy and momentum"), window);
    plotDock->setObjectName("plotDock");
    plotDock->setWidget(d.plotPanel);
    window->addDockWidget(Qt::BottomDockWidgetArea, plotDock);

    d.bodyPlotPanel = new BodyPlotPanel;
    d.bodyPlotPanel->setObjectName("bodyPlotPanel");
    auto* bodyPlotDock = new QDockWidget(QObject::tr("Per body"), window);
    bodyPlotDock->setObjectName("bodyPlotDock");
    bodyPlotDock->setWidget(d.bodyPlotPanel);
    window->addDockWidget(Qt::BottomDockWidgetArea, bodyPlotDock);
    window->tabifyDockWidget(plotDock, bodyPlotDock);
    // A dock that is a tab behind another stays "visible" as a widget; its plots are
    // redrawn only while it can be seen (visibilityChanged), not behind the other tab.
    QObject::connect(plotDock, &QDockWidget::visibilityChanged, d.plotPanel, &PlotPanel::setOnScreen);
    QObject::connect(bodyPlotDock, &QDockWidget::visibilityChanged, d.bodyPlotPanel, &BodyPlotPanel::setOnScreen);

    // The physics statement behind a row of the table (Show code), beside the plots so
    // that the table and the code are on screen together.
    d.codeView = new CodeView;
    d.codeView->setObjectName("codeView");
    d.codeDock = new QDockWidget(QObject::tr("Code"), window);
    d.codeDock->setObjectName("codeDock");
    d.codeDock->setWidget(d.codeView);
    window->addDockWidget(Qt::BottomDockWidgetArea, d.codeDock);
    window->tabifyDockWidget(bodyPlotDock, d.codeDock);

    d.quantityPlots = new QuantityPlotPanel;
    d.quantityPlots->setObjectName("quantityPlotPanel");
    d.quantityPlotDock = new QDockWidget(QObject::tr("Plot over time"), window);
    d.quantityPlotDock->setObjectName("quantityPlotDock");
    d.quantityPlotDock->setWidget(d.quantityPlots);
    window->addDockWidget(Qt::BottomDockWidgetArea, d.quantityPlotDock);
    window->tabifyDockWidget(d.codeDock, d.quantityPlotDock);
    plotDock->raise();

    d.accuracyPanel = new AccuracyPanel;
    d.accuracyPanel->setObjectName("accuracyPanel");
    auto* accuracyDock = new QDockWidget(QObject::tr("Accuracy"), window);
    accuracyDock->setObjectName("accuracyDock");
    // The panel (chart, table, settings) needs more room than the bottom strip has at
    // 1366x768: it scrolls there, and fills the screen when the dock is floated.
    auto* accuracyScroll = new QScrollArea;
    accuracyScroll->setWidgetResizable(true);
    accuracyScroll->setWidget(d.accuracyPanel);
    accuracyScroll->setMinimumSize(200, 120);
    // Its second tab: the contact problems (issue 11), error against cost per model.
    auto* contactStudy = new ContactStudyPanel;
    contactStudy->setObjectName("contactStudyPanel");
    auto* contactScroll = new QScrollArea;
    contactScroll->setWidgetResizable(true);
    contactScroll->setWidget(contactStudy);
    auto* accuracyTabs = new QTabWidget;
    accuracyTabs->setObjectName("accuracyTabs");
    accuracyTabs->addTab(accuracyScroll, QObject::tr("Integrators"));
    accuracyTabs->addTab(contactScroll, QObject::tr("Contacts"));
    accuracyDock->setWidget(accuracyTabs);
    window->addDockWidget(Qt::RightDockWidgetArea, accuracyDock);
    window->tabifyDockWidget(d.derivationDock, accuracyDock);

    // Check my numbers: the student's own numbers for this step, beside the workbook's.
    d.checkPanel = new CheckPanel;
    d.checkPanel->setObjectName("checkPanel");
    d.checkDock = new QDockWidget(QObject::tr("Check my numbers"), window);
    d.checkDock->setObjectName("checkDock");
    d.checkDock->setWidget(d.checkPanel);
    window->addDockWidget(Qt::RightDockWidgetArea, d.checkDock);
    window->tabifyDockWidget(traceDock, d.checkDock);
    traceDock->raise();

    window->resizeDocks({lessonsDock, traceDock}, {250, 540}, Qt::Horizontal);
    window->resizeDocks({lessonsDock, textDock}, {190, 420}, Qt::Vertical);
    window->resizeDocks({plotDock}, {230}, Qt::Vertical);

    // The scene editor: a tab beside the quantities of the step, where a key and its
    // value fit side by side.
    d.sceneEditor = new SceneEditor;
    d.sceneEditor->setObjectName("sceneEditor");
    d.editorDock = new QDockWidget(QObject::tr("Scene editor"), window);
    d.editorDock->setObjectName("sceneEditorDock");
    d.editorDock->setWidget(d.sceneEditor);
    window->addDockWidget(Qt::RightDockWidgetArea, d.editorDock);
    window->tabifyDockWidget(traceDock, d.editorDock);
    traceDock->raise();
    return d;
}

void fitDocksToWindow(QMainWindow* window)
{
    // (resizeDocks before the window is laid out is overridden by the layout.)
    QTimer::singleShot(0, window, [window] {
        auto* lessons = window->findChild<QDockWidget*>(QStringLiteral("lessonsDock"));
        auto* trace = window->findChild<QDockWidget*>(QStringLiteral("traceDock"));
        if (lessons == nullptr || trace == nullptr) return;
        window->resizeDocks({lessons, trace},
                            {std::max(270, window->width() * 19 / 100), std::max(560, window->width() * 45 / 100)},   // a readable Lesson panel (issue 20)
                            Qt::Horizontal);
    });
}

} // namespace rbw
