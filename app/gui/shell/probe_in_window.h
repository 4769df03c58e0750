// Compare with my simulator → Open in the main window (issue 23, docs/user-guide.md):
// one probe of a diagnosed run becomes the window's scene (physics' probeScene(), the
// same conversion replayWithEngine() runs; a collision probe with the c fitted to the
// student's answers), the quantities table gets its Yours column with the student's
// numbers for the state quantities their `state` lines gave (x, v, ω and r when
// printed, per body and step; marked by answerDifferences(), the rule of the first
// divergence), and the history slider a mark at the probe's first divergence. Any
// other scene started (a lesson, a file, new numbers, the editor's Apply) closes the
// probe: the column and the mark go.
#pragma once

#include "app/simulator/diagnose_report.h"
#include "physics/workbook/probes/replay.h"

#include <QObject>
#include <QString>

#include <vector>

namespace rbw {

class HistoryScrubber;
class LessonController;
class TraceModel;
struct SceneDef;
struct StartedScene;

class ProbeInWindow : public QObject {
    Q_OBJECT
public:
    ProbeInWindow(LessonController* lessons, TraceModel* table, HistoryScrubber* scrubber, QObject* parent = nullptr);

    // Opens probe `probe` of `run`; `right` holds the right algorithm's answers beside
    // run.given (rightAnswers(run)). False (nothing changes) if the run has no such probe.
    bool open(const DiagnoseRun& run, const std::vector<probes::Answers>& right, int probe);
    bool isOpen() const { return !name_.isEmpty(); }
    QString probeName() const { return name_; }

private:
    void onSceneStarted(const SceneDef& scene, const StartedScene& info);
    void close();

    LessonController* lessons_;
    TraceModel* table_;
    HistoryScrubber* scrubber_;
    QString name_;   // the open probe's, empty when none
};

} // namespace rbw
