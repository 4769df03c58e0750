#include "app/gui/panels/quantities/formula_pane.h"

#include "app/derivation/derivation_page.h"
#include "app/gui/panels/quantities/trace_model.h"

namespace rbw {

FormulaPane::FormulaPane(QWidget* parent) : DerivationView(parent)
{
    setMinimumHeight(90);
    showRow(QModelIndex());
}

QString FormulaPane::rowBodyHtml(const QModelIndex& index)
{
    const QModelIndex row = index.siblingAtColumn(TraceModel::QuantityColumn);
    const QString formula = row.data(TraceModel::FormulaLatexRole).toString();
    if (!row.isValid() || formula.isEmpty()) {
        return QStringLiteral("<p class=\"stepinfo\">Select a quantity in the table to see its formula typeset, "
                              "its value before and after the step, and where it is computed.</p>\n");
    }
    const QString name = row.data(TraceModel::NameRole).toString();
    const QString symbol = row.data(TraceModel::LatexRole).toString().section(QStringLiteral(" = "), 0, 0);
    const QString unit = unitLatex(row.siblingAtColumn(TraceModel::UnitColumn).data().toString());
    const QString frame = row.siblingAtColumn(TraceModel::FrameColumn).data().toString();
    const QString after = row.data(TraceModel::ValueLatexRole).toString();
    const QVariant before = row.data(TraceModel::BeforeLatexRole);
    const QString withUnit = unit.isEmpty() ? QString() : QStringLiteral("\\ ") + unit;

    QString html = QStringLiteral("<p><strong>%1</strong></p>\n").arg(htmlEscape(name));
    html += displayMathHtml(formula);
    if (before.isValid()) {
        html += displayMathHtml(QStringLiteral("\\text{before: }") + symbol + QStringLiteral(" = ") +
                                before.toString() + withUnit + QStringLiteral(",\\qquad \\text{after: }") + symbol +
                                QStringLiteral(" = ") + after + withUnit);
    } else {
        html += displayMathHtml(symbol + QStringLiteral(" = ") + after + withUnit);
    }
    const QString source = row.data(TraceModel::SourceFileRole).toString();
    html += QStringLiteral("<p class=\"stepinfo\">%1computed in <code>%2:%3</code> (F2 shows the code)</p>\n")
                .arg(frame.isEmpty() ? QString() : QStringLiteral("%1 frame · ").arg(htmlEscape(frame)),
                     htmlEscape(source))
                .arg(row.data(TraceModel::SourceLineRole).toInt());
    return html;
}

void FormulaPane::showRow(const QModelIndex& index)
{
    showStep(derivationPage(rowBodyHtml(index), QStringLiteral("Formula"), katexUrl()));
}

} // namespace rbw
