// The app stays responsive on a heavy step (issue 22, item 4): issue 22's freeze was
// one Step on a pile of coincident boxes in the manifold model (n² work in one step)
// with the window frozen and Ctrl+Q ignored. Now the step runs off the GUI thread
// (Session::startRun) and, here:
//  - Step on a pile shows the busy bar, the window answers (a timer fires, the
//    history syncs, a second Step says it is still computing), and Cancel leaves the
//    world exactly at the last finished step, also after the abandoned run has ended;
//  - Play, then Cancel while a run computes: playing stops, the world is at the step
//    shown when Cancel was clicked, the history's current entry, bit for bit;
//  - Quit (the Quit action, Ctrl+Q) while a step computes closes the window at once:
//    the step's thread is still held when the window is gone;
//  - a step that is not cancelled is recorded when it finishes, the same numbers as
//    the session's own step().
// A step "that has not finished" is made certain with StepRun::HoldForTest (every run
// waits before its first step while it lives) and the busy bar's waits set to 0 ms,
// whatever the machine's speed: one step of a 200-box pile takes about 0.25 s here.
#include "app/core/step_numbering.h"
#include "app/gui/shell/history_scrubber.h"
#include "app/gui/shell/main_window.h"
#include "app/gui/shell/run_busy_bar.h"
#include "tests/app/gui/shell/window_test_support.h"
#include "tests/support/pile_scene.h"

#include <QAction>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <optional>

using namespace rbw;

namespace {

// n unit boxes in one place (0.1 m into the air), on a ground plane, in the manifold model.
QString writePile(const QString& path, int n)
{
    const QJsonObject scene =
        rbw::test::pileScene({.boxes = n, .y = 0.6, .dt = 1.0 / 60.0, .steps = 60, .boxPrefix = QStringLiteral("b")});
    QFile out(path);
    if (!out.open(QIODevice::WriteOnly | QIODevice::Truncate)) return {};
    out.write(QJsonDocument(scene).toJson(QJsonDocument::Compact));
    return path;
}

bool sameSnapshot(const WorldSnapshot& a, const WorldSnapshot& b)
{
    if (a.stepIndex != b.stepIndex || a.time != b.time || a.states.size() != b.states.size()) return false;
    for (std::size_t i = 0; i < a.states.size(); ++i) {
        if (a.states[i].x_W != b.states[i].x_W || a.states[i].v_W != b.states[i].v_W ||
            a.states[i].q_WB.coeffs() != b.states[i].q_WB.coeffs() || a.states[i].L_W != b.states[i].L_W) {
            return false;
        }
    }
    return true;
}

constexpr int kPile = 200;
// Within the manifold model's work limits (32 n + 128 pairs: up to 68 coincident
// boxes), so it steps on and on, each step heavy.
constexpr int kSteppingPile = 60;

} // namespace

class TestResponsive : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
        QVERIFY(dir_.isValid());
        QVERIFY(!writePile(dir_.filePath("pile.json"), kPile).isEmpty());
        QVERIFY(!writePile(dir_.filePath("pile60.json"), kSteppingPile).isEmpty());
    }
    void cleanupTestCase() { QVERIFY(StepRun::waitForAll(120000)); }

    void stepThenCancel();
    void playThenCancel();
    void quitDuringAStep();
    void aStepNotCancelledIsRecorded();
    void goToAFarStepThenCancel();

private:
    // A window on a scene file whose runs never wait (see the top).
    void open(MainWindow& w, const QString& scene)
    {
        w.resize(1366, 768);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.openSceneFile(scene));
        w.runBusyBar()->setWaitMs(0, 0);
    }

    QTemporaryDir dir_;
};

void TestResponsive::stepThenCancel()
{
    MainWindow w;
    open(w, dir_.filePath("pile.json"));
    const WorldSnapshot start = w.world()->snapshot();
    {
        const StepRun::HoldForTest hold;
        w.findChild<QAction*>("actionStep")->trigger();
        QVERIFY(w.session()->busy());
        QVERIFY(w.runBusyBar()->isVisible());
        QVERIFY2(w.runBusyBar()->label()->text().contains("Computing the next step"),
                 qPrintable(w.runBusyBar()->label()->text()));
        // The window answers: a timer fires; the history shows the last finished step.
        bool answered = false;
        QTimer::singleShot(0, &w, [&] { answered = true; });
        QTRY_VERIFY_WITH_TIMEOUT(answered, 3000);
        QVERIFY(w.session()->busy());
        w.historyScrubber()->sync();
        QCOMPARE(w.historyScrubber()->label()->text(), QStringLiteral("before step k = 0 · 0 of 0 steps"));
        // A second Step while it computes is not queued: it says so.
        w.findChild<QAction*>("actionStep")->trigger();
        QVERIFY(w.statusBar()->currentMessage().contains("Still computing"));

        QTest::mouseClick(w.runBusyBar()->cancelButton(), Qt::LeftButton);
        QVERIFY(!w.session()->busy());
        QVERIFY(!w.runBusyBar()->isVisible());
        QVERIFY(sameSnapshot(w.world()->snapshot(), start));
        QVERIFY2(w.statusBar()->currentMessage().contains("Cancelled: the scene is at step 0"),
                 qPrintable(w.statusBar()->currentMessage()));
    }
    // The abandoned run ends and is dropped.
    QVERIFY(StepRun::waitForAll(120000));
    QTest::qWait(50);
    QVERIFY(sameSnapshot(w.world()->snapshot(), start));
    QCOMPARE(w.session()->history().size(), std::size_t(1));
    QVERIFY(w.session()->currentTrace() == nullptr);
}

void TestResponsive::playThenCancel()
{
    MainWindow w;
    open(w, QStringLiteral(RBW_SOURCE_DIR "/lessons/04-many-boxes/scene.json"));
    // Cancel when the third run of Play starts computing (two have been recorded by
    // then), clicked as the student would: the run is certainly unfinished then.
    int runs = 0;
    long stepAtCancel = -1;
    connect(w.session(), &Session::busyChanged, &w, [&](bool busy) {
        if (!busy || ++runs != 3) return;
        QVERIFY(w.runBusyBar()->isVisible());
        stepAtCancel = w.world()->stepIndex();
        QTest::mouseClick(w.runBusyBar()->cancelButton(), Qt::LeftButton);
    });
    w.findChild<QAction*>("actionPlay")->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(runs >= 3, 60000);
    QVERIFY(!w.findChild<QAction*>("actionPlay")->isChecked());
    QVERIFY(!w.session()->busy());
    QVERIFY(stepAtCancel >= 2);   // at least one step from each of the two recorded runs
    QVERIFY(StepRun::waitForAll(120000));
    QTest::qWait(50);
    // A finished step: the one shown when Cancel was clicked, the history's current
    // entry, bit for bit, and nothing after it.
    const StepHistory& h = w.session()->history();
    QCOMPARE(w.world()->stepIndex(), stepAtCancel);
    QCOMPARE(h.lastStep(), stepAtCancel);
    QVERIFY(sameSnapshot(w.world()->snapshot(), h.current().state));
    QVERIFY(w.world()->status().ok);
}

void TestResponsive::quitDuringAStep()
{
    MainWindow w;
    open(w, dir_.filePath("pile.json"));
    {
        const StepRun::HoldForTest hold;
        w.findChild<QAction*>("actionStep")->trigger();
        QVERIFY(w.session()->busy());
        w.findChild<QAction*>("actionQuit")->trigger();   // Ctrl+Q
        // Closed while the step's thread is held: Quit did not wait for it (had it
        // waited, this line would never come).
        QVERIFY(!w.isVisible());
        QVERIFY(!w.session()->busy());
        QCOMPARE(StepRun::running(), 1);
        QCOMPARE(w.world()->stepIndex(), 0L);
    }
    QVERIFY(StepRun::waitForAll(120000));
}

void TestResponsive::aStepNotCancelledIsRecorded()
{
    MainWindow w;
    open(w, QStringLiteral(RBW_SOURCE_DIR "/lessons/04-many-boxes/scene.json"));
    QSignalSpy finished(w.session(), &Session::runFinished);
    {
        const StepRun::HoldForTest hold;
        w.findChild<QAction*>("actionStep")->trigger();
        QVERIFY(w.session()->busy());
        QTest::qWait(100);
        QCOMPARE(w.world()->stepIndex(), 0L);   // nothing recorded while it computes
        QCOMPARE(finished.count(), 0);
    }
    QTRY_VERIFY_WITH_TIMEOUT(!w.session()->busy(), 120000);
    QCOMPARE(finished.count(), 1);
    QCOMPARE(w.world()->stepIndex(), 1L);
    QVERIFY(!w.runBusyBar()->isVisible());
    QCOMPARE(w.historyScrubber()->label()->text(), QStringLiteral("after step k = 0 · 1 of 1 steps"));
    // The numbers are the session's own step's.
    Session direct;
    direct.load(w.world()->scene());
    QVERIFY(direct.step());
    QVERIFY(sameSnapshot(w.world()->snapshot(), direct.world()->snapshot()));
    QCOMPARE(w.session()->currentTrace()->diagnostics.total, direct.currentTrace()->diagnostics.total);
}

// Go to a far step (beyond the recording) on a heavy pile: before issue 22's fix the
// window computed every step on the GUI thread and froze until the last. Now the busy
// bar says where it goes, the event loop answers while the steps come in (a timer
// fires; the history grows slice by slice and the scrubber shows it), Cancel stops it
// at the last finished step with the history consistent (its last step is the world's,
// bit for bit, and three direct steps from the same scene give the same state), and a
// Go to that is left alone arrives.
void TestResponsive::goToAFarStepThenCancel()
{
    MainWindow w;
    open(w, dir_.filePath("pile60.json"));
    QSignalSpy over(w.session(), &Session::goToFinished);
    HistoryScrubber* scrubber = w.historyScrubber();
    {
        const StepRun::HoldForTest hold;   // the first slice certainly runs
        scrubber->stepBox()->setValue(100000);
        QTest::mouseClick(scrubber->goButton(), Qt::LeftButton);
        QVERIFY(w.session()->busy());
        QVERIFY(w.runBusyBar()->isVisible());
        QVERIFY2(w.runBusyBar()->label()->text().startsWith("Going to step 100000"),
                 qPrintable(w.runBusyBar()->label()->text()));
        bool answered = false;
        QTimer::singleShot(0, &w, [&] { answered = true; });
        QTRY_VERIFY_WITH_TIMEOUT(answered, 3000);
        QCOMPARE(w.world()->stepIndex(), 0L);
    }
    // Released: the steps come in while the window answers. Once three steps are
    // recorded, the next slice is held (it waits before its first step), so Cancel
    // below certainly meets a run, whatever the machine's speed.
    std::optional<StepRun::HoldForTest> holdNext;
    connect(w.session(), &Session::runFinished, &w, [&] {
        if (!holdNext && w.world()->stepIndex() >= 3) holdNext.emplace();
    });
    QTRY_VERIFY_WITH_TIMEOUT(holdNext.has_value(), 120000);
    QVERIFY(w.session()->busy());   // the next slice started, held
    bool answered = false;
    QTimer::singleShot(0, &w, [&] { answered = true; });
    QTRY_VERIFY_WITH_TIMEOUT(answered, 3000);
    w.historyScrubber()->sync();
    // the slider shows the last recorded step, which is the world's (the label's words
    // come from app/core/step_numbering.h)
    const long shownNow = w.world()->stepIndex();
    const QString expectedLabel = QStringLiteral("%1 · %2 of %2 steps").arg(steps::stateName(shownNow)).arg(shownNow);
    QVERIFY2(scrubber->label()->text().startsWith(expectedLabel),
             qPrintable(scrubber->label()->text() + QStringLiteral(" does not start with ") + expectedLabel));
    QTest::mouseClick(w.runBusyBar()->cancelButton(), Qt::LeftButton);
    QVERIFY(!w.session()->busy());
    QVERIFY(!w.runBusyBar()->isVisible());
    const long k = w.world()->stepIndex();
    QVERIFY(k >= 3 && k < 100000);
    holdNext.reset();   // the abandoned slice computes alone now
    QVERIFY2(w.statusBar()->currentMessage().contains(QStringLiteral("Cancelled: the scene is at step %1").arg(k)),
             qPrintable(w.statusBar()->currentMessage()));
    QVERIFY(StepRun::waitForAll(120000));
    QTest::qWait(50);
    // Nothing of the abandoned slice, and no "not reached" note: it was cancelled.
    const StepHistory& h = w.session()->history();
    QCOMPARE(w.world()->stepIndex(), k);
    QCOMPARE(h.lastStep(), k);
    QVERIFY(sameSnapshot(w.world()->snapshot(), h.current().state));
    QCOMPARE(over.count(), 0);
    QVERIFY(!scrubber->note()->isVisible());
    // "(from n = …)" follows once the budget drops steps
    const QString expectedAtCancel = QStringLiteral("%1 · %2 of %2 steps").arg(steps::stateName(k)).arg(k);
    QVERIFY2(scrubber->label()->text().startsWith(expectedAtCancel),
             qPrintable(scrubber->label()->text() + QStringLiteral(" does not start with ") + expectedAtCancel));
    // The recorded steps are the session's own steps (the oldest kept one after step 3).
    const long s = std::max(3L, h.firstStep());
    Session direct;
    direct.load(w.world()->scene());
    for (long i = 0; i < s; ++i) QVERIFY(direct.step());
    QVERIFY(sameSnapshot(h.at(static_cast<std::size_t>(h.indexOfStep(s))).state, direct.world()->snapshot()));
    // Left alone, a Go to arrives (from the event loop, the bar gone after it).
    scrubber->stepBox()->setValue(static_cast<int>(k + 2));
    QTest::mouseClick(scrubber->goButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!w.session()->busy(), 120000);
    QCOMPARE(w.world()->stepIndex(), k + 2);
    QCOMPARE(over.count(), 1);
    QCOMPARE(over.first().at(1).toBool(), true);
    QVERIFY(!w.runBusyBar()->isVisible());
}

RBW_WINDOW_TEST_MAIN(TestResponsive)

#include "tst_responsive.moc"
