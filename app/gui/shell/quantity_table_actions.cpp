#include "app/gui/shell/quantity_table_actions.h"

#include "app/core/session.h"
#include "app/gui/panels/plots/quantity_plot_panel.h"
#include "app/gui/panels/quantities/code_view.h"
#include "app/gui/panels/quantities/trace_model.h"

#include <QApplication>
#include <QClipboard>
#include <QChartView>
#include <QDockWidget>
#include <QMainWindow>
#include <QPointer>
#include <QStatusBar>
#include <QTimer>
#include <QTreeView>

#include <cstring>

namespace rbw {

QuantityTableActions::QuantityTableActions(const Parts& parts, Session* session, QObject* parent)
    : QObject(parent)
    , p_(parts)
    , session_(session)
{
}

void QuantityTableActions::copySelection(bool asLatex)
{
    QStringList lines;
    for (const QModelIndex& index : p_.table->selectionModel()->selectedRows()) {
        if (p_.model->entryAt(index) == nullptr) continue;
        lines << (asLatex ? p_.model->data(index, TraceModel::LatexRole).toString() : p_.model->rowText(index));
    }
    if (!lines.isEmpty()) QApplication::clipboard()->setText(lines.join('\n'));
}

bool QuantityTableActions::showCodeOfCurrentRow()
{
    QModelIndex index = p_.table->currentIndex();
    if (p_.model->entryAt(index) == nullptr) {
        const QModelIndexList selected = p_.table->selectionModel()->selectedRows();
        index = selected.isEmpty() ? QModelIndex() : selected.first();
    }
    const QString file = index.data(TraceModel::SourceFileRole).toString();
    if (p_.model->entryAt(index) == nullptr || file.isEmpty()) {
        p_.status->showMessage(tr("Select a quantity in the table to see the code that computed it"), 3000);
        return false;
    }
    const int line = index.data(TraceModel::SourceLineRole).toInt();
    const bool shown = p_.codeView->showSource(file, line);
    p_.codeDock->show();
    p_.codeDock->raise();
    if (!shown) p_.status->showMessage(p_.codeView->headerText(), 5000);
    return shown;
}

bool QuantityTableActions::plotRowOverTime(const QModelIndex& row, bool norm)
{
    const TraceEntry* e = p_.model->entryAt(row);
    if (e == nullptr || !session_->isLoaded()) {
        p_.status->showMessage(tr("Right-click a quantity's row (not a group) to plot it over time"), 3000);
        return false;
    }
    const SceneDef& scene = session_->world()->scene();
    QString label = QString::fromUtf8(e->info->text);
    if (e->index >= 0 && std::strcmp(indexKindName(e->info->indexKind), "") != 0) {
        label += QStringLiteral(" %1 %2").arg(QString::fromLatin1(indexKindName(e->info->indexKind))).arg(e->index);
    }
    if (e->body >= 0 && e->body < static_cast<int>(scene.bodies.size())) {
        label += QStringLiteral(" (%1)").arg(QString::fromStdString(scene.bodies[static_cast<std::size_t>(e->body)].name));
    }
    QuantityPlot* plot = p_.plots->addQuantity(QuantityKey{QString::fromLatin1(e->info->id), e->body, e->index}, label,
                                               QString::fromUtf8(e->info->unit), session_->history(), norm,
                                               QString::fromUtf8(e->info->text));
    p_.plotDock->show();
    p_.plotDock->raise();
    growForChart(p_.plotDock, plot, kChartFitRounds, 0, 0);
    return true;
}

// A chart tall enough to read (issue 20: about 90 px at 1366x768 before): the docked
// plot grows until its chart is kReadableChartHeight tall, the 3D view giving the room
// (the student can drag the splitter back). resizeDocks sizes the dock area, which
// holds the tab bar of the docks tabbed with this one as well: asked for the dock's
// height plus what the chart lacks, the chart fell short by that tab bar (274 px at
// 1366x768, measured). So it is measured again once laid out, and what it still lacks
// is added to the area's size asked before, until the chart has its height.
void QuantityTableActions::growForChart(QDockWidget* dock, QuantityPlot* plot, int rounds, int delayMs, int asked)
{
    QTimer::singleShot(delayMs, dock, [dock, chart = QPointer<QuantityPlot>(plot), rounds, asked] {
        auto* window = qobject_cast<QMainWindow*>(dock->parentWidget());
        if (window == nullptr || dock->isFloating() || chart == nullptr || !chart->isVisible()) return;
        const int missing = kReadableChartHeight - chart->chartView()->height();
        if (missing <= 0) return;
        const int size = (asked > 0 ? asked : dock->height()) + missing;
        window->resizeDocks({dock}, {size}, Qt::Vertical);
        if (rounds > 1) growForChart(dock, chart, rounds - 1, kChartFitDelayMs, size);
    });
}

} // namespace rbw
