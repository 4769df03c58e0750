// The step pipeline a world builds from what its scene declares (World::pipeline()):
// no gravity stage without gravity, no broad/narrow phase or response without a
// collidable pair, no plane tests without a plane, no correction unless asked, no
// probes stage without probes; one integration entry per integrator group.
// Expected lists are read off each lesson's scene.json (gravity, planes,
// box_collisions, the number of bodies, position_correction, probes, integrators).
#include "app/scene/scene_loader.h"
#include "physics/engine/quantities.h"
#include "physics/engine/world.h"
#include "tests/test_support.h"

#include <QtTest>

using rbw::Quat;
using rbw::Vec3;

namespace {

QString labels(const rbw::World& w)
{
    QStringList out;
    for (const std::string& s : w.pipelineLabels()) out << QString::fromStdString(s);
    return out.join(QLatin1Char(','));
}

bool traceHasStage(const rbw::StepTrace& t, rbw::Stage stage)
{
    for (const rbw::TraceEntry& e : t.entries) {
        if (e.info->stage == stage) return true;
    }
    return false;
}

bool traceHas(const rbw::StepTrace& t, const char* id)
{
    for (const rbw::TraceEntry& e : t.entries) {
        if (std::string_view(e.info->id) == id) return true;
    }
    return false;
}

// Two free boxes far apart, optionally with gravity, planes, box collisions.
rbw::SceneDef twoBoxes(bool gravity, bool plane, bool boxCollisions)
{
    rbw::SceneDef s;
    s.name = "two boxes";
    s.dt = 0.01;
    s.boxCollisions = boxCollisions;
    if (gravity) s.g_W = Vec3(0, -9.81, 0);
    if (plane) s.planes.push_back(rbw::PlaneDef{"ground", Vec3(0, -100, 0), Vec3::UnitY()});
    s.bodies.push_back(rbw::test::boxDef("a", Vec3(1, 0.6, 0.5), 2.0, Vec3(-5, 0, 0), Quat::Identity(),
                                         Vec3(0, 0, 0), Vec3(0.3, 0.2, 0.1)));
    s.bodies.push_back(rbw::test::boxDef("b", Vec3(1, 0.6, 0.5), 2.0, Vec3(5, 0, 0), Quat::Identity(),
                                         Vec3(0, 0, 0), Vec3(0.1, 0.2, 0.3)));
    return s;
}

} // namespace

class TestPipeline : public QObject {
    Q_OBJECT

private slots:
    void lessonPipelines_data();
    void lessonPipelines();
    void freeBodyTraceHasNoCollisionOrGravity();
    void gravityWithoutPlanesOrPairs();
    void allStagesOption();
    void perBodyIntegratorGroups();
    void explicitEulerUnchangedByGrouping();
};

void TestPipeline::lessonPipelines_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<QString>("expected");
    const QString ee = QStringLiteral("integration:explicit-euler");
    // energy_bound (T_n and T_max before the integration) and energy_check after it
    // come with the scene's energy_jump; a second finite_check follows the contact stages.
    // 1 body: no pair even with box_collisions on; 2 probes.
    QTest::newRow("01") << "01-one-step/scene.json" << "loads,energy_bound," + ee + ",finite_check,energy_check,probes";
    QTest::newRow("02") << "02-single-body/scene.json" << "loads,energy_bound," + ee + ",finite_check,energy_check,probes";
    QTest::newRow("03") << "03-two-box-collision/scene.json" << "loads,energy_bound," + ee + ",finite_check,energy_check,box_box,finite_check";
    QTest::newRow("04") << "04-many-boxes/scene.json"
                        << "gravity,loads,energy_bound," + ee + ",finite_check,energy_check,box_box,box_plane,correction,finite_check";
    QTest::newRow("05") << "05-spinning/scene.json" << "loads,energy_bound," + ee + ",finite_check,energy_check";
    QTest::newRow("06") << "06-box-on-plane/scene.json" << "gravity,loads,energy_bound," + ee + ",finite_check,energy_check,box_plane,finite_check";
    QTest::newRow("07") << "07-bounce/scene.json"
                        << "gravity,loads,energy_bound," + ee + ",finite_check,energy_check,box_plane,correction,finite_check";
    QTest::newRow("07 impulses") << "07-bounce/impulses.json" << "loads,energy_bound," + ee + ",finite_check,energy_check,box_box,finite_check";
    QTest::newRow("08") << "08-conventions/scene.json" << "loads,energy_bound," + ee + ",finite_check,energy_check,probes";
    QTest::newRow("09") << "09-tennis-racket/scene.json"
                        << "loads,energy_bound," + ee + ",integration:rk4,integration:implicit-midpoint,finite_check,energy_check";
}

void TestPipeline::lessonPipelines()
{
    QFETCH(QString, scene);
    QFETCH(QString, expected);
    rbw::World world(rbw::test::lessonScene(scene));
    QCOMPARE(labels(world), expected);
}

// Lesson 2 (one free body, no gravity): its trace over many steps has no collision
// entries and no gravity rows. Negative control: lesson 6 has both.
void TestPipeline::freeBodyTraceHasNoCollisionOrGravity()
{
    rbw::World world(rbw::test::lessonScene("02-single-body/scene.json"));
    rbw::StepTrace trace;
    for (int k = 0; k < 50; ++k) {
        QVERIFY(world.step(&trace).ok);
        QVERIFY(!traceHasStage(trace, rbw::Stage::Collision));
        QVERIFY(!traceHas(trace, "gravity_force"));
        QVERIFY(!traceHas(trace, "pairs_tested"));
    }
    rbw::World control(rbw::test::lessonScene("06-box-on-plane/scene.json"));
    bool collided = false;
    bool gravity = false;
    for (int k = 0; k < 300; ++k) {
        QVERIFY(control.step(&trace).ok);
        collided = collided || traceHasStage(trace, rbw::Stage::Collision);
        gravity = gravity || traceHas(trace, "gravity_force");
    }
    QVERIFY(collided);
    QVERIFY(gravity);
}

// Gravity but no plane and box collisions off: gravity runs, no collision stage.
void TestPipeline::gravityWithoutPlanesOrPairs()
{
    rbw::World world(twoBoxes(true, false, false));
    QCOMPARE(labels(world), QStringLiteral("gravity,loads,energy_bound,integration:explicit-euler,finite_check,energy_check"));
    QVERIFY(!world.runsCollisionStage());
    rbw::StepTrace trace;
    QVERIFY(world.step(&trace).ok);
    QVERIFY(traceHas(trace, "gravity_force"));
    QVERIFY(!traceHasStage(trace, rbw::Stage::Collision));
    QCOMPARE(world.lastBroadPhaseStats().pairsTested, 0);
}

// WorldOptions::allStages runs every stage on a free scene (a far plane given), and
// since nothing touches and g = 0 the states equal the minimal pipeline's.
void TestPipeline::allStagesOption()
{
    rbw::SceneDef s = twoBoxes(false, true, false);
    rbw::World minimal(twoBoxes(false, false, false));
    rbw::World all(s, rbw::WorldOptions{true});
    QCOMPARE(labels(all),
             QStringLiteral("gravity,loads,energy_bound,integration:explicit-euler,finite_check,energy_check,box_box,box_plane,finite_check"));
    QCOMPARE(labels(minimal), QStringLiteral("loads,energy_bound,integration:explicit-euler,finite_check,energy_check"));
    for (int k = 0; k < 100; ++k) {
        QVERIFY(all.step().ok);
        QVERIFY(minimal.step().ok);
    }
    // The broad phase ran (its counts are in the trace), found nothing to resolve.
    rbw::StepTrace trace;
    QVERIFY(all.step(&trace).ok);
    QVERIFY(minimal.step().ok);
    QVERIFY(traceHas(trace, "pairs_tested"));
    QVERIFY(trace.contacts.empty());
    QVERIFY(traceHas(trace, "gravity_force"));
    for (int b = 0; b < 2; ++b) {
        QCOMPARE(all.states()[b].x_W, minimal.states()[b].x_W);
        QCOMPARE(all.states()[b].L_W, minimal.states()[b].L_W);
        QCOMPARE(all.states()[b].q_WB.coeffs(), minimal.states()[b].q_WB.coeffs());
    }
}

// bodies[i].integrator groups the bodies; each body's trace rows are those of its own
// integrator (rk4 writes its stage rows, explicit Euler none).
void TestPipeline::perBodyIntegratorGroups()
{
    rbw::SceneDef s = twoBoxes(false, false, false);
    s.bodies[1].integrator = "rk4";
    rbw::World world(s);
    QCOMPARE(labels(world),
             QStringLiteral("loads,energy_bound,integration:explicit-euler,integration:rk4,finite_check,energy_check"));
    QCOMPARE(QString::fromLatin1(world.integratorOf(0).name()), QStringLiteral("explicit-euler"));
    QCOMPARE(QString::fromLatin1(world.integratorOf(1).name()), QStringLiteral("rk4"));
    QCOMPARE(world.pipeline()[3].bodies, std::vector<int>{1});
    rbw::StepTrace trace;
    QVERIFY(world.step(&trace).ok);
    QVERIFY(trace.find("stage_angular_velocity", 1, 1) != nullptr);
    QVERIFY(trace.find("stage_angular_velocity", 0, 1) == nullptr);
    QVERIFY(trace.find("angular_velocity", 0) != nullptr);
    QVERIFY(trace.find("angular_velocity", 1) != nullptr);
    // Body 1 alone under rk4 gives bit-for-bit the same state as in its own scene.
    rbw::SceneDef alone = s;
    alone.integrator = "rk4";
    alone.bodies[0].integrator.clear();
    alone.bodies[1].integrator.clear();
    rbw::World ref(alone);
    QVERIFY(ref.step().ok);
    QCOMPARE(world.states()[1].q_WB.coeffs(), ref.states()[1].q_WB.coeffs());
    QCOMPARE(world.states()[1].omega_W, ref.states()[1].omega_W);
    // Negative control: body 0 (explicit Euler) differs from its rk4 self.
    QVERIFY(world.states()[0].q_WB.coeffs() != ref.states()[0].q_WB.coeffs());
}

// A body that names the scene's own integrator explicitly is in the one group, with
// results bit-identical to not naming it.
void TestPipeline::explicitEulerUnchangedByGrouping()
{
    rbw::SceneDef named = twoBoxes(false, false, false);
    named.bodies[0].integrator = "explicit-euler";
    rbw::World a(named);
    rbw::World b(twoBoxes(false, false, false));
    QCOMPARE(labels(a), labels(b));
    for (int k = 0; k < 100; ++k) {
        QVERIFY(a.step().ok);
        QVERIFY(b.step().ok);
    }
    QCOMPARE(a.states()[0].q_WB.coeffs(), b.states()[0].q_WB.coeffs());
    QCOMPARE(a.states()[1].omega_W, b.states()[1].omega_W);
}

QTEST_GUILESS_MAIN(TestPipeline)
#include "tst_pipeline.moc"
