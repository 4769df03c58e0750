#include "app/exercise/exercise_worksheet.h"

#include "app/output/value_format.h"
#include "app/scene/scene_format.h"
#include "physics/engine/quantity_catalogue.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStringList>

namespace rbw {

namespace {

QString cellText(const QJsonValue& v)
{
    if (v.isObject()) {
        QStringList parts;
        const QJsonObject o = v.toObject();
        for (auto it = o.begin(); it != o.end(); ++it) parts << it.key() + ": " + cellText(it.value());
        return parts.join("; ");
    }
    if (v.isArray()) {
        QStringList parts;
        for (const QJsonValue& x : v.toArray()) parts << cellText(x);
        return '[' + parts.join(", ") + ']';
    }
    if (v.isDouble()) return QString::number(v.toDouble(), 'g', 15);
    if (v.isBool()) return v.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    return v.toString();
}

QString tableOf(const QString& title, const QJsonArray& rows)
{
    if (rows.isEmpty()) return QString();
    QStringList columns;
    for (const QJsonValue& r : rows) {
        for (const QString& k : r.toObject().keys()) {
            if (!columns.contains(k)) columns << k;
        }
    }
    QString html = "<h3>" + title + "</h3>\n<table>\n<tr>";
    for (const QString& c : columns) html += "<th>" + c.toHtmlEscaped() + "</th>";
    html += "</tr>\n";
    for (const QJsonValue& r : rows) {
        html += "<tr>";
        for (const QString& c : columns) html += "<td>" + cellText(r.toObject().value(c)).toHtmlEscaped() + "</td>";
        html += "</tr>\n";
    }
    return html + "</table>\n";
}

} // namespace

QString exerciseWorksheetHtml(const ExerciseSpec& spec, const GeneratedExercise& g, bool withAnswers)
{
    using sceneformat::Key;
    using sceneformat::key;
    const QJsonObject scene = QJsonDocument::fromJson(g.sceneJson).object();
    const QString title = scene.value(key(Key::Name)).toString();
    QString html;
    html += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + title.toHtmlEscaped() +
            (withAnswers ? QStringLiteral(" (answer key)") : QString()) + "</title>\n";
    html += "<style>body{font-family:sans-serif;max-width:60em;margin:2em auto}table{border-collapse:collapse;margin:.5em 0}"
            "th,td{border:1px solid #888;padding:.3em .6em;text-align:left}td.answer{min-width:18em;height:1.6em}</style>\n"
            "</head>\n<body>\n";
    html += "<h1>" + title.toHtmlEscaped() + (withAnswers ? QStringLiteral(" &mdash; answer key") : QString()) + "</h1>\n";
    html += "<p>Lesson " + spec.lessonId.toHtmlEscaped() + ", seed " + QString::number(g.seed) +
            ". Regenerate with <code>rbw exercise " + spec.lessonId.toHtmlEscaped() + " --seed " + QString::number(g.seed) +
            "</code>.</p>\n";
    html += "<h2>Setup</h2>\n<table>\n";
    for (auto it = scene.begin(); it != scene.end(); ++it) {
        if (it.value().isArray() && !it.value().toArray().isEmpty() && it.value().toArray()[0].isObject()) continue;
        if (it.key() == key(Key::Name) || it.key() == key(Key::Description)) continue;
        html += "<tr><th>" + it.key().toHtmlEscaped() + "</th><td>" + cellText(it.value()).toHtmlEscaped() + "</td></tr>\n";
    }
    html += "</table>\n";
    // Each list of the scene (bodies, forces, torques, ...) as a table, in the table's order.
    for (const sceneformat::KeyRow& r : sceneformat::rows()) {
        if (r.section != sceneformat::Section::Scene || r.type != sceneformat::Type::List) continue;
        const QString list = key(r.id);
        html += tableOf(list.left(1).toUpper() + list.mid(1), scene.value(list).toArray());
    }
    html += "<p>Lengths in m, masses in kg, forces in N, velocities in m/s and rad/s, times in s; "
            "a force acts from step from_step up to (not including) to_step.</p>\n";
    html += "<h2>Your task</h2>\n<p>";
    if (!spec.task.isEmpty()) html += spec.task.toHtmlEscaped() + ' ';
    html += "Compute the numbers of step k = " + QString::number(g.answerStep) + " (from t = " +
            QString::number(g.answerStep * g.scene->dt, 'g', 10) + " s to t = " +
            QString::number((g.answerStep + 1) * g.scene->dt, 'g', 10) + " s).</p>\n";
    html += "<table>\n<tr><th>quantity</th><th>id</th><th>body / contact</th><th>index</th><th>unit</th><th>your answer</th></tr>\n";
    for (const TraceEntry& e : g.key) {
        const bool contact = e.info->indexKind == IndexKind::Contact;
        const QString who = contact ? "contact " + QString::number(e.index)
                                    : (e.body >= 0 ? QString::fromStdString(g.scene->bodies[e.body].name) : QString());
        const QString index = (!contact && e.index >= 0) ? QString::number(e.index) : QString();
        html += "<tr><td>" + QString::fromUtf8(e.info->text).toHtmlEscaped() + "</td><td><code>" +
                QString::fromLatin1(e.info->id) + "</code></td><td>" + who.toHtmlEscaped() + "</td><td>" + index +
                "</td><td>" + QString::fromUtf8(e.info->unit).toHtmlEscaped() + "</td><td class=\"answer\">" +
                (withAnswers ? formatValue(e.value).toHtmlEscaped() : QString()) + "</td></tr>\n";
    }
    html += "</table>\n";
    if (withAnswers) {
        html += "<p>The workbook's numbers, from the physics' trace of step " + QString::number(g.answerStep) +
                ". Check your own with <code>rbw check</code> (docs/checker.md).</p>\n";
    }
    html += "</body>\n</html>\n";
    return html;
}

} // namespace rbw
