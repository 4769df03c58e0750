// What `rbw diagnose` prints (issue 23, docs/simulator-protocol.md, "Running the
// check"): one program's (or one offline folder's) diagnosis as text for the student
// or as one JSON document for scripts; several programs' as CSV for tutors (one row per
// program and probe, then the program's summary row).
#pragma once

#include "physics/workbook/probes/probe_verdict.h"
#include "physics/workbook/probes/probes.h"
#include "physics/workbook/probes/template_tests.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <QTextStream>

#include <optional>
#include <vector>

namespace rbw {

// One of the template's public tests as the program ran it.
struct TemplateTestResult {
    const probes::TemplateTest* test = nullptr;
    std::optional<probes::TemplateFailure> failure;   // nullopt: passes
};

struct DiagnoseRun {
    QString source;       // the simulator's command, the answers folder or the CSV file
    QString sourceKind;   // "simulator", "folder" or "trajectory"
    QString group;        // "motion", "collision", "all" (of the probes in `probes`)
    std::vector<probes::Probe> probes;
    std::vector<probes::Answers> given;   // the program's answers, one list per probe
    probes::SimulatorDiagnosis diagnosis;
    std::vector<TemplateTestResult> templateTests;   // live runs only
    QString failure;   // the program could not be diagnosed (exit 2); the rest is empty
    QStringList stderrTail;   // with a failure of the program: its last lines on standard error
    bool cancelled = false;   // the app's Cancel stopped the run (failure says so)
};

QJsonObject diagnoseJson(const DiagnoseRun& run);
void writeDiagnoseText(QTextStream& out, const DiagnoseRun& run);
// The header, then per run its probe rows and its summary row.
void writeDiagnoseCsv(QTextStream& out, const std::vector<DiagnoseRun>& runs);

} // namespace rbw
