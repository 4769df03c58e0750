#include "app/cli/diagnose_command.h"
#include "app/cli/standard_output.h"

#include "app/simulator/diagnose_report.h"
#include "app/simulator/diagnose_run.h"
#include "physics/workbook/probes/probe_verdict.h"
#include "physics/workbook/probes/probes.h"

#include <QJsonDocument>
#include <QTextStream>

#include <algorithm>
#include <cmath>
#include <optional>

namespace rbw {

namespace {

constexpr int kMatches = 0;
constexpr int kNotMatching = 1;
constexpr int kBadInput = 2;

void report(const QString& message, const QStringList& stderrTail = {})
{
    QTextStream err(stderr);
    err << "rbw: diagnose: " << message << '\n';
    if (!stderrTail.isEmpty()) {
        err << "rbw: diagnose: its last lines on standard error:\n";
        for (const QString& l : stderrTail) err << "  " << l << '\n';
    }
}

int fail(const QString& message)
{
    report(message);
    return kBadInput;
}

} // namespace

int runDiagnoseCommand(const QCommandLineParser& parser, const QStringList& arguments)
{
    const QStringList simulators = parser.values("simulator");
    const bool live = !simulators.isEmpty();
    const bool trajectory = parser.isSet("trajectory");
    const int sources = (live ? 1 : 0) + (trajectory ? 1 : 0) + (arguments.isEmpty() ? 0 : 1);
    if (sources == 0) {
        return fail("what to diagnose: --simulator \"CMD\" (the command that starts your program), "
                    "--trajectory FILE.csv or a folder of answers (rbw diagnose DIR)");
    }
    if (sources > 1 || arguments.size() > 1) {
        return fail("give one of --simulator \"CMD\", --trajectory FILE.csv or one folder DIR, got " +
                    QString(live ? "--simulator " : "") + (trajectory ? "--trajectory " : "") + arguments.join(' '));
    }

    DiagnoseSettings settings;
    if (parser.isSet("timeout")) {
        if (!live) return fail("--timeout: only for --simulator (offline answers are read, not run)");
        bool ok = false;
        settings.timeoutSeconds = parser.value("timeout").toDouble(&ok);
        if (!ok || !std::isfinite(settings.timeoutSeconds) || settings.timeoutSeconds <= 0.0 ||
            settings.timeoutSeconds > kMaxProbeTimeout) {
            return fail("--timeout: must be a number of seconds > 0 and at most 86400, got \"" +
                        parser.value("timeout") + "\"");
        }
    }
    const QString format = parser.isSet("format") ? parser.value("format") : QStringLiteral("text");
    if (format != "text" && format != "json" && format != "csv") {
        return fail("--format: must be text, json or csv for diagnose, got \"" + format + "\"");
    }
    if (simulators.size() > 1 && format != "csv") {
        return fail(QStringLiteral("%1 --simulator options: several programs need --format csv (one row per program "
                                   "and probe)")
                        .arg(simulators.size()));
    }
    if (parser.isSet("probes")) {
        settings.group = probes::probeGroupNamed(parser.value("probes").toStdString());
        if (!settings.group) {
            return fail("--probes: must be motion, collision or all, got \"" + parser.value("probes") + "\"");
        }
    }

    std::vector<DiagnoseRun> runs;
    if (live) {
        for (const QString& commandText : simulators) {
            DiagnoseRun run = runSimulatorDiagnosis(commandText, settings);
            if (!run.failure.isEmpty()) {
                report(run.failure, run.stderrTail);
                if (format != "csv") return kBadInput;
            }
            runs.push_back(run);
        }
    } else {
        DiagnoseRun run = readAnswersDiagnosis(trajectory ? parser.value("trajectory") : arguments.first(), trajectory,
                                               settings.group);
        if (!run.failure.isEmpty()) return fail(run.failure);
        runs.push_back(run);
    }

    QTextStream& out = cli::out();   // checked: a write error is exit 2 (standard_output.h)
    if (format == "csv") {
        writeDiagnoseCsv(out, runs);
    } else if (format == "json") {
        out << QJsonDocument(diagnoseJson(runs.front())).toJson(QJsonDocument::Indented);
    } else {
        writeDiagnoseText(out, runs.front());
    }
    int status = kMatches;
    for (const DiagnoseRun& r : runs) {
        if (!r.failure.isEmpty()) status = kBadInput;
        else if (r.diagnosis.verdict != probes::Verdict::Matches) status = std::max(status, kNotMatching);
    }
    return status;
}

} // namespace rbw
