#include "app/derivation/template_expander.h"

#include "app/derivation/derivation_fallback.h"
#include "app/derivation/derivation_page.h"
#include "app/derivation/integrator_sections.h"
#include "physics/engine/quantities.h"
#include "physics/engine/scene_words.h"

#include <QRegularExpression>

#include <algorithm>

namespace rbw {

namespace {

// The body an indexed entry belongs to (a force's body, a probe's body).
int bodyOfIndexed(const StepTrace& trace, IndexKind kind, int index)
{
    for (const TraceEntry& e : trace.entries) {
        if (e.index == index && indexKindOf(e.info->id) == kind) return e.body;
    }
    return -1;
}

} // namespace

QString TemplateExpander::nodes(const std::vector<TemplateNode>& list, const ExpansionContext& ctx)
{
    QString html;
    for (const TemplateNode& n : list) html += node(n, ctx);
    return html;
}

QString TemplateExpander::node(const TemplateNode& n, const ExpansionContext& ctx)
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
        ExpansionContext c = ctx;
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

std::vector<int> TemplateExpander::loopIndices(IndexKind kind, const ExpansionContext& ctx) const
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

bool TemplateExpander::condition(const TemplateNode& n, const ExpansionContext& ctx)
{
    const QString& cond = n.text;
    bool value = false;
    if (cond.startsWith(QLatin1String("convention="))) {
        // The context body's own convention (a body may override the scene's).
        const int b = ctx.look.body;
        const InertiaConvention convention = b >= 0 && b < static_cast<int>(scene_.bodies.size())
                                                 ? scene_.conventionOf(b)
                                                 : scene_.inertiaConvention;
        value = sceneWordValue<InertiaConvention>(cond.mid(11).toStdString()) == convention;
    } else if (cond.startsWith(QLatin1String("model="))) {
        value = sceneWordValue<ContactModel>(cond.mid(6).toStdString()) == scene_.contactModel;
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

QString TemplateExpander::loop(const TemplateNode& n, const ExpansionContext& ctx)
{
    QString html;
    if (n.text == QLatin1String("body")) {
        const std::vector<int> bodies = bodiesInTrace(trace_);
        for (const int b : bodies) {
            ExpansionContext c = ctx;
            c.look.body = b;
            c.loopIndex = b;
            html += nodes(n.children, c);
        }
        return bodies.empty() ? nodes(n.elseChildren, ctx) : html;
    }
    const IndexKind kind = indexKindFromName(n.text);
    const std::vector<int> indices = loopIndices(kind, ctx);
    for (const int i : indices) {
        ExpansionContext c = ctx;
        c.look.setIndex(kind, i);
        c.loopIndex = i;
        if (c.look.body < 0 && kind != IndexKind::Contact && kind != IndexKind::Correction) c.look.body = bodyOfIndexed(trace_, kind, i);
        html += nodes(n.children, c);
    }
    return indices.empty() ? nodes(n.elseChildren, ctx) : html;
}

// The integrator of the context's body, else the one every body shares; empty when the
// bodies of a world-level context have different integrators. The one that ran this
// step (tracedIntegrator), else the scene's: switching the integrator after a step does
// not relabel the step already taken.
QString TemplateExpander::integratorOf(const ExpansionContext& ctx) const
{
    auto ofBody = [this](int b) {
        const QString scene = QString::fromStdString(scene_.integratorOf(b));
        const QString traced = tracedIntegrator(trace_, b);
        // Integrators that share one file (rotation-matrix and its orthonormalised
        // variant) are one family to the trace: there the scene's name decides.
        const bool family = scene.startsWith(traced + QLatin1Char('-')) || traced.startsWith(scene + QLatin1Char('-'));
        return traced.isEmpty() || family ? scene : traced;
    };
    if (ctx.look.body >= 0 && ctx.look.body < static_cast<int>(scene_.bodies.size())) return ofBody(ctx.look.body);
    QString shared;
    for (int b = 0; b < static_cast<int>(scene_.bodies.size()); ++b) {
        if (scene_.bodies[b].fixed) continue;
        const QString name = ofBody(b);
        if (!shared.isEmpty() && name != shared) return QString();
        shared = name;
    }
    return shared.isEmpty() ? QString::fromStdString(scene_.integrator) : shared;
}

// @integration: the current body's integrator's own section (integrator_sections.h),
// expanded here with the same context; its rows and notes name the section's file.
QString TemplateExpander::integration(const TemplateNode& n, const ExpansionContext& ctx)
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
        TemplateExpander inner(trace_, scene_, section->label, digits_);
        html += inner.nodes(section->nodes, ctx);
        errors << inner.errors;
        notes << inner.notes;
        rows.insert(rows.end(), inner.rows.begin(), inner.rows.end());
    }
    return html;
}

} // namespace rbw
