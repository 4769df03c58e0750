// The mistake models of physics/workbook/checker/mistakes.h against hand-derived numbers.
//
// Table 2.1 (lesson 1): box a, b, c = 1, 0.6, 0.5, M = 2, x = 0, v = 0, L = 0,
// r = 90 deg about z = [0.7071068, 0, 0, 0.7071068], f = (1, 1, 0) at p = (0.3, 0.5, 0.25),
// h = 2. By hand:
//   q = (p - x) x f = (0.5*0 - 0.25*1, 0.25*1 - 0.3*0, 0.3*1 - 0.5*1) = (-0.25, 0.25, -0.2)
//   v' = v + h F/M = (1, 1, 0),  x' = x + h v = 0,  L' = L + h q = (-0.5, 0.5, -0.4)
//   I0 = M/12 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2) = diag(0.61, 1.25, 1.36)/6
//      = diag(0.1016667, 0.2083333, 0.2266667);  I0^-1 = diag(9.836066, 4.8, 4.411765)
//   R = Rz(90): I^-1 = R I0^-1 R^T = diag(4.8, 9.836066, 4.411765)
//   omega' = I^-1 L' = (-2.4, 4.918033, -1.764706)
// Lesson 3: p = (1.02, 0.5, 0), n = (-1, 0, 0), x_A = (0.03, 0, 0), v_A = (1, 0, 0),
// v_B = (-1, 0, 0), no spin, c = 1, 1/M_A = 0.5, 1/M_B = 1, I_A^-1 = 3/4 E, B's lever arm
// along n: v_rel = (2, 0, 0), v_rel.n = -2, numerator 4, denominator 27/16, J = 64/27.
#include "tests/test_support.h"

#include "physics/workbook/checker/mistakes.h"
#include "physics/engine/quantities.h"
#include "physics/engine/world.h"

#include <QtTest>

using rbw::Mistake;
using rbw::Quat;
using rbw::Vec3;

Q_DECLARE_METATYPE(rbw::Mistake)

namespace {

rbw::BodyStepInputs table21()
{
    rbw::BodyStepInputs in;
    in.h = 2.0;
    in.mass = 2.0;
    in.size = Vec3(1, 0.6, 0.5);
    in.q_WB = Quat(std::sqrt(0.5), 0, 0, std::sqrt(0.5));
    in.forces = {{Vec3(0.3, 0.5, 0.25), Vec3(1, 1, 0)}};
    // probes at (-0.3, -0.5, -0.25) and (0.3, 0.5, 0.25) in the world at t = 0: body
    // frame p_B = R^T p = Rz(-90) p
    in.probes_B = {Vec3(-0.5, 0.3, -0.25), Vec3(0.5, -0.3, 0.25)};
    return in;
}

rbw::ContactInputs lesson3()
{
    rbw::ContactInputs c;
    c.g.p_W = Vec3(1.02, 0.5, 0);
    c.g.n_W = Vec3(-1, 0, 0);
    c.restitution = 1.0;
    c.x_A = Vec3(0.03, 0, 0);
    c.v_A = Vec3(1, 0, 0);
    c.Iinv_A = 0.75 * rbw::Mat3::Identity();
    c.invM_A = 0.5;
    c.x_B = Vec3(1.02 + 0.866, 0.5, 0);   // x_b = p - x_B along n: no rotational term
    c.v_B = Vec3(-1, 0, 0);
    c.Iinv_B = 6.0 * rbw::Mat3::Identity();
    c.invM_B = 1.0;
    // body-frame inverses that differ from I^-1 (impulse-body-inverse-inertia)
    c.I0inv_A = Vec3(1, 2, 3).asDiagonal();
    c.I0inv_B = Vec3(1, 1, 1).asDiagonal();
    return c;
}

QList<double> handValue(const rbw::HandEulerStep& s, const char* id, int index = -1)
{
    rbw::TraceValue v;
    if (!s.value(id, index, v)) qFatal("no %s in the hand step", id);
    return rbw::test::flatten(v);
}

QList<double> impulseValue(const rbw::HandImpulse& s, const char* id)
{
    rbw::TraceValue v;
    if (!s.value(id, v)) qFatal("no %s in the hand impulse", id);
    return rbw::test::flatten(v);
}

// Table 2.1's box spinning about x: r = 1, omega0 = (10, 0, 0) (L = I0_xx omega0 =
// (1.016667, 0, 0)), a couple (0, 1, 0), no force, h = 0.1. By hand:
//   L' = (1.016667, 0.1, 0);  r' = normalise((1, 0, 0, 0) + 0.05 (0, 10, 0, 0)) = (1, 0.5, 0, 0)/sqrt(1.25)
//      = (0.894427, 0.447214, 0, 0): a turn by th = 2 atan(0.5) about x, cos th = 0.6, sin th = 0.8
//   with a, b, c = 9.836066, 4.8, 4.411765 (I0^-1): I^-1 L' = R D R^T L' = (a L_x,
//      0.1 (b cos^2 + c sin^2), 0.1 (b - c) sin cos) = (10, 0.455153, 0.018635)
rbw::BodyStepInputs spinningAboutX()
{
    rbw::BodyStepInputs in = table21();
    in.q_WB = Quat::Identity();
    in.forces.clear();
    in.couple_W = Vec3(0, 1, 0);
    in.h = 0.1;
    in.L_W = Vec3(0.61 / 6.0 * 10.0, 0, 0);
    return in;
}

} // namespace

class TestMistakes : public QObject {
    Q_OBJECT
private slots:
    // The correct hand step is the physics' own step: lesson 1's trace, number for number.
    void correctHandStepIsThePhysics()
    {
        rbw::World world(rbw::test::lessonScene(QStringLiteral("01-one-step/scene.json")));
        rbw::StepTrace trace;
        QVERIFY(world.step(&trace).ok);
        const rbw::HandEulerStep s = rbw::handEulerStep(table21());
        for (const rbw::QuantityInfo* q : {&rbw::q::position, &rbw::q::linear_velocity, &rbw::q::orientation,
                                           &rbw::q::angular_momentum, &rbw::q::inverse_inertia_world,
                                           &rbw::q::angular_velocity, &rbw::q::inertia_body}) {
            const rbw::TraceEntry* e = trace.find(q->id, 0);
            QVERIFY2(e != nullptr, q->id);
            const QString m = rbw::test::mismatch(handValue(s, q->id), rbw::test::flatten(e->value), 1e-12);
            QVERIFY2(m.isEmpty(), qPrintable(QString::fromLatin1(q->id) + QStringLiteral(": ") + m));
        }
        for (int i = 0; i < 2; ++i) {
            const rbw::TraceEntry* e = trace.find(rbw::q::point_velocity.id, 0, i);
            QVERIFY(e != nullptr);
            const QString m =
                rbw::test::mismatch(handValue(s, rbw::q::point_velocity.id, i), rbw::test::flatten(e->value), 1e-12);
            QVERIFY2(m.isEmpty(), qPrintable(m));
        }
    }

    void eulerMistake_data()
    {
        QTest::addColumn<Mistake>("mistake");
        QTest::addColumn<QString>("id");
        QTest::addColumn<int>("index");
        QTest::addColumn<QList<double>>("expected");
        // x <- x + h v_{n+1} = 0 + 2 (1, 1, 0)
        QTest::newRow("velocity-before-position") << Mistake::VelocityBeforePosition << "position" << -1
                                                  << QList<double>{2, 2, 0};
        // L <- L + q, v <- v + F/M = (0.5, 0.5, 0)
        QTest::newRow("missing-time-step L") << Mistake::MissingTimeStep << "angular_momentum" << -1
                                             << QList<double>{-0.25, 0.25, -0.2};
        QTest::newRow("missing-time-step v") << Mistake::MissingTimeStep << "linear_velocity" << -1
                                             << QList<double>{0.5, 0.5, 0};
        // q = f x (p - x) = -(p - x) x f
        QTest::newRow("torque-reversed") << Mistake::TorqueReversed << "torque" << -1
                                         << QList<double>{0.25, -0.25, 0.2};
        // omega = I0^-1 L' = (9.836066 * -0.5, 4.8 * 0.5, 4.411765 * -0.4)
        QTest::newRow("body-inverse-inertia") << Mistake::BodyInverseInertia << "angular_velocity" << -1
                                              << QList<double>{-4.918033, 2.4, -1.764706};
        // omega = I L' with I = R I0 R^T = diag(1.25, 0.61, 1.36)/6:
        //   (-1.25/12, 0.61/12, -1.36*0.4/6)
        QTest::newRow("inertia-not-inverted") << Mistake::InertiaNotInverted << "angular_velocity" << -1
                                              << QList<double>{-0.1041667, 0.0508333, -0.0906667};
        // I0 of the half extents: a quarter of the right one
        QTest::newRow("half-extents-for-size") << Mistake::HalfExtentsForSize << "inertia_body" << -1
                                               << QList<double>{0.0254167, 0, 0, 0, 0.0520833, 0, 0, 0, 0.0566667};
        // v_p = v = (1, 1, 0) (the right one is (3.111861, 1.070588, -2.67541))
        QTest::newRow("point-velocity-without-rotation") << Mistake::PointVelocityWithoutRotation << "point_velocity"
                                                         << 1 << QList<double>{1, 1, 0};
        // r' = normalise(r + (h/2)(0, omega') r), omega' = (-2.4, 4.918033, -1.764706), h/2 = 1:
        //   (0, omega') r = (-omega'.v, s omega' + omega' x v) with r = (s, v), s = sqrt(1/2),
        //   v = (0, 0, s): (1.247835, 1.780518, 5.174631, -1.247835)  [w, x, y, z]
        //   r + that = (1.954942, 1.780518, 5.174631, -0.540729), |.| = 5.836200
        QTest::newRow("omega-before-orientation") << Mistake::OmegaBeforeOrientation << "orientation" << -1
                                                  << QList<double>{0.3349683, 0.3050817, 0.8866438, -0.0926508};
        // Probe 1 at p = R p_B = (0.3, 0.5, 0.25) (x' = 0): omega' x p = (2.111861, 0.070588, -2.675410),
        // so the right v_p = v + omega' x p = (3.111861, 1.070588, -2.675410) and the reversed
        // v + p x omega' = v - omega' x p = (1 - 2.111861, 1 - 0.070588, 0 + 2.675410).
        QTest::newRow("point-velocity-cross-reversed") << Mistake::PointVelocityCrossReversed << "point_velocity" << 1
                                                       << QList<double>{-1.111861, 0.929412, 2.675410};
        // Without the half angle the initial r = 90 deg about z becomes 180 deg: r0^2 =
        // (1/2 - 1/2, 0, 0, 2 * 1/2) = (0, 0, 0, 1), which stays (omega0 = 0).
        QTest::newRow("quaternion-without-half-angle r") << Mistake::QuaternionWithoutHalfAngle << "orientation" << -1
                                                         << QList<double>{0, 0, 0, 1};
        // R = diag(-1, -1, 1) leaves the diagonal I0^-1 as it is: omega' = I0^-1 L' =
        // (9.836066 * -0.5, 4.8 * 0.5, 4.411765 * -0.4), the same number as body-inverse-inertia.
        QTest::newRow("quaternion-without-half-angle omega") << Mistake::QuaternionWithoutHalfAngle << "angular_velocity"
                                                             << -1 << QList<double>{-4.918033, 2.4, -1.764706};
        // I0 = diag(0.1016667, 0.2083333, 0.2266667) with x and y exchanged (variant 0).
        QTest::newRow("inertia-axes-swapped I0") << Mistake::InertiaAxesSwapped << "inertia_body" << -1
                                                 << QList<double>{0.2083333, 0, 0, 0, 0.1016667, 0, 0, 0, 0.2266667};
        // I0^-1 = diag(4.8, 9.836066, 4.411765), Rz(90) exchanges x and y again: I^-1 =
        // diag(9.836066, 4.8, 4.411765) = I0^-1 of the right I0, so omega' = I0^-1 L' again.
        QTest::newRow("inertia-axes-swapped omega") << Mistake::InertiaAxesSwapped << "angular_velocity" << -1
                                                    << QList<double>{-4.918033, 2.4, -1.764706};
        // M diag(b^2 + c^2, ...) of the half extents 0.5, 0.3, 0.25: 2 diag(0.1525, 0.3125,
        // 0.34), three times I0; so omega' is a third of (-2.4, 4.918033, -1.764706).
        QTest::newRow("inertia-half-extents-without-third I0") << Mistake::InertiaHalfExtentsWithoutThird
                                                               << "inertia_body" << -1
                                                               << QList<double>{0.305, 0, 0, 0, 0.625, 0, 0, 0, 0.68};
        QTest::newRow("inertia-half-extents-without-third omega") << Mistake::InertiaHalfExtentsWithoutThird
                                                                  << "angular_velocity" << -1
                                                                  << QList<double>{-0.8, 1.639344, -0.588235};
    }

    // The models of issue 21 item 1 a one-step check can show, on spinningAboutX() and Table 2.1.
    void moreEulerMistakes_data()
    {
        QTest::addColumn<Mistake>("mistake");
        QTest::addColumn<bool>("spinning");   // spinningAboutX(), else table21()
        QTest::addColumn<QString>("id");
        QTest::addColumn<QList<double>>("expected");
        QTest::addColumn<QList<double>>("right");
        // R_n = E: I^-1 = I0^-1, omega' = (a L_x, b 0.1, 0) = (10, 0.48, 0); the right
        // R D R^T = [[a, 0, 0], [0, b cos^2 + c sin^2, (b - c) sin cos], [0, ., b sin^2 + c cos^2]]
        //         = [[9.836066, 0, 0], [0, 4.551529, 0.186353], [0, 0.186353, 4.660235]]
        QTest::newRow("inertia-from-old-orientation omega") << Mistake::InertiaFromOldOrientation << true
                                                            << "angular_velocity" << QList<double>{10, 0.48, 0}
                                                            << QList<double>{10, 0.455153, 0.018635};
        QTest::newRow("inertia-from-old-orientation I^-1")
            << Mistake::InertiaFromOldOrientation << true << "inverse_inertia_world"
            << QList<double>{9.836066, 0, 0, 0, 4.8, 0, 0, 0, 4.411765}
            << QList<double>{9.836066, 0, 0, 0, 4.551529, 0.186353, 0, 0.186353, 4.660235};
        // Table 2.1 without the h: r0 = 90 deg about z, th' = 90 rad, th'/2 = 45 rad:
        // (cos 45, 0, 0, sin 45) = (0.525322, 0, 0, 0.850904); omega0 = 0, so r' = r0'
        QTest::newRow("angle-in-degrees r") << Mistake::AngleInDegrees << false << "orientation"
                                            << QList<double>{0.525322, 0, 0, 0.850904}
                                            << QList<double>{std::sqrt(0.5), 0, 0, std::sqrt(0.5)};
    }

    void moreEulerMistakes()
    {
        QFETCH(Mistake, mistake);
        QFETCH(bool, spinning);
        QFETCH(QString, id);
        QFETCH(QList<double>, expected);
        QFETCH(QList<double>, right);
        const rbw::BodyStepInputs in = spinning ? spinningAboutX() : table21();
        const QString m = rbw::test::mismatch(handValue(rbw::handEulerStep(in, mistake), qPrintable(id)), expected, 2e-6);
        QVERIFY2(m.isEmpty(), qPrintable(m));
        // Negative control: the right step gives the right number, which is another one.
        const QString r = rbw::test::mismatch(handValue(rbw::handEulerStep(in), qPrintable(id)), right, 2e-6);
        QVERIFY2(r.isEmpty(), qPrintable(r));
        QVERIFY(!rbw::test::mismatch(right, expected, 1e-3).isEmpty());
    }

    // quaternion-right-multiplied needs r != 1 (r (0, w) = (0, w) r when r = 1): r = Rz(90) =
    // s (1, 0, 0, 1), s = sqrt(1/2), omega0 = (1, 0, 0) (L = (I0_yy, 0, 0): Rz(90) puts the
    // body's y along the world's x), h = 0.1, no load. With w = (1, 0, 0), v = (0, 0, s):
    //   (0, w) r = (-w.v, s w + w x v) = (0, s, -s, 0);  r (0, w) = (-v.w, s w + v x w) = (0, s, s, 0)
    //   right r' = normalise(s (1, 0.05, -0.05, 1)) = (1, 0.05, -0.05, 1)/sqrt(2.005)
    //          = (0.706225, 0.035311, -0.035311, 0.706225);  the model's (0.706225, 0.035311, 0.035311, 0.706225)
    void quaternionRightMultiplied()
    {
        rbw::BodyStepInputs in = table21();
        in.forces.clear();
        in.h = 0.1;
        in.L_W = Vec3(1.25 / 6.0, 0, 0);
        const QString wrong =
            rbw::test::mismatch(handValue(rbw::handEulerStep(in, Mistake::QuaternionRightMultiplied), "orientation"),
                                {0.706225, 0.035311, 0.035311, 0.706225}, 2e-6);
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong));
        const QString right = rbw::test::mismatch(handValue(rbw::handEulerStep(in), "orientation"),
                                                  {0.706225, 0.035311, -0.035311, 0.706225}, 2e-6);
        QVERIFY2(right.isEmpty(), qPrintable(right));
        // Negative control: at r = 1 the two products agree (the model is the right step).
        in.q_WB = Quat::Identity();
        in.L_W = Vec3(0.61 / 6.0, 0, 0);
        const QList<double> atOne = handValue(rbw::handEulerStep(in), "orientation");
        QVERIFY(rbw::test::mismatch(handValue(rbw::handEulerStep(in, Mistake::QuaternionRightMultiplied), "orientation"),
                                    atOne, 1e-12)
                    .isEmpty());
    }

    // inertia-axes-swapped has three variants: the pair of axes exchanged.
    void inertiaAxesSwappedVariants_data()
    {
        QTest::addColumn<int>("variant");
        QTest::addColumn<QList<double>>("diagonal");
        // diag(0.1016667, 0.2083333, 0.2266667) with two entries exchanged
        QTest::newRow("x-y") << 0 << QList<double>{0.2083333, 0.1016667, 0.2266667};
        QTest::newRow("y-z") << 1 << QList<double>{0.1016667, 0.2266667, 0.2083333};
        QTest::newRow("x-z") << 2 << QList<double>{0.2266667, 0.2083333, 0.1016667};
    }

    void inertiaAxesSwappedVariants()
    {
        QFETCH(int, variant);
        QFETCH(QList<double>, diagonal);
        const rbw::Mat3 I0 = rbw::handEulerStep(table21(), Mistake::InertiaAxesSwapped, variant).I0_B;
        const QString m = rbw::test::mismatch({I0(0, 0), I0(1, 1), I0(2, 2)}, diagonal, 1e-6);
        QVERIFY2(m.isEmpty(), qPrintable(m));
    }

    // The point's lever arm from the origin shows when x' != 0: x = (1, 0, 0), v = 0, the
    // force at p = (1.3, 0.5, 0.25) (the same lever arm, so the same q, L', omega'); x' = x,
    // probe 1 at p = (1.3, 0.5, 0.25). Right: (3.111861, 1.070588, -2.675410) as above;
    // wrong v + omega' x p adds omega' x x = (0, omega_z, -omega_y) = (0, -1.764706, -4.918033).
    void pointVelocityLeverArmFromOrigin()
    {
        rbw::BodyStepInputs in = table21();
        in.x_W = Vec3(1, 0, 0);
        in.forces = {{Vec3(1.3, 0.5, 0.25), Vec3(1, 1, 0)}};
        const QString wrong = rbw::test::mismatch(
            handValue(rbw::handEulerStep(in, Mistake::PointVelocityLeverArmFromOrigin), "point_velocity", 1),
            {3.111861, -0.694118, -7.593443}, 2e-6);
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong));
        // Negative control: the right step's v_p.
        const QString right = rbw::test::mismatch(handValue(rbw::handEulerStep(in), "point_velocity", 1),
                                                  {3.111861, 1.070588, -2.675410}, 2e-6);
        QVERIFY2(right.isEmpty(), qPrintable(right));
    }

    // The set-up mistakes of quaternion-without-half-angle and angle-in-degrees belong to
    // the initial orientation: at a later step (firstStep false) the model is the right step.
    void initialOrientationMistakesOnlyAtTheStart()
    {
        rbw::BodyStepInputs in = table21();
        in.firstStep = false;
        for (Mistake m : {Mistake::QuaternionWithoutHalfAngle, Mistake::AngleInDegrees}) {
            const QString s = rbw::test::mismatch(handValue(rbw::handEulerStep(in, m), "orientation"),
                                                  {std::sqrt(0.5), 0, 0, std::sqrt(0.5)}, 1e-12);
            QVERIFY2(s.isEmpty(), qPrintable(s));
        }
    }

    void eulerMistake()
    {
        QFETCH(Mistake, mistake);
        QFETCH(QString, id);
        QFETCH(int, index);
        QFETCH(QList<double>, expected);
        const rbw::HandEulerStep wrong = rbw::handEulerStep(table21(), mistake);
        const QString m = rbw::test::mismatch(handValue(wrong, qPrintable(id), index), expected, 2e-6);
        QVERIFY2(m.isEmpty(), qPrintable(m));
        // Negative control: the correct step gives another number.
        const rbw::HandEulerStep right = rbw::handEulerStep(table21());
        QVERIFY(!rbw::test::mismatch(handValue(right, qPrintable(id), index), expected, 1e-3).isEmpty());
    }

    // A lever arm from the origin only shows when x != 0: x = (1, 0, 0), p = (0.3, 0.5, 0.25),
    // f = (1, 1, 0): right (p - x) x f = (-0.7, 0.5, 0.25) x f = (-0.25, 0.25, -1.2),
    // wrong p x f = (-0.25, 0.25, -0.2).
    void leverArmFromOrigin()
    {
        rbw::BodyStepInputs in = table21();
        in.x_W = Vec3(1, 0, 0);
        const QString wrong = rbw::test::mismatch(
            handValue(rbw::handEulerStep(in, Mistake::LeverArmFromOrigin), "torque"), {-0.25, 0.25, -0.2}, 1e-12);
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong));
        const QString right = rbw::test::mismatch(handValue(rbw::handEulerStep(in), "torque"), {-0.25, 0.25, -1.2}, 1e-12);
        QVERIFY2(right.isEmpty(), qPrintable(right));
    }

    // Transposed inertia at r = 30 deg about z (where the two orders differ): L0 = 0 so r
    // does not turn, f = (0, 0, 1) at p = (0, 0.5, 0) gives q = (0.5, 0, 0), L' = (1, 0, 0).
    // With a, b = 9.836066, 4.8 and c, s = cos 30, sin 30:
    //   R I0^-1 R^T = [[a c^2 + b s^2, (a - b) c s, 0], [(a - b) c s, a s^2 + b c^2, 0], [0, 0, 4.411765]]
    //   a c^2 + b s^2 = 8.577049,  (a - b) c s = 2.180681
    // so omega' = (8.577049, 2.180681, 0) and, transposed, (8.577049, -2.180681, 0).
    void transposedInertia()
    {
        rbw::BodyStepInputs in = table21();
        in.q_WB = Quat(Eigen::AngleAxisd(M_PI / 6, Vec3::UnitZ()));
        in.forces = {{Vec3(0, 0.5, 0), Vec3(0, 0, 1)}};
        const QString right =
            rbw::test::mismatch(handValue(rbw::handEulerStep(in), "angular_velocity"), {8.577049, 2.180681, 0}, 1e-6);
        QVERIFY2(right.isEmpty(), qPrintable(right));
        const QString wrong = rbw::test::mismatch(
            handValue(rbw::handEulerStep(in, Mistake::TransposedInertia), "angular_velocity"), {8.577049, -2.180681, 0},
            1e-6);
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong));
    }

    // The quaternion mistakes need a spin: r = 1, omega0 = (1, 0, 0) (L = (I0_xx, 0, 0)),
    // h = 0.1: right normalise(1, 0.05, 0, 0) = (0.9987523, 0.0499376, 0, 0); without the
    // half normalise(1, 0.1, 0, 0) = (0.9950372, 0.0995037, 0, 0); not normalised (1, 0.05, 0, 0).
    void quaternionMistakes_data()
    {
        QTest::addColumn<Mistake>("mistake");
        QTest::addColumn<QList<double>>("expected");
        QTest::newRow("correct") << Mistake::None << QList<double>{0.9987523, 0.0499376, 0, 0};
        QTest::newRow("quaternion-missing-half") << Mistake::QuaternionMissingHalf
                                                 << QList<double>{0.9950372, 0.0995037, 0, 0};
        QTest::newRow("quaternion-not-normalised") << Mistake::QuaternionNotNormalised
                                                   << QList<double>{1, 0.05, 0, 0};
    }

    void quaternionMistakes()
    {
        QFETCH(Mistake, mistake);
        QFETCH(QList<double>, expected);
        rbw::BodyStepInputs in = table21();
        in.q_WB = Quat::Identity();
        in.forces.clear();
        in.h = 0.1;
        in.L_W = Vec3(0.61 / 6.0, 0, 0);
        const QString m = rbw::test::mismatch(handValue(rbw::handEulerStep(in, mistake), "orientation"), expected, 1e-6);
        QVERIFY2(m.isEmpty(), qPrintable(m));
    }

    void impulseMistake_data()
    {
        QTest::addColumn<Mistake>("mistake");
        QTest::addColumn<QString>("id");
        QTest::addColumn<QList<double>>("expected");
        QTest::newRow("correct J = 64/27") << Mistake::None << "impulse" << QList<double>{64.0 / 27.0};
        QTest::newRow("correct denominator 27/16") << Mistake::None << "denominator" << QList<double>{27.0 / 16.0};
        // v_rel = v_B - v_A = (-2, 0, 0), J = -(1 + 1)(+2)/(27/16) = -64/27
        QTest::newRow("relative-velocity-reversed v_rel") << Mistake::RelativeVelocityReversed << "relative_velocity"
                                                          << QList<double>{-2, 0, 0};
        QTest::newRow("relative-velocity-reversed J") << Mistake::RelativeVelocityReversed << "impulse"
                                                      << QList<double>{-64.0 / 27.0};
        // J = 4 / (0.5 + 1) = 8/3
        QTest::newRow("impulse-linear-only") << Mistake::ImpulseLinearOnly << "impulse" << QList<double>{8.0 / 3.0};
        // J = -1 * (-2) / (27/16) = 32/27
        QTest::newRow("impulse-without-one-plus") << Mistake::ImpulseWithoutOnePlus << "impulse"
                                                  << QList<double>{32.0 / 27.0};
        // numerator -(1 - c) v_rel.n = -(1 - 1)(-2) = 0 at c = 1: J = 0
        QTest::newRow("restitution-one-minus") << Mistake::RestitutionOneMinus << "impulse" << QList<double>{0.0};
        // x_a = x_b = p = (1.02, 0.5, 0): x x n = (0, 0, 0.5) for both; A: (0, 0, 0.375) x p . n
        // = 0.1875 (as right, x_A is along n); B: (0, 0, 3) x p = (-1.5, 3.06, 0), . n = 1.5:
        // denominator 0.5 + 1 + 0.1875 + 1.5 = 51/16, J = 4 / (51/16) = 64/51
        QTest::newRow("impulse-lever-arm-from-origin rotational_b") << Mistake::ImpulseLeverArmFromOrigin
                                                                    << "rotational_b" << QList<double>{1.5};
        QTest::newRow("impulse-lever-arm-from-origin J") << Mistake::ImpulseLeverArmFromOrigin << "impulse"
                                                         << QList<double>{64.0 / 51.0};
        // (I_A^-1 (x_a x n)) . n = (0, 0, 0.375) . n = 0, B's x_b x n = 0: denominator 1.5,
        // J = 8/3, the linear-only number (the terms are right: rotational_a 0.1875 for linear-only)
        QTest::newRow("impulse-denominator-missing-cross rotational_a") << Mistake::ImpulseDenominatorMissingCross
                                                                        << "rotational_a" << QList<double>{0.0};
        QTest::newRow("impulse-denominator-missing-cross J") << Mistake::ImpulseDenominatorMissingCross << "impulse"
                                                             << QList<double>{8.0 / 3.0};
        QTest::newRow("impulse-linear-only rotational_a") << Mistake::ImpulseLinearOnly << "rotational_a"
                                                          << QList<double>{0.1875};
        // I0_A^-1 = diag(1, 2, 3) for I_A^-1 = 3/4 E: x_a = (0.99, 0.5, 0), x_a x n = (0, 0, 0.5),
        // I0^-1 (x_a x n) = (0, 0, 1.5), x x_a = (-0.75, 1.485, 0), . n = 0.75 (right: 0.1875);
        // B's lever arm is along n (0 either way): denominator 2.25, J = 4 / 2.25 = 16/9
        QTest::newRow("impulse-body-inverse-inertia rotational_a") << Mistake::ImpulseBodyInverseInertia
                                                                   << "rotational_a" << QList<double>{0.75};
        QTest::newRow("impulse-body-inverse-inertia J") << Mistake::ImpulseBodyInverseInertia << "impulse"
                                                        << QList<double>{16.0 / 9.0};
    }

    // The boxes of lesson 3 moving apart: v_A = (-1, 0, 0), v_B = (1, 0, 0), v_rel.n = +2:
    // no impulse (J = 0); without the check J = -(1 + 1)(2) / (27/16) = -64/27.
    void noSeparatingCheck()
    {
        rbw::ContactInputs in = lesson3();
        in.v_A = Vec3(-1, 0, 0);
        in.v_B = Vec3(1, 0, 0);
        const QString wrong =
            rbw::test::mismatch(impulseValue(rbw::handImpulse(in, Mistake::NoSeparatingCheck), "impulse"), {-64.0 / 27.0}, 1e-12);
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong));
        const QString right = rbw::test::mismatch(impulseValue(rbw::handImpulse(in), "impulse"), {0.0}, 1e-12);
        QVERIFY2(right.isEmpty(), qPrintable(right));
        // Negative control: approaching (lesson 3 as it is), the model is the right impulse.
        const QString approaching = rbw::test::mismatch(
            impulseValue(rbw::handImpulse(lesson3(), Mistake::NoSeparatingCheck), "impulse"), {64.0 / 27.0}, 1e-12);
        QVERIFY2(approaching.isEmpty(), qPrintable(approaching));
    }

    // omega' = omega_n + I^-1 L' needs a spin: the quaternion case below (r = 1, omega0 =
    // (1, 0, 0), no force, h = 0.1): r' turns about x, which I^-1 L' = R I0^-1 R^T (L_x, 0, 0)
    // leaves alone: right omega' = (1, 0, 0), accumulated (2, 0, 0).
    void omegaAccumulated()
    {
        rbw::BodyStepInputs in = table21();
        in.q_WB = Quat::Identity();
        in.forces.clear();
        in.h = 0.1;
        in.L_W = Vec3(0.61 / 6.0, 0, 0);
        const QString wrong = rbw::test::mismatch(
            handValue(rbw::handEulerStep(in, Mistake::OmegaAccumulated), "angular_velocity"), {2, 0, 0}, 1e-9);
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong));
        const QString right = rbw::test::mismatch(handValue(rbw::handEulerStep(in), "angular_velocity"), {1, 0, 0}, 1e-9);
        QVERIFY2(right.isEmpty(), qPrintable(right));
    }

    // At c = 0.5, 1 - c = c: restitution-one-minus and impulse-without-one-plus give one
    // number, -0.5 (-2) / (27/16) = 16/27, the right one -1.5 (-2) / (27/16) = 16/9.
    void oneMinusAtHalf()
    {
        rbw::ContactInputs in = lesson3();
        in.restitution = 0.5;
        for (Mistake m : {Mistake::RestitutionOneMinus, Mistake::ImpulseWithoutOnePlus}) {
            const QString s = rbw::test::mismatch(impulseValue(rbw::handImpulse(in, m), "impulse"), {16.0 / 27.0}, 1e-12);
            QVERIFY2(s.isEmpty(), qPrintable(s));
        }
        const QString right = rbw::test::mismatch(impulseValue(rbw::handImpulse(in), "impulse"), {16.0 / 9.0}, 1e-12);
        QVERIFY2(right.isEmpty(), qPrintable(right));
    }

    void impulseMistake()
    {
        QFETCH(Mistake, mistake);
        QFETCH(QString, id);
        QFETCH(QList<double>, expected);
        const QString m =
            rbw::test::mismatch(impulseValue(rbw::handImpulse(lesson3(), mistake), qPrintable(id)), expected, 1e-12);
        QVERIFY2(m.isEmpty(), qPrintable(m));
    }

    // Every model has a stable id, an equation and an explanation, and is found by its id.
    void catalogue()
    {
        QCOMPARE(rbw::mistakeCatalogue().size(), size_t(34));   // 15 of issue 10, 19 of issue 21
        for (const rbw::MistakeInfo& m : rbw::mistakeCatalogue()) {
            QVERIFY(rbw::findMistake(m.id) == &m);
            QVERIFY(std::strlen(m.equation) > 0 && std::strlen(m.explanation) > 0);
        }
        QVERIFY(rbw::findMistake("no-such-mistake") == nullptr);
    }
};

QTEST_GUILESS_MAIN(TestMistakes)
#include "tst_mistakes.moc"
