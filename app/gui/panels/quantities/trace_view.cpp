#include "app/gui/panels/quantities/trace_view.h"

#include "app/gui/panels/quantities/trace_model.h"

#include <QFontMetrics>
#include <QHeaderView>
#include <QScrollBar>
#include <QStyle>
#include <QTimer>

#include <functional>
#include <vector>

#include <algorithm>

namespace rbw {

namespace {

// Columns sized to their widest cell, in the order they get their room (Yours, a
// student simulator's numbers, only while it is shown; Before unless it gave way to it).
std::vector<int> valueColumns(const QTreeView* view, bool withBefore)
{
    std::vector<int> columns;
    if (withBefore || !view->isColumnHidden(TraceModel::BeforeColumn)) columns.push_back(TraceModel::BeforeColumn);
    columns.push_back(TraceModel::ValueColumn);
    if (!view->isColumnHidden(TraceModel::YoursColumn)) columns.push_back(TraceModel::YoursColumn);
    columns.push_back(TraceModel::FrameColumn);
    columns.push_back(TraceModel::UnitColumn);
    return columns;
}

void forEachIndex(const QAbstractItemModel* model, const QModelIndex& parent, int column,
                  const std::function<void(const QModelIndex&)>& f)
{
    for (int r = 0; r < model->rowCount(parent); ++r) {
        f(model->index(r, column, parent));
        const QModelIndex first = model->index(r, 0, parent);
        if (model->rowCount(first) > 0) forEachIndex(model, first, column, f);
    }
}

} // namespace

TraceView::TraceView(TraceModel* model, QWidget* parent)
    : QTreeView(parent)
    , model_(model)
{
    setObjectName("traceView");
    setModel(model);
    setAlternatingRowColors(true);
    setSelectionBehavior(QAbstractItemView::SelectRows);
    setSelectionMode(QAbstractItemView::ExtendedSelection);
    // Matrices take three lines (one row each), so rows differ in height.
    setUniformRowHeights(false);
    setWordWrap(false);
    setIndentation(12);   // three levels (stage, body, row) without losing the values' room
    setTextElideMode(Qt::ElideRight);
    header()->setStretchLastSection(true);
    header()->setMinimumSectionSize(24);
    // The formula is typeset in the pane below the table, not shown as raw LaTeX.
    setColumnHidden(TraceModel::FormulaColumn, true);
    // A student's own numbers (Yours) sit beside the workbook's After, shown only with them.
    header()->moveSection(header()->visualIndex(TraceModel::YoursColumn), header()->visualIndex(TraceModel::ValueColumn) + 1);
    setColumnHidden(TraceModel::YoursColumn, true);
    connect(model, &QAbstractItemModel::modelReset, this, [this] {
        setColumnHidden(TraceModel::YoursColumn, !model_->hasStudentValues());
        expandAll();
        spanGroupRows(QModelIndex());
        fitColumns();
    });
    connect(model, &QAbstractItemModel::dataChanged, this, &TraceView::onDataChanged);
}

int TraceView::cellWidth(const QModelIndex& index) const
{
    const QString text = index.data(Qt::DisplayRole).toString();
    if (text.isEmpty()) return 0;
    const QVariant fontData = index.data(Qt::FontRole);
    const QFontMetrics metrics(fontData.isValid() ? fontData.value<QFont>() : font());
    int widest = 0;
    for (const QString& line : text.split('\n')) widest = std::max(widest, metrics.horizontalAdvance(line));
    // QStyledItemDelegate's text margin on each side, and a pixel to spare.
    const int margin = style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, this) + 1;
    return widest + 2 * margin + 2;
}

void TraceView::spanGroupRows(const QModelIndex& parent)
{
    // A group's label (a stage, a body, a contact's pair, feature and point) has the
    // whole row: it is never elided, and it does not widen the Quantity column.
    for (int r = 0; r < model()->rowCount(parent); ++r) {
        const QModelIndex first = model()->index(r, 0, parent);
        const bool group = model()->rowCount(first) > 0;
        setFirstColumnSpanned(r, parent, group);
        if (group) spanGroupRows(first);
    }
}

int TraceView::quantityNamesWidth() const
{
    // The widest quantity name with its indentation (the depth of its row, and the
    // root's decoration).
    int widest = headerWidth(TraceModel::QuantityColumn);
    std::function<void(const QModelIndex&, int)> visit = [&](const QModelIndex& parent, int depth) {
        for (int r = 0; r < model()->rowCount(parent); ++r) {
            const QModelIndex first = model()->index(r, 0, parent);
            if (model()->rowCount(first) > 0) {
                visit(first, depth + 1);
            } else {
                widest = std::max(widest, cellWidth(first) + indentation() * (depth + 1));
            }
        }
    };
    visit(QModelIndex(), 0);
    return widest;
}

int TraceView::widestCell(int column) const
{
    int widest = 0;
    forEachIndex(model(), QModelIndex(), column, [&](const QModelIndex& i) { widest = std::max(widest, cellWidth(i)); });
    return widest;
}

int TraceView::headerWidth(int column) const
{
    const QFontMetrics metrics(header()->font());
    const int margin = style()->pixelMetric(QStyle::PM_HeaderMargin, nullptr, header());
    return metrics.horizontalAdvance(model()->headerData(column, Qt::Horizontal).toString()) + 2 * margin + 4;
}

void TraceView::fitColumns()
{
    if (fitting_) return;
    fitting_ = true;
    const int available = viewport()->width() > 50 ? viewport()->width() : width() - 20;
    const int symbol = std::min(kMaxSymbolWidth, std::max(headerWidth(TraceModel::SymbolColumn),
                                                          widestCell(TraceModel::SymbolColumn)));
    std::vector<int> columns = valueColumns(this, true);
    std::vector<int> widths(columns.size());
    auto valuesWidth = [&](std::vector<int>& w) {
        int sum = 0;
        for (size_t k = 0; k < columns.size(); ++k) {
            w[k] = std::max(headerWidth(columns[k]), widestCell(columns[k]));
            sum += w[k];
        }
        return sum;
    };
    model_->setMatrixDigits(7);
    model_->setVectorDigits(7);
    int needed = valuesWidth(widths);
    // The Quantity column: every name whole (group labels span their row), on one line
    // where there is room, else broken at its spaces into the room the values leave
    // (never narrower than kMinQuantityWidth).
    const int wrapBefore = model_->nameWrap();
    model_->setNameWrap(0, font());
    int quantity = std::max(kMinQuantityWidth, quantityNamesWidth());
    const int room = available - symbol - needed;
    if (quantity > room) {
        const int deepest = 3 * indentation();   // stage, body, row
        const int margins = 2 * (style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, this) + 1) + 2;
        model_->setNameWrap(std::max(kMinQuantityWidth, room) - deepest - margins, font());
        quantity = std::max(kMinQuantityWidth, quantityNamesWidth());
    }
    if (model_->nameWrap() != wrapBefore) scheduleDelayedItemsLayout();   // rows change height
    auto shrink = [&] {
        // Two matrices side by side still too wide: fewer digits in the cells (never below 3).
        for (int digits = 6; digits >= 3 && symbol + needed + quantity > available; --digits) {
            model_->setMatrixDigits(digits);
            needed = valuesWidth(widths);
        }
        // Still too wide: vectors and quaternions in fewer digits too (never below 4).
        for (int digits = 6; digits >= 4 && symbol + needed + quantity > available; --digits) {
            model_->setVectorDigits(digits);
            needed = valuesWidth(widths);
        }
    };
    shrink();
    // With a student's numbers (Yours) and still too wide (1366x768): Before gives way,
    // so that After and Yours stand side by side on screen (the step's start is the
    // previous step's After; the formula pane shows both), and the digits come back.
    const bool beforeGives = !isColumnHidden(TraceModel::YoursColumn) && symbol + needed + quantity > available;
    setColumnHidden(TraceModel::BeforeColumn, beforeGives);
    if (beforeGives) {
        columns.erase(columns.begin());
        widths.erase(widths.begin());
        model_->setMatrixDigits(7);
        model_->setVectorDigits(7);
        needed = valuesWidth(widths);
        shrink();
    }
    setColumnWidth(TraceModel::QuantityColumn, quantity);
    setColumnWidth(TraceModel::SymbolColumn, symbol);
    for (size_t k = 0; k < columns.size(); ++k) setColumnWidth(columns[k], widths[k]);
    // Source: the room that is left (issue 20: it made the table scroll sideways at
    // 1366x768), elided there; its tooltip has the whole path and line. With less room
    // than a section's minimum it is not shown at all: the formula pane below the table
    // and every row's tooltip say where the value is computed.
    const int sourceLeft = available - quantity - symbol - needed;
    setColumnHidden(TraceModel::SourceColumn, sourceLeft < header()->minimumSectionSize());
    setColumnWidth(TraceModel::SourceColumn,
                   std::min(std::max(headerWidth(TraceModel::SourceColumn), widestCell(TraceModel::SourceColumn)),
                            std::max(header()->minimumSectionSize(), sourceLeft)));
    horizontalScrollBar()->setValue(0);
    viewport()->update();
    fitting_ = false;
}

void TraceView::onDataChanged(const QModelIndex& topLeft, const QModelIndex& bottomRight)
{
    // A value that grew (playing: -5.8 becomes -5.886) must not be clipped.
    const QModelIndex parent = topLeft.parent();
    for (int r = topLeft.row(); r <= bottomRight.row(); ++r) {
        for (int c : valueColumns(this, false)) {
            if (c < topLeft.column() || c > bottomRight.column()) continue;
            if (cellWidth(model()->index(r, c, parent)) > columnWidth(c)) {
                QTimer::singleShot(0, this, &TraceView::fitColumns);   // once, after the batch
                return;
            }
        }
    }
}

void TraceView::resizeEvent(QResizeEvent* event)
{
    QTreeView::resizeEvent(event);
    fitColumns();
}

} // namespace rbw
