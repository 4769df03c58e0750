// The derivation page put together (derivation_builder.h): the template expanded by
// TemplateExpander (template_expander.h) or the fallback's body, under the step line,
// any template errors and the focus note, inside the page skeleton with KaTeX
// (derivation_page.h).
#include "app/derivation/derivation_builder.h"

#include "app/core/focus_filter.h"
#include "app/core/step_numbering.h"
#include "app/derivation/derivation_fallback.h"
#include "app/derivation/derivation_template.h"
#include "app/derivation/template_expander.h"
#include "app/output/value_format.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

namespace rbw {

namespace {

QString stepInfo(const StepTrace& trace, const SceneDef& scene, int digits)
{
    // Step k advances t_k to t_{k+1} (trace.h), worded as on every screen
    // (app/core/step_numbering.h): "step k = 2, from t₂ = 0.0333 to t₃ = 0.05".
    return QStringLiteral("<p class=\"stepinfo\">%1 \u00b7 step k = %2, from %3 = %4 to %5 = %6 (h = %7)</p>\n")
        .arg(htmlEscape(QString::fromStdString(scene.name)))
        .arg(trace.step)
        .arg(steps::timeName(trace.step), formatNumber(double(trace.step) * scene.dt, digits),
             steps::timeName(trace.step + 1), formatNumber(trace.time, digits), formatNumber(scene.dt, digits));
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
                                    const QString& templateLabel, const DerivationOptions& options,
                                    const StepTrace* whole = nullptr)
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
    TemplateExpander expander(trace, scene, templateLabel, options.digits);
    if (whole != nullptr) expander.setWholeTrace(whole, focusContacts(*whole, options.focusBody));
    const QString content = expander.nodes(parsed.parsed->nodes, ExpansionContext{});
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
        return templateDocument(focusTrace(trace, options.focusBody), scene, templateText, templateLabel, options, &trace);
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
