#include "app/simulator/diagnose_run.h"

#include "app/simulator/simulator_process.h"
#include "physics/workbook/probes/collision_replay.h"
#include "physics/workbook/probes/probe_models.h"
#include "physics/workbook/probes/probe_verdict.h"
#include "physics/workbook/probes/template_tests.h"

#include <algorithm>
#include <cmath>

namespace rbw {

namespace {

// The diagnosis of the answers read or run: every motion model, and with collision
// probes every collision model too.
void diagnose(DiagnoseRun& run, const OfflineAnswers& answers)
{
    run.probes = answers.probes;
    run.given = answers.given;
    // the group of the probes answered (offline without --probes: those found)
    const auto colliding =
        std::count_if(run.probes.begin(), run.probes.end(), [](const probes::Probe& p) { return p.collides; });
    run.group = colliding == 0                                       ? QStringLiteral("motion")
                : colliding == static_cast<long>(run.probes.size()) ? QStringLiteral("collision")
                                                                    : QStringLiteral("all");
    std::vector<probes::ReplayModel> candidates = probes::motionModels();
    if (colliding > 0) {
        for (const probes::ReplayModel& m : probes::collisionModels()) candidates.push_back(m);
    }
    run.diagnosis = probes::diagnoseAnswers(run.probes, answers.given, candidates);
}

QString templateTestName(const probes::TemplateTest& t)
{
    return "the template's " + QString::fromStdString(t.name) +
           (t.version.empty() ? QString() : " (" + QString::fromStdString(t.version) + ")");
}

} // namespace

DiagnoseRun runSimulatorDiagnosis(const QString& commandText, const DiagnoseSettings& settings,
                                  const DiagnoseProgress& progress, const std::atomic<bool>* cancel)
{
    DiagnoseRun run;
    run.source = commandText;
    run.sourceKind = QStringLiteral("simulator");
    const SimulatorCommand command = parseSimulatorCommand(commandText);
    if (command.program.isEmpty()) {
        run.failure = "--simulator: no program given, got \"" + commandText + "\"";
        return run;
    }
    const int timeoutMs = static_cast<int>(std::lround(settings.timeoutSeconds * 1000.0));
    const std::vector<probes::Probe> all = probes::probesOf(settings.group.value_or(probes::ProbeGroup::All));
    const std::vector<probes::TemplateTest>& templateTests = probes::templatePublicTests();
    const int total = static_cast<int>(all.size() + templateTests.size());
    int done = 0;
    auto runOne = [&](const probes::Probe& probe, const QString& name) -> std::optional<probes::Answers> {
        if (progress) progress(done, total, name);
        ++done;
        const SimulatorRun r = runSimulatorProbe(command, probes::protocolLines(probe), done, name, timeoutMs, cancel);
        if (r.ok) return r.answers;
        run.failure = r.failure;
        run.stderrTail = r.stderrTail;
        run.cancelled = r.cancelled;
        return std::nullopt;
    };
    OfflineAnswers answers;
    for (const probes::Probe& p : all) {
        const std::optional<probes::Answers> a = runOne(p, QString::fromStdString(p.name));
        if (!a) return run;
        answers.given.push_back(*a);
    }
    answers.probes = all;
    // the template's public tests, numbered after the probes
    std::vector<TemplateTestResult> tests;
    for (const probes::TemplateTest& t : templateTests) {
        const std::optional<probes::Answers> a = runOne(t.scene, templateTestName(t));
        if (!a) return run;
        tests.push_back({&t, probes::runTemplateTest(t, *a)});
    }
    if (progress) progress(done, total, QString());
    diagnose(run, answers);
    run.templateTests = tests;
    return run;
}

DiagnoseRun readAnswersDiagnosis(const QString& path, bool trajectory, std::optional<probes::ProbeGroup> group)
{
    DiagnoseRun run;
    run.source = path;
    run.sourceKind = trajectory ? QStringLiteral("trajectory") : QStringLiteral("folder");
    const OfflineAnswers answers = trajectory ? readTrajectoryCsv(path, group) : readAnswersFolder(path, group);
    if (!answers.ok) {
        run.failure = answers.failure;
        return run;
    }
    diagnose(run, answers);
    return run;
}

std::vector<probes::Answers> rightAnswers(const DiagnoseRun& run)
{
    return probes::modelAnswers(run.probes, run.given, probes::ReplayModel{});
}

} // namespace rbw
