// The quantities table: a QTreeView over a TraceModel that keeps every value on
// screen (issue 20, item 3). The columns are sized to what they hold: Before, After,
// Frame and Unit to their widest cell, so a value is never clipped (a matrix's digits
// are lowered, down to 3, when two matrices side by side would not fit; the tooltip
// has all of them); Frame and Unit stay narrow; the Quantity column is as wide as its
// widest name (never elided; a group's label spans its whole row), the Symbol column
// at most kMaxSymbolWidth, and Source the rest (elided there, its tooltip has the whole
// path; hidden when less than a section's minimum is left, the formula pane saying where
// the value is computed: the table never scrolls sideways for it). With a student simulator's numbers
// (TraceModel's Yours column, beside After) that column is fitted like the values, and
// where they do not all fit (1366x768) Before gives way to it. Every
// new step, scrub or resize fits the columns again; a value that grows while playing
// widens its column.
#pragma once

#include <QTreeView>

namespace rbw {

class TraceModel;

class TraceView : public QTreeView {
    Q_OBJECT
public:
    static constexpr int kMinQuantityWidth = 96;
    static constexpr int kMaxSymbolWidth = 56;

    explicit TraceView(TraceModel* model, QWidget* parent = nullptr);
    TraceModel* traceModel() const { return model_; }

    // The width a cell's text needs: its widest line in the cell's font, with the
    // delegate's margins.
    int cellWidth(const QModelIndex& index) const;
    // Sizes every column as described above.
    void fitColumns();

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void onDataChanged(const QModelIndex& topLeft, const QModelIndex& bottomRight);
    // Group rows (rows with children) span all columns, recursively.
    void spanGroupRows(const QModelIndex& parent);
    // The widest quantity name of a leaf row, with its indentation.
    int quantityNamesWidth() const;
    // The widest cell of a column over every row (expanded or not).
    int widestCell(int column) const;
    int headerWidth(int column) const;

    TraceModel* model_;
    bool fitting_ = false;
};

} // namespace rbw
