#include "app/exercise/exercise_worksheet.h"

#include "app/output/value_format.h"
#include "app/scene/scene_format.h"
#include "physics/engine/integrator_registry.h"
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

// A scene key as a student reads it: "angular velocity", never "angular_velocity",
// which a narrow PDF column breaks mid-word.
QString label(const QString& key)
{
    QString t = key;
    t.replace(QLatin1Char('_'), QLatin1Char(' '));
    return t;
}

// A list of the scene (bodies, forces, ...) as a table with one column per item (its
// name, else its number) and one row per key: a row label is one or two words, so no
// header is broken mid-word however many keys a body has.
QString tableOf(const QString& title, const QJsonArray& items)
{
    if (items.isEmpty()) return QString();
    const QString nameKey = sceneformat::key(sceneformat::Key::Name);
    QStringList keys;
    for (const QJsonValue& r : items) {
        for (const QString& k : r.toObject().keys()) {
            if (!keys.contains(k) && k != nameKey) keys << k;
        }
    }
    // Full width, the labels' column wide enough for "restitution threshold": a PDF
    // table is laid out by QTextDocument, which squeezes columns to their narrowest.
    const int itemWidth = static_cast<int>(78 / items.size());
    QString html = "<h3>" + title.toHtmlEscaped() + "</h3>\n<table width=\"100%\" style=\"font-size:9pt\">\n<tr><th width=\"22%\"></th>";
    for (qsizetype i = 0; i < items.size(); ++i) {
        const QString name = items[i].toObject().value(nameKey).toString();
        html += "<th width=\"" + QString::number(itemWidth) + "%\">" + (name.isEmpty() ? QString::number(i) : name).toHtmlEscaped() + "</th>";
    }
    html += "</tr>\n";
    for (const QString& k : keys) {
        html += "<tr><th>" + label(k).toHtmlEscaped() + "</th>";
        for (const QJsonValue& r : items) {
            const QJsonValue v = r.toObject().value(k);
            html += "<td>" + (v.isUndefined() ? QString() : cellText(v)).toHtmlEscaped() + "</td>";
        }
        html += "</tr>\n";
    }
    return html + "</table>\n";
}

QString partName(const SceneDef& s, int body, int plane)
{
    if (body >= 0 && body < static_cast<int>(s.bodies.size())) return QString::fromStdString(s.bodies[body].name);
    if (plane >= 0 && plane < static_cast<int>(s.planes.size())) return QString::fromStdString(s.planes[plane].name);
    return QString();
}

// "contact 0 (vertex and ground)": which two bodies (or a body and a plane) it joins.
QString contactName(const SceneDef& s, const StepTrace& t, int k)
{
    if (k < 0 || k >= static_cast<int>(t.contacts.size())) return "contact " + QString::number(k);
    const ContactHeader& c = t.contacts[k];
    return "contact " + QString::number(k) + " (" + partName(s, c.bodyA, -1) + " and " + partName(s, c.bodyB, c.plane) + ")";
}

// The state at the start of a later step, as the physics had it: without it a student
// could not start the step by hand.
QString startStateOf(const GeneratedExercise& g)
{
    if (g.answerStep == 0 || g.startStates.size() != g.scene->bodies.size()) return QString();
    // "after step 0" for step 1, "after steps 0 to 4" for step 5
    const QString after = g.answerStep == 1 ? QStringLiteral("after step 0")
                                            : QStringLiteral("after steps 0 to %1").arg(g.answerStep - 1);
    QString html = "<p>The state at the start of step " + QString::number(g.answerStep) + " (t = " +
                   QString::number(g.answerStep * g.scene->dt, 'g', 10) + " s), as the simulation has it " + after +
                   ":</p>\n<table width=\"100%\" style=\"font-size:9pt\">\n<tr><th width=\"18%\">body</th>"
                   "<th width=\"82%\">position x (m), orientation r [w, x, y, z], velocity v (m/s), angular momentum L "
                   "(kg m²/s), angular velocity ω (rad/s)</th></tr>\n";
    for (size_t b = 0; b < g.startStates.size(); ++b) {
        const BodyState& s = g.startStates[b];
        QStringList lines;
        const std::pair<const char*, TraceValue> values[] = {
            {"x = ", s.x_W}, {"r = ", s.q_WB}, {"v = ", s.v_W}, {"L = ", s.L_W}, {"ω = ", s.omega_W}};
        for (const auto& [name, v] : values) {
            QString text = formatValue(v);
            text.remove(QStringLiteral("[w x y z] = "));
            lines << (QString::fromUtf8(name) + text).toHtmlEscaped();
        }
        html += "<tr><td>" + QString::fromStdString(g.scene->bodies[b].name).toHtmlEscaped() + "</td><td>" +
                lines.join(QStringLiteral("<br>")) + "</td></tr>\n";
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
            "th,td{border:1px solid #888;padding:.2em .4em;text-align:left}td.answer{min-width:18em;height:1.6em}"
            "td.key{min-width:14em;font-weight:bold}</style>\n"
            "</head>\n<body>\n";
    html += "<h1>" + title.toHtmlEscaped() + (withAnswers ? QStringLiteral(" &mdash; answer key") : QString()) + "</h1>\n";
    html += "<p>Lesson " + spec.lessonId.toHtmlEscaped() + ", seed " + QString::number(g.seed) + ".";
    // The command that makes the same scene is for the teacher's copy.
    if (withAnswers) {
        html += " The same scene: <code>rbw exercise " + spec.lessonId.toHtmlEscaped() + " --seed " + QString::number(g.seed) +
                "</code>, or New numbers with seed " + QString::number(g.seed) + " in the app.";
    }
    html += "</p>\n";
    html += "<h2>Setup</h2>\n<table width=\"60%\">\n";
    for (auto it = scene.begin(); it != scene.end(); ++it) {
        if (it.value().isArray() && !it.value().toArray().isEmpty() && it.value().toArray()[0].isObject()) continue;
        if (it.key() == key(Key::Name) || it.key() == key(Key::Description)) continue;
        QString text = cellText(it.value());
        // The integrator by its name ("explicit Euler"), as the app's integrator box shows it.
        if (it.key() == key(Key::Integrator)) {
            const IntegratorInfo* info = findIntegrator(it.value().toString().toStdString());
            if (info != nullptr && *info->title != '\0') text = QString::fromUtf8(info->title);
        }
        html += "<tr><th>" + label(it.key()).toHtmlEscaped() + "</th><td>" + text.toHtmlEscaped() + "</td></tr>\n";
    }
    html += "</table>\n";
    // Each list of the scene (bodies, forces, torques, ...) as a table, in the table's order.
    for (const sceneformat::KeyRow& r : sceneformat::rows()) {
        if (r.section != sceneformat::Section::Scene || r.type != sceneformat::Type::List) continue;
        const QString list = key(r.id);
        html += tableOf(label(list.left(1).toUpper() + list.mid(1)), scene.value(list).toArray());
    }
    html += "<p>Lengths in m, masses in kg, forces in N, velocities in m/s and rad/s, times in s; "
            "a force acts from step “from step” up to (not including) step “to step”.</p>\n";
    html += "<h2>Your task</h2>\n<p>";
    if (!spec.task.isEmpty()) html += spec.task.toHtmlEscaped() + ' ';
    html += "Compute the numbers of step k = " + QString::number(g.answerStep) + " (from t = " +
            QString::number(g.answerStep * g.scene->dt, 'g', 10) + " s to t = " +
            QString::number((g.answerStep + 1) * g.scene->dt, 'g', 10) + " s).</p>\n";
    html += startStateOf(g);
    // Four columns, so that no id is squeezed: the unit beside the symbol, the probe or
    // force beside its body.
    html += "<table width=\"100%\" style=\"font-size:9pt\">\n<tr><th width=\"20%\">quantity [unit]</th>"
            "<th width=\"28%\">id</th><th width=\"24%\">body / contact</th>" +
            (withAnswers ? QStringLiteral("<th width=\"28%\">answer</th>") : QStringLiteral("<th width=\"28%\">your answer</th>")) +
            "</tr>\n";
    for (const TraceEntry& e : g.key) {
        const bool contact = e.info->indexKind == IndexKind::Contact;
        QString who = contact ? contactName(*g.scene, g.answerTrace, e.index)
                              : (e.body >= 0 ? QString::fromStdString(g.scene->bodies[e.body].name) : QString());
        if (!contact && e.index >= 0) {
            who += (who.isEmpty() ? "" : ", ") + QString::fromUtf8(indexKindName(e.info->indexKind)) + ' ' + QString::number(e.index);
        }
        const QString unit = QString::fromUtf8(e.info->unit);
        const QString quantity = QString::fromUtf8(e.info->text) + (unit.isEmpty() ? QString() : " [" + unit + "]");
        html += "<tr><td>" + quantity.toHtmlEscaped() + "</td><td><code>" + QString::fromLatin1(e.info->id) + "</code></td><td>" +
                who.toHtmlEscaped() + "</td>" +
                (withAnswers ? "<td class=\"key\">" + formatValue(e.value).toHtmlEscaped() : QStringLiteral("<td class=\"answer\">")) +
                "</td></tr>\n";
    }
    html += "</table>\n";
    html += withAnswers ? "<p>The workbook's numbers, from the simulation's own step " + QString::number(g.answerStep) +
                              ". Students check theirs with <code>rbw check</code> or the app's Check my numbers.</p>\n"
                        : QStringLiteral("<p>Check your numbers with <code>rbw check</code> or the app's Check my numbers "
                                         "(the quantity ids above are its names).</p>\n");
    html += "</body>\n</html>\n";
    return html;
}

} // namespace rbw
