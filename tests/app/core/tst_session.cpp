// The session behind the app's controls: Step back restores the state and its trace
// exactly, the history keeps 1000 steps, parameter switches carry the state over,
// the mouse spring pulls the way it is dragged, a push and the K toggle act as
// documented, and a blow-up stops the run with a message instead of numbers.
#include "app/core/session.h"
#include "physics/engine/quantities.h"
#include "tests/test_support.h"

#include <QSignalSpy>
#include <QtTest>

using namespace rbw;
using rbw::test::lessonScene;

Q_DECLARE_METATYPE(rbw::StepTrace)

namespace {

// Bitwise equality of two body states (the primary state and the derived one).
bool sameState(const BodyState& a, const BodyState& b)
{
    return a.x_W == b.x_W && a.v_W == b.v_W && a.q_WB.coeffs() == b.q_WB.coeffs() && a.L_W == b.L_W &&
           a.R_WB == b.R_WB && a.Iinv_W == b.Iinv_W && a.omega_W == b.omega_W;
}

bool sameStates(const std::vector<BodyState>& a, const std::vector<BodyState>& b)
{
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        if (!sameState(a[i], b[i])) return false;
    }
    return true;
}

bool sameTrace(const StepTrace& a, const StepTrace& b)
{
    if (a.step != b.step || a.time != b.time || a.entries.size() != b.entries.size()) return false;
    for (size_t i = 0; i < a.entries.size(); ++i) {
        const TraceEntry& x = a.entries[i];
        const TraceEntry& y = b.entries[i];
        if (x.info != y.info || x.body != y.body || x.index != y.index) return false;
        if (rbw::test::flatten(x.value) != rbw::test::flatten(y.value)) return false;
        // The statement that computed the value travels with it through the history.
        if (sourceText(x) != sourceText(y)) return false;
    }
    // and the state the step started from (the table's Before column)
    if (a.start.bodies.size() != b.start.bodies.size() || a.start.probes.size() != b.start.probes.size()) return false;
    for (size_t i = 0; i < a.start.bodies.size(); ++i) {
        const BodyState& x = a.start.bodies[i];
        const BodyState& y = b.start.bodies[i];
        if (x.x_W != y.x_W || x.v_W != y.v_W || x.q_WB.coeffs() != y.q_WB.coeffs() || x.L_W != y.L_W ||
            x.R_WB != y.R_WB || x.Iinv_W != y.Iinv_W || x.omega_W != y.omega_W) {
            return false;
        }
    }
    for (size_t i = 0; i < a.start.probes.size(); ++i) {
        if (a.start.probes[i].p_W != b.start.probes[i].p_W || a.start.probes[i].v_W != b.start.probes[i].v_W) return false;
    }
    return a.diagnostics.total == b.diagnostics.total && a.diagnostics.P_W == b.diagnostics.P_W;
}

} // namespace

class TestSession : public QObject {
    Q_OBJECT
private slots:
    void stepBackRestoresExactly_data();
    void stepBackRestoresExactly();
    void historyKeeps1000Steps();
    void stepBackWithManyForces();
    void parameterSwitchKeepsState();
    void badParameterIsRefused();
    void parametersChangedOnlyForParameters();
    void dragPullsTowardsTarget_data();
    void dragPullsTowardsTarget();
    void pushActsForOneStep();
    void toggleTorques();
    void blowUpStopsTheRun();
    void advanceIsBounded();
    void goToStepIsExact_data();
    void goToStepIsExact();
    void steppingFromEarlierDiscardsLater();
    void goToStepLimits();
    void historyKeepsWithinItsByteBudget_data();
    void historyKeepsWithinItsByteBudget();
    void historyCountsTheWarmStartCache_data();
    void historyCountsTheWarmStartCache();
};

void TestSession::stepBackRestoresExactly_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::newRow("01 one step (h = 2)") << "01-one-step/scene.json";
    QTest::newRow("03 two-box collision") << "03-two-box-collision/scene.json";
    QTest::newRow("04 many boxes") << "04-many-boxes/scene.json";
    QTest::newRow("05 spinning") << "05-spinning/scene.json";
    QTest::newRow("07 bounce") << "07-bounce/scene.json";
}

void TestSession::stepBackRestoresExactly()
{
    QFETCH(QString, lesson);
    Session s;
    s.load(lessonScene(lesson));
    QSignalSpy rewound(&s, &Session::rewound);

    for (int k = 0; k < 9; ++k) QVERIFY(s.step());
    const std::vector<BodyState> after9 = s.world()->states();
    const StepTrace trace9 = *s.currentTrace();
    const double t9 = s.world()->time();
    QVERIFY(s.step());   // the 10th step
    QVERIFY(!sameStates(s.world()->states(), after9) || lesson.startsWith("01"));

    QVERIFY(s.stepBack());
    QCOMPARE(rewound.count(), 1);
    QCOMPARE(rewound.at(0).at(0).toLongLong(), 9LL);
    QVERIFY2(sameStates(s.world()->states(), after9), "state after step back differs from the state after step 9");
    QVERIFY2(sameTrace(*s.currentTrace(), trace9), "the trace shown after step back is not step 9's trace");
    QCOMPARE(s.world()->stepIndex(), 9L);
    QCOMPARE(s.world()->time(), t9);

    // Stepping forward again replays the same step bit for bit (determinism).
    QVERIFY(s.step());
    const std::vector<BodyState> again10 = s.world()->states();
    QVERIFY(s.stepBack());
    QVERIFY(s.step());
    QVERIFY(sameStates(s.world()->states(), again10));

    // Ten steps back reach the initial state, which has no trace; then no further.
    for (int k = 0; k < 10; ++k) QVERIFY(s.stepBack());
    QCOMPARE(s.world()->stepIndex(), 0L);
    QVERIFY(s.currentTrace() == nullptr);
    QVERIFY(!s.stepBack());
}

void TestSession::historyKeeps1000Steps()
{
    Session s;
    s.load(lessonScene("05-spinning/scene.json"));
    for (int k = 0; k < 1005; ++k) QVERIFY(s.step());
    QCOMPARE(s.history().stepsBackAvailable(), std::size_t(1000));
    int back = 0;
    while (s.stepBack()) ++back;
    QCOMPARE(back, 1000);
    QCOMPARE(s.world()->stepIndex(), 5L);   // the oldest kept state is after step 5
}

// The history packs each entry's index (which force, probe, contact) as wide as
// TraceEntry::index: a scene with more forces than an int16 holds (32 767) steps back
// to exactly the trace it recorded. 40 000 forces of f = (0.5, 0, 0) N through the
// centre of one box: F = 40 000 * 0.5 = 20 000 N exactly (sums of halves are exact),
// q = 0, and the trace has one applied_force row per force, index 0 ... 39 999.
void TestSession::stepBackWithManyForces()
{
    constexpr int kForces = 40000;
    SceneDef scene;
    scene.name = "many forces";
    scene.dt = 0.01;
    BodyDef box;
    box.name = "box";
    box.mass = 2.0;
    scene.bodies.push_back(box);
    for (int i = 0; i < kForces; ++i) {
        ForceDef f;
        f.body = 0;
        f.p_W = Vec3::Zero();
        f.f_W = Vec3(0.5, 0, 0);
        f.fromStep = 0;
        f.toStep = 1000;
        scene.forces.push_back(f);
    }
    QVERIFY(validate(scene).empty());
    Session s;
    s.load(scene);
    QVERIFY(s.step());
    QVERIFY(s.step());
    const StepTrace trace2 = *s.currentTrace();   // step k = 1
    const TraceEntry* last = trace2.find("applied_force", 0, kForces - 1);
    QVERIFY(last != nullptr);
    QVERIFY(trace2.find("applied_force", 0, 32768) != nullptr);   // the first index an int16 wraps
    const TraceEntry* F = trace2.find("force", 0);
    QVERIFY(F != nullptr);
    QCOMPARE(std::get<Vec3>(F->value), Vec3(20000, 0, 0));

    // Forward, back to step 2's state: the packed trace unpacks bit for bit.
    QVERIFY(s.step());
    QVERIFY(s.stepBack());
    QVERIFY2(sameTrace(*s.currentTrace(), trace2), "the trace after step back is not the one recorded");
    QVERIFY(s.currentTrace()->find("applied_force", 0, kForces - 1) != nullptr);
    // Back again, and forward: the replayed step 2 gives the same trace (determinism).
    QVERIFY(s.stepBack());
    QVERIFY(s.step());
    QVERIFY(sameTrace(*s.currentTrace(), trace2));
}

void TestSession::parameterSwitchKeepsState()
{
    Session s;
    s.load(lessonScene("07-bounce/scene.json"));
    for (int k = 0; k < 20; ++k) QVERIFY(s.step());
    const std::vector<BodyState> before = s.world()->states();
    const long k0 = s.world()->stepIndex();

    QVERIFY(s.gravityEnabled());
    s.setGravityEnabled(false);
    QVERIFY(!s.gravityEnabled());
    QVERIFY(s.setDt(0.005));
    QVERIFY(s.setRestitution(0.3));
    QVERIFY(s.setFriction(0.2));
    QVERIFY(sameStates(s.world()->states(), before));
    QCOMPARE(s.world()->stepIndex(), k0);
    QCOMPARE(s.world()->scene().dt, 0.005);
    QCOMPARE(s.world()->scene().restitution, 0.3);
    QCOMPARE(s.world()->scene().g_W, Vec3::Zero());

    // Gravity off: nothing acts on a body in free flight, so v stays the same.
    // (Body 0 of lesson 7 is above the ground at step 20; checked, not assumed.)
    const Vec3 v = s.world()->states()[0].v_W;
    QVERIFY(s.step());
    QVERIFY(s.currentTrace()->find("gravity_force", 0) == nullptr);
    if (s.currentTrace()->contacts.empty()) {
        QCOMPARE(s.world()->states()[0].v_W, v);
    }
    s.setGravityEnabled(true);
    QCOMPARE(s.world()->scene().g_W, s.baseScene().g_W);
}

void TestSession::badParameterIsRefused()
{
    Session s;
    s.load(lessonScene("01-one-step/scene.json"));
    QString error;
    QVERIFY(!s.setDt(-1.0, &error));
    QVERIFY2(error.contains("dt"), qPrintable(error));
    QVERIFY(!s.setIntegrator("no-such-method", &error));
    QVERIFY2(error.contains("integrator"), qPrintable(error));
    QVERIFY(!s.setRestitution(1.5, &error));
    QVERIFY2(error.contains("restitution"), qPrintable(error));
    // The world is untouched by a refused change.
    QCOMPARE(s.world()->scene().dt, 2.0);
    QVERIFY(s.step());
}

void TestSession::parametersChangedOnlyForParameters()
{
    // The parameter bar follows parametersChanged: once per accepted switch, load or
    // reset, and never for a step (the bar must not repaint at every frame of Play).
    Session s;
    QSignalSpy changed(&s, &Session::parametersChanged);
    s.load(lessonScene("07-bounce/scene.json"));
    QCOMPARE(changed.count(), 1);
    QVERIFY(s.step());
    QCOMPARE(s.advance(5, 1e9), 5);
    QVERIFY(s.stepBack());
    QCOMPARE(changed.count(), 1);
    QVERIFY(s.setDt(0.01));
    QVERIFY(s.setIntegrator("rk4"));
    s.setGravityEnabled(false);
    QVERIFY(s.setRestitution(0.5));
    QVERIFY(s.setFriction(0.1));
    QCOMPARE(changed.count(), 6);
    // Negative control: a refused value changes nothing and says nothing.
    QVERIFY(!s.setDt(-1.0));
    QCOMPARE(changed.count(), 6);
    s.reset();
    QCOMPARE(changed.count(), 7);
    QCOMPARE(s.world()->scene().dt, 0.01);   // reset keeps the student's parameters
}

void TestSession::dragPullsTowardsTarget_data()
{
    QTest::addColumn<Vec3>("drag");   // target minus picked point
    QTest::newRow("+x") << Vec3(1, 0, 0);
    QTest::newRow("-y") << Vec3(0, -1, 0);
    QTest::newRow("diagonal") << Vec3(0.5, 0.5, -0.5);
}

void TestSession::dragPullsTowardsTarget()
{
    // The mouse spring at rest: v_p = 0, so f = M w^2 (t - p), along the drag.
    // One step of explicit Euler: P = M v = h f, so P is parallel to the drag.
    QFETCH(Vec3, drag);
    SceneDef scene = lessonScene("02-single-body/scene.json");
    scene.forces.clear();   // only the spring acts
    Session s;
    s.load(scene);
    const Vec3 p_W = s.world()->states()[0].x_W + Vec3(0.2, 0.1, 0.0);
    s.beginGrab(0, p_W);
    s.moveGrab(p_W + drag);
    QVERIFY(s.isGrabbing());
    QVERIFY(s.step());
    const Vec3 P = s.world()->massProperties()[0].M * s.world()->states()[0].v_W;
    QVERIFY2(P.normalized().dot(drag.normalized()) > 1.0 - 1e-12, "momentum not along the drag");
    // The spring is an external force like any other: it is in the trace.
    const TraceEntry* f = s.currentTrace()->find("applied_force", 0, 0);
    QVERIFY(f != nullptr);
    QVERIFY(std::get<Vec3>(f->value).normalized().dot(drag.normalized()) > 1.0 - 1e-12);
    s.endGrab();
    QVERIFY(s.step());
    QVERIFY(s.currentTrace()->find("applied_force", 0, 0) == nullptr);
}

void TestSession::pushActsForOneStep()
{
    SceneDef scene = lessonScene("02-single-body/scene.json");
    scene.forces.clear();
    Session s;
    s.load(scene);
    QVERIFY(s.push(Vec3(0, 0, 2)));   // direction only; the scene sets 5 N
    // Queued for the next step (the view draws it before that step): 5 N along +z at
    // the scene's corner (0.5, 0.3, 0.25) in the body frame.
    QCOMPARE(s.pendingPushes().size(), std::size_t(1));
    QVERIFY(s.pendingPushes()[0].second == Vec3(0, 0, 5));
    QVERIFY(s.pendingPushes()[0].first == s.world()->bodyToWorld(0, Vec3(0.5, 0.3, 0.25)));
    QVERIFY(s.step());
    QVERIFY(s.pendingPushes().empty());
    // v = h f / M = 0.01 * 5 / 2 = 0.025 along +z
    RBW_COMPARE_NEAR_STRICT(s.world()->states()[0].v_W, Vec3(0, 0, 0.025), 1e-15);
    QVERIFY(s.step());
    RBW_COMPARE_NEAR_STRICT(s.world()->states()[0].v_W, Vec3(0, 0, 0.025), 1e-15);

    Session none;
    none.load(lessonScene("01-one-step/scene.json"));
    QVERIFY(!none.push(Vec3(1, 0, 0)));   // lesson 1 declares no push
}

void TestSession::toggleTorques()
{
    Session s;
    s.load(lessonScene("05-spinning/scene.json"));
    QVERIFY(s.torquesOn());
    for (int k = 0; k < 10; ++k) QVERIFY(s.step());
    QVERIFY(s.toggleTorques());
    QVERIFY(!s.torquesOn());
    const Vec3 omega = s.world()->states()[1].omega_W;
    for (int k = 0; k < 10; ++k) QVERIFY(s.step());
    QCOMPARE(s.world()->states()[1].omega_W, omega);

    Session none;
    none.load(lessonScene("02-single-body/scene.json"));
    QVERIFY(!none.toggleTorques());
}

void TestSession::blowUpStopsTheRun()
{
    // A box with v0 = (1e8, 0, 0) and h = 1e300 overflows x in step 1: step 0 gives
    // x = h v0 = 1e308 (finite), step 1 x = 2e308 > DBL_MAX -> +inf. Its energy
    // T = 1/2 6 (1e8)^2 = 3e16 and momentum stay finite, so only x blows up, and the
    // recorded step 0 passes every check (v0 = 1e308 with h = 1, as in
    // tst_invariants' "runaway velocity", has T0 = inf, which a traced step refuses).
    SceneDef scene;
    scene.name = "runaway";
    scene.dt = 1e300;
    scene.bodies.push_back(rbw::test::boxDef("spinner", Vec3(1, 1, 1), 6.0, Vec3::Zero(), Quat::Identity(),
                                                  Vec3(1e8, 0, 0)));
    QVERIFY(validate(scene).empty());
    Session s;
    s.load(scene);
    QSignalSpy blown(&s, &Session::blownUp);
    QSignalSpy recorded(&s, &Session::stepRecorded);
    QVERIFY(s.step());
    QVERIFY(!s.step());
    QCOMPARE(blown.count(), 1);
    QCOMPARE(recorded.count(), 1);   // the blown-up step is not recorded
    const QString message = blown.at(0).at(0).toString();
    QVERIFY2(message.contains("spinner") && message.contains("position"), qPrintable(message));
    QVERIFY(!s.step());
    // The last good state is still there, and Step back works.
    QCOMPARE(s.history().size(), std::size_t(2));
    QVERIFY(s.stepBack());
}

void TestSession::advanceIsBounded()
{
    Session s;
    s.load(lessonScene("05-spinning/scene.json"));
    QSignalSpy recorded(&s, &Session::stepRecorded);
    QCOMPARE(s.advance(7, 1e9), 7);
    QCOMPARE(recorded.count(), 7);   // one sample per step, also inside a batch
    // With a zero budget, one step is still taken each call, so play always progresses.
    QCOMPARE(s.advance(1000, 0.0), 1);
}

// The history scrubber: going to step k, back or forward through the recorded
// history, gives the state and trace of a run that simply took k steps, bit for bit
// (a second session that steps straight to k is the reference).
void TestSession::goToStepIsExact_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::addColumn<long>("steps");   // recorded first
    QTest::addColumn<long>("target");
    QTest::newRow("01 back to 0") << "01-one-step/scene.json" << 3L << 0L;
    QTest::newRow("03 back over the collision") << "03-two-box-collision/scene.json" << 10L << 2L;
    QTest::newRow("04 back to 400 of 600") << "04-many-boxes/scene.json" << 600L << 400L;
    QTest::newRow("04 forward to 400 (new steps)") << "04-many-boxes/scene.json" << 0L << 400L;
    QTest::newRow("07 bounce, back to 123") << "07-bounce/scene.json" << 300L << 123L;
    QTest::newRow("09 racket, back to 999 of 1000") << "09-tennis-racket/scene.json" << 1000L << 999L;
}

void TestSession::goToStepIsExact()
{
    QFETCH(QString, lesson);
    QFETCH(long, steps);
    QFETCH(long, target);
    const SceneDef scene = lessonScene(lesson);

    Session reference;
    reference.load(scene);
    for (long k = 0; k < target; ++k) QVERIFY(reference.step());

    Session s;
    s.load(scene);
    for (long k = 0; k < steps; ++k) QVERIFY(s.step());
    QSignalSpy rewound(&s, &Session::rewound);
    QVERIFY(s.goToStep(target));
    QCOMPARE(s.world()->stepIndex(), target);
    QCOMPARE(rewound.count(), target < steps ? 1 : 0);
    QVERIFY2(sameStates(s.world()->states(), reference.world()->states()), "state differs from a straight run");
    QCOMPARE(s.world()->time(), reference.world()->time());
    QCOMPARE(s.currentTrace() == nullptr, reference.currentTrace() == nullptr);
    if (target > 0) QVERIFY2(sameTrace(*s.currentTrace(), *reference.currentTrace()), "trace differs");

    // Forward again within the history: the later steps come back exactly as recorded,
    // one stepRecorded per step passed (the plots' samples).
    if (steps > target) {
        for (long k = target; k < steps; ++k) QVERIFY(reference.step());
        QSignalSpy recorded(&s, &Session::stepRecorded);
        QVERIFY(s.goToStep(steps));
        QCOMPARE(recorded.count(), static_cast<qsizetype>(steps - target));
        QVERIFY(sameStates(s.world()->states(), reference.world()->states()));
        QVERIFY(sameTrace(*s.currentTrace(), *reference.currentTrace()));
    }
}

void TestSession::steppingFromEarlierDiscardsLater()
{
    Session s;
    s.load(lessonScene("05-spinning/scene.json"));
    for (int k = 0; k < 20; ++k) QVERIFY(s.step());
    QVERIFY(s.goToStep(5));
    // The later steps are kept while only the cursor moves (redo) ...
    QCOMPARE(s.history().stepsForwardAvailable(), std::size_t(15));
    QCOMPARE(s.history().stepsBackAvailable(), std::size_t(5));
    QVERIFY(s.stepBack());
    QCOMPARE(s.history().stepsForwardAvailable(), std::size_t(16));
    // ... and a step from here discards them, as typing after an undo drops the redo.
    QVERIFY(s.step());
    QCOMPARE(s.world()->stepIndex(), 5L);
    QCOMPARE(s.history().stepsForwardAvailable(), std::size_t(0));
    QCOMPARE(s.history().lastStep(), 5L);
    // So does an edit of a parameter (the later steps used the old h).
    for (int k = 0; k < 5; ++k) QVERIFY(s.step());
    QVERIFY(s.goToStep(7));
    QCOMPARE(s.history().lastStep(), 10L);
    QVERIFY(s.setDt(s.world()->scene().dt / 2));
    QCOMPARE(s.history().lastStep(), 7L);
    QCOMPARE(s.world()->stepIndex(), 7L);
}

void TestSession::goToStepLimits()
{
    Session s;
    s.load(lessonScene("05-spinning/scene.json"));
    for (int k = 0; k < 1010; ++k) QVERIFY(s.step());
    // The history keeps 1000 steps back: step 10 is the oldest kept state.
    QCOMPARE(s.history().firstStep(), 10L);
    QVERIFY(!s.goToStep(9));   // negative control: no longer recorded
    QCOMPARE(s.world()->stepIndex(), 1010L);
    QVERIFY(s.goToStep(10));
    QCOMPARE(s.world()->stepIndex(), 10L);
    QVERIFY(!s.goToStep(-1));
    // Beyond the recording: at most maxNewSteps new steps.
    QVERIFY(!s.goToStep(2000, 5));
    QCOMPARE(s.world()->stepIndex(), 1015L);
}

// The history keeps up to 1000 steps, or as many as fit in its byte budget: a small
// scene keeps all 1000 (lesson 4's six boxes: the scrubber reaches any of them), the
// fifty-box variant fewer, and never more bytes than the budget.
void TestSession::historyKeepsWithinItsByteBudget_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::addColumn<int>("steps");
    QTest::addColumn<bool>("keepsAll");   // all 1000 steps back
    QTest::newRow("04 six boxes") << "04-many-boxes/scene.json" << 1100 << true;
    QTest::newRow("05 two cubes") << "05-spinning/scene.json" << 1100 << true;
    QTest::newRow("04 fifty boxes") << "04-many-boxes/fifty-boxes.json" << 1000 << false;
}

void TestSession::historyKeepsWithinItsByteBudget()
{
    QFETCH(QString, lesson);
    QFETCH(int, steps);
    QFETCH(bool, keepsAll);
    Session s;
    s.load(lessonScene(lesson));
    for (int k = 0; k < steps; ++k) QVERIFY(s.step());
    const StepHistory& h = s.history();
    QVERIFY2(h.bytes() <= h.byteBudget(), qPrintable(QString::number(h.bytes())));
    qInfo("%s: %zu steps back kept, %.1f MB", qPrintable(lesson), h.stepsBackAvailable(), h.bytes() / 1e6);
    // The running sum is the entries' own sizes.
    std::size_t sum = 0;
    for (std::size_t i = 0; i < h.size(); ++i) sum += h.at(i).bytes();
    QCOMPARE(h.bytes(), sum);
    if (keepsAll) {
        QCOMPARE(h.stepsBackAvailable(), std::size_t(1000));
    } else {
        QVERIFY(h.stepsBackAvailable() < 1000);
        QVERIFY2(h.stepsBackAvailable() >= 300, qPrintable(QString::number(h.stepsBackAvailable())));
    }
    // Every kept step still comes back exactly: the oldest one too.
    QVERIFY(s.goToStep(h.firstStep()));
    QCOMPARE(s.world()->stepIndex(), h.firstStep());
    // Scrubbing and discarding keep the sum right.
    QVERIFY(s.step());
    sum = 0;
    for (std::size_t i = 0; i < h.size(); ++i) sum += h.at(i).bytes();
    QCOMPARE(h.bytes(), sum);
}

// A kept state's size is its whole snapshot: in a manifold scene that includes the
// warm-start cache and sleep state (WorldSnapshot::bytes()), so a pile with many
// contacts keeps fewer steps rather than overrunning the budget. Lesson 11's box
// rests on the ground after 60 steps: its contact points carry warm-start impulses,
// so the cache holds bytes and the entry counts them (with the per-body sleep state)
// on top of the body states. Control: the course model's lesson 4 leaves the cache
// empty (its sleep state still has one entry per body, counted the same way).
void TestSession::historyCountsTheWarmStartCache_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::addColumn<bool>("hasCache");
    QTest::newRow("11 manifold") << "11-resting-contact/scene.json" << true;
    QTest::newRow("04 course (control)") << "04-many-boxes/scene.json" << false;
}

void TestSession::historyCountsTheWarmStartCache()
{
    QFETCH(QString, lesson);
    QFETCH(bool, hasCache);
    Session s;
    s.load(lessonScene(lesson));
    for (int k = 0; k < 60; ++k) QVERIFY(s.step());
    const HistoryEntry& e = s.history().last();
    QCOMPARE(e.state.contacts.cache.bytes() > 0, hasCache);
    const std::size_t cacheBytes = e.state.contacts.bytes();
    const std::size_t bodyBytes =
        e.state.states.capacity() * sizeof(BodyState) + e.state.torqueEnabled.capacity();
    QCOMPARE(e.bytes(), sizeof(HistoryEntry) + e.trace.bytes() + bodyBytes + cacheBytes);
}

QTEST_GUILESS_MAIN(TestSession)
#include "tst_session.moc"
