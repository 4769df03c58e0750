// The soft-step solver ("solver": "soft-step", issue 19) in a world: the resting
// impulse per step, restitution at the end of the step, the friction cone after every
// substep. Expected values are derived in the comments; the scenes are those of
// tst_contact_solver (manifold_test_scenes.h).
#include "physics/engine/world.h"
#include "tests/physics/engine/manifold/manifold_test_scenes.h"
#include "tests/test_support.h"

#include <QtTest>

#include <cmath>

using rbw::SceneDef;
using rbw::Vec3;
using rbw::World;
using namespace rbw::test::manifold;

class TestSoftStepSolver : public QObject {
    Q_OBJECT

private slots:
    // The soft step ("solver": "soft-step", 4 substeps of h_s = h/4) on a box resting on
    // the ground. Over one step v_end = v_start - g h + P_n / M (P_n the step's normal
    // impulse, summed over substeps: step_normal_impulse), so at rest (v_end = v_start)
    // P_n = M g h = 0.1635 N s, however many substeps carry it. After 2 s (120 steps, no
    // sleeping) the box is at rest within 1e-6 m/s per step, so the sum of the four
    // corners' P_n is M g h within M * 1e-6 m/s = 1e-6 N s; and each substep's own
    // impulse (normal_impulse, the last substep's) is M g h_s: the sum over the corners
    // within 1e-6 N s of M g h / n. It sinks as a spring of the contact's frequency does
    // under its weight: a solve pass changes nothing (v_n = 0 after the warm start) when
    // -m_n s_m beta_s s = s_i lambda_n, lambda_n = M g h_s over the corners: s = -g/omega^2,
    // omega = 2 pi f, f = 2/(8 h_s) against the ground: 0.017 mm at 120 Hz (8 substeps),
    // 0.069 mm at 60 Hz (4), 1.10 mm at 15 Hz (1). Within 5 % (the corners' rows couple).
    void softStepRestingImpulse_data()
    {
        QTest::addColumn<int>("substeps");
        QTest::newRow("1 substep") << 1;
        QTest::newRow("4 substeps") << 4;
        QTest::newRow("8 substeps") << 8;
    }

    void softStepRestingImpulse()
    {
        QFETCH(int, substeps);
        SceneDef s = groundScene(0.5, false);
        s.solver = rbw::ManifoldSolver::SoftStep;
        s.substeps = substeps;
        addBox(s, Vec3(0.0, 0.5, 0.0));
        World w(s);
        rbw::StepTrace t;
        for (int k = 0; k < 120; ++k) w.step(&t);
        const double vBefore = w.states()[0].v_W.y();
        w.step(&t);
        QVERIFY(std::abs(w.states()[0].v_W.y() - vBefore) <= 1e-6);
        const std::vector<double> P_n = scalars(t, "step_normal_impulse");
        QCOMPARE(P_n.size(), std::size_t(4));
        RBW_COMPARE_NEAR_STRICT(sum(P_n), kG * kH, 1e-6);
        RBW_COMPARE_NEAR_STRICT(sum(scalars(t, "normal_impulse")), kG * kH / substeps, 1e-6);
        const double f = 2.0 / (8.0 * kH / substeps);
        const double omega = 2.0 * 3.14159265358979323846 * f;
        const double sink = kG / (omega * omega);
        RBW_COMPARE_NEAR_STRICT(0.5 - w.states()[0].x_W.y(), sink, 0.05 * sink);
    }

    // Restitution at the end of the soft step (Box2D's b2ApplyRestitution): a box that
    // cannot turn (so that the four corners' rows do not disturb each other) falls at
    // 3 m/s onto the ground from 1 cm above it, c = 0.5, threshold 1 m/s. The substeps
    // stop it; the restitution pass then sets each hit point's v_n to -c v_n0, where v_n0
    // = -3 m/s is the normal velocity at the start of the step: v_y = 1.5 m/s after the
    // step. c = 0 is the control: the box stays, v_y = 0 within the rest tolerance.
    void softStepRestitution_data()
    {
        QTest::addColumn<double>("c");
        QTest::newRow("c = 0.5") << 0.5;
        QTest::newRow("c = 0 (control)") << 0.0;
    }

    void softStepRestitution()
    {
        QFETCH(double, c);
        SceneDef s = groundScene(0.0, false);
        s.solver = rbw::ManifoldSolver::SoftStep;
        s.restitution = c;
        s.restitutionThreshold = 1.0;
        addBox(s, Vec3(0.0, 0.51, 0.0), Vec3(0.0, -3.0, 0.0));
        s.bodies[0].angularResponse = false;
        World w(s);
        w.step(nullptr);
        RBW_COMPARE_NEAR_STRICT(w.states()[0].v_W.y(), c * 3.0, c > 0.0 ? 1e-9 : 0.01);
    }

    // The friction cone after every substep: a box sliding at 2 m/s (mu = 0.3); each
    // substep's accumulated impulses (ContactHeader::iterations, one per substep) keep
    // lambda_n >= 0 and |lambda_t| <= mu lambda_n. Sliding all the time, each substep's
    // friction impulse is on the cone, mu lambda_n against the sliding (along x), so over
    // two steps v_x = 2 - mu sum P_n / M, P_n the steps' normal impulses
    // (step_normal_impulse), about 2 - 2 mu g h = 1.9019 m/s. mu = 0: v_x = 2 (control).
    void softStepFrictionCone_data()
    {
        QTest::addColumn<double>("mu");
        QTest::newRow("mu = 0.3") << 0.3;
        QTest::newRow("mu = 0 (control)") << 0.0;
    }

    void softStepFrictionCone()
    {
        QFETCH(double, mu);
        SceneDef s = groundScene(mu, false);
        s.solver = rbw::ManifoldSolver::SoftStep;
        addBox(s, Vec3(0.0, 0.5, 0.0), Vec3(2.0, 0.0, 0.0));
        World w(s);
        rbw::StepTrace first, t;
        w.step(&first);
        w.step(&t);   // the second step: warm-started, the corners share the weight
        const double P_n = sum(scalars(first, "step_normal_impulse")) + sum(scalars(t, "step_normal_impulse"));
        RBW_COMPARE_NEAR_STRICT(P_n, 2.0 * kG * kH, 1e-3 * kG * kH);
        QCOMPARE(t.contacts.size(), std::size_t(4));
        bool sawFriction = false;
        for (const rbw::ContactHeader& h : t.contacts) {
            QCOMPARE(h.iterations.size(), std::size_t(5));   // one per substep (the default 5)
            for (const rbw::ImpulseIterate& it : h.iterations) {
                QVERIFY(it.lambda_n >= 0.0);
                QVERIFY(it.lambda_t_W.norm() <= mu * it.lambda_n * (1.0 + 1e-12) + 1e-15);
                sawFriction = sawFriction || it.lambda_t_W.norm() > 0.0;
            }
        }
        QCOMPARE(sawFriction, mu > 0.0);
        // (1e-6: the box yaws a little, its corners solved in turn; measured 6e-8 m/s)
        RBW_COMPARE_NEAR_STRICT(w.states()[0].v_W.x(), 2.0 - mu * P_n, 1e-6);
    }
};

QTEST_APPLESS_MAIN(TestSoftStepSolver)
#include "tst_soft_step_solver.moc"
