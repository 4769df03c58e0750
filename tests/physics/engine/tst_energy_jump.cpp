// Energy-jump blow-up detection (World::step, docs/stability.md): a step stops the run
// when a body's kinetic energy after the integration exceeds
//   T_max = factor (T_n + W_n) + floor,
//   W_n = h |F.v| + h^2 |F|^2/(2M) + h |q.omega| + h^2 |q|^2 max(I0^-1)/2,
// and the status names the step, the body and "kinetic_energy".
//
// The case, derived by hand. A symmetric needle: size (sqrt 199, 1, 1), M = 12, so
//   I0 = M/12 diag(1 + 1, 199 + 1, 199 + 1) = diag(i, J, J) = diag(2, 200, 200).
// It rests (r = identity) until a couple q acts in step 2 only, with h q = L* = (2, 200, 0):
//   steps 0, 1: nothing moves, T = 0 stays 0 (W = 0, T_max = floor).
//   step 2: L = h q = (2, 200, 0); r moves with the OLD omega = 0, so R = E and
//     omega = I0^-1 L = (1, 1, 0), T_3 = 1/2 omega.L = 1/2 (2 + 200) = 101 J.
//     W_2 = h^2 |q|^2 max(I0^-1)/2 = |L*|^2 / (2 i) = (4 + 40000)/4 = 10001 J, so
//     T_max = 10 * 10001 + floor: no jump.
//   step 3: no load, W_3 = 0, T_max = 10 * 101 J + floor. Explicit Euler turns r by
//     r <- normalise((1, (h/2) omega) r): the turn by 2 atan(h |omega| / 2) about omega.
//     With h = sqrt 2 and |omega| = sqrt 2, h |omega| / 2 = 1: a 90 degree turn about
//     w = (1, 1, 0)/sqrt 2. L stays (2, 200, 0). For a symmetric body
//       I^-1_W = (1/J) E + (1/i - 1/J) e e^T,  e = R e_x (the needle's axis),
//     and turning e_x = (w + u)/sqrt 2, u = (1, -1, 0)/sqrt 2, by 90 degrees about w gives
//       e = (w + w x u)/sqrt 2 = (1/2, 1/2, -1/sqrt 2),  e.L = (2 + 200)/2 = 101.
//     T = 1/2 (|L|^2/J + (1/i - 1/J)(e.L)^2) = 1/2 (40004/200 + 0.495 * 10201)
//       = 1/2 (200.02 + 5049.495) = 2624.7575 J = 25.988 * 101 J  > 10 * 101 J:
//   the run stops in step 3, body "needle", T 101 J -> 2624.7575 J.
// With factor 25.9 it still stops there; with factor 26 (> 25.988) it does not: the
// bound is exactly the one derived. The control with h = 0.01 (the same L, q = L/h)
// runs 2000 steps without firing: explicit Euler's T may grow by at most I_max/I_min
// overall, and per step by far less than 10 times.
#include "app/output/json_output.h"
#include "app/core/lesson_catalogue.h"
#include "app/scene/scene_loader.h"
#include "physics/engine/world.h"
#include "tests/test_support.h"

#include <QJsonDocument>
#include <QtTest>

#include <cmath>

using rbw::Quat;
using rbw::Vec3;

namespace {

rbw::SceneDef needle(double h, double factor)
{
    rbw::SceneDef s;
    s.name = "needle";
    s.dt = h;
    s.steps = 10;
    s.energyJumpFactor = factor;
    rbw::BodyDef b = rbw::test::boxDef("needle", Vec3(std::sqrt(199.0), 1, 1), 12.0, Vec3::Zero(),
                                       Quat::Identity(), Vec3::Zero(), Vec3::Zero());
    s.bodies.push_back(b);
    rbw::TorqueDef t;
    t.body = 0;
    t.q_W = Vec3(2, 200, 0) / h;   // h q = L* = (2, 200, 0)
    t.fromStep = 2;
    t.toStep = 3;
    s.torques.push_back(t);
    return s;
}

} // namespace

class TestEnergyJump : public QObject {
    Q_OBJECT

private slots:
    void largeDtStopsAtStep3_data();
    void largeDtStopsAtStep3();
    void smallDtControl();
    void switchedOff();
    void blowUpJsonHasNoNaN();
    void lessonsRunWithoutFiring_data();
    void lessonsRunWithoutFiring();
};

void TestEnergyJump::largeDtStopsAtStep3_data()
{
    QTest::addColumn<double>("factor");
    QTest::addColumn<bool>("fires");
    QTest::newRow("default factor 10") << 10.0 << true;
    QTest::newRow("factor 25.9 < 25.988") << 25.9 << true;
    QTest::newRow("factor 26 > 25.988 (control)") << 26.0 << false;
}

void TestEnergyJump::largeDtStopsAtStep3()
{
    QFETCH(double, factor);
    QFETCH(bool, fires);
    const rbw::SceneDef s = needle(std::sqrt(2.0), factor);
    QVERIFY(rbw::validate(s).empty());
    rbw::World world(s);
    for (int k = 0; k < 3; ++k) {
        const rbw::StepStatus st = world.step();
        QVERIFY2(st.ok, st.message.c_str());
    }
    RBW_COMPARE_NEAR(world.diagnostics().kinetic, 101.0, 1e-12 * 101.0);
    const rbw::StepStatus st = world.step();
    if (!fires) {
        QVERIFY2(st.ok, st.message.c_str());
        // T after step 3 is the derived 2624.7575 J.
        RBW_COMPARE_NEAR(world.diagnostics().kinetic, 2624.7575, 1e-9 * 2624.7575);
        return;
    }
    QVERIFY(!st.ok);
    QCOMPARE(st.step, 3L);
    QCOMPARE(st.body, 0);
    QCOMPARE(QString::fromStdString(st.quantity), QStringLiteral("kinetic_energy"));
    QCOMPARE(QString::fromStdString(st.kind), QStringLiteral("energy-jump"));
    RBW_COMPARE_NEAR(st.kineticBefore, 101.0, 1e-12 * 101.0);
    RBW_COMPARE_NEAR(st.kineticAfter, 2624.7575, 1e-9 * 2624.7575);
    RBW_COMPARE_NEAR(st.kineticBound, (factor * 101.0 + s.energyJumpFloor), 1e-12 * factor * 101.0);
    const QString m = QString::fromStdString(st.message);
    QVERIFY2(m.contains("step 3") && m.contains("\"needle\"") && m.contains("kinetic_energy") &&
                 m.contains("smaller dt"),
             qPrintable(m));
    // The world refuses further steps.
    QCOMPARE(world.step().step, 3L);
}

void TestEnergyJump::smallDtControl()
{
    rbw::SceneDef s = needle(0.01, 10.0);
    rbw::World world(s);
    for (int k = 0; k < 2000; ++k) {
        const rbw::StepStatus st = world.step();
        QVERIFY2(st.ok, st.message.c_str());
    }
}

void TestEnergyJump::switchedOff()
{
    rbw::World world(needle(std::sqrt(2.0), 0.0));
    QVERIFY(!world.runsStage(rbw::PipelineStage::EnergyCheck));
    for (int k = 0; k < 10; ++k) QVERIFY(world.step().ok);
}

// The CLI's blow-up document carries the numbers, all finite: no NaN is printed.
void TestEnergyJump::blowUpJsonHasNoNaN()
{
    rbw::World world(needle(std::sqrt(2.0), 10.0));
    rbw::StepStatus st;
    for (int k = 0; k < 4; ++k) st = world.step();
    QVERIFY(!st.ok);
    const QJsonObject o = rbw::blowUpToJson(st, "needle.json");
    QCOMPARE(o.value("kind").toString(), QStringLiteral("energy-jump"));
    QCOMPARE(o.value("step").toInteger(), 3);
    QCOMPARE(o.value("quantity").toString(), QStringLiteral("kinetic_energy"));
    const QByteArray text = QJsonDocument(o).toJson();
    QVERIFY2(!text.contains("nan") && !text.contains("inf"), text.constData());
    RBW_COMPARE_NEAR_STRICT(o.value("kinetic_energy_after").toDouble(), 2624.7575, 1e-6);
}

// Every lesson, including its drags and pushes by key (applyForceOnce each step),
// runs its steps without the detector firing.
void TestEnergyJump::lessonsRunWithoutFiring_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<bool>("push");
    for (const rbw::Lesson& l : rbw::lessonCatalogue(QStringLiteral(RBW_SOURCE_DIR "/lessons"))) {
        QTest::newRow(qPrintable(l.id)) << l.scenePath << false;
        QTest::newRow(qPrintable(l.id + " pushed")) << l.scenePath << true;
    }
}

void TestEnergyJump::lessonsRunWithoutFiring()
{
    QFETCH(QString, path);
    QFETCH(bool, push);
    const rbw::SceneLoadResult r = rbw::loadSceneFile(path);
    QVERIFY2(r.ok(), qPrintable(r.errors.join('\n')));
    rbw::World world(*r.scene);
    QVERIFY(world.runsStage(rbw::PipelineStage::EnergyCheck));
    const long steps = std::max(r.scene->steps, 200L);
    for (long k = 0; k < steps; ++k) {
        if (push) {
            // A hard drag on every movable body, off-centre, in every 10th step: 100 N
            // per kg, as a mouse spring pulling a box across the screen.
            for (int b = 0; b < static_cast<int>(r.scene->bodies.size()); ++b) {
                if (r.scene->bodies[b].fixed || k % 10 != 0) continue;
                const Vec3 p = world.bodyToWorld(b, 0.4 * r.scene->bodies[b].size);
                world.applyForceOnce(b, p, Vec3(100.0, 50.0, -30.0) * r.scene->bodies[b].mass);
            }
        }
        const rbw::StepStatus st = world.step();
        QVERIFY2(st.ok, st.message.c_str());
    }
}

QTEST_GUILESS_MAIN(TestEnergyJump)
#include "tst_energy_jump.moc"
