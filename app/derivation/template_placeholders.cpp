#include "app/derivation/template_expander.h"

#include "app/derivation/derivation_fallback.h"
#include "app/derivation/derivation_page.h"
#include "app/output/value_format.h"
#include "physics/engine/integrator_registry.h"
#include "physics/engine/quantities.h"

#include <QRegularExpression>

#include <cmath>

namespace rbw {

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

namespace {

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

} // namespace

QString TemplateExpander::missing(const QString& shown, const QString& reason, int line, bool math)
{
    notes << where(line) + QStringLiteral("{{%1}}: %2").arg(shown, reason);
    return math ? missingLatex(shown, reason) : missingHtml(shown, reason);
}

int TemplateExpander::resolveBody(const QString& name, const ExpansionContext& ctx, int line, QString* problem)
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

QString TemplateExpander::metaText(const Placeholder& p, const ExpansionContext& ctx, int line, bool* ok)
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

QString TemplateExpander::valueLatex(const Placeholder& p, const ExpansionContext& ctx, int line, const QString& shown, QString* unit)
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
        // On a focused page the whole trace: the other body's integration and its
        // contacts with third bodies are not in the selection.
        const int k = ctx.look.contact;
        entry = whole_ != nullptr && k < static_cast<int>(contactInWhole_.size())
                    ? valueBeforeContact(*whole_, id, b, contactInWhole_[static_cast<std::size_t>(k)])
                    : valueBeforeContact(trace_, id, b, k);
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
        entry = r.entry;
        if (entry == nullptr && whole_ != nullptr && explicitBody >= 0 && indexKindOf(id) == IndexKind::None) {
            // A body-level value of another body (a contact's partner) on a focused page.
            LookupContext look;
            look.body = explicitBody;
            entry = lookupEntry(*whole_, id, look, -1, explicitBody).entry;
        }
        if (entry == nullptr) return missing(shown, r.problem, line, true);
    }
    if (!isFiniteValue(entry->value)) {
        return missing(shown, QStringLiteral("not finite, the step blew up"), line, true);
    }
    const QString out = selectLatex(entry->value, p.selector, digits_, &problem);
    if (!problem.isEmpty()) return missing(shown, problem, line, true);
    if (unit != nullptr) *unit = unitLatex(QString::fromUtf8(entry->info->unit));
    return out;
}

QString TemplateExpander::placeholder(const QString& inside, const ExpansionContext& ctx, int line, bool math)
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

QString TemplateExpander::section(IndexKind kind, const QString& inner, const ExpansionContext& ctx, int line, bool math)
{
    // {{#force}} x {{/force}}: x once per force, joined by " + " (a sum written out).
    QStringList parts;
    for (const int i : loopIndices(kind, ctx)) {
        ExpansionContext c = ctx;
        c.look.setIndex(kind, i);
        c.loopIndex = i;
        parts << text(inner, c, line, math);
    }
    if (parts.isEmpty()) return math ? QStringLiteral("\\mathbf{0}") : QStringLiteral("0");
    return parts.join(QStringLiteral(" + "));
}

QString TemplateExpander::text(const QString& source, const ExpansionContext& ctx, int line, bool math)
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

QString TemplateExpander::prose(const QString& source, const ExpansionContext& ctx, int line)
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

} // namespace rbw
