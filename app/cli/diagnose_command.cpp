#include "app/cli/diagnose_command.h"
#include "app/cli/standard_output.h"

#include "app/simulator/diagnose_report.h"
#include "app/simulator/probe_answer_files.h"
#include "app/simulator/simulator_process.h"
#include "physics/workbook/probes/collision_replay.h"
#include "physics/workbook/probes/probe_models.h"
#include "physics/workbook/probes/probe_verdict.h"
#include "physics/workbook/probes/probes.h"
#include "physics/workbook/probes/template_tests.h"

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
constexpr double kDefaultTimeout = 10.0;   // seconds a probe may take
constexpr double kMaxTimeout = 86400.0;

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

struct Settings {
    std::optional<probes::ProbeGroup> group;
    double timeout = kDefaultTimeout;
};

// One program through the probes and the template's public tests; run.failure set (and
// reported) when it could not be run or broke the protocol.
DiagnoseRun runLive(const QString& commandText, const Settings& settings, OfflineAnswers& answers)
{
    DiagnoseRun run;
    run.source = commandText;
    run.sourceKind = QStringLiteral("simulator");
    const SimulatorCommand command = parseSimulatorCommand(commandText);
    if (command.program.isEmpty()) {
        run.failure = "--simulator: no program given, got \"" + commandText + "\"";
        report(run.failure);
        return run;
    }
    const int timeoutMs = static_cast<int>(std::lround(settings.timeout * 1000.0));
    const std::vector<probes::Probe> all = probes::probesOf(settings.group.value_or(probes::ProbeGroup::All));
    auto runOne = [&](const probes::Probe& probe, int number, const QString& name) -> std::optional<probes::Answers> {
        const SimulatorRun r = runSimulatorProbe(command, probes::protocolLines(probe), number, name, timeoutMs);
        if (r.ok) return r.answers;
        run.failure = r.failure;
        report(r.failure, r.stderrTail);
        return std::nullopt;
    };
    for (std::size_t p = 0; p < all.size(); ++p) {
        const std::optional<probes::Answers> a =
            runOne(all[p], static_cast<int>(p) + 1, QString::fromStdString(all[p].name));
        if (!a) return run;
        answers.given.push_back(*a);
    }
    answers.probes = all;
    answers.ok = true;
    // the template's public tests, numbered after the probes
    int number = static_cast<int>(all.size());
    for (const probes::TemplateTest& t : probes::templatePublicTests()) {
        ++number;
        const QString name = "the template's " + QString::fromStdString(t.name) +
                             (t.version.empty() ? QString() : " (" + QString::fromStdString(t.version) + ")");
        const std::optional<probes::Answers> a = runOne(t.scene, number, name);
        if (!a) {
            answers.ok = false;
            return run;
        }
        run.templateTests.push_back({&t, probes::runTemplateTest(t, *a)});
    }
    return run;
}

// The diagnosis of answers read or run.
void diagnose(DiagnoseRun& run, const OfflineAnswers& answers)
{
    run.probes = answers.probes;
    // the group of the probes answered (offline without --probes: those found)
    const auto colliding =
        std::count_if(run.probes.begin(), run.probes.end(), [](const probes::Probe& p) { return p.collides; });
    run.group = colliding == 0                                             ? QStringLiteral("motion")
                : colliding == static_cast<long>(run.probes.size()) ? QStringLiteral("collision")
                                                                    : QStringLiteral("all");
    std::vector<probes::ReplayModel> candidates = probes::motionModels();
    if (colliding > 0) {
        for (const probes::ReplayModel& m : probes::collisionModels()) candidates.push_back(m);
    }
    run.diagnosis = probes::diagnoseAnswers(run.probes, answers.given, candidates);
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

    Settings settings;
    if (parser.isSet("timeout")) {
        if (!live) return fail("--timeout: only for --simulator (offline answers are read, not run)");
        bool ok = false;
        settings.timeout = parser.value("timeout").toDouble(&ok);
        if (!ok || !std::isfinite(settings.timeout) || settings.timeout <= 0.0 || settings.timeout > kMaxTimeout) {
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
            OfflineAnswers answers;
            DiagnoseRun run = runLive(commandText, settings, answers);
            if (run.failure.isEmpty()) diagnose(run, answers);
            else if (format != "csv") return kBadInput;
            runs.push_back(run);
        }
    } else {
        DiagnoseRun run;
        run.source = trajectory ? parser.value("trajectory") : arguments.first();
        run.sourceKind = trajectory ? QStringLiteral("trajectory") : QStringLiteral("folder");
        const OfflineAnswers answers = trajectory ? readTrajectoryCsv(run.source, settings.group)
                                                  : readAnswersFolder(run.source, settings.group);
        if (!answers.ok) return fail(answers.failure);
        diagnose(run, answers);
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
