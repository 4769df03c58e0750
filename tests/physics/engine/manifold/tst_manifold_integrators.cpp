// The manifold model with every integrator (issue 19, item 1): forces -> velocities ->
// contacts -> positions, whatever integrator the scene names; the integrator's own
// position and orientation formula is applied with the solved velocities
// (manifold_velocity_stage.h, docs/collisions.md "Every integrator").
#include "tests/test_support.h"

#include "physics/engine/integrator_registry.h"
#include "physics/engine/world.h"
#include "physics/workbook/lab/contact_problems.h"

#include <QtTest>

#include <algorithm>

using namespace rbw;

namespace {

// One unit box (M = 1 kg) over a ground plane, c = 0, mu = 0.5, in the manifold model.
SceneDef boxOverGround(const std::string& integrator, double y0, double dt)
{
    SceneDef s;
    s.name = "box";
    s.dt = dt;
    s.integrator = integrator;
    s.g_W = Vec3(0.0, -9.81, 0.0);
    s.contactModel = ContactModel::Manifold;
    // The sequential impulses, whose step moves a body by h v_{n+1} (the soft step moves
    // it by its substeps' sum of h_s v_i; the rain's rows below test both)
    s.solver = ManifoldSolver::SequentialImpulses;
    s.restitution = 0.0;
    s.friction = 0.5;
    PlaneDef ground;
    ground.name = "ground";
    ground.point_W = Vec3::Zero();
    ground.n_W = Vec3::UnitY();
    s.planes.push_back(ground);
    BodyDef b;
    b.name = "box";
    b.x0_W = Vec3(0.0, y0, 0.0);
    s.bodies.push_back(b);
    return s;
}

double speed(const BodyState& s) { return s.v_W.norm(); }

} // namespace

class TestManifoldIntegrators : public QObject {
    Q_OBJECT

private slots:
    // One step of free fall from rest, h = 0.01 s, g = 9.81 m/s^2, far above the ground
    // (no contact within the margin). Forces -> velocities -> positions:
    //   v_1 = v_0 + h g = -0.0981 m/s,  x_1 = x_0 + h v_1 = 10 - 0.000981 m
    // for every integrator (the translation of each is x_{n+1} = x_n + h v_{n+1} once
    // the velocity has been updated first). In the course model explicit Euler gives
    // x_1 = x_0 + h v_0 = 10 m exactly (the control).
    void freeFallPositionUsesTheNewVelocity_data()
    {
        QTest::addColumn<QString>("integrator");
        for (const IntegratorInfo& info : integratorCatalogue()) QTest::newRow(info.name) << QString::fromLatin1(info.name);
    }

    void freeFallPositionUsesTheNewVelocity()
    {
        QFETCH(QString, integrator);
        const double h = 0.01;
        World w(boxOverGround(integrator.toStdString(), 10.0, h));
        QVERIFY(w.step().ok);
        const BodyState& s = w.states()[0];
        RBW_COMPARE_NEAR(s.v_W, Vec3(0.0, -9.81 * h, 0.0), 1e-15);
        RBW_COMPARE_NEAR(s.x_W, Vec3(0.0, 10.0 - 9.81 * h * h, 0.0), 1e-15);

        if (integrator == QLatin1String("explicit-euler")) {
            SceneDef course = boxOverGround("explicit-euler", 10.0, h);
            course.contactModel = ContactModel::Course;
            course.solver = std::nullopt;   // a manifold key: the course model refuses it
            World c(course);
            QVERIFY(c.step().ok);
            QCOMPARE(c.states()[0].x_W.y(), 10.0);   // x_1 = x_0 + h v_0, v_0 = 0
        }
    }

    // A unit box put on the ground at rest stays there under every integrator: 600 steps
    // of h = 1/60 s. Before the fix, explicit Euler moved it with v_n = 0 and then
    // gave it v = -g h every step, so it sank g h^2 = 2.7 mm per step before the position
    // fix. Bound: 1 mm of drift (a fifth of the 5 mm slop the position fix leaves) and
    // the sleep tolerance, 1 cm/s: the box is at rest as the engine itself defines it.
    void restingBoxStaysPut_data() { freeFallPositionUsesTheNewVelocity_data(); }

    void restingBoxStaysPut()
    {
        QFETCH(QString, integrator);
        World w(boxOverGround(integrator.toStdString(), 0.5, 1.0 / 60.0));
        double worstDrift = 0.0;
        for (int k = 0; k < 600; ++k) {
            QVERIFY(w.step().ok);
            worstDrift = std::max(worstDrift, (w.states()[0].x_W - Vec3(0.0, 0.5, 0.0)).norm());
        }
        QVERIFY2(worstDrift <= 1e-3, qPrintable(QString::number(worstDrift)));
        QVERIFY(speed(w.states()[0]) <= 0.01);
    }

    // The 100-box rain (contact_problems.h: one 10 x 10 layer of unit boxes, turned by up
    // to 0.2 rad, dropped from 3 m; mu = 0.5, c = 0, h = 1/60 s) with explicit Euler, the
    // integrator every lesson starts with, rests: after 10 s every box is slower than the
    // sleep tolerance 1 cm/s (the engine's own definition of rest; asleep boxes have
    // v = 0), the kinetic energy is at most 1e-3 J (100 boxes at the tolerance:
    // 100 * 1/2 * 1 kg * (0.01 m/s)^2 = 5e-3 J, so this also rules out a few boxes just
    // under it), and no box is deeper than 1 cm in the ground (issue 19's target for the
    // overlap; the position fix's slop is 5 mm). Non-vacuous: after 40 steps (t = 2/3 s,
    // before the lowest corners, about 2.2 m up, reach the ground) every box falls at
    // g t = 6.5 m/s: KE = 100 * 1/2 * 1 kg * (6.54 m/s)^2 = 2.1 kJ > 1 kJ.
    // Both solvers of the manifold model: the sequential impulses and the soft step.
    void rainRestsUnderExplicitEuler_data()
    {
        QTest::addColumn<bool>("soft");
        QTest::newRow("sequential impulses") << false;
        QTest::newRow("soft step") << true;
    }

    void rainRestsUnderExplicitEuler()
    {
        QFETCH(bool, soft);
        SceneDef s = lab::contactProblemScene(lab::ContactProblem::Rain, ContactModel::Manifold, 100);
        s.integrator = "explicit-euler";
        s.solver = soft ? ManifoldSolver::SoftStep : ManifoldSolver::SequentialImpulses;
        World w(s);
        for (int k = 0; k < 600; ++k) {
            QVERIFY(w.step().ok);
            if (k == 39) QVERIFY2(w.diagnostics().kinetic > 1000.0, qPrintable(QString::number(w.diagnostics().kinetic)));
        }
        const lab::ContactMeasure m = lab::measureContacts(s, w.massProperties(), w.states());
        double fastest = 0.0;
        for (const BodyState& b : w.states()) fastest = std::max(fastest, speed(b));
        const double ke = w.diagnostics().kinetic;
        QVERIFY2(fastest <= 0.01, qPrintable(QStringLiteral("fastest box %1 m/s").arg(fastest)));
        QVERIFY2(ke <= 1e-3, qPrintable(QStringLiteral("KE %1 J").arg(ke)));
        QVERIFY2(m.deepestBelow <= 0.01, qPrintable(QStringLiteral("%1 m below the ground").arg(m.deepestBelow)));
        QVERIFY2(m.deepestOverlap <= 0.01, qPrintable(QStringLiteral("box-box overlap %1 m").arg(m.deepestOverlap)));
    }
};

QTEST_GUILESS_MAIN(TestManifoldIntegrators)
#include "tst_manifold_integrators.moc"
