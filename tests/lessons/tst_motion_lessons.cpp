// Lessons 2 (one body, many small steps) and 5 (two spinning bodies) reproduce the
// numbers their texts derive by hand, and the interaction hooks they rely on (a
// switchable torque, one-step pushes, body points) behave as documented.
#include "physics/engine/quantities.h"
#include "physics/engine/world.h"
#include "tests/test_support.h"

#include <QtTest>

using namespace rbw;
using rbw::test::lessonScene;

namespace {

bool near(const Vec3& a, const Vec3& b, double tol) { return (a - b).cwiseAbs().maxCoeff() <= tol; }

QByteArray text(const Vec3& v)
{
    return QByteArray::number(v.x(), 'g', 17) + ", " + QByteArray::number(v.y(), 'g', 17) + ", " +
           QByteArray::number(v.z(), 'g', 17);
}

void stepN(World& w, int n, StepTrace* trace = nullptr)
{
    for (int k = 0; k < n; ++k) {
        const StepStatus s = w.step(trace);
        if (!s.ok) qFatal("step %d failed: %s", k, s.message.c_str());
    }
}

// Rounding of n additions of h*F/M and similar: n * eps * |value| with margin.
constexpr double kSumTol = 1e-12;

} // namespace

class TestMotionLessons : public QObject {
    Q_OBJECT
private slots:
    void lesson2ConstantForce();
    void lesson2PushIsOneStepForceAtCorner();
    void lesson5Spin_data();
    void lesson5Spin();
    void lesson5ToggleKeepsOmega();
    void lesson5SnapshotRestoresToggle();
    void bodyPointRoundTrip();
};

void TestMotionLessons::lesson2ConstantForce()
{
    // f = (1, 1, 0) for steps 0..199, M = 2, h = 0.01 (lesson 2's scene).
    //   v_n = n h f / M                      -> v_200 = (1, 1, 0)
    //   x_n = sum_{k<n} h v_k = h^2 (f/M) n(n-1)/2 -> x_200 = 1e-4 * 0.5 * 19900 = 0.995
    // The exact solution 1/2 a t^2 = 1 differs by h a t / 2 = 0.005: first order.
    World w(lessonScene("02-single-body/scene.json"));
    stepN(w, 200);
    const BodyState& s = w.states()[0];
    QVERIFY2(near(s.v_W, Vec3(1, 1, 0), kSumTol), text(s.v_W));
    QVERIFY2(near(s.x_W, Vec3(0.995, 0.995, 0), kSumTol), text(s.x_W));
    // Negative control: the exact-solution position is 5 mm away, far outside kSumTol.
    QVERIFY(!near(s.x_W, Vec3(1, 1, 0), kSumTol));

    // After the force window nothing acts: L_W stays constant to the bit.
    const Vec3 L = s.L_W;
    StepTrace trace;
    stepN(w, 50, &trace);
    QCOMPARE(w.states()[0].L_W, L);
    QVERIFY2(trace.find("torque", 0) == nullptr, "no forces stage rows once the force has stopped");
}

void TestMotionLessons::lesson2PushIsOneStepForceAtCorner()
{
    // A push is a force applied for one step at the corner p_B = (0.5, 0.3, 0.25).
    // At t = 0 the box is turned 90 deg about z: R p_B = (-0.3, 0.5, 0.25).
    SceneDef scene = lessonScene("02-single-body/scene.json");
    scene.forces.clear();
    World w(scene);
    const PushDef& push = w.scene().push;
    QCOMPARE(push.body, 0);
    QCOMPARE(push.magnitude, 5.0);
    const Vec3 p_W = w.bodyToWorld(push.body, push.p_B);
    QVERIFY2(near(p_W, Vec3(-0.3, 0.5, 0.25), 1e-15), text(p_W));

    // f = (5, 0, 0) at p: v = h f / M = (0.025, 0, 0); L = h (p - x) x f
    //   (p - x) x f = (-0.3, 0.5, 0.25) x (5, 0, 0) = (0, 1.25, -2.5) -> L = (0, 0.0125, -0.025)
    w.applyForceOnce(push.body, p_W, Vec3(push.magnitude, 0, 0));
    StepTrace trace;
    stepN(w, 1, &trace);
    QVERIFY2(near(w.states()[0].v_W, Vec3(0.025, 0, 0), 1e-15), text(w.states()[0].v_W));
    QVERIFY2(near(w.states()[0].L_W, Vec3(0, 0.0125, -0.025), 1e-15), text(w.states()[0].L_W));
    QVERIFY(trace.find("applied_force", 0, 0) != nullptr);
    // The push lasts one step only.
    const Vec3 v1 = w.states()[0].v_W;
    stepN(w, 1, &trace);
    QCOMPARE(w.states()[0].v_W, v1);
    QVERIFY(trace.find("applied_force", 0, 0) == nullptr);
}

void TestMotionLessons::lesson5Spin_data()
{
    QTest::addColumn<int>("steps");
    QTest::addColumn<double>("omegaY");   // of the accelerated cube
    // Cube M = 1, size 1: I = 1/6 * identity in every orientation, q = (0, 0.05, 0).
    //   L_n = n h q, omega_n = I^-1 L_n = (0, 0.3 n h, 0)
    QTest::newRow("1 step") << 1 << 0.003;
    QTest::newRow("100 steps (1 s)") << 100 << 0.3;
    QTest::newRow("500 steps (5 s)") << 500 << 1.5;
}

void TestMotionLessons::lesson5Spin()
{
    QFETCH(int, steps);
    QFETCH(double, omegaY);
    World w(lessonScene("05-spinning/scene.json"));
    stepN(w, steps);
    // Left cube: no load, L = I omega = (0, 1/3, 0) for ever; omega stays (0, 2, 0).
    QVERIFY2(near(w.states()[0].omega_W, Vec3(0, 2, 0), 1e-13), text(w.states()[0].omega_W));
    QVERIFY2(near(w.states()[1].omega_W, Vec3(0, omegaY, 0), 1e-13 * steps), text(w.states()[1].omega_W));
}

void TestMotionLessons::lesson5ToggleKeepsOmega()
{
    World w(lessonScene("05-spinning/scene.json"));
    QVERIFY(w.hasSwitchableTorque());
    QVERIFY(w.torqueEnabled(0));
    stepN(w, 100);
    const Vec3 omega = w.states()[1].omega_W;   // (0, 0.3, 0)
    w.setTorqueEnabled(0, false);               // the K key
    StepTrace trace;
    stepN(w, 200, &trace);
    // Off: q = 0, so L and, for a cube, omega keep their values exactly.
    QCOMPARE(w.states()[1].omega_W, omega);
    QVERIFY2(trace.find("applied_torque", 1, 0) == nullptr, "no couple while switched off");
    w.setTorqueEnabled(0, true);
    stepN(w, 100, &trace);
    QVERIFY2(near(w.states()[1].omega_W, Vec3(0, 0.6, 0), 1e-12), text(w.states()[1].omega_W));
    // The couple and the total torque are in the trace; q_j = (0, 0.05, 0).
    const TraceEntry* qj = trace.find("applied_torque", 1, 0);
    QVERIFY(qj != nullptr);
    QCOMPARE(std::get<Vec3>(qj->value), Vec3(0, 0.05, 0));
    QCOMPARE(std::string(trace.find("torque", 1)->info->formula), std::string(q::torque_with_couples.formula));
}

void TestMotionLessons::lesson5SnapshotRestoresToggle()
{
    // Step back must restore the switch too, or the replayed steps would differ.
    World w(lessonScene("05-spinning/scene.json"));
    const WorldSnapshot on = w.snapshot();
    w.setTorqueEnabled(0, false);
    w.restore(on);
    QVERIFY(w.torqueEnabled(0));
    stepN(w, 10);
    QVERIFY2(near(w.states()[1].omega_W, Vec3(0, 0.03, 0), 1e-14), text(w.states()[1].omega_W));
}

void TestMotionLessons::bodyPointRoundTrip()
{
    World w(lessonScene("02-single-body/scene.json"));
    stepN(w, 137);   // some general pose
    const Vec3 p_B(0.5, -0.3, 0.25);
    const Vec3 p_W = w.bodyToWorld(0, p_B);
    QVERIFY(near(w.worldToBody(0, p_W), p_B, 1e-14));
    // The world point moves with the body: |p_W - x| = |p_B| (R is a rotation).
    QCOMPARE(qRound64(1e12 * (p_W - w.states()[0].x_W).norm()), qRound64(1e12 * p_B.norm()));
}

QTEST_GUILESS_MAIN(TestMotionLessons)
#include "tst_motion_lessons.moc"
