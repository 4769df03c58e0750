// Compare with my simulator → Open in the main window (issue 23, item 5): the shipped
// reference simulator (examples/simulator/, target rbw_reference_simulator) with one
// --mistake switched on is run from the Tools menu's dialog; the probe with the first
// divergence is opened in the main window. Then:
//   - the quantities table shows a "Yours" column, beside After;
//   - the window's world at the divergence is the workbook's answer there (the scene is
//     the probe the diagnosis replayed; for a collision probe, with the fitted c);
//   - at the first divergence's step n, the cell of its body and quantity holds the
//     student's numbers (the diagnosis's `given`, as the program printed them) and is
//     coloured as a wrong entry of Check my numbers (its tooltip says it differs);
//   - negative control: an earlier answer of the probe (by the definition of the first
//     divergence, every number before it agrees) is shown and not marked;
//   - every Yours cell fits its column (the table's own fitting, TraceView), and at
//     1366x768 After, Yours, Frame and Unit are on screen without scrolling sideways;
//   - the history slider carries the mark at n, worded by the one step numbering;
//   - loading a lesson removes the column and the mark.
#include "app/core/step_numbering.h"
#include "app/gui/panels/quantities/student_column.h"
#include "app/gui/panels/quantities/trace_view.h"
#include "app/gui/panels/simulator/simulator_dialog.h"
#include "app/gui/panels/simulator/simulator_result_view.h"
#include "app/gui/shell/history_scrubber.h"
#include "app/gui/shell/main_window.h"
#include "app/gui/shell/probe_in_window.h"
#include "physics/engine/world.h"
#include "physics/workbook/probes/probe_verdict.h"
#include "tests/app/gui/shell/window_test_support.h"

#include <QAction>
#include <QHeaderView>
#include <QPushButton>
#include <QScrollBar>
#include <QSlider>
#include <QtTest>

#include <cmath>

using namespace rbw;

namespace {

const QString kReference = QStringLiteral(RBW_REFERENCE_SIMULATOR_PATH);
constexpr int kRunMs = 120000;

QString traceIdOf(const std::string& quantity)
{
    if (quantity == "x") return QStringLiteral("position");
    if (quantity == "v") return QStringLiteral("linear_velocity");
    if (quantity == "omega") return QStringLiteral("angular_velocity");
    return QStringLiteral("orientation");
}

// The row the Yours column uses for body `body`'s `id`: the last row of that id under
// the body's group (the state after the step), found by walking the tree.
QModelIndex stateRow(const QAbstractItemModel* model, const QString& id, int body)
{
    QModelIndex found;
    std::function<void(const QModelIndex&)> visit = [&](const QModelIndex& parent) {
        for (int r = 0; r < model->rowCount(parent); ++r) {
            const QModelIndex i = model->index(r, 0, parent);
            if (model->rowCount(i) > 0) {
                visit(i);
                continue;
            }
            const TraceEntry* e = static_cast<const TraceModel*>(model)->entryAt(i);
            if (e != nullptr && e->body == body && QString::fromLatin1(e->info->id) == id) found = i;
        }
    };
    visit(QModelIndex());
    return found;
}

// Where a quantity starts in a `state` line: x, v, ω, r at 0, 3, 6, 9.
size_t firstNumberOf(const std::string& quantity)
{
    if (quantity == "x") return 0;
    if (quantity == "v") return 3;
    if (quantity == "omega") return 6;
    return 9;
}

QString numbers(const std::vector<double>& values)
{
    QStringList parts;
    for (double v : values) parts << QString::number(v, 'g', 9);
    return '(' + parts.join(", ") + ')';
}

void goTo(MainWindow& w, long n)
{
    w.goToStep(n);
    QTRY_COMPARE_WITH_TIMEOUT(w.world()->stepIndex(), n, 20000);
    QTRY_VERIFY(!w.session()->busy());
    w.setPlaying(false);   // paused: the table catches up with the state
    QApplication::processEvents();
}

} // namespace

class TestProbeInWindow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void yoursColumnAndMark_data();
    void yoursColumnAndMark();
};

void TestProbeInWindow::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QVERIFY2(QFile::exists(kReference), qPrintable(kReference));
}

void TestProbeInWindow::yoursColumnAndMark_data()
{
    QTest::addColumn<QString>("options");   // the reference simulator's
    QTest::addColumn<QString>("group");     // the dialog's probe group
    QTest::newRow("transposed-inertia") << "--mistake transposed-inertia" << "motion";
    QTest::newRow("lever-arm-from-origin") << "--mistake lever-arm-from-origin" << "motion";
    // A collision probe: the scene's c is the one fitted to the student's answers.
    QTest::newRow("impulse-linear-only, c = 0.35") << "--restitution 0.35 --mistake impulse-linear-only" << "collision";
}

void TestProbeInWindow::yoursColumnAndMark()
{
    QFETCH(QString, options);
    QFETCH(QString, group);
    MainWindow w;
    w.resize(1366, 740);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("01-one-step"));
    auto* view = w.findChild<TraceView*>("traceView");
    QVERIFY(view != nullptr);
    QVERIFY(view->isColumnHidden(TraceModel::YoursColumn));   // no student's numbers yet

    w.findChild<QAction*>("actionCompareSimulator")->trigger();
    auto* dialog = w.findChild<SimulatorDialog*>();
    QVERIFY(dialog != nullptr);
    auto* open = dialog->findChild<QPushButton*>("openInMainWindowButton");
    QVERIFY(open != nullptr);
    QVERIFY(!open->isEnabled());   // nothing diagnosed yet
    dialog->setCommand(kReference + " " + options);
    dialog->setProbeGroup(probes::probeGroupNamed(group.toStdString()));
    QSignalSpy done(dialog, &SimulatorDialog::checkFinished);
    QVERIFY(dialog->run());
    QVERIFY(done.wait(kRunMs));
    const DiagnoseRun& run = dialog->outcome().run;
    QVERIFY2(run.failure.isEmpty(), qPrintable(run.failure));
    QVERIFY(run.diagnosis.firstDivergence.has_value());
    const int probe = run.diagnosis.divergenceProbe;
    QVERIFY(probe >= 0);
    const probes::Divergence d = *run.diagnosis.firstDivergence;
    QVERIFY(open->isEnabled());

    dialog->resultView()->selectProbe(probe);
    QVERIFY(dialog->isVisible());
    open->click();
    QVERIFY(w.probeInWindow()->isOpen());
    // The dialog steps aside: it would otherwise stay on top of the window it opened the probe in.
    QVERIFY(!dialog->isVisible());
    QCOMPARE(w.probeInWindow()->probeName(), QString::fromStdString(run.probes[size_t(probe)].name));
    const TraceModel* model = w.traceModel();
    QVERIFY(!view->isColumnHidden(TraceModel::YoursColumn));
    QCOMPARE(model->headerData(TraceModel::YoursColumn, Qt::Horizontal).toString(), QStringLiteral("Yours"));
    // Beside After.
    QCOMPARE(view->header()->visualIndex(TraceModel::YoursColumn), view->header()->visualIndex(TraceModel::ValueColumn) + 1);

    // The cell at the first divergence: the student's numbers, marked.
    goTo(w, d.step);
    if (QTest::currentTestFailed()) return;
    const QModelIndex row = stateRow(model, traceIdOf(d.quantity), d.body);
    QVERIFY2(row.isValid(), d.quantity.c_str());
    const QModelIndex cell = row.siblingAtColumn(TraceModel::YoursColumn);
    QVERIFY(!cell.data().toString().isEmpty());
    const QString tip = cell.data(Qt::ToolTipRole).toString();
    QVERIFY2(tip.contains(numbers(d.given)), qPrintable(tip + " / " + numbers(d.given)));
    QVERIFY2(tip.contains(QStringLiteral("Differs")), qPrintable(tip));
    QCOMPARE(cell.data(Qt::BackgroundRole).value<QBrush>().color(), StudentColumn::differColour());
    // The student's numbers as the program printed them: the answer itself.
    const probes::Answer& given = run.given[size_t(probe)][size_t(d.answer)];
    QCOMPARE(d.given.front(), given[firstNumberOf(d.quantity)]);

    // The scene in the window is the probe the diagnosis replayed: its state at n is the
    // workbook's answer beside which the student's differs (the engine and the replay
    // agree, tst_probes; a collision probe with the c fitted to the student's answers).
    {
        const BodyState& state = w.world()->states()[size_t(d.body)];
        std::vector<double> engine;
        if (d.quantity == "x") engine = {state.x_W.x(), state.x_W.y(), state.x_W.z()};
        else if (d.quantity == "v") engine = {state.v_W.x(), state.v_W.y(), state.v_W.z()};
        else if (d.quantity == "omega") engine = {state.omega_W.x(), state.omega_W.y(), state.omega_W.z()};
        else engine = {state.q_WB.w(), state.q_WB.x(), state.q_WB.y(), state.q_WB.z()};
        QCOMPARE(engine.size(), d.expected.size());
        for (size_t i = 0; i < engine.size(); ++i) {
            QVERIFY2(std::abs(engine[i] - d.expected[i]) <= d.tolerance,
                     qPrintable(QStringLiteral("%1[%2]: engine %3, workbook %4").arg(QString::fromStdString(d.quantity)).arg(i)
                                    .arg(engine[i], 0, 'g', 10).arg(d.expected[i], 0, 'g', 10)));
        }
    }

    // Every Yours cell fits its column.
    std::function<void(const QModelIndex&)> fits = [&](const QModelIndex& parent) {
        for (int r = 0; r < model->rowCount(parent); ++r) {
            const QModelIndex i = model->index(r, TraceModel::YoursColumn, parent);
            QVERIFY2(view->cellWidth(i) <= view->columnWidth(TraceModel::YoursColumn), qPrintable(i.data().toString()));
            fits(model->index(r, 0, parent));
        }
    };
    fits(QModelIndex());
    // ... and at 1366x768 After, Yours, Frame and Unit are on screen side by side: the
    // table does not scroll sideways (Before gives way where they would not all fit).
    QCOMPARE(view->horizontalScrollBar()->maximum(), 0);
    for (int c : {int(TraceModel::ValueColumn), int(TraceModel::YoursColumn), int(TraceModel::FrameColumn),
                  int(TraceModel::UnitColumn)}) {
        QVERIFY(!view->isColumnHidden(c));
        QVERIFY2(view->columnViewportPosition(c) + view->columnWidth(c) <= view->viewport()->width(), qPrintable(QString::number(c)));
    }

    // Negative control: before the first divergence nothing is marked. An earlier answer
    // of the probe (its step and body), or else the same answer's earlier quantity.
    const std::vector<probes::AnswerSlot> answerSlots = probes::answerSlots(run.probes[size_t(probe)]);
    static const std::string kPosition = "x";
    const bool sameAnswer = d.answer == 0;   // then x, read before v, ω and r
    const long controlStep = sameAnswer ? (d.quantity != kPosition ? d.step : -1) : answerSlots[size_t(d.answer - 1)].step;
    const int controlBody = sameAnswer ? d.body : answerSlots[size_t(d.answer - 1)].body;
    const std::string& controlQuantity = sameAnswer ? kPosition : d.quantity;
    QVERIFY2(controlStep >= 0, "no earlier number to control with");
    qInfo("first divergence: probe %d, answer %d (n = %d, body %d, %s); control: n = %ld, body %d, %s", probe, d.answer,
          d.step, d.body, d.quantity.c_str(), controlStep, controlBody, controlQuantity.c_str());
    goTo(w, controlStep);
    if (QTest::currentTestFailed()) return;
    const QModelIndex before = stateRow(model, traceIdOf(controlQuantity), controlBody).siblingAtColumn(TraceModel::YoursColumn);
    QVERIFY(!before.data().toString().isEmpty());
    QCOMPARE(before.data(Qt::BackgroundRole).value<QBrush>().color(), StudentColumn::agreeColour());
    QVERIFY(before.data(Qt::ToolTipRole).toString().contains(QStringLiteral("Agrees")));

    // The slider's mark at n, in the one step numbering.
    HistoryScrubber* scrubber = w.historyScrubber();
    QCOMPARE(scrubber->divergenceMark(), long(d.step));
    QVERIFY(scrubber->divergenceButton()->isVisible());
    QVERIFY2(scrubber->divergenceButton()->text().contains(steps::stateName(d.step)),
             qPrintable(scrubber->divergenceButton()->text()));
    QVERIFY(scrubber->slider()->toolTip().contains(steps::stateName(d.step)));
    scrubber->divergenceButton()->click();   // goes there
    QTRY_COMPARE(w.world()->stepIndex(), long(d.step));

    // Another lesson: the probe closes, the column and the mark go.
    QVERIFY(w.openLesson("02-single-body"));
    QVERIFY(!w.probeInWindow()->isOpen());
    QVERIFY(!model->hasStudentValues());
    QVERIFY(view->isColumnHidden(TraceModel::YoursColumn));
    QCOMPARE(scrubber->divergenceMark(), -1L);
    QVERIFY(!scrubber->divergenceButton()->isVisible());
    dialog->close();
}

RBW_WINDOW_TEST_MAIN(TestProbeInWindow)

#include "tst_probe_in_window.moc"
