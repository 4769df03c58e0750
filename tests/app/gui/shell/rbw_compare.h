// Helpers for the window tests that compare with the real rbw binary bit for bit
// (tst_history_scrubber, tst_plot_over_time): rbw's JSON with exact numbers, the
// world and trace against it, one quantity's series over time.
//
// Expected numbers come from the real rbw binary (tests/test_support.h, runRbw) and
// are compared bit for bit: both front ends run the same physics.
#pragma once

#include "app/gui/panels/quantities/trace_model.h"
#include "physics/engine/world.h"
#include "tests/test_support.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPointF>
#include <QRegularExpression>

#include <cstdio>
#include <cstdlib>

namespace rbw::test {

// Numbers are read from rbw's text with strtod (correctly rounded), not through
// QJsonValue::toDouble, whose parser can be one ulp off: see exactJson().
inline QList<double> jsonNumbers(const QJsonValue& v)
{
    QList<double> out;
    if (v.isString()) {
        const QByteArray text = v.toString().toLatin1();
        out << std::strtod(text.constData(), nullptr);
    } else if (v.isDouble()) {
        out << v.toDouble();
    } else if (v.isArray()) {
        for (const QJsonValue& x : v.toArray()) out << jsonNumbers(x);
    }
    return out;
}

// rbw's JSON with every number turned into a string holding its exact text (rbw
// pretty-prints one number per line, after `"key": ` or alone in an array), so the
// comparison is bit for bit.
inline QJsonObject exactJson(const QByteArray& out)
{
    static const QRegularExpression number(QStringLiteral(R"(^(\s*|.*": )(-?[0-9][0-9.eE+-]*)(,?)$)"),
                                           QRegularExpression::MultilineOption);
    QString text = QString::fromUtf8(out);
    text.replace(number, QStringLiteral("\\1\"\\2\"\\3"));
    return QJsonDocument::fromJson(text.toUtf8()).object();
}

// rbw's JSON for a scene run for `steps` steps with the given --trace.
inline QJsonObject rbwRun(const QString& scene, long steps, const QString& trace)
{
    const rbw::test::RbwRun r = rbw::test::runRbw({"run", QStringLiteral(RBW_SOURCE_DIR "/lessons/") + scene, "--steps",
                                        QString::number(steps), "--trace", trace, "--format", "json"});
    if (r.exitCode != 0) qWarning("rbw failed: %s", qPrintable(r.err));
    return exactJson(r.out);
}

// Exact equality, element by element. The only two doubles == treats as equal that
// differ in their bits are +0 and -0, and rbw prints -0 as "0" (value_format.cpp), so
// that is the one difference a text comparison cannot see anyway.
inline bool sameNumbers(const QList<double>& a, const QList<double>& b)
{
    if (a.size() != b.size()) return false;
    for (qsizetype i = 0; i < a.size(); ++i) {
        if (!(a[i] == b[i])) return false;
    }
    return true;
}

inline QString hexText(const QList<double>& v)
{
    QStringList parts;
    for (double d : v) {
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%a", d);
        parts << QString::fromLatin1(buffer);
    }
    return parts.join(' ');
}

// Compares the world's state with rbw's "bodies" (bit for bit) and the current trace
// with rbw's last trace entry by entry. Empty when equal, else the first difference.
inline QString compareWithRbw(const World& world, const StepTrace* trace, const QJsonObject& run)
{
    const QJsonArray bodies = run.value("bodies").toArray();
    if (bodies.size() != static_cast<qsizetype>(world.states().size())) return "body count differs";
    for (int b = 0; b < bodies.size(); ++b) {
        const QJsonObject o = bodies[b].toObject();
        const BodyState& s = world.states()[b];
        const QList<QPair<QString, QList<double>>> fields = {
            {"position", rbw::test::flat(s.x_W)},          {"linear_velocity", rbw::test::flat(s.v_W)},
            {"orientation", rbw::test::flat(s.q_WB)},      {"angular_momentum", rbw::test::flat(s.L_W)},
            {"angular_velocity", rbw::test::flat(s.omega_W)}};
        for (const auto& [key, mine] : fields) {
            if (!sameNumbers(jsonNumbers(o.value(key)), mine)) {
                return QStringLiteral("body %1 %2: app %3, rbw %4")
                    .arg(b)
                    .arg(key, rbw::test::listText(mine), rbw::test::listText(jsonNumbers(o.value(key))));
            }
        }
    }
    if (!sameNumbers(jsonNumbers(run.value("time")), {world.time()})) return "time differs";
    const QJsonArray traces = run.value("trace").toArray();
    if (traces.isEmpty() || trace == nullptr) return "no trace";
    const QJsonArray quantities = traces.last().toObject().value("quantities").toArray();
    if (quantities.size() != static_cast<qsizetype>(trace->entries.size())) {
        return QStringLiteral("trace has %1 entries, rbw %2").arg(trace->entries.size()).arg(quantities.size());
    }
    for (int i = 0; i < quantities.size(); ++i) {
        const QJsonObject q = quantities[i].toObject();
        const TraceEntry& e = trace->entries[static_cast<size_t>(i)];
        if (q.value("id").toString() != QLatin1String(e.info->id) || !sameNumbers(jsonNumbers(q.value("value")), rbw::test::flatten(e.value))) {
            return QStringLiteral("entry %1 (%2): app %3, rbw %4 %5")
                .arg(i)
                .arg(QLatin1String(e.info->id), hexText(rbw::test::flatten(e.value)), q.value("id").toString(),
                     hexText(jsonNumbers(q.value("value"))));
        }
    }
    return {};
}

// The table row of quantity `id` of body `body` (depth first).
inline QModelIndex findEntryRow(const TraceModel* model, const QString& id, int body, const QModelIndex& parent = {})
{
    for (int r = 0; r < model->rowCount(parent); ++r) {
        const QModelIndex i = model->index(r, 0, parent);
        const TraceEntry* e = model->entryAt(i);
        if (e != nullptr && id == QLatin1String(e->info->id) && e->body == body) return i;
        const QModelIndex found = findEntryRow(model, id, body, i);
        if (found.isValid()) return found;
    }
    return {};
}

// (t, component c) of quantity `id` of body `bodyName` in every step of rbw's
// --trace all, bit for bit.
inline QList<QPointF> rbwSeries(const QJsonObject& run, const QString& id, const QString& bodyName, int component)
{
    QList<QPointF> out;
    for (const QJsonValue& step : run.value("trace").toArray()) {
        const QJsonObject o = step.toObject();
        for (const QJsonValue& q : o.value("quantities").toArray()) {
            const QJsonObject e = q.toObject();
            if (e.value("id").toString() == id && e.value("body").toString() == bodyName) {
                out.append(QPointF(jsonNumbers(o.value("time")).value(0), jsonNumbers(e.value("value")).value(component)));
            }
        }
    }
    return out;
}

} // namespace rbw::test
