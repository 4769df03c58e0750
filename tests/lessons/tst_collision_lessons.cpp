// The collision lessons reproduce what their texts promise: lesson 3's hand
// calculation, lesson 6's 1/2/4 contacts, lesson 4's 20 s run staying sane, and the
// Napier impulse experiments.
#include "app/scene/scene_loader.h"
#include "physics/engine/quantities.h"
#include "physics/engine/world.h"
#include "tests/test_support.h"

#include <QtTest>

using namespace rbw;

namespace {

using rbw::test::lessonScene;

double value(const StepTrace& t, const char* id, int body, int index)
{
    const TraceEntry* e = t.find(id, body, index);
    if (e == nullptr) qFatal("no %s in the trace", id);
    return std::get<double>(e->value);
}

Vec3 vec(const StepTrace& t, const char* id, int body, int index)
{
    const TraceEntry* e = t.find(id, body, index);
    if (e == nullptr) qFatal("no %s in the trace", id);
    return std::get<Vec3>(e->value);
}

bool near(const Vec3& a, const Vec3& b, double tol) { return (a - b).cwiseAbs().maxCoeff() <= tol; }

// World-frame corners of a body.
std::array<Vec3, 8> corners(const World& w, int b)
{
    std::array<Vec3, 8> out;
    const Vec3 h = 0.5 * w.scene().bodies[b].size;
    const BodyState& s = w.states()[b];
    for (int i = 0; i < 8; ++i) {
        const Vec3 local((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z());
        out[i] = s.x_W + s.R_WB * local;
    }
    return out;
}

} // namespace

class TestCollisionLessons : public QObject {
    Q_OBJECT
private slots:
    void lesson3HandCalculation();
    void lesson6ContactCounts_data();
    void lesson6ContactCounts();
    void lesson4TwentySeconds();
    void napierImpulses_data();
    void napierImpulses();
    void frictionBringsCuboidToRest();
    void freeBodyHasNoCollisionStage();
};

void TestCollisionLessons::lesson3HandCalculation()
{
    // lessons/03-two-box-collision/lesson.md derives this. A: 2 m cube, M_A = 2,
    // I_A^-1 = 1/(2 (4 + 4)/12) = 3/4; B: unit cube, M_B = 1, I_B^-1 = 6 (isotropic).
    // They close at 2 m/s with a 0.05 m gap, so step k = 2 (t = 0.03) brings B's corner
    // 0.01 m into A's +x face: n = (-1,0,0), p = (1.02, 0.5, 0), depth 0.01.
    World w(lessonScene("03-two-box-collision/scene.json"));
    StepTrace t;
    for (int k = 0; k < 3; ++k) {
        QVERIFY(w.step(&t).ok);
        if (k < 2) QCOMPARE(int(t.contacts.size()), 0);
    }
    QCOMPARE(int(t.contacts.size()), 1);
    QCOMPARE(QString(t.contacts[0].feature), QString("vertex-face"));
    QVERIFY(near(vec(t, "normal", 0, 0), Vec3(-1, 0, 0), 1e-15));
    QVERIFY(near(vec(t, "point", 0, 0), Vec3(1.02, 0.5, 0), 1e-12));
    RBW_COMPARE_NEAR_STRICT(value(t, "depth", 0, 0), 0.01, 1e-12);
    // x_a = p - x_A = (1.02 - 0.03, 0.5, 0) = (0.99, 0.5, 0);  x_b = p - x_B = (-sqrt(3)/2, 0, 0)
    QVERIFY(near(vec(t, "x_a", 0, 0), Vec3(0.99, 0.5, 0), 1e-12));
    QVERIFY(near(vec(t, "x_b", 1, 0), Vec3(-std::sqrt(3.0) / 2, 0, 0), 1e-12));
    // v_rel = (1,0,0) - (-1,0,0) = (2,0,0);  v_rel.n = -2;  numerator = -(1 + 1)(-2) = 4
    QVERIFY(near(vec(t, "relative_velocity", 0, 0), Vec3(2, 0, 0), 1e-15));
    QCOMPARE(value(t, "normal_velocity", 0, 0), -2.0);
    QCOMPARE(value(t, "numerator", 0, 0), 4.0);
    // 1/M_A = 0.5, 1/M_B = 1; x_a x n = (0,0,0.5), I_A^-1 (.) = (0,0,0.375),
    // (0,0,0.375) x x_a = (-0.1875, 0.37125, 0), . n = 0.1875 = 3/16; x_b || n -> 0.
    QCOMPARE(value(t, "inv_mass_a", 0, 0), 0.5);
    QCOMPARE(value(t, "inv_mass_b", 1, 0), 1.0);
    RBW_COMPARE_NEAR_STRICT(value(t, "rotational_a", 0, 0), 3.0 / 16, 1e-12);
    RBW_COMPARE_NEAR_STRICT(value(t, "rotational_b", 1, 0), 0.0, 1e-12);
    // J = 4 / (0.5 + 1 + 3/16) = 4 / (27/16) = 64/27
    RBW_COMPARE_NEAR_STRICT(value(t, "impulse", 0, 0), 64.0 / 27, 1e-12);
    // v_A' = 1 - (64/27)/2 = -5/27;  v_B' = -1 + 64/27 = 37/27;  L_A' = (64/27)(0,0,0.5) = (0,0,32/27);
    // omega_A' = (3/4) L_A' = (0,0,8/9);  B's L and omega stay 0.
    QVERIFY(near(w.states()[0].v_W, Vec3(-5.0 / 27, 0, 0), 1e-12));
    QVERIFY(near(w.states()[1].v_W, Vec3(37.0 / 27, 0, 0), 1e-12));
    QVERIFY(near(w.states()[0].L_W, Vec3(0, 0, 32.0 / 27), 1e-12));
    QVERIFY(near(w.states()[0].omega_W, Vec3(0, 0, 8.0 / 9), 1e-12));
    QVERIFY(near(w.states()[1].omega_W, Vec3::Zero(), 1e-12));
    // c = 1: kinetic energy 1/2 2 1 + 1/2 1 1 = 1.5 before and after.
    RBW_COMPARE_NEAR_STRICT(value(t, "kinetic_energy_before", 0, 0), 1.5, 1e-12);
    RBW_COMPARE_NEAR_STRICT(value(t, "kinetic_energy_after", 0, 0), 1.5, 1e-12);
}

void TestCollisionLessons::lesson6ContactCounts_data()
{
    QTest::addColumn<int>("body");
    QTest::addColumn<int>("expected");
    QTest::newRow("vertex: 1 contact") << 0 << 1;
    QTest::newRow("edge: 2 contacts") << 1 << 2;
    QTest::newRow("face: 4 contacts") << 2 << 4;
}

void TestCollisionLessons::lesson6ContactCounts()
{
    // Each cube falls from rest; in the first step in which any of its corners is below
    // the ground, the number of corners below is its landing feature's: 1, 2 or 4.
    QFETCH(int, body);
    QFETCH(int, expected);
    World w(lessonScene("06-box-on-plane/scene.json"));
    StepTrace t;
    for (int k = 0; k < 200; ++k) {
        QVERIFY(w.step(&t).ok);
        int count = 0;
        for (const ContactHeader& c : t.contacts) {
            if (c.bodyA == body) {
                QCOMPARE(QString(c.feature), QString("vertex-plane"));
                ++count;
            }
        }
        if (count > 0) {
            QCOMPARE(count, expected);
            return;
        }
    }
    QFAIL("the box never landed");
}

void TestCollisionLessons::lesson4TwentySeconds()
{
    World w(lessonScene("04-many-boxes/scene.json"));
    const SceneDef& s = w.scene();
    QVERIFY(s.bodies.size() >= 4 && s.hasGravity() && s.planes.size() == 5 && s.restitution < 1.0);
    const int steps = int(std::lround(20.0 / s.dt));
    const double E0 = w.diagnostics().total;

    // Explicit Euler's gain in free flight, per body and step: with x' = x + h v and
    // v' = v + h g,  dE = 1/2 M (|v + h g|^2 - |v|^2) - M g.(h v) = 1/2 M h^2 |g|^2.
    double gainPerStep = 0.0;
    for (const BodyDef& b : s.bodies) gainPerStep += 0.5 * b.mass * s.dt * s.dt * s.g_W.squaredNorm();

    StepTrace t;
    int contactsSeen = 0;
    for (int k = 0; k < steps; ++k) {
        const StepStatus st = w.step(&t);
        QVERIFY2(st.ok, st.message.c_str());
        // With c < 1 (and friction), no impulse raises the kinetic energy of its pair.
        for (int c = 0; c < int(t.contacts.size()); ++c) {
            ++contactsSeen;
            if (t.contacts[c].separating) continue;
            const double before = value(t, "kinetic_energy_before", t.contacts[c].bodyA, c);
            const double after = value(t, "kinetic_energy_after", t.contacts[c].bodyA, c);
            QVERIFY2(after <= before * (1 + 1e-12) + 1e-15,
                     qPrintable(QString("step %1 contact %2: T %3 -> %4").arg(k).arg(c).arg(before).arg(after)));
        }
        // No body more than 2 cm below the ground or outside the walls (|x|, |z| <= 3).
        for (int b = 0; b < int(s.bodies.size()); ++b) {
            for (const Vec3& p : corners(w, b)) {
                QVERIFY2(p.y() >= -0.02, qPrintable(QString("step %1: %2 at y = %3").arg(k).arg(QString::fromStdString(s.bodies[b].name)).arg(p.y())));
                QVERIFY(std::abs(p.x()) <= 3.02 && std::abs(p.z()) <= 3.02);
            }
        }
    }
    QVERIFY(contactsSeen > 100);   // it really collided
    const double E1 = w.diagnostics().total;
    QVERIFY(std::isfinite(E1));
    QVERIFY2(E1 - steps * gainPerStep < E0, qPrintable(QString("E0 %1, E1 %2, gain bound %3").arg(E0).arg(E1).arg(steps * gainPerStep)));
}

void TestCollisionLessons::napierImpulses_data()
{
    QTest::addColumn<int>("body");
    QTest::addColumn<double>("vx");
    QTest::addColumn<double>("omegaZ");
    // Cuboid w x h x d = 2 x 6 x 2, m = 1: I0_zz = m (w^2 + h^2)/12 = 40/12 = 10/3.
    // At t = 2 s a force of -300 N acts for one step h = 0.01: impulse (-3, 0, 0).
    //   stop:    at the centre: v = 3 - 3 = 0.
    //   reverse: -600 N: v = 3 - 6 = -3.
    //   spin:    the stopping impulse 3 m below or above the centre: v = 0, and
    //            L = x_i x J with J = (-3, 0, 0):  L_z = x_i,x J_y - x_i,y J_x = 3 x_i,y.
    //            x_i = (0, -3, 0): L_z = -9, omega_z = -9 / (10/3) = -2.7 (clockwise seen from +z);
    //            x_i = (0, +3, 0): L_z = +9, omega_z = +2.7 (anticlockwise).
    QTest::newRow("stop") << 0 << 0.0 << 0.0;
    QTest::newRow("reverse") << 1 << -3.0 << 0.0;
    QTest::newRow("spin clockwise") << 2 << 0.0 << -2.7;
    QTest::newRow("spin anticlockwise") << 3 << 0.0 << 2.7;
}

void TestCollisionLessons::napierImpulses()
{
    QFETCH(int, body);
    QFETCH(double, vx);
    QFETCH(double, omegaZ);
    World w(lessonScene("07-bounce/impulses.json"));
    for (int k = 0; k < 200; ++k) QVERIFY(w.step().ok);
    QVERIFY(near(w.states()[body].v_W, Vec3(3, 0, 0), 1e-12));   // unchanged before t = 2 s
    QVERIFY(w.step().ok);                                          // step 200: the impulse
    QVERIFY(near(w.states()[body].v_W, Vec3(vx, 0, 0), 1e-9));
    QVERIFY(near(w.states()[body].omega_W, Vec3(0, 0, omegaZ), 1e-9));
}

void TestCollisionLessons::frictionBringsCuboidToRest()
{
    // Napier assessment: c = 0.6 with mu = 0.5 brings the bouncing cuboid to rest. With
    // impulse-only contact a resting box micro-bounces (each step gravity gives it
    // v_y = -g h = -0.049 m/s, which bounces back at 0.6 of that) and friction acts only
    // every other step, so it creeps. The scene's restitution_threshold (0.5 m/s) makes
    // slow approaches plastic; then the horizontal speed dies out.
    SceneDef scene = lessonScene("07-bounce/scene.json");
    QCOMPARE(scene.restitutionThreshold, 0.5);
    const int body = scene.bodyIndex("friction");
    auto horizontalSpeedAfter12s = [&](const SceneDef& s) {
        World w(s);
        for (int k = 0; k < 2400; ++k) {
            if (!w.step().ok) qFatal("blew up");
        }
        const Vec3 v = w.states()[body].v_W;
        return std::hypot(v.x(), v.z());
    };
    const double withThreshold = horizontalSpeedAfter12s(scene);
    QVERIFY2(withThreshold < 0.01, qPrintable(QString("still sliding at %1 m/s").arg(withThreshold)));
    // Negative control: without the threshold the same cuboid is still creeping.
    scene.restitutionThreshold = 0.0;
    QVERIFY(horizontalSpeedAfter12s(scene) > 0.01);
}

void TestCollisionLessons::freeBodyHasNoCollisionStage()
{
    // Lesson 1 has one body and no planes: the pipeline has no collision stage at all.
    World w(lessonScene("01-one-step/scene.json"));
    QVERIFY(!w.runsCollisionStage());
    StepTrace t;
    QVERIFY(w.step(&t).ok);
    for (const TraceEntry& e : t.entries) QVERIFY(e.info->stage != Stage::Collision);
    // Negative control: lesson 3 (two bodies) does run it and records broad-phase counts.
    World two(lessonScene("03-two-box-collision/scene.json"));
    QVERIFY(two.runsCollisionStage());
    QVERIFY(two.step(&t).ok);
    QVERIFY(t.find("pairs_tested", -1) != nullptr);
    // The manifold model (lesson 11) collides in its own stage, before the integration:
    // that counts too (the app enables c and mu by it).
    World manifold(lessonScene("11-resting-contact/scene.json"));
    QVERIFY(!manifold.runsStage(PipelineStage::BoxPlane));
    QVERIFY(manifold.runsCollisionStage());
}

QTEST_APPLESS_MAIN(TestCollisionLessons)
#include "tst_collision_lessons.moc"
