#include "app/derivation/derivation_builder.h"

#include "physics/engine/quantities.h"

#include "app/core/focus_filter.h"
#include "app/output/value_format.h"
#include "app/derivation/derivation_fallback.h"
#include "app/derivation/derivation_template.h"
#include "app/derivation/integrator_sections.h"
#include "app/derivation/trace_lookup.h"
#include "physics/engine/integrator_registry.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>

namespace rbw {

namespace {

// Where a block is expanded: the lookup context plus the loop number for {{i}}.
struct Context {
    LookupContext look;
    int loopIndex = -1;
};

// Expands a parsed template against one step's trace.
class Expander {
public:
    Expander(const StepTrace& trace, const SceneDef& scene, const QString& label, int digits)
        : trace_(trace), scene_(scene), label_(label), digits_(digits)
    {
    }

    QString nodes(const std::vector<TemplateNode>& list, const Context& ctx);

    QStringList errors;
    QStringList notes;
    std::vector<DerivationRow> rows;

private:
    QString integration(const TemplateNode& n, const Context& ctx);
    QString iterations(const TemplateNode& n, const Context& ctx);
    QString integratorOf(const Context& ctx) const;
    QString node(const TemplateNode& n, const Context& ctx);
    QString loop(const TemplateNode& n, const Context& ctx);
    bool condition(const TemplateNode& n, const Context& ctx);
    std::vector<int> loopIndices(IndexKind kind, const Context& ctx) const;

    // Text with placeholders: as LaTeX (math) or as HTML (prose, outside $...$).
    QString text(const QString& source, const Context& ctx, int line, bool math);
    QString prose(const QString& source, const Context& ctx, int line);
    QString placeholder(const QString& inside, const Context& ctx, int line, bool math);
    QString section(IndexKind kind, const QString& inner, const Context& ctx, int line, bool math);

    QString valueLatex(const Placeholder& p, const Context& ctx, int line, const QString& shown, QString* unit);
    QString metaText(const Placeholder& p, const Context& ctx, int line, bool* ok);
    int resolveBody(const QString& name, const Context& ctx, int line, QString* problem);
    QString missing(const QString& shown, const QString& reason, int line, bool math);
    QString where(int line) const { return QStringLiteral("%1:%2: ").arg(label_).arg(line); }

    const StepTrace& trace_;
    const SceneDef& scene_;
    QString label_;
    int digits_;
};

QString numberLatex(double x, int digits)
{
    return formatNumber(x, digits);
}

// Component i of v with round-off chopped as latexValue does: below 1e-12 of the
// largest entry is 0.
double choppedComponent(const Vec3& v, int i)
{
    return std::abs(v[i]) < 1e-12 * v.cwiseAbs().maxCoeff() ? 0.0 : v[i];
}

// Components and transposes are formatting of a traced value, not new physics.
QString selectLatex(const TraceValue& value, const QString& selector, int digits, QString* problem)
{
    if (selector.isEmpty()) return latexValue(value, digits);
    if (selector == QLatin1String("T")) {
        if (const Mat3* m = std::get_if<Mat3>(&value)) {
            const Mat3 mT = m->transpose();
            return latexValue(TraceValue(mT), digits);
        }
        *problem = QStringLiteral(".T needs a matrix");
        return QString();
    }
    const Vec3* v = std::get_if<Vec3>(&value);
    if (v == nullptr) {
        *problem = QStringLiteral(".%1 needs a vector").arg(selector);
        return QString();
    }
    const int i = selector == QLatin1String("x") ? 0 : selector == QLatin1String("y") ? 1 : 2;
    return numberLatex(choppedComponent(*v, i), digits);
}

QString Expander::missing(const QString& shown, const QString& reason, int line, bool math)
{
    notes << where(line) + QStringLiteral("{{%1}}: %2").arg(shown, reason);
    return math ? missingLatex(shown, reason) : missingHtml(shown, reason);
}

int Expander::resolveBody(const QString& name, const Context& ctx, int line, QString* problem)
{
    if (name.isEmpty()) return ctx.look.body;
    const int k = ctx.look.contact;
    if (k >= 0 && k < static_cast<int>(trace_.contacts.size()) &&
        (name == QLatin1String("A") || name == QLatin1String("B"))) {
        const ContactHeader& h = trace_.contacts[k];
        const int b = name == QLatin1String("A") ? h.bodyA : h.bodyB;
        if (b < 0) *problem = QStringLiteral("body B of this contact is a plane");
        return b;
    }
    const int b = scene_.bodyIndex(name.toStdString());
    if (b < 0) {
        const QString e = where(line) + QStringLiteral("no body named '%1' in this scene").arg(name);
        if (!errors.contains(e)) errors << e;
        *problem = QStringLiteral("no body named '%1'").arg(name);
    }
    return b;
}

QString Expander::metaText(const Placeholder& p, const Context& ctx, int line, bool* ok)
{
    *ok = true;
    const int k = ctx.look.contact;
    const bool inContact = k >= 0 && k < static_cast<int>(trace_.contacts.size());
    if (p.name == QLatin1String("body")) {
        QString problem;
        const int b = resolveBody(p.body, ctx, line, &problem);
        if (b >= 0) return bodyLabel(scene_, b);
    } else if (p.name == QLatin1String("i")) {
        if (ctx.loopIndex >= 0) return QString::number(ctx.loopIndex);
    } else if (p.name == QLatin1String("step")) {
        return QString::number(trace_.step);
    } else if (p.name == QLatin1String("t")) {
        return formatNumber(trace_.time, digits_);
    } else if (p.name == QLatin1String("integrator_id")) {
        return integratorOf(ctx);
    } else if (p.name == QLatin1String("integrator")) {
        const QString name = integratorOf(ctx);
        if (name.isEmpty()) return QStringLiteral("several integrators");
        const IntegratorInfo* info = findIntegrator(name.toStdString());
        return info != nullptr ? QString::fromUtf8(info->title) : name;
    } else if (inContact) {
        const ContactHeader& h = trace_.contacts[k];
        if (p.name == QLatin1String("A")) return bodyLabel(scene_, h.bodyA);
        if (p.name == QLatin1String("B")) {
            if (h.bodyB >= 0) return bodyLabel(scene_, h.bodyB);
            if (h.plane >= 0 && h.plane < static_cast<int>(scene_.planes.size())) {
                return QString::fromStdString(scene_.planes[h.plane].name);
            }
            return QStringLiteral("plane");
        }
        if (p.name == QLatin1String("feature")) return QString::fromLatin1(h.feature);
        if (p.name == QLatin1String("resolution")) return QString::fromLatin1(h.resolution);
    }
    *ok = false;
    return QString();
}

QString Expander::valueLatex(const Placeholder& p, const Context& ctx, int line, const QString& shown, QString* unit)
{
    QString problem;
    if (p.prefix == QLatin1String("scene")) {
        if (p.name == QLatin1String("h")) return numberLatex(scene_.dt, digits_);
        if (p.name == QLatin1String("g")) return selectLatex(TraceValue(scene_.g_W), p.selector, digits_, &problem);
        const int b = resolveBody(p.body, ctx, line, &problem);
        if (b < 0 || b >= static_cast<int>(scene_.bodies.size())) {
            return missing(shown, problem.isEmpty() ? QStringLiteral("which body? use @name or @foreach body") : problem,
                           line, true);
        }
        const BodyDef& def = scene_.bodies[b];
        const QString out = p.name == QLatin1String("mass")
                                ? (def.fixed ? QStringLiteral("\\infty") : numberLatex(def.mass, digits_))
                                : selectLatex(TraceValue(def.size), p.selector, digits_, &problem);
        return problem.isEmpty() ? out : missing(shown, problem, line, true);
    }

    const std::string id = p.name.toStdString();
    if (p.prefix == QLatin1String("start")) {
        // The value at the start of the step (StepTrace::start), before this step changed it.
        const int b = resolveBody(p.body, ctx, line, &problem);
        if (!problem.isEmpty()) return missing(shown, problem, line, true);
        if (b < 0) return missing(shown, QStringLiteral("which body? use @name or @foreach body"), line, true);
        const int index = indexKindOf(id) == IndexKind::Probe ? (p.index >= 0 ? p.index : ctx.look.probe) : -1;
        TraceValue v;
        if (!startValue(trace_, id, b, index, &v)) {
            return missing(shown, QStringLiteral("no start-of-step value here"), line, true);
        }
        if (!isFiniteValue(v)) return missing(shown, QStringLiteral("not finite, the step blew up"), line, true);
        const QString out = selectLatex(v, p.selector, digits_, &problem);
        if (!problem.isEmpty()) return missing(shown, problem, line, true);
        if (unit != nullptr) *unit = unitLatex(QString::fromUtf8(findQuantity(id)->unit));
        return out;
    }
    const TraceEntry* entry = nullptr;
    if (p.prefix == QLatin1String("pre")) {
        // The body's value when this contact started (after the integration and the
        // contacts before it in this step).
        if (ctx.look.contact < 0) return missing(shown, QStringLiteral("{{pre:...}} works inside @foreach contact"), line, true);
        const int b = resolveBody(p.body, ctx, line, &problem);
        if (!problem.isEmpty()) return missing(shown, problem, line, true);
        entry = valueBeforeContact(trace_, id, b, ctx.look.contact);
        if (entry == nullptr) return missing(shown, QStringLiteral("not computed in this step"), line, true);
    } else {
        const int explicitBody = p.body.isEmpty() ? -1 : resolveBody(p.body, ctx, line, &problem);
        if (!problem.isEmpty()) return missing(shown, problem, line, true);
        const LookupResult r = lookupEntry(trace_, id, ctx.look, p.index, explicitBody);
        if (p.prefix == QLatin1String("symbol") || p.prefix == QLatin1String("formula") ||
            p.prefix == QLatin1String("unit")) {
            // Text from the catalogue; the trace's own entry knows the scene's variant
            // (F with gravity, I^-1 in the course-template convention).
            const QuantityInfo* info = r.entry != nullptr ? r.entry->info : nullptr;
            if (info == nullptr) {
                for (const TraceEntry& e : trace_.entries) {
                    if (id == e.info->id) {
                        info = e.info;
                        break;
                    }
                }
            }
            if (info == nullptr) info = findQuantity(id);
            if (p.prefix == QLatin1String("symbol")) return QString::fromUtf8(info->symbol);
            if (p.prefix == QLatin1String("formula")) return QString::fromUtf8(info->formula);
            return unitLatex(QString::fromUtf8(info->unit));
        }
        if (r.entry == nullptr) return missing(shown, r.problem, line, true);
        entry = r.entry;
    }
    if (!isFiniteValue(entry->value)) {
        return missing(shown, QStringLiteral("not finite, the step blew up"), line, true);
    }
    const QString out = selectLatex(entry->value, p.selector, digits_, &problem);
    if (!problem.isEmpty()) return missing(shown, problem, line, true);
    if (unit != nullptr) *unit = unitLatex(QString::fromUtf8(entry->info->unit));
    return out;
}

QString Expander::placeholder(const QString& inside, const Context& ctx, int line, bool math)
{
    Placeholder p;
    const QString problem = parsePlaceholder(inside, &p);
    if (!problem.isEmpty()) {
        // The parser has already reported it; keep the page readable.
        return missing(inside.trimmed(), problem, line, math);
    }
    if (p.prefix.isEmpty() && isMetaName(p.name)) {
        bool ok = false;
        const QString t = metaText(p, ctx, line, &ok);
        if (!ok) return missing(inside.trimmed(), QStringLiteral("not available here"), line, math);
        // Numbers (i, step, t) stay math; names become \text{...} in math.
        bool isNumber = false;
        t.toDouble(&isNumber);
        if (math) return isNumber ? t : QStringLiteral("\\text{%1}").arg(latexTextEscape(t));
        return htmlEscape(t);
    }
    const QString latex = valueLatex(p, ctx, line, inside.trimmed(), nullptr);
    if (math) return latex;
    // A value in prose: its LaTeX as inline math (a missing note is already HTML-safe
    // LaTeX too, so it renders red in the same way).
    return inlineMathHtml(latex);
}

std::vector<int> Expander::loopIndices(IndexKind kind, const Context& ctx) const
{
    switch (kind) {
    case IndexKind::Force: return indicesOf(trace_, q::applied_force.id, ctx.look.body);
    case IndexKind::Torque: return indicesOf(trace_, q::applied_torque.id, ctx.look.body);
    case IndexKind::Probe: return indicesOf(trace_, q::point_velocity.id, ctx.look.body);
    case IndexKind::Contact: {
        std::vector<int> all;
        for (int k = 0; k < static_cast<int>(trace_.contacts.size()); ++k) {
            const ContactHeader& h = trace_.contacts[k];
            if (ctx.look.body < 0 || h.bodyA == ctx.look.body || h.bodyB == ctx.look.body) all.push_back(k);
        }
        return all;
    }
    case IndexKind::RkStage: return indicesOf(trace_, q::stage_velocity.id, ctx.look.body);
    case IndexKind::Correction: {
        std::vector<int> a = indicesOf(trace_, q::correction_a.id, ctx.look.body);
        for (int i : indicesOf(trace_, q::correction_b.id, ctx.look.body)) {
            if (std::find(a.begin(), a.end(), i) == a.end()) a.push_back(i);
        }
        std::sort(a.begin(), a.end());
        return a;
    }
    case IndexKind::None: break;
    }
    return {};
}

// The body an indexed entry belongs to (a force's body, a probe's body).
int bodyOfIndexed(const StepTrace& trace, IndexKind kind, int index)
{
    for (const TraceEntry& e : trace.entries) {
        if (e.index == index && indexKindOf(e.info->id) == kind) return e.body;
    }
    return -1;
}

QString Expander::section(IndexKind kind, const QString& inner, const Context& ctx, int line, bool math)
{
    // {{#force}} x {{/force}}: x once per force, joined by " + " (a sum written out).
    QStringList parts;
    for (const int i : loopIndices(kind, ctx)) {
        Context c = ctx;
        c.look.setIndex(kind, i);
        c.loopIndex = i;
        parts << text(inner, c, line, math);
    }
    if (parts.isEmpty()) return math ? QStringLiteral("\\mathbf{0}") : QStringLiteral("0");
    return parts.join(QStringLiteral(" + "));
}

QString Expander::text(const QString& source, const Context& ctx, int line, bool math)
{
    // Generated pieces stand in the skeleton as private-use characters until the
    // literal text has been escaped, so emphasis markers and escapes never touch them.
    QStringList pieces;
    QString skeleton;
    auto token = [&](const QString& piece) {
        skeleton += QChar(0xE000 + static_cast<int>(pieces.size()));
        pieces << piece;
    };
    int pos = 0;
    while (pos < source.size()) {
        const int open = source.indexOf(QLatin1String("{{"), pos);
        if (open < 0) break;
        const int close = source.indexOf(QLatin1String("}}"), open + 2);
        if (close < 0) break;   // reported by the parser
        skeleton += source.mid(pos, open - pos);
        const QString inside = source.mid(open + 2, close - open - 2).trimmed();
        pos = close + 2;
        if (inside.startsWith(QLatin1Char('#'))) {
            const QString kindName = inside.mid(1).trimmed();
            const QString end = QStringLiteral("{{/%1}}").arg(kindName);
            const int endAt = source.indexOf(end, pos);
            if (endAt < 0) break;   // reported by the parser
            token(section(indexKindFromName(kindName), source.mid(pos, endAt - pos), ctx, line, math));
            pos = endAt + end.size();
            continue;
        }
        token(placeholder(inside, ctx, line, math));
    }
    skeleton += source.mid(pos);

    QString out = math ? skeleton : htmlEscape(skeleton);
    if (!math) {
        static const QRegularExpression bold(QStringLiteral(R"(\*\*(.+?)\*\*)"));
        static const QRegularExpression italic(QStringLiteral(R"(\*(.+?)\*)"));
        static const QRegularExpression code(QStringLiteral(R"(`(.+?)`)"));
        out.replace(bold, QStringLiteral("<strong>\\1</strong>"));
        out.replace(italic, QStringLiteral("<em>\\1</em>"));
        out.replace(code, QStringLiteral("<code>\\1</code>"));
    }
    QString filled;
    for (const QChar c : out) {
        const int n = c.unicode() - 0xE000;
        if (n >= 0 && n < pieces.size()) {
            filled += pieces[n];
        } else {
            filled += c;
        }
    }
    return filled;
}

QString Expander::prose(const QString& source, const Context& ctx, int line)
{
    // $...$ is inline math, the rest is text.
    const QStringList parts = source.split(QLatin1Char('$'));
    QString html;
    for (int i = 0; i < parts.size(); ++i) {
        if (i % 2 == 1) {
            html += inlineMathHtml(text(parts[i], ctx, line, true));
        } else {
            html += text(parts[i], ctx, line, false);
        }
    }
    return html;
}

bool Expander::condition(const TemplateNode& n, const Context& ctx)
{
    const QString& cond = n.text;
    bool value = false;
    if (cond.startsWith(QLatin1String("convention="))) {
        // The context body's own convention (a body may override the scene's).
        const int b = ctx.look.body;
        const InertiaConvention convention = b >= 0 && b < static_cast<int>(scene_.bodies.size())
                                                 ? scene_.conventionOf(b)
                                                 : scene_.inertiaConvention;
        const bool courseTemplate = convention == InertiaConvention::CourseTemplate;
        value = (cond.mid(11) == QLatin1String("course-template")) == courseTemplate;
    } else if (cond.startsWith(QLatin1String("model="))) {
        const bool manifold = scene_.contactModel == ContactModel::Manifold;
        value = (cond.mid(6) == QLatin1String("manifold")) == manifold;
    } else if (cond == QLatin1String("plane")) {
        const int k = ctx.look.contact;
        value = k >= 0 && k < static_cast<int>(trace_.contacts.size()) && trace_.contacts[k].bodyB < 0;
    } else if (cond == QLatin1String("particle") || cond.startsWith(QLatin1String("particle@"))) {
        QString problem;
        const int b = resolveBody(cond.section(QLatin1Char('@'), 1), ctx, n.line, &problem);
        value = b >= 0 && b < static_cast<int>(scene_.bodies.size()) && !scene_.bodies[b].angularResponse;
    } else {
        Placeholder p;
        if (parsePlaceholder(cond, &p).isEmpty()) {
            QString problem;
            const int explicitBody = p.body.isEmpty() ? -1 : resolveBody(p.body, ctx, n.line, &problem);
            // Present here: one entry, or several (e.g. two couples) that a loop would pick from.
            value = problem.isEmpty() && !lookupEntry(trace_, p.name.toStdString(), ctx.look, p.index, explicitBody).missing;
        }
    }
    return n.negate ? !value : value;
}

QString Expander::loop(const TemplateNode& n, const Context& ctx)
{
    QString html;
    if (n.text == QLatin1String("body")) {
        const std::vector<int> bodies = bodiesInTrace(trace_);
        for (const int b : bodies) {
            Context c = ctx;
            c.look.body = b;
            c.loopIndex = b;
            html += nodes(n.children, c);
        }
        return bodies.empty() ? nodes(n.elseChildren, ctx) : html;
    }
    const IndexKind kind = indexKindFromName(n.text);
    const std::vector<int> indices = loopIndices(kind, ctx);
    for (const int i : indices) {
        Context c = ctx;
        c.look.setIndex(kind, i);
        c.loopIndex = i;
        if (c.look.body < 0 && kind != IndexKind::Contact && kind != IndexKind::Correction) c.look.body = bodyOfIndexed(trace_, kind, i);
        html += nodes(n.children, c);
    }
    return indices.empty() ? nodes(n.elseChildren, ctx) : html;
}

QString Expander::node(const TemplateNode& n, const Context& ctx)
{
    switch (n.kind) {
    case TemplateNode::Kind::Heading:
        return QStringLiteral("<h%1>%2</h%1>\n").arg(n.level).arg(prose(n.text, ctx, n.line));
    case TemplateNode::Kind::Paragraph:
        return QStringLiteral("<p>%1</p>\n").arg(prose(n.text, ctx, n.line));
    case TemplateNode::Kind::List: {
        QString html = QStringLiteral("<ul>\n");
        for (const QString& item : n.items) html += QStringLiteral("<li>%1</li>\n").arg(prose(item, ctx, n.line));
        return html + QStringLiteral("</ul>\n");
    }
    case TemplateNode::Kind::DisplayMath:
        return displayMathHtml(text(n.text, ctx, n.line, true));
    case TemplateNode::Kind::Row: {
        const QString formula = text(n.items.value(0), ctx, n.line, true);
        QString substituted;
        QString result;
        const QString resultSource = n.items.size() == 3 ? n.items[2] : n.items.value(1);
        if (n.items.size() == 3) substituted = text(n.items[1], ctx, n.line, true);
        if (!resultSource.isEmpty()) result = text(resultSource, ctx, n.line, true);
        // A result that is exactly one traced value gets its unit.
        static const QRegularExpression single(QStringLiteral(R"(^\{\{([^{}]*)\}\}$)"));
        const QRegularExpressionMatch m = single.match(resultSource);
        Placeholder p;
        if (m.hasMatch() && parsePlaceholder(m.captured(1), &p).isEmpty() && p.prefix.isEmpty() &&
            !isMetaName(p.name) && p.selector.isEmpty()) {
            QStringList quiet;   // the value itself was expanded (and any note given) above
            quiet.swap(notes);
            QString unit;
            valueLatex(p, ctx, n.line, m.captured(1), &unit);
            quiet.swap(notes);
            if (!unit.isEmpty()) result += QStringLiteral("\\ ") + unit;
        }
        rows.push_back(DerivationRow{where(n.line).chopped(2), formula, substituted, result});
        return rowHtml(rowLatex(formula, substituted, result), rowInlineLatex(formula, substituted, result));
    }
    case TemplateNode::Kind::Loop:
        return loop(n, ctx);
    case TemplateNode::Kind::Body: {
        QString problem;
        const int b = resolveBody(n.text, ctx, n.line, &problem);
        if (b < 0) return QString();
        Context c = ctx;
        c.look.body = b;
        return nodes(n.children, c);
    }
    case TemplateNode::Kind::If:
        return nodes(condition(n, ctx) ? n.children : n.elseChildren, ctx);
    case TemplateNode::Kind::Integration:
        return integration(n, ctx);
    case TemplateNode::Kind::Iterations:
        return iterations(n, ctx);
    }
    return QString();
}

// The integrator of the context's body, else the scene's if every body shares it;
// empty when the bodies of a world-level context have different integrators.
QString Expander::integratorOf(const Context& ctx) const
{
    if (ctx.look.body >= 0 && ctx.look.body < static_cast<int>(scene_.bodies.size())) {
        return QString::fromStdString(scene_.integratorOf(ctx.look.body));
    }
    for (int b = 0; b < static_cast<int>(scene_.bodies.size()); ++b) {
        if (scene_.integratorOf(b) != scene_.integrator) return QString();
    }
    return QString::fromStdString(scene_.integrator);
}

// @integration: the current body's integrator's own section (integrator_sections.h),
// expanded here with the same context; its rows and notes name the section's file.
QString Expander::integration(const TemplateNode& n, const Context& ctx)
{
    if (ctx.look.body < 0) {
        const QString e = where(n.line) + QStringLiteral("@integration needs a body: use it inside @foreach body or @body");
        if (!errors.contains(e)) errors << e;
        return QString();
    }
    const bool moves = std::any_of(trace_.entries.begin(), trace_.entries.end(), [&](const TraceEntry& e) {
        return e.body == ctx.look.body && e.info->stage == Stage::Integration;
    });
    if (!moves) {
        return QStringLiteral("<p>%1 is not integrated in this step (a fixed body).</p>\n")
            .arg(htmlEscape(bodyLabel(scene_, ctx.look.body)));
    }
    const QString name = integratorOf(ctx);
    QString html;
    for (const IntegratorSection* section : integratorSections(name)) {
        if (!section->errors.isEmpty()) {
            for (const QString& e : section->errors) {
                if (!errors.contains(e)) errors << e;
            }
            continue;
        }
        Expander inner(trace_, scene_, section->label, digits_);
        html += inner.nodes(section->nodes, ctx);
        errors << inner.errors;
        notes << inner.notes;
        rows.insert(rows.end(), inner.rows.begin(), inner.rows.end());
    }
    return html;
}

// @iterations: the contact's accumulated impulses after each velocity iteration of the
// manifold solver (ContactHeader::iterations), after the warm start they began from, as
// one table; nothing for a contact of the course model (one impulse, no iterations).
QString Expander::iterations(const TemplateNode& n, const Context& ctx)
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
    return displayMathHtml(latex);
}

QString Expander::nodes(const std::vector<TemplateNode>& list, const Context& ctx)
{
    QString html;
    for (const TemplateNode& n : list) html += node(n, ctx);
    return html;
}

QString stepInfo(const StepTrace& trace, const SceneDef& scene, int digits)
{
    // Step k advances t_k = k h to t_{k+1} (trace.h).
    return QStringLiteral("<p class=\"stepinfo\">%1 \u00b7 step k = %2, from t = %3 to t = %4 (h = %5)</p>\n")
        .arg(htmlEscape(QString::fromStdString(scene.name)))
        .arg(trace.step)
        .arg(formatNumber(double(trace.step) * scene.dt, digits), formatNumber(trace.time, digits),
             formatNumber(scene.dt, digits));
}

QString errorBox(const QStringList& errors)
{
    return QStringLiteral("<div class=\"template-error\"><strong>The derivation template has errors</strong>"
                          "<pre>%1</pre></div>\n")
        .arg(htmlEscape(errors.join(QLatin1Char('\n'))));
}

QString titleOf(const SceneDef& scene, const StepTrace& trace)
{
    return QStringLiteral("%1 \u2014 step %2").arg(QString::fromStdString(scene.name)).arg(trace.step);
}

bool focused(const SceneDef& scene, const DerivationOptions& options)
{
    return options.focusBody >= 0 && options.focusBody < static_cast<int>(scene.bodies.size());
}

// The note at the top of a page that writes out one body of many.
QString focusNote(const SceneDef& scene, const DerivationOptions& options)
{
    if (!focused(scene, options)) return {};
    return QStringLiteral("<p class=\"focus-note\" style=\"background:#fff4d6;padding:6px 10px;border-radius:4px\">"
                          "This scene has %1 bodies: the page writes out <b>%2</b> and its contacts. "
                          "Press on another box in the 3D view to follow it.</p>\n")
        .arg(static_cast<int>(scene.bodies.size()))
        .arg(htmlEscape(QString::fromStdString(scene.bodies[options.focusBody].name)));
}

// The page around a body, with the focus note first.
QString page(const QString& body, const SceneDef& scene, const StepTrace& trace, const DerivationOptions& options)
{
    return derivationPage(focusNote(scene, options) + body, titleOf(scene, trace), options.katexUrl);
}

DerivationDocument fallbackDocument(const StepTrace& trace, const SceneDef& scene, const DerivationOptions& options)
{
    DerivationDocument doc;
    doc.fallback = true;
    const QString body = QStringLiteral("<h1>Step %1: every traced quantity</h1>\n").arg(trace.step) +
                         stepInfo(trace, scene, options.digits) + fallbackDerivationBody(trace, scene, options.digits);
    doc.html = page(body, scene, trace, options);
    return doc;
}

DerivationDocument templateDocument(const StepTrace& trace, const SceneDef& scene, const QString& templateText,
                                    const QString& templateLabel, const DerivationOptions& options)
{
    const TemplateParseResult parsed = parseDerivationTemplate(templateText, templateLabel);
    if (!parsed.ok()) {
        DerivationDocument doc;
        doc.fallback = true;
        doc.errors = parsed.errors;
        const QString body = errorBox(parsed.errors) +
                             QStringLiteral("<h1>Step %1: every traced quantity</h1>\n").arg(trace.step) +
                             stepInfo(trace, scene, options.digits) +
                             fallbackDerivationBody(trace, scene, options.digits);
        doc.html = page(body, scene, trace, options);
        return doc;
    }
    Expander expander(trace, scene, templateLabel, options.digits);
    const QString content = expander.nodes(parsed.parsed->nodes, Context{});
    DerivationDocument doc;
    doc.errors = expander.errors;
    doc.notes = expander.notes;
    doc.rows = std::move(expander.rows);
    QString body = doc.errors.isEmpty() ? QString() : errorBox(doc.errors);
    // The step line goes under the template's title (its first heading), if any.
    const int firstHeadingEnd = content.startsWith(QLatin1String("<h1>")) ? content.indexOf(QLatin1String("</h1>\n")) : -1;
    if (firstHeadingEnd >= 0) {
        body += content.left(firstHeadingEnd + 6) + stepInfo(trace, scene, options.digits) + content.mid(firstHeadingEnd + 6);
    } else {
        body += stepInfo(trace, scene, options.digits) + content;
    }
    doc.html = page(body, scene, trace, options);
    return doc;
}

} // namespace

DerivationDocument buildFallbackDerivation(const StepTrace& trace, const SceneDef& scene, const DerivationOptions& options)
{
    if (focused(scene, options)) return fallbackDocument(focusTrace(trace, options.focusBody), scene, options);
    return fallbackDocument(trace, scene, options);
}

DerivationDocument buildDerivation(const StepTrace& trace, const SceneDef& scene, const QString& templateText,
                                   const QString& templateLabel, const DerivationOptions& options)
{
    if (focused(scene, options)) {
        return templateDocument(focusTrace(trace, options.focusBody), scene, templateText, templateLabel, options);
    }
    return templateDocument(trace, scene, templateText, templateLabel, options);
}

DerivationDocument buildLessonDerivation(const StepTrace& trace, const SceneDef& scene, const QString& lessonDirectory,
                                         const DerivationOptions& options)
{
    const QString path = QDir(lessonDirectory).filePath(QStringLiteral("derivation.md"));
    if (!QFileInfo::exists(path)) return buildFallbackDerivation(trace, scene, options);
    const QString label = QStringLiteral("lessons/%1/derivation.md").arg(QDir(lessonDirectory).dirName());
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        DerivationDocument doc = buildFallbackDerivation(trace, scene, options);
        doc.errors << QStringLiteral("%1: cannot read the file: %2").arg(label, file.errorString());
        doc.html.replace(QLatin1String("<main class=\"derivation\">\n"),
                         QLatin1String("<main class=\"derivation\">\n") + errorBox(doc.errors));
        return doc;
    }
    return buildDerivation(trace, scene, QString::fromUtf8(file.readAll()), label, options);
}

} // namespace rbw
