// The exact motion of a scene (physics/workbook/lab/exact_motion.h): which reference a scene
// gets, the reasons a scene gets none, and the exact answer checked against its own
// equations before any integrator is measured against it.
#include "physics/engine/inertia.h"
#include "physics/workbook/lab/exact_motion.h"
#include "physics/workbook/lab/study.h"
#include "tests/test_support.h"

#include <QtTest>

using rbw::Mat3;
using rbw::Quat;
using rbw::SceneDef;
using rbw::Vec3;
using rbw::lab::ExactMotion;
using rbw::lab::RotationKind;
using rbw::test::lessonScene;

Q_DECLARE_METATYPE(RotationKind)

namespace {

// The exact state's own consistency at t:
//   (a) omega_W = I^-1(q) L_W with I^-1 = R I0^-1 R^T (the orientation agrees with omega
//       and the fixed L: this pins theta and psi of the asymmetric top);
//   (b) q' = 1/2 (0, omega_W) q by central differences with step d (this pins phi, the
//       quadrature-integrated precession angle).
// Returns the larger residual, relative to |omega|.
double kinematicResidual(const ExactMotion& m, const SceneDef& scene, double t, double tOmega)
{
    const rbw::BodyDef& body = scene.bodies[0];
    const Mat3 I0inv_B = rbw::boxInertiaBody(body.size, body.mass).inverse();
    const rbw::reference::ExactState s = m.at(t);
    const double w = s.omega_W.norm();
    const Mat3 Iinv_W = rbw::inverseInertiaWorld(s.q_WB.toRotationMatrix(), I0inv_B);
    const Vec3 omegaFromL = Iinv_W * s.L_W;
    const double a = (omegaFromL - s.omega_W).norm() / w;
    // d = 1e-5: truncation |q'''| d^2/6 ~ |omega|^3 1e-10/48, rounding 1e-16/d = 1e-11
    const double d = 1e-5;
    const Quat qp = m.at(t + d).q_WB;
    Quat qm = m.at(t - d).q_WB;
    if (qp.dot(qm) < 0.0) qm.coeffs() = -qm.coeffs();   // same hemisphere
    Quat q = s.q_WB;
    if (q.dot(qp) < 0.0) q.coeffs() = -q.coeffs();
    const Eigen::Vector4d dq = (qp.coeffs() - qm.coeffs()) / (2.0 * d);
    const Vec3 omega = m.at(tOmega).omega_W;
    // q' = 1/2 (0, omega) q   (Baraff 2001, eq. for the quaternion rate)
    const Quat rate = Quat(0.0, 0.5 * omega.x(), 0.5 * omega.y(), 0.5 * omega.z()) * q;
    const double b = (dq - rate.coeffs()).norm() / w;
    return std::max(a, b);
}

SceneDef withOneBodyOnly(const SceneDef& s)
{
    SceneDef one = s;
    one.bodies.resize(1);
    one.pairs.clear();
    one.probes.clear();
    return one;
}

} // namespace

class TestExactMotion : public QObject {
    Q_OBJECT
private slots:
    void kinds_data();
    void kinds();
    void refusals_data();
    void refusals();
    void exactAnswerSolvesItsEquations_data();
    void exactAnswerSolvesItsEquations();
    void residualCatchesATimingError();
    void constantSpinWorkedNumbers();
};

void TestExactMotion::kinds_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<Vec3>("size");          // (0,0,0): the file's
    QTest::addColumn<RotationKind>("kind");
    QTest::addColumn<bool>("gravity");
    // omega (0, -1.5, 2.598) = 3 R_x(30 deg) e_z: along the body z axis, a principal axis
    QTest::newRow("constant spin") << "constant-spin.json" << Vec3(0, 0, 0) << RotationKind::ConstantSpin << false;
    // a cube: every axis is principal, so any omega is a constant spin
    QTest::newRow("projectile (cube)") << "projectile.json" << Vec3(0, 0, 0) << RotationKind::ConstantSpin << true;
    // size (1, 1, 0.4): I_x = I_y = M/12 (1 + 0.16), I_z = M/12 * 2
    QTest::newRow("symmetric top") << "symmetric-top.json" << Vec3(0, 0, 0) << RotationKind::SymmetricTop << false;
    // the same body with the odd axis on x: the relabelling must find it
    QTest::newRow("symmetric top, odd axis x") << "symmetric-top.json" << Vec3(0.4, 1, 1)
                                               << RotationKind::SymmetricTop << false;
    // size (0.24, 0.04, 0.17): three different moments, omega on no principal axis
    QTest::newRow("asymmetric top") << "scene.json" << Vec3(0, 0, 0) << RotationKind::AsymmetricTop << true;
    // the same moments in another order on the body axes
    QTest::newRow("asymmetric top, axes reordered") << "scene.json" << Vec3(0.17, 0.24, 0.04)
                                                    << RotationKind::AsymmetricTop << true;
}

void TestExactMotion::kinds()
{
    QFETCH(QString, file);
    QFETCH(Vec3, size);
    QFETCH(RotationKind, kind);
    QFETCH(bool, gravity);
    SceneDef scene = lessonScene("10-accuracy-lab/" + file);
    if (size != Vec3::Zero()) scene.bodies[0].size = size;
    std::vector<rbw::SceneIssue> reasons;
    const std::optional<ExactMotion> m = ExactMotion::fromScene(scene, reasons);
    QVERIFY2(m.has_value(), reasons.empty() ? "" : reasons[0].reason.c_str());
    QVERIFY(reasons.empty());
    QCOMPARE(m->rotationKind(), kind);
    QCOMPARE(m->hasGravity(), gravity);
    // at t = 0 the exact answer is the scene's initial state
    const rbw::reference::ExactState s0 = m->at(0.0);
    QVERIFY((s0.x_W - scene.bodies[0].x0_W).norm() == 0.0);
    QVERIFY((s0.v_W - scene.bodies[0].v0_W).norm() == 0.0);
    RBW_COMPARE_NEAR(s0.omega_W, scene.bodies[0].omega0_W, 1e-14 * scene.bodies[0].omega0_W.norm());
    QVERIFY(rbw::lab::orientationAngle(s0.q_WB, scene.bodies[0].q0_WB) <= 1e-14);
}

void TestExactMotion::refusals_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::addColumn<QString>("change");
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("reasonPart");
    QTest::newRow("two bodies") << "03-two-box-collision/scene.json" << "" << "bodies" << "exactly one body, the scene has 2";
    QTest::newRow("one body on a plane") << "06-box-on-plane/scene.json" << "one body" << "planes" << "1 plane(s)";
    QTest::newRow("a force (lesson 1)") << "01-one-step/scene.json" << "" << "forces" << "1 force(s)";
    QTest::newRow("a torque") << "10-accuracy-lab/constant-spin.json" << "torque" << "torques" << "torque-free";
    QTest::newRow("course-template") << "10-accuracy-lab/constant-spin.json" << "template" << "inertia_convention"
                                     << "standard convention";
}

void TestExactMotion::refusals()
{
    QFETCH(QString, lesson);
    QFETCH(QString, change);
    QFETCH(QString, path);
    QFETCH(QString, reasonPart);
    SceneDef scene = lessonScene(lesson);
    if (change == "one body") scene = withOneBodyOnly(scene);
    if (change == "torque") scene.torques.push_back(rbw::TorqueDef{0, Vec3(0, 0, 1), 0, 10, false, true});
    if (change == "template") scene.inertiaConvention = rbw::InertiaConvention::CourseTemplate;
    std::vector<rbw::SceneIssue> reasons;
    QVERIFY(!ExactMotion::fromScene(scene, reasons).has_value());
    QVERIFY(!reasons.empty());
    QCOMPARE(QString::fromStdString(reasons[0].path), path);
    QVERIFY2(QString::fromStdString(reasons[0].reason).contains(reasonPart), reasons[0].reason.c_str());
}

void TestExactMotion::exactAnswerSolvesItsEquations_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<Vec3>("size");
    QTest::addColumn<double>("t");
    for (double t : {0.3, 1.7, 2.0, 9.5}) {
        QTest::addRow("asymmetric, t=%g", t) << "scene.json" << Vec3(0, 0, 0) << t;
        QTest::addRow("asymmetric reordered, t=%g", t) << "scene.json" << Vec3(0.17, 0.24, 0.04) << t;
        QTest::addRow("symmetric, t=%g", t) << "symmetric-top.json" << Vec3(0, 0, 0) << t;
        QTest::addRow("symmetric odd x, t=%g", t) << "symmetric-top.json" << Vec3(0.4, 1, 1) << t;
        QTest::addRow("constant spin, t=%g", t) << "constant-spin.json" << Vec3(0, 0, 0) << t;
    }
}

void TestExactMotion::exactAnswerSolvesItsEquations()
{
    QFETCH(QString, file);
    QFETCH(Vec3, size);
    QFETCH(double, t);
    SceneDef scene = lessonScene("10-accuracy-lab/" + file);
    if (size != Vec3::Zero()) scene.bodies[0].size = size;
    std::vector<rbw::SceneIssue> reasons;
    const std::optional<ExactMotion> m = ExactMotion::fromScene(scene, reasons);
    QVERIFY(m.has_value());
    const double residual = kinematicResidual(*m, scene, t, t);
    // truncation ~ |omega|^2 d^2 / 6 ~ 50 * 1e-10 / 6 < 1e-8 (|omega| <= 7 rad/s here)
    QVERIFY2(residual <= 1e-8, qPrintable(QString::number(residual)));
    // |L| and T of the exact state stay those of t = 0
    const rbw::reference::ExactState s0 = m->at(0.0);
    const rbw::reference::ExactState s = m->at(t);
    RBW_COMPARE_NEAR(s.L_W.norm(), s0.L_W.norm(), 1e-13 * s0.L_W.norm());
    const double T0 = 0.5 * s0.omega_W.dot(s0.L_W);
    RBW_COMPARE_NEAR(0.5 * s.omega_W.dot(s.L_W), T0, 1e-12 * T0);
}

// Negative control: the same check fails for an omega taken 0.01 s late, an error the
// size an integrator at h = 0.01 makes. So a wrong precession angle would not pass.
void TestExactMotion::residualCatchesATimingError()
{
    const SceneDef scene = lessonScene("10-accuracy-lab/scene.json");
    std::vector<rbw::SceneIssue> reasons;
    const std::optional<ExactMotion> m = ExactMotion::fromScene(scene, reasons);
    QVERIFY(m.has_value());
    QVERIFY(kinematicResidual(*m, scene, 1.7, 1.71) > 1e-3);
}

// Constant spin by hand: omega = 3 rad/s about the world axis n = (0, -1/2, sqrt(3)/2);
// after t = 2 s the body has turned by 6 rad about n, so q(2) = [cos 3, n sin 3] q0.
void TestExactMotion::constantSpinWorkedNumbers()
{
    const SceneDef scene = lessonScene("10-accuracy-lab/constant-spin.json");
    std::vector<rbw::SceneIssue> reasons;
    const std::optional<ExactMotion> m = ExactMotion::fromScene(scene, reasons);
    QVERIFY(m.has_value());
    const Vec3 n(0.0, -0.5, std::sqrt(3.0) / 2.0);
    const Quat turn(std::cos(3.0), n.x() * std::sin(3.0), n.y() * std::sin(3.0), n.z() * std::sin(3.0));
    const Quat expected = turn * scene.bodies[0].q0_WB;
    QVERIFY(rbw::lab::orientationAngle(m->at(2.0).q_WB, expected) <= 1e-14);
    RBW_COMPARE_NEAR(m->at(2.0).omega_W, 3.0 * n, 1e-15 * 3.0 * 4);
}

QTEST_APPLESS_MAIN(TestExactMotion)
#include "tst_exact_motion.moc"
