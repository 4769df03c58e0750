#include "app/cli/diagnose_command.h"
#include "app/cli/standard_output.h"

#include "app/cli/simulator_process.h"
#include "physics/workbook/checker/mistakes.h"
#include "physics/workbook/probes/probe_models.h"
#include "physics/workbook/probes/probe_verdict.h"
#include "physics/workbook/probes/probes.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

#include <cmath>

namespace rbw {

namespace {

constexpr int kMatches = 0;
constexpr int kNotMatching = 1;
constexpr int kBadInput = 2;
constexpr double kDefaultTimeout = 10.0;   // seconds a probe may take
constexpr double kMaxTimeout = 86400.0;

int fail(const QString& message, const QStringList& stderrTail = {})
{
    QTextStream err(stderr);
    err << "rbw: diagnose: " << message << '\n';
    if (!stderrTail.isEmpty()) {
        err << "rbw: diagnose: its last lines on standard error:\n";
        for (const QString& l : stderrTail) err << "  " << l << '\n';
    }
    return kBadInput;
}

QString numbers(const std::vector<double>& v)
{
    QStringList parts;
    for (double x : v) parts << QString::number(x, 'g', 9);
    return QLatin1Char('(') + parts.join(", ") + QLatin1Char(')');
}

QJsonArray jsonNumbers(const std::vector<double>& v)
{
    QJsonArray a;
    for (double x : v) a.append(x);
    return a;
}

QJsonArray jsonStrings(const std::vector<std::string>& v)
{
    QJsonArray a;
    for (const std::string& s : v) a.append(QString::fromStdString(s));
    return a;
}

// The ids the motion probes cannot check: the collision models and the hand-only ones.
std::vector<std::string> notChecked(probes::ProbeScope scope)
{
    std::vector<std::string> ids;
    for (const MistakeInfo& m : mistakeCatalogue()) {
        if (probes::scopeOf(m.mistake) == scope) ids.push_back(m.id);
    }
    return ids;
}

QJsonObject toJson(const QString& command, const std::vector<probes::Probe>& all,
                   const probes::SimulatorDiagnosis& d)
{
    QJsonObject doc;
    doc["simulator"] = command;
    doc["probes_group"] = QStringLiteral("motion");
    doc["tolerance"] = QJsonObject{{"relative", probes::kRelativeTolerance},
                                   {"of", "the largest |value| of that quantity (x, v, omega or r) in the probe"}};
    doc["verdict"] = QString::fromLatin1(probes::verdictName(d.verdict));
    doc["mistakes"] = jsonStrings(d.mistakes);
    doc["possible_mistakes"] = jsonStrings(d.possibleMistakes);
    QJsonArray details;
    for (const std::vector<std::string>* ids : {&d.mistakes, &d.possibleMistakes}) {
        for (const std::string& id : *ids) {
            if (const MistakeInfo* m = findMistake(id)) {
                details.append(QJsonObject{{"id", m->id}, {"equation", m->equation}, {"explanation", m->explanation}});
            }
        }
    }
    doc["mistake_details"] = details;
    if (d.firstDivergence) {
        const probes::Divergence& f = *d.firstDivergence;
        doc["first_divergence"] = QJsonObject{
            {"probe", d.divergenceProbe + 1},
            {"probe_name", QString::fromStdString(all[d.divergenceProbe].name)},
            {"step", f.step},
            {"body", f.body},
            {"quantity", QString::fromStdString(f.quantity)},
            {"component", f.component},
            {"expected", jsonNumbers(f.expected)},
            {"given", jsonNumbers(f.given)},
        };
    } else {
        doc["first_divergence"] = QJsonValue::Null;
    }
    QJsonArray rows;
    for (std::size_t p = 0; p < d.probes.size(); ++p) {
        rows.append(QJsonObject{{"probe", static_cast<int>(p) + 1},
                                {"name", QString::fromStdString(all[p].name)},
                                {"purpose", QString::fromStdString(all[p].purpose)},
                                {"matches", d.probes[p].matchesRight},
                                {"reproduced_by", jsonStrings(d.probes[p].reproducedBy)}});
    }
    doc["probes"] = rows;
    doc["not_checked"] = QJsonObject{{"collision", jsonStrings(notChecked(probes::ProbeScope::Collision))},
                                     {"hand_only", jsonStrings(notChecked(probes::ProbeScope::HandOnly))}};
    return doc;
}

void writeText(QTextStream& out, const QString& command, const std::vector<probes::Probe>& all,
               const probes::SimulatorDiagnosis& d)
{
    out << "rbw diagnose: " << all.size() << " motion probes through \"" << command << "\"\n";
    out << "verdict: " << probes::verdictName(d.verdict) << '\n';
    auto describe = [&out](const std::string& id) {
        const MistakeInfo* m = findMistake(id);
        if (m == nullptr) return;
        out << "  " << m->id << ": " << m->equation << '\n' << "    " << m->explanation << '\n';
    };
    if (!d.mistakes.empty()) out << "mistake:\n";
    for (const std::string& id : d.mistakes) describe(id);
    if (!d.possibleMistakes.empty()) out << "possible mistakes (each explains your answers equally well):\n";
    for (const std::string& id : d.possibleMistakes) describe(id);
    if (d.firstDivergence) {
        const probes::Divergence& f = *d.firstDivergence;
        out << "first divergence from the right algorithm: probe " << d.divergenceProbe + 1 << " ("
            << QString::fromStdString(all[d.divergenceProbe].name) << "), step " << f.step << ", body " << f.body
            << ", " << QString::fromStdString(f.quantity) << ": expected " << numbers(f.expected) << ", yours "
            << numbers(f.given) << '\n';
    }
    out << "probes:\n";
    for (std::size_t p = 0; p < d.probes.size(); ++p) {
        out << "  " << p + 1 << ' ' << QString::fromStdString(all[p].name) << "  ";
        if (d.probes[p].matchesRight) {
            out << "matches";
        } else {
            out << "differs";
            if (!d.probes[p].reproducedBy.empty()) {
                QStringList labels;
                for (const std::string& l : d.probes[p].reproducedBy) labels << QString::fromStdString(l);
                out << "; reproduced by " << labels.join(", ");
            }
        }
        out << "  (" << QString::fromStdString(all[p].purpose) << ")\n";
    }
    out << "Numbers match within " << probes::kRelativeTolerance
        << " of the largest |value| of that quantity in the probe (float round-off matches).\n"
        << "Not checked yet: the collision group (its impulse mistakes) and the template's public tests.\n";
}

} // namespace

int runDiagnoseCommand(const QCommandLineParser& parser, const QStringList& arguments)
{
    if (!arguments.isEmpty()) {
        return fail("reading a folder of answers (rbw diagnose DIR) is not built yet; use --simulator \"CMD\"");
    }
    if (!parser.isSet("simulator")) return fail("--simulator \"CMD\" is required (the command that starts your program)");
    const QString commandText = parser.value("simulator");
    const SimulatorCommand command = parseSimulatorCommand(commandText);
    if (command.program.isEmpty()) return fail("--simulator: no program given, got \"" + commandText + "\"");

    double timeout = kDefaultTimeout;
    if (parser.isSet("timeout")) {
        bool ok = false;
        timeout = parser.value("timeout").toDouble(&ok);
        if (!ok || !std::isfinite(timeout) || timeout <= 0.0 || timeout > kMaxTimeout) {
            return fail("--timeout: must be a number of seconds > 0 and at most 86400, got \"" +
                        parser.value("timeout") + "\"");
        }
    }
    const QString format = parser.isSet("format") ? parser.value("format") : QStringLiteral("text");
    if (format != "text" && format != "json") {
        return fail("--format: must be text or json for diagnose, got \"" + format + "\"");
    }

    const std::vector<probes::Probe>& all = probes::motionProbes();
    std::vector<probes::Answers> given;
    for (std::size_t p = 0; p < all.size(); ++p) {
        const SimulatorRun run =
            runSimulatorProbe(command, probes::protocolLines(all[p]), static_cast<int>(p) + 1,
                              QString::fromStdString(all[p].name), static_cast<int>(std::lround(timeout * 1000.0)));
        if (!run.ok) return fail(run.failure, run.stderrTail);
        given.push_back(run.answers);
    }

    const probes::SimulatorDiagnosis d = probes::diagnoseAnswers(all, given, probes::motionModels());
    QTextStream& out = cli::out();   // checked: a write error is exit 2 (standard_output.h)
    if (format == "json") {
        out << QJsonDocument(toJson(commandText, all, d)).toJson(QJsonDocument::Indented);
    } else {
        writeText(out, commandText, all, d);
    }
    return d.verdict == probes::Verdict::Matches ? kMatches : kNotMatching;
}

} // namespace rbw
