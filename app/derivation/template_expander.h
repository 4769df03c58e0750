// Expands a parsed derivation template (derivation_template.h) against one step's
// trace: the builder's engine (derivation_builder.h). Its jobs are split by file:
//   template_expander.cpp     the blocks: headings, rows, @foreach, @if, @body, @integration
//   template_placeholders.cpp the text of a block: each {{...}} filled in from the trace
//                             (values, start/pre values, scene inputs, names), the
//                             {{#force}} sums, **emphasis**, `code` and $math$
//   iterations_table.cpp      @iterations: the manifold solver's impulses per iteration
// Every number comes from the trace through value_format; nothing is computed here.
// Private to app/derivation.
#pragma once

#include "app/derivation/derivation_builder.h"
#include "app/derivation/derivation_template.h"
#include "app/derivation/trace_lookup.h"
#include "physics/engine/trace.h"
#include "physics/engine/scene.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace rbw {

// Where a block is expanded: the lookup context plus the loop number for {{i}}.
struct ExpansionContext {
    LookupContext look;
    int loopIndex = -1;
};

// Expands a parsed template against one step's trace.
class TemplateExpander {
public:
    TemplateExpander(const StepTrace& trace, const SceneDef& scene, const QString& label, int digits)
        : trace_(trace), scene_(scene), label_(label), digits_(digits)
    {
    }

    QString nodes(const std::vector<TemplateNode>& list, const ExpansionContext& ctx);

    // A page that follows one body (focus_filter.h) reads the other body of a contact
    // ({{position@B}}, {{pre:linear_velocity@B}}) from the whole trace: `whole` and, per
    // contact of the selection, its number there (focusContacts).
    void setWholeTrace(const StepTrace* whole, std::vector<int> contactInWhole)
    {
        whole_ = whole;
        contactInWhole_ = std::move(contactInWhole);
    }

    QStringList errors;
    QStringList notes;
    std::vector<DerivationRow> rows;

private:
    // The blocks (template_expander.cpp), @iterations (iterations_table.cpp).
    QString integration(const TemplateNode& n, const ExpansionContext& ctx);
    QString iterations(const TemplateNode& n, const ExpansionContext& ctx);
    QString integratorOf(const ExpansionContext& ctx) const;
    QString node(const TemplateNode& n, const ExpansionContext& ctx);
    QString loop(const TemplateNode& n, const ExpansionContext& ctx);
    bool condition(const TemplateNode& n, const ExpansionContext& ctx);
    std::vector<int> loopIndices(IndexKind kind, const ExpansionContext& ctx) const;

    // Text with placeholders (template_placeholders.cpp): as LaTeX (math) or as HTML
    // (prose, outside $...$).
    QString text(const QString& source, const ExpansionContext& ctx, int line, bool math);
    QString prose(const QString& source, const ExpansionContext& ctx, int line);
    QString placeholder(const QString& inside, const ExpansionContext& ctx, int line, bool math);
    QString section(IndexKind kind, const QString& inner, const ExpansionContext& ctx, int line, bool math);

    QString valueLatex(const Placeholder& p, const ExpansionContext& ctx, int line, const QString& shown, QString* unit);
    QString metaText(const Placeholder& p, const ExpansionContext& ctx, int line, bool* ok);
    int resolveBody(const QString& name, const ExpansionContext& ctx, int line, QString* problem);
    QString missing(const QString& shown, const QString& reason, int line, bool math);
    QString where(int line) const { return QStringLiteral("%1:%2: ").arg(label_).arg(line); }

    const StepTrace& trace_;
    const StepTrace* whole_ = nullptr;   // a focused page: the trace before the selection
    std::vector<int> contactInWhole_;
    const SceneDef& scene_;
    QString label_;
    int digits_;
};

// A number as LaTeX with `digits` significant digits.
QString numberLatex(double x, int digits);

// Component i of v with round-off chopped as latexValue does: below 1e-12 of the
// largest entry is 0.
double choppedComponent(const Vec3& v, int i);

} // namespace rbw
