// A marking sheet simulates its scene once (issue 22, "bounded work"): StepStates
// (app/exercise/answers_input.h), which rbw check and the check panel use, runs the
// scene from t = 0 once for all the steps a sheet asks, and every prepared step stands
// exactly where a world stepped on its own from t = 0 stands (bit for bit).
#include "app/exercise/answers_input.h"
#include "app/scene/scene_loader.h"
#include "physics/engine/world.h"

#include <QtTest>

#include <vector>

using namespace rbw;

Q_DECLARE_METATYPE(std::vector<long>)

namespace {

SceneDef loadLesson(const QString& relative)
{
    const SceneLoadResult r = loadSceneFile(QStringLiteral(RBW_SOURCE_DIR "/lessons/") + relative);
    if (!r.ok()) qFatal("%s", qPrintable(r.errors.join('\n')));
    return *r.scene;
}

bool sameBits(const BodyState& a, const BodyState& b)
{
    return a.x_W == b.x_W && a.v_W == b.v_W && a.q_WB.coeffs() == b.q_WB.coeffs() && a.L_W == b.L_W;
}

} // namespace

class TestStepStates : public QObject {
    Q_OBJECT
private slots:
    void oneSimulationForASheet_data();
    void oneSimulationForASheet();
    void aNewStepSimulatesAgain();
};

void TestStepStates::oneSimulationForASheet_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::addColumn<std::vector<long>>("asked");   // the steps of five answers files, in sheet order
    QTest::newRow("lesson 2") << "02-single-body/scene.json" << std::vector<long>{2, 9, 4, 9, 0};
    QTest::newRow("lesson 3, its three steps") << "03-two-box-collision/scene.json" << std::vector<long>{2, 0, 2, 1, 0};
}

void TestStepStates::oneSimulationForASheet()
{
    QFETCH(QString, lesson);
    QFETCH(std::vector<long>, asked);
    const SceneDef scene = loadLesson(lesson);
    StepStates states(scene);
    QCOMPARE(states.simulations(), 0);
    QString error;
    QVERIFY2(states.prepare(asked, &error), qPrintable(error));
    QCOMPARE(states.simulations(), 1);   // five files, one run from t = 0
    // Each asked step is held, and only those (a step no file asked is not: control).
    long last = 0;
    for (long k : asked) {
        QVERIFY(states.has(k));
        last = std::max(last, k);
    }
    QVERIFY(!states.has(last + 1));
    // The world before each asked step equals a world stepped k times on its own.
    for (long k : asked) {
        World alone(scene);
        for (long i = 0; i < k; ++i) QVERIFY(alone.step().ok);
        const std::unique_ptr<World> before = states.worldBefore(k);
        QVERIFY(before != nullptr);
        QCOMPARE(before->stepIndex(), k);
        QCOMPARE(before->states().size(), alone.states().size());
        for (size_t b = 0; b < alone.states().size(); ++b) {
            QVERIFY2(sameBits(before->states()[b], alone.states()[b]), qPrintable(QStringLiteral("step %1, body %2").arg(k).arg(b)));
        }
    }
    // Asking the same steps again costs nothing.
    QVERIFY(states.prepare(asked, &error));
    QCOMPARE(states.simulations(), 1);
}

// The counter counts: a step beyond the prepared ones needs one more run (control for
// the test above, which would pass vacuously with a counter that never moves).
void TestStepStates::aNewStepSimulatesAgain()
{
    const SceneDef scene = loadLesson(QStringLiteral("02-single-body/scene.json"));
    StepStates states(scene);
    QString error;
    QVERIFY(states.prepare({1, 3}, &error));
    QCOMPARE(states.simulations(), 1);
    QVERIFY(states.prepare({3, 6}, &error));
    QCOMPARE(states.simulations(), 2);
    QVERIFY(states.has(6));
}

QTEST_GUILESS_MAIN(TestStepStates)
#include "tst_step_states.moc"
