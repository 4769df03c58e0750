#include "app/gui/shell/probe_in_window.h"

#include "app/core/step_numbering.h"
#include "app/gui/panels/quantities/trace_model.h"
#include "app/gui/shell/history_scrubber.h"
#include "app/gui/shell/lesson_controller.h"
#include "physics/engine/quantities.h"
#include "physics/workbook/probes/probe_verdict.h"

#include <optional>

namespace rbw {

namespace {

// The trace id of the rows that show a `state` line's quantity (the catalogue's entry).
const char* traceIdOf(const std::string& quantity)
{
    if (quantity == "x") return q::position.id;
    if (quantity == "v") return q::linear_velocity.id;
    if (quantity == "omega") return q::angular_velocity.id;
    return q::orientation.id;   // "r"
}

QString numbers(const std::vector<double>& values)
{
    QStringList parts;
    for (double v : values) parts << QString::number(v, 'g', 9);
    return QLatin1Char('(') + parts.join(QStringLiteral(", ")) + QLatin1Char(')');
}

} // namespace

ProbeInWindow::ProbeInWindow(LessonController* lessons, TraceModel* table, HistoryScrubber* scrubber, QObject* parent)
    : QObject(parent)
    , lessons_(lessons)
    , table_(table)
    , scrubber_(scrubber)
{
    connect(lessons_, &LessonController::started, this, &ProbeInWindow::onSceneStarted);
}

bool ProbeInWindow::open(const DiagnoseRun& run, const std::vector<probes::Answers>& right, int probe)
{
    const auto p = static_cast<size_t>(probe);
    if (probe < 0 || p >= run.probes.size() || p >= run.given.size() || p >= right.size()) return false;
    const probes::Probe& pr = run.probes[p];
    SceneDef scene = probes::probeScene(pr);
    if (pr.collides) {   // the c the diagnosis fitted to the student's answers, as in `right`
        std::optional<double> c;
        probes::modelAnswers(run.probes, run.given, probes::ReplayModel{}, &c);
        if (c) scene.restitution = *c;
    }
    const QString name = QString::fromStdString(pr.name);
    scene.name = tr("Probe %1: your simulator beside the workbook's").arg(name).toStdString();
    scene.description = pr.purpose;

    std::vector<StudentValue> values;
    for (const probes::QuantityDifference& q : probes::answerDifferences(pr, right[p], run.given[p])) {
        values.push_back({q.step, q.body, traceIdOf(q.quantity), q.given, q.expected, q.largest, q.tolerance, q.differs});
    }
    const std::optional<probes::Divergence>& d =
        p < run.diagnosis.probes.size() ? run.diagnosis.probes[p].divergence : std::optional<probes::Divergence>();

    QString text = tr("# Probe %1: your simulator beside the workbook's\n\n%2\n\n"
                      "The **Yours** column of the quantities table shows what your program printed (`%3`) for "
                      "x, v, ω and r of each body after each step, beside the workbook's After: red where it differs "
                      "(its tooltip gives both numbers and the difference), green where it agrees. Step through the "
                      "probe (S) or drag the history slider.\n\n")
                       .arg(name, QString::fromStdString(pr.purpose), run.source);
    QString detail;
    if (d) {
        detail = tr("Body %1, %2: the workbook's %3, yours %4")
                     .arg(d->body)
                     .arg(QString::fromStdString(d->quantity), numbers(d->expected), numbers(d->given));
        text += tr("**First divergence:** %1 (n = %2): %3. The red mark on the history slider is there.\n")
                    .arg(steps::stateName(d->step))
                    .arg(d->step)
                    .arg(detail);
    } else {
        text += tr("Every answer of this probe agrees with the workbook's.\n");
    }
    lessons_->openProbe(scene, QString::fromStdString(scene.name), text);
    name_ = name;
    table_->setStudentValues(std::move(values), run.source);
    if (d) scrubber_->setDivergenceMark(d->step, detail);
    else scrubber_->clearDivergenceMark();
    return true;
}

void ProbeInWindow::onSceneStarted(const SceneDef&, const StartedScene& info)
{
    if (info.origin != SceneOrigin::Probe) close();
}

void ProbeInWindow::close()
{
    if (!isOpen()) return;
    name_.clear();
    table_->clearStudentValues();
    scrubber_->clearDivergenceMark();
}

} // namespace rbw
