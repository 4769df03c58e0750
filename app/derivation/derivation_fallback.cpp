#include "app/derivation/derivation_fallback.h"

#include "app/output/value_format.h"
#include "app/derivation/derivation_page.h"
#include "app/derivation/trace_lookup.h"

#include <algorithm>
#include <vector>

namespace rbw {

QString bodyLabel(const SceneDef& scene, int body)
{
    if (body >= 0 && body < static_cast<int>(scene.bodies.size())) {
        return QString::fromStdString(scene.bodies[body].name);
    }
    return QStringLiteral("body %1").arg(body);
}

QString contactTitle(const SceneDef& scene, const ContactHeader& header, int k)
{
    QString b;
    if (header.bodyB >= 0) {
        b = bodyLabel(scene, header.bodyB);
    } else if (header.plane >= 0 && header.plane < static_cast<int>(scene.planes.size())) {
        b = QStringLiteral("plane ") + QString::fromStdString(scene.planes[header.plane].name);
    } else {
        b = QStringLiteral("plane");
    }
    return QStringLiteral("Contact %1: %2 \u2194 %3 \u00b7 %4")
        .arg(k)
        .arg(bodyLabel(scene, header.bodyA), b, QString::fromLatin1(header.feature));
}

namespace {

QString entryRow(const TraceEntry& e, int digits, const QString& indexLabel)
{
    QString formula = QString::fromUtf8(e.info->formula);
    if (!indexLabel.isEmpty()) {
        formula = QStringLiteral("\\text{%1:}\\quad ").arg(latexTextEscape(indexLabel)) + formula;
    }
    QString result;
    if (isFiniteValue(e.value)) {
        result = latexValue(e.value, digits);
        const QString unit = unitLatex(QString::fromUtf8(e.info->unit));
        if (!unit.isEmpty()) result += QStringLiteral("\\ ") + unit;
    } else {
        result = missingLatex(QString::fromLatin1(e.info->id), QStringLiteral("not finite, the step blew up"));
    }
    return rowHtml(rowLatex(formula, QString(), result), rowInlineLatex(formula, QString(), result));
}

QString stageTitle(Stage s)
{
    QString name = QString::fromLatin1(stageName(s));
    if (!name.isEmpty()) name[0] = name[0].toUpper();
    return name;
}

} // namespace

QString fallbackDerivationBody(const StepTrace& trace, const SceneDef& scene, int digits)
{
    QString html;
    for (const Stage stage : {Stage::Forces, Stage::Integration, Stage::Collision, Stage::Correction, Stage::Probes}) {
        std::vector<const TraceEntry*> entries;
        for (const TraceEntry& e : trace.entries) {
            if (e.info->stage == stage) entries.push_back(&e);
        }
        if (entries.empty()) continue;
        html += QStringLiteral("<h2>%1</h2>\n").arg(htmlEscape(stageTitle(stage)));

        if (stage == Stage::Collision) {
            // World-level counts first, then one group per contact.
            for (const TraceEntry* e : entries) {
                if (e->index < 0) html += entryRow(*e, digits, QString());
            }
            for (int k = 0; k < static_cast<int>(trace.contacts.size()); ++k) {
                html += QStringLiteral("<h3>%1</h3>\n").arg(htmlEscape(contactTitle(scene, trace.contacts[k], k)));
                if (trace.contacts[k].separating) {
                    html += QStringLiteral("<p class=\"note\">The bodies separate here "
                                           "(v<sub>rel</sub>\u00b7n &gt; 0): no impulse.</p>\n");
                }
                for (const TraceEntry* e : entries) {
                    if (e->index == k) html += entryRow(*e, digits, QString());
                }
            }
            continue;
        }
        // Other stages: one group per body, in the order the bodies appear.
        std::vector<int> bodies;
        for (const TraceEntry* e : entries) {
            if (std::find(bodies.begin(), bodies.end(), e->body) == bodies.end()) bodies.push_back(e->body);
        }
        for (const int b : bodies) {
            html += QStringLiteral("<h3>%1</h3>\n").arg(htmlEscape(b >= 0 ? bodyLabel(scene, b) : QStringLiteral("world")));
            for (const TraceEntry* e : entries) {
                if (e->body != b) continue;
                const IndexKind kind = indexKindOf(e->info->id);
                const QString label =
                    e->index >= 0 && kind != IndexKind::None ? QLatin1String(indexKindName(kind)) + QLatin1Char(' ') + QString::number(e->index)
                                                             : QString();
                html += entryRow(*e, digits, label);
            }
        }
    }
    if (html.isEmpty()) {
        html = QStringLiteral("<p class=\"note\">This step recorded no quantities.</p>\n");
    }
    return html;
}

} // namespace rbw
