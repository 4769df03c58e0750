// The typeset formula of the quantities table's current row (issue 12: the Formula
// column was raw LaTeX): the quantity's name, its formula, its value before and after
// the step, its frame, unit and the physics statement that computed it, with the same
// KaTeX as the derivation. Presentation only: every piece comes from the table's
// model (TraceModel's roles), which reads the trace.
#pragma once

#include "app/gui/panels/derivation/derivation_view.h"

#include <QModelIndex>
#include <QString>

namespace rbw {

class FormulaPane : public DerivationView {
    Q_OBJECT
public:
    explicit FormulaPane(QWidget* parent = nullptr);

    // Shows the row of `index` (a TraceModel index; any column); a group row or an
    // invalid index shows a hint instead.
    void showRow(const QModelIndex& index);

    // The page body for a row, as HTML with .tex elements (derivation_page.h).
    static QString rowBodyHtml(const QModelIndex& index);
};

} // namespace rbw
