#include "app/derivation/template_expander.h"

#include "app/derivation/derivation_page.h"

#include <cstddef>
#include <variant>

namespace rbw {

// @iterations: the contact's accumulated impulses after each velocity iteration of the
// manifold solver (ContactHeader::iterations), after the warm start they began from, as
// one table, with what one iteration is (the solver's ContactHeader::iteration) under
// it; nothing for a contact of the course model (one impulse, no iterations).
QString TemplateExpander::iterations(const TemplateNode& n, const ExpansionContext& ctx)
{
    const int k = ctx.look.contact;
    if (k < 0 || k >= static_cast<int>(trace_.contacts.size())) {
        const QString e = where(n.line) + QStringLiteral("@iterations needs a contact: use it inside @foreach contact");
        if (!errors.contains(e)) errors << e;
        return QString();
    }
    const ContactHeader& h = trace_.contacts[static_cast<std::size_t>(k)];
    if (h.iterations.empty()) return QString();
    // (x, y, z) on one line, so that each iteration is one row of the table
    const auto tuple = [this](const Vec3& v) {
        QStringList parts;
        for (int i = 0; i < 3; ++i) parts << numberLatex(choppedComponent(v, i), digits_);
        return QStringLiteral("(") + parts.join(QStringLiteral(",\\ ")) + QStringLiteral(")");
    };
    QString latex = QStringLiteral("\\begin{array}{r|r|l}\\text{iteration} & \\lambda_n\\ [\\mathrm{N\\,s}] & "
                                   "\\boldsymbol{\\lambda}_t\\ [\\mathrm{N\\,s}]\\ \\text{(world)} \\\\ \\hline ");
    const TraceEntry* warmN = trace_.find("warm_start_normal", h.bodyA, k);
    const TraceEntry* warmT = trace_.find("warm_start_tangent", h.bodyA, k);
    if (warmN != nullptr && warmT != nullptr && std::holds_alternative<double>(warmN->value) &&
        std::holds_alternative<Vec3>(warmT->value)) {
        latex += QStringLiteral("0\\ \\text{(warm start)} & %1 & %2 \\\\ ")
                     .arg(numberLatex(std::get<double>(warmN->value), digits_), tuple(std::get<Vec3>(warmT->value)));
    }
    for (std::size_t i = 0; i < h.iterations.size(); ++i) {
        latex += QStringLiteral("%1 & %2 & %3 \\\\ ")
                     .arg(i + 1)
                     .arg(numberLatex(h.iterations[i].lambda_n, digits_), tuple(h.iterations[i].lambda_t_W));
    }
    latex += QStringLiteral("\\end{array}");
    // What one row is, in the solver's words (ContactHeader::iteration)
    QString caption;
    if (h.iteration != nullptr && h.iteration[0] != '\0') {
        caption = QStringLiteral("<p class=\"iteration-caption\">One iteration: %1.</p>")
                      .arg(QString::fromUtf8(h.iteration).toHtmlEscaped());
    }
    return displayMathHtml(latex) + caption;
}

} // namespace rbw
