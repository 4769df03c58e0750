// Steps off the GUI thread (Session::startRun, app/core/step_run.h; issue 22 item 4):
// a run records exactly what step() records, bit for bit; a heavy step leaves the
// session busy and the event loop free; Cancel leaves the world at the last finished
// step (its WorldSnapshot, bitwise) and the abandoned result is never taken, even when
// its thread finishes later; the pushes queued for a cancelled run wait for the next;
// every change of the world or its parameters cancels a run first. A run "that has
// not finished" is made certain with StepRun::HoldForTest.
#include "app/core/session.h"
#include "tests/test_support.h"

#include <QSignalSpy>

#include <functional>
#include <QtTest>

using namespace rbw;
using rbw::test::boxDef;
using rbw::test::lessonScene;

Q_DECLARE_METATYPE(rbw::StepTrace)

namespace {

bool sameSnapshot(const WorldSnapshot& a, const WorldSnapshot& b)
{
    if (a.stepIndex != b.stepIndex || a.time != b.time || a.states.size() != b.states.size()) return false;
    for (std::size_t i = 0; i < a.states.size(); ++i) {
        const BodyState& x = a.states[i];
        const BodyState& y = b.states[i];
        if (x.x_W != y.x_W || x.v_W != y.v_W || x.q_WB.coeffs() != y.q_WB.coeffs() || x.L_W != y.L_W ||
            x.R_WB != y.R_WB || x.Iinv_W != y.Iinv_W || x.omega_W != y.omega_W) {
            return false;
        }
    }
    return a.torqueEnabled == b.torqueEnabled && a.status.ok == b.status.ok;
}

// Issue 22's freeze: n boxes in one place, manifold model, on a ground plane. Every
// pair overlaps, so one step does n² work (n = 300: 1.4 s before the piles
// were capped; whatever it costs, the tests below do not depend on how long it takes,
// only the first waits 0 ms for it).
// n = 60: the manifold model's work limits (physics/engine/manifold/work_limits.h) stop
// a step whose broad phase finds more than 32 n + 128 pairs; n coincident boxes have
// n (n - 1) / 2 pairs, within the limit up to n = 68, so 60 boxes step in full.
constexpr int kPile = 60;

SceneDef coincidentPile(int n)
{
    SceneDef s;
    s.name = "pile";
    s.dt = 1.0 / 60.0;
    s.steps = 10;
    s.integrator = "symplectic-euler";
    s.g_W = Vec3(0.0, -9.81, 0.0);
    s.contactModel = ContactModel::Manifold;
    for (int i = 0; i < n; ++i) {
        const QByteArray name = "b" + QByteArray::number(i);
        s.bodies.push_back(boxDef(name.constData(), Vec3(1.0, 1.0, 1.0), 1.0, Vec3(0.0, 0.6, 0.0)));
    }
    s.push.body = 0;   // a keyboard push on the first box
    s.push.bodyName = "b0";
    s.push.p_B = Vec3(0.5, 0.0, 0.0);
    s.push.magnitude = 5.0;
    PlaneDef ground;
    ground.name = "ground";
    ground.n_W = Vec3(0.0, 1.0, 0.0);
    s.planes.push_back(ground);
    return s;
}

} // namespace

class TestSessionRun : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { qRegisterMetaType<rbw::StepTrace>(); }
    void cleanupTestCase() { QVERIFY(StepRun::waitForAll(120000)); }

    void runRecordsWhatStepRecords_data();
    void runRecordsWhatStepRecords();
    void runningStepLeavesTheEventLoopFree();
    void cancelLeavesTheLastFinishedStep();
    void cancelledRunKeepsItsPushes();
    void everyChangeCancelsTheRun();
    void goToRecordsWhatGoToStepRecords();
    void goToOnAPileLeavesTheEventLoopFree();
    void goToCancelledIsNeverFinished();
};

void TestSessionRun::runRecordsWhatStepRecords_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<int>("steps");
    QTest::newRow("lesson 1, one step") << "01-one-step/scene.json" << 1;
    QTest::newRow("lesson 4, 20 steps (collisions)") << "04-many-boxes/scene.json" << 20;
    QTest::newRow("lesson 11, 30 steps (manifold warm start)") << "11-resting-contact/scene.json" << 30;
}

void TestSessionRun::runRecordsWhatStepRecords()
{
    QFETCH(QString, scene);
    QFETCH(int, steps);
    const SceneDef def = lessonScene(scene);
    Session direct;
    direct.load(def);
    for (int i = 0; i < steps; ++i) QVERIFY(direct.step());

    Session threaded;
    threaded.load(def);
    QSignalSpy recorded(&threaded, &Session::stepRecorded);
    QSignalSpy finished(&threaded, &Session::runFinished);
    // No budget, a generous wait: the run finishes within it and is recorded at once.
    QCOMPARE(threaded.startRun(steps, 0.0, 60000), Session::RunStart::Finished);
    QVERIFY(!threaded.busy());
    QCOMPARE(recorded.count(), steps);
    QCOMPARE(finished.count(), 1);
    QCOMPARE(finished.first().first().toInt(), steps);
    QCOMPARE(threaded.world()->stepIndex(), long(steps));
    QVERIFY(sameSnapshot(threaded.world()->snapshot(), direct.world()->snapshot()));
    QCOMPARE(threaded.history().size(), direct.history().size());
    // Every recorded step's state, bitwise, and the current trace's diagnostics.
    for (std::size_t i = 0; i < direct.history().size(); ++i) {
        QVERIFY2(sameSnapshot(threaded.history().at(i).state, direct.history().at(i).state), qPrintable(QString::number(i)));
    }
    QCOMPARE(threaded.currentTrace()->diagnostics.total, direct.currentTrace()->diagnostics.total);
    // Step back works on the run's history as on step()'s.
    QVERIFY(threaded.stepBack());
    QVERIFY(direct.stepBack());
    QVERIFY(sameSnapshot(threaded.world()->snapshot(), direct.world()->snapshot()));
}

void TestSessionRun::runningStepLeavesTheEventLoopFree()
{
    Session session;
    session.load(coincidentPile(kPile));
    const WorldSnapshot before = session.world()->snapshot();
    QSignalSpy busy(&session, &Session::busyChanged);
    QSignalSpy finished(&session, &Session::runFinished);
    {
        const StepRun::HoldForTest hold;   // the step cannot finish while it lives
        QCOMPARE(session.startRun(1, 0.0, 50), Session::RunStart::Running);
        QVERIFY(session.busy());
        QCOMPARE(busy.count(), 1);
        QCOMPARE(busy.first().first().toBool(), true);
        // While it computes, the world is the last finished step and a second run is refused.
        QVERIFY(sameSnapshot(session.world()->snapshot(), before));
        QCOMPARE(session.startRun(1, 0.0, 0), Session::RunStart::Refused);
        // The event loop turns meanwhile (a timer fires).
        bool timerFired = false;
        QTimer::singleShot(0, &session, [&] { timerFired = true; });
        QTRY_VERIFY_WITH_TIMEOUT(timerFired, 5000);
        QVERIFY(session.busy());
        QCOMPARE(finished.count(), 0);
    }
    // The step is recorded from the event loop when it finishes.
    QTRY_VERIFY_WITH_TIMEOUT(!session.busy(), 120000);
    QCOMPARE(finished.count(), 1);
    QCOMPARE(session.world()->stepIndex(), 1L);
    QCOMPARE(session.history().lastStep(), 1L);

    // The same step taken directly: bit for bit what the thread computed.
    Session direct;
    direct.load(coincidentPile(kPile));
    QVERIFY(direct.step());
    QVERIFY(sameSnapshot(session.world()->snapshot(), direct.world()->snapshot()));
}

void TestSessionRun::cancelLeavesTheLastFinishedStep()
{
    Session session;
    session.load(coincidentPile(kPile));
    QVERIFY(session.step());   // step 1 finished (directly)
    const WorldSnapshot atOne = session.world()->snapshot();
    QSignalSpy recorded(&session, &Session::stepRecorded);
    QSignalSpy changed(&session, &Session::stateChanged);
    {
        const StepRun::HoldForTest hold;
        QCOMPARE(session.startRun(5, 0.0, 0), Session::RunStart::Running);
        session.cancelRun();
        QVERIFY(!session.busy());
        QVERIFY(sameSnapshot(session.world()->snapshot(), atOne));
    }
    // The abandoned thread finishes its step alone; its result is never taken.
    QVERIFY(StepRun::waitForAll(120000));
    QCoreApplication::processEvents();
    QCoreApplication::processEvents();
    QCOMPARE(recorded.count(), 0);
    QCOMPARE(changed.count(), 0);
    QVERIFY(sameSnapshot(session.world()->snapshot(), atOne));
    QCOMPARE(session.history().lastStep(), 1L);
    QCOMPARE(session.currentTrace()->step, 0L);   // the trace of step k = 0, which led to state 1
    // And stepping on from there is the same step as without the cancelled run.
    QVERIFY(session.step());
    Session direct;
    direct.load(coincidentPile(kPile));
    QVERIFY(direct.step());
    QVERIFY(direct.step());
    QVERIFY(sameSnapshot(session.world()->snapshot(), direct.world()->snapshot()));
}

void TestSessionRun::cancelledRunKeepsItsPushes()
{
    // A push queued before a cancelled run acts in the next step that is taken, not in
    // the dropped one: the same state as a push and one step without the run.
    const SceneDef def = coincidentPile(kPile);
    Session session;
    session.load(def);
    QVERIFY(session.push(Vec3(1.0, 0.0, 0.0)));
    {
        const StepRun::HoldForTest hold;
        QCOMPARE(session.startRun(1, 0.0, 0), Session::RunStart::Running);
        session.cancelRun();
    }
    QCOMPARE(session.world()->stepIndex(), 0L);
    QCOMPARE(session.pendingPushes().size(), std::size_t(1));
    QVERIFY(session.step());
    QVERIFY(session.pendingPushes().empty());
    Session direct;
    direct.load(def);
    QVERIFY(direct.push(Vec3(1.0, 0.0, 0.0)));
    QVERIFY(direct.step());
    QVERIFY(sameSnapshot(session.world()->snapshot(), direct.world()->snapshot()));
    // Negative control: without the push the step differs.
    Session without;
    without.load(def);
    QVERIFY(without.step());
    QVERIFY(!sameSnapshot(session.world()->snapshot(), without.world()->snapshot()));
}

void TestSessionRun::everyChangeCancelsTheRun()
{
    Session session;
    session.load(coincidentPile(kPile));
    {
        const StepRun::HoldForTest hold;
        QCOMPARE(session.startRun(1, 0.0, 0), Session::RunStart::Running);
        // A parameter change (a new branch) drops the run first: no step of the old
        // parameters is recorded after it.
        QVERIFY(session.setDt(1.0 / 120.0));
        QVERIFY(!session.busy());
    }
    QVERIFY(StepRun::waitForAll(120000));
    QCoreApplication::processEvents();
    QCOMPARE(session.world()->stepIndex(), 0L);
    QCOMPARE(session.world()->scene().dt, 1.0 / 120.0);
    // Each of these drops it too.
    const std::vector<std::pair<const char*, std::function<void()>>> changes = {
        {"reset", [&] { session.reset(); }},
        {"step back", [&] { session.stepBack(); }},
        {"go to step 0", [&] { session.goToStep(0); }},
        {"a direct step", [&] { QVERIFY(session.step()); }},
        {"the integrator", [&] { QVERIFY(session.setIntegrator("explicit-euler")); }},
    };
    for (const auto& [what, change] : changes) {
        const long k = session.world()->stepIndex();
        {
            const StepRun::HoldForTest hold;
            QCOMPARE(session.startRun(3, 0.0, 0), Session::RunStart::Running);
            change();
            QVERIFY2(!session.busy(), what);
        }
        QVERIFY(StepRun::waitForAll(120000));
        QCoreApplication::processEvents();
        // nothing of the dropped run: at most the direct step
        QVERIFY2(session.world()->stepIndex() <= k + 1, what);
        QCOMPARE(session.history().lastStep(), session.world()->stepIndex());
    }
}

// Go to a step beyond the recording, off the GUI thread (Session::startGoToStep):
// lesson 4, 600 steps with collisions, recorded exactly as goToStep(600) records them
// (every state bitwise, one stepRecorded per step), and goToFinished(600, true) once.
// A generous wait: it finishes within it, in slices, and is over on return.
void TestSessionRun::goToRecordsWhatGoToStepRecords()
{
    const SceneDef def = lessonScene("04-many-boxes/scene.json");
    Session direct;
    direct.load(def);
    QVERIFY(direct.goToStep(600));
    Session threaded;
    threaded.load(def);
    QSignalSpy recorded(&threaded, &Session::stepRecorded);
    QSignalSpy over(&threaded, &Session::goToFinished);
    QSignalSpy busy(&threaded, &Session::busyChanged);
    QCOMPARE(threaded.startGoToStep(600, 60000), Session::RunStart::Finished);
    QVERIFY(!threaded.busy());
    QCOMPARE(busy.count(), 0);   // over within the wait: the busy bar never showed
    QCOMPARE(over.count(), 1);
    QCOMPARE(over.first().at(0).toLongLong(), 600LL);
    QCOMPARE(over.first().at(1).toBool(), true);
    QCOMPARE(recorded.count(), 600);
    QCOMPARE(threaded.goToTarget(), -1L);
    QCOMPARE(threaded.history().size(), direct.history().size());
    for (std::size_t i = 0; i < direct.history().size(); ++i) {
        QVERIFY2(sameSnapshot(threaded.history().at(i).state, direct.history().at(i).state), qPrintable(QString::number(i)));
    }
    // Back into the recording: restored at once, no run, goToFinished all the same.
    QCOMPARE(threaded.startGoToStep(250, 0), Session::RunStart::Finished);
    QCOMPARE(threaded.world()->stepIndex(), 250L);
    QCOMPARE(over.count(), 2);
    QCOMPARE(recorded.count(), 600);
    // The limit of new steps: stops there, not reached (the world at the last step taken).
    QCOMPARE(threaded.startGoToStep(5000, 60000, 50), Session::RunStart::Finished);
    QCOMPARE(over.count(), 3);
    QCOMPARE(over.last().at(1).toBool(), false);
    QCOMPARE(threaded.world()->stepIndex(), 650L);   // 600 recorded, then 50 new
    QCOMPARE(threaded.history().lastStep(), 650L);
}

// The heavy pile: Go to step 3 with the first step held, so it certainly runs. The
// session is busy, says where it goes, the event loop turns; released, the steps are
// recorded from the event loop, the same as three direct steps, bit for bit.
void TestSessionRun::goToOnAPileLeavesTheEventLoopFree()
{
    Session session;
    session.load(coincidentPile(kPile));
    QSignalSpy over(&session, &Session::goToFinished);
    QSignalSpy busy(&session, &Session::busyChanged);
    {
        const StepRun::HoldForTest hold;
        QCOMPARE(session.startGoToStep(3, 0), Session::RunStart::Running);
        QVERIFY(session.busy());
        QCOMPARE(session.goToTarget(), 3L);
        QCOMPARE(session.startRun(1, 0.0, 0), Session::RunStart::Refused);   // one run at a time
        bool timerFired = false;
        QTimer::singleShot(0, &session, [&] { timerFired = true; });
        QTRY_VERIFY_WITH_TIMEOUT(timerFired, 5000);
        QCOMPARE(over.count(), 0);
        QCOMPARE(session.world()->stepIndex(), 0L);
    }
    QTRY_VERIFY_WITH_TIMEOUT(!session.busy(), 120000);
    QCOMPARE(over.count(), 1);
    QCOMPARE(over.first().at(1).toBool(), true);
    // busy once, idle once: the slices in between never hid the bar
    QCOMPARE(busy.count(), 2);
    QCOMPARE(session.world()->stepIndex(), 3L);
    QCOMPARE(session.history().lastStep(), 3L);
    Session direct;
    direct.load(coincidentPile(kPile));
    for (int i = 0; i < 3; ++i) QVERIFY(direct.step());
    for (std::size_t i = 0; i < direct.history().size(); ++i) {
        QVERIFY2(sameSnapshot(session.history().at(i).state, direct.history().at(i).state), qPrintable(QString::number(i)));
    }
}

// Cancel of a Go to: the world stays at the last finished step, goToFinished never
// comes (not even when the abandoned thread ends), and nothing more is recorded.
void TestSessionRun::goToCancelledIsNeverFinished()
{
    Session session;
    session.load(coincidentPile(kPile));
    QVERIFY(session.step());
    const WorldSnapshot atOne = session.world()->snapshot();
    QSignalSpy over(&session, &Session::goToFinished);
    QSignalSpy recorded(&session, &Session::stepRecorded);
    {
        const StepRun::HoldForTest hold;
        QCOMPARE(session.startGoToStep(50, 0), Session::RunStart::Running);
        session.cancelRun();
        QVERIFY(!session.busy());
        QCOMPARE(session.goToTarget(), -1L);
    }
    QVERIFY(StepRun::waitForAll(120000));
    QCoreApplication::processEvents();
    QCoreApplication::processEvents();
    QCOMPARE(over.count(), 0);
    QCOMPARE(recorded.count(), 0);
    QVERIFY(sameSnapshot(session.world()->snapshot(), atOne));
    QCOMPARE(session.history().lastStep(), 1L);
}

QTEST_GUILESS_MAIN(TestSessionRun)
#include "tst_session_run.moc"
