// One diagnosis of Check my simulator (issue 23, docs/simulator-protocol.md), the same
// for `rbw diagnose` and the app's Compare with my simulator: the student's program run
// through the probes and the template's public tests (one run of the program each,
// simulator_process.h), or its answers read offline (probe_answer_files.h), then the
// verdict of physics/workbook/probes/probe_verdict.h over the probes answered.
//
// runSimulatorDiagnosis() blocks; the app calls it off the GUI thread. `progress` is
// called on the calling thread before each run of the program; `cancel`, when set
// from another thread, stops the program being run within about 50 ms (its process
// group killed) and ends the diagnosis with `cancelled`.
#pragma once

#include "app/simulator/diagnose_report.h"
#include "app/simulator/probe_answer_files.h"

#include <QString>

#include <atomic>
#include <functional>
#include <optional>

namespace rbw {

constexpr double kDefaultProbeTimeout = 10.0;   // seconds a probe may take (--timeout)
constexpr double kMaxProbeTimeout = 86400.0;

struct DiagnoseSettings {
    std::optional<probes::ProbeGroup> group;   // nullopt: all (offline: the probes found)
    double timeoutSeconds = kDefaultProbeTimeout;
};

// done runs of the program so far, of total; `name` the probe (or template test) next.
using DiagnoseProgress = std::function<void(int done, int total, const QString& name)>;

// The program `commandText` (split as parseSimulatorCommand() does) through the probes of
// the group and the template's public tests, then the diagnosis. On failure
// run.failure says why (the sentence rbw diagnose prints) and run.stderrTail holds the
// program's last lines on standard error; nothing else is set.
DiagnoseRun runSimulatorDiagnosis(const QString& commandText, const DiagnoseSettings& settings,
                                  const DiagnoseProgress& progress = {}, const std::atomic<bool>* cancel = nullptr);

// The answers of the offline mode: `path` a folder (rbw diagnose DIR) or, with
// `trajectory`, a CSV file (--trajectory); run.failure names the file, line and reason.
DiagnoseRun readAnswersDiagnosis(const QString& path, bool trajectory, std::optional<probes::ProbeGroup> group);

// What the right algorithm answers to probe p of a diagnosed run (its c fitted to the
// program's answers, as the verdict compares): the "workbook" column beside run.given.
std::vector<probes::Answers> rightAnswers(const DiagnoseRun& run);

} // namespace rbw
