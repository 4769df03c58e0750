// A second one-step case, derived completely by hand, that code which only gets
// Table 2.1 right will fail. Compared with Table 2.1 it has
//   - a non-principal initial rotation (60 degrees about (1,1,1)/sqrt3), so the world
//     inertia has off-diagonal entries and the order R I0^-1 R^T matters;
//   - a non-zero initial linear velocity, so "x <- x + h v" must use the OLD v;
//   - a non-zero initial angular velocity, so the quaternion update must use the OLD
//     omega and the quaternion product order (0, omega) r;
//   - a force with three non-zero components at a point off the centre of mass;
//   - a centre away from the origin, so the lever arm is p - x and not p. The force
//     point is chosen equal to the NEW centre x + h v: code that takes the lever arm
//     after the position update gets a torque of exactly zero.
//
// All numbers are chosen so that every quantity is a small fraction.
//
// Scene (h = 1/2):
//   box size (a, b, c) = (1, 2, 3), mass M = 1
//   x0     = (1, -2, 3)
//   v0     = (-1, 2, 2)
//   r0     = 60 degrees about n = (1,1,1)/sqrt3:
//            r0 = (cos 30, sin 30 n) = (sqrt3/2, 1/(2 sqrt3) (1,1,1)) = (3, 1, 1, 1)/sqrt12
//   omega0 = (4/3, -2/3, -2/3)  (world frame)
//   force  f = (-2, 1, -2) at p = (1/2, -1, 4), acting in step 0
//   probe 0 at the body corner p_B = (a/2, b/2, c/2) = (1/2, 1, 3/2)
//   probe 1 at the centre of mass p0 = x0
//
// Tolerance: a traced value a is accepted when |a_i - e_i| <= relTol * max_j |e_j|.
// relTol = 0 (exact ==) for quantities whose hand value and every intermediate are
// dyadic rationals (sums and products of small halves and quarters are exact in
// binary): f, p, lever arm, F, q, x, v, and the probe at the centre. For all others
// relTol = 1e-12: the hand values are exact fractions (thirds, sevenths, 1/sqrt14)
// that doubles round at ~1e-16 relative, while the mistakes this case guards against
// (R^T I0^-1 R, new v or new omega, r (0,omega) instead of (0,omega) r, p instead of
// p - x, no renormalisation) change them by 1e-3 or more, so 1e-12 is tight and still
// has four orders of headroom.

#include "tests/test_support.h"

#include <QtTest>

#include "physics/engine/quantities.h"
#include "physics/engine/scene.h"
#include "physics/engine/trace.h"
#include "physics/engine/world.h"

#include <cmath>
#include <numbers>
#include <type_traits>
#include <variant>

namespace {

using rbw::Mat3;
using rbw::Quat;
using rbw::Vec3;

using namespace rbw::test;


constexpr double kExact = 0.0;
constexpr double kRel = 1e-12;

rbw::SceneDef customScene()
{
    rbw::SceneDef s;
    s.name = "custom one step";
    s.dt = 0.5;   // h = 1/2
    s.steps = 1;
    rbw::BodyDef box;
    box.name = "box";
    box.size = Vec3(1.0, 2.0, 3.0);
    box.mass = 1.0;
    box.x0_W = Vec3(1.0, -2.0, 3.0);
    box.v0_W = Vec3(-1.0, 2.0, 2.0);
    // 60 degrees about (1,1,1)/sqrt3, i.e. r0 = (3, 1, 1, 1)/sqrt12.
    box.q0_WB = Quat(Eigen::AngleAxisd(std::numbers::pi / 3.0, Vec3(1.0, 1.0, 1.0).normalized()));
    box.omega0_W = Vec3(4.0 / 3.0, -2.0 / 3.0, -2.0 / 3.0);
    s.bodies.push_back(box);

    rbw::ForceDef f;
    f.body = 0;
    f.p_W = Vec3(0.5, -1.0, 4.0);
    f.f_W = Vec3(-2.0, 1.0, -2.0);
    f.fromStep = 0;
    f.toStep = 1;
    s.forces.push_back(f);

    // Probe 0 at the corner p_B = (1/2, 1, 3/2): p0 = x0 + R0 p_B = (2, -3/2, 9/2) (see below).
    s.probes.push_back(rbw::ProbeDef{0, Vec3(2.0, -1.5, 4.5)});
    // Probe 1 at the centre of mass.
    s.probes.push_back(rbw::ProbeDef{0, Vec3(1.0, -2.0, 3.0)});
    return s;
}

// R0 = R(r0) for r0 = (w, x, y, z) = (3, 1, 1, 1)/sqrt12, |.|^2 = 12:
//   R = 1/12 [[w2+x2-y2-z2, 2(xy-wz),    2(xz+wy)   ],
//             [2(xy+wz),    w2-x2+y2-z2, 2(yz-wx)   ],
//             [2(xz-wy),    2(yz+wx),    w2-x2-y2+z2]]
//     = 1/12 [[8, -4, 8], [8, 8, -4], [-4, 8, 8]]
//     = 1/3  [[2, -1, 2], [2, 2, -1], [-1, 2, 2]]
// (trace 2 = 1 + 2 cos 60, as it must be for a 60 degree rotation.)
//
// I0 = M/12 diag(b2+c2, a2+c2, a2+b2) = 1/12 diag(4+9, 1+9, 1+4) = diag(13/12, 5/6, 5/12)
// I0^-1 = diag(12/13, 6/5, 12/5).
//
// Initial state (body.cpp: L0 = R0 I0 R0^T omega0):
//   R0^T omega0 = 1/3 [[2,2,-1],[-1,2,2],[2,-1,2]] (4,-2,-2)/3
//               = 1/9 (8-4+2, -4-4-4, 8+2-4) = 1/9 (6, -12, 6) = (2/3, -4/3, 2/3)
//   I0 (2/3, -4/3, 2/3) = (13/12*2/3, 5/6*(-4/3), 5/12*2/3) = (13/18, -10/9, 5/18) = (13, -20, 5)/18
//   L0 = R0 (13, -20, 5)/18 = 1/54 (26+20+10, 26-40-5, -13-40+10) = 1/54 (56, -19, -43)
//      = (28/27, -19/54, -43/54).
// omega_old (the one the quaternion update uses) = I^-1(r0) L0 = omega0.

} // namespace

class TestCustomStep : public QObject {
    Q_OBJECT

private slots:
    void sceneIsValid();
    void initialState();
    void traceQuantity_data();
    void traceQuantity();
    void quaternionUpdate();
    void worldStateMatchesTrace();
};

void TestCustomStep::sceneIsValid()
{
    const auto issues = rbw::validate(customScene());
    QVERIFY2(issues.empty(), issues.empty() ? "" : issues.front().reason.c_str());
}

void TestCustomStep::initialState()
{
    // Before any step: r0 = (3,1,1,1)/sqrt12, L0 = (28/27, -19/54, -43/54) (derived
    // above) and omega = I^-1(r0) L0 = omega0 = (4/3, -2/3, -2/3).
    rbw::World world(customScene());
    const rbw::BodyState& s = world.states()[0];
    const double r12 = std::sqrt(12.0);
    QString why = mismatch(flat(s.q_WB), {3.0 / r12, 1.0 / r12, 1.0 / r12, 1.0 / r12}, kRel);
    QVERIFY2(why.isEmpty(), qPrintable(QStringLiteral("r0: ") + why));
    why = mismatch(flatten(s.R_WB), {2.0 / 3, -1.0 / 3, 2.0 / 3, 2.0 / 3, 2.0 / 3, -1.0 / 3, -1.0 / 3, 2.0 / 3, 2.0 / 3},
                   kRel);
    QVERIFY2(why.isEmpty(), qPrintable(QStringLiteral("R0: ") + why));
    why = mismatch(flat(s.L_W), {28.0 / 27.0, -19.0 / 54.0, -43.0 / 54.0}, kRel);
    QVERIFY2(why.isEmpty(), qPrintable(QStringLiteral("L0: ") + why));
    why = mismatch(flat(s.omega_W), {4.0 / 3.0, -2.0 / 3.0, -2.0 / 3.0}, kRel);
    QVERIFY2(why.isEmpty(), qPrintable(QStringLiteral("omega0: ") + why));
}

void TestCustomStep::traceQuantity_data()
{
    QTest::addColumn<QString>("id");
    QTest::addColumn<int>("index");
    QTest::addColumn<QList<double>>("expected");
    QTest::addColumn<double>("relTol");

    // --- forces stage ---
    // f_0 and p_0 as given.
    QTest::newRow("applied_force") << "applied_force" << 0 << QList<double>{-2, 1, -2} << kExact;
    QTest::newRow("application_point") << "application_point" << 0 << QList<double>{0.5, -1, 4} << kExact;
    // Lever arm with the OLD centre: x_0 = p - x0 = (1/2 - 1, -1 + 2, 4 - 3) = (-1/2, 1, 1).
    // (It equals h v0, so p is the NEW centre x0 + h v0: using the new x would give 0.)
    QTest::newRow("lever_arm") << "lever_arm" << 0 << QList<double>{-0.5, 1, 1} << kExact;
    // F = f_0 = (-2, 1, -2).
    QTest::newRow("force") << "force" << -1 << QList<double>{-2, 1, -2} << kExact;
    // q = x_0 x f_0 = (-1/2, 1, 1) x (-2, 1, -2):
    //   q_x = 1*(-2)    - 1*1        = -3
    //   q_y = 1*(-2)    - (-1/2)(-2) = -2 - 1 = -3
    //   q_z = (-1/2)*1  - 1*(-2)     = -1/2 + 2 = 3/2
    QTest::newRow("torque") << "torque" << -1 << QList<double>{-3, -3, 1.5} << kExact;

    // --- integration stage ---
    // x <- x0 + h v0 = (1, -2, 3) + 1/2 (-1, 2, 2) = (1/2, -1, 4)   (OLD v).
    // (With the new v it would be (0, -3/4, 7/2).)
    QTest::newRow("position") << "position" << -1 << QList<double>{0.5, -1, 4} << kExact;
    // v <- v0 + h F / M = (-1, 2, 2) + 1/2 (-2, 1, -2) = (-2, 5/2, 1).
    QTest::newRow("linear_velocity") << "linear_velocity" << -1 << QList<double>{-2, 2.5, 1} << kExact;
    // r <- normalise(r0 + (h/2)(0, omega0) r0), see quaternionUpdate() for the product:
    //   r0 + (h/2)(0, omega0) r0 = [(3,1,1,1) + (0,1,-1,0)]/sqrt12 = (3, 2, 0, 1)/sqrt12,
    //   |(3, 2, 0, 1)|^2 = 9 + 4 + 0 + 1 = 14   ->   r = (3, 2, 0, 1)/sqrt14.
    {
        const double r14 = std::sqrt(14.0);
        QTest::newRow("orientation") << "orientation" << -1
                                     << QList<double>{3.0 / r14, 2.0 / r14, 0.0, 1.0 / r14} << kRel;
    }
    // L <- L0 + h q = (56, -19, -43)/54 + 1/2 (-3, -3, 3/2)
    //   = (112, -38, -86)/108 + (-162, -162, 81)/108 = (-50, -200, -5)/108
    //   = (-25/54, -50/27, -5/108).
    QTest::newRow("angular_momentum") << "angular_momentum" << -1
                                      << QList<double>{-25.0 / 54.0, -50.0 / 27.0, -5.0 / 108.0} << kRel;
    // I0 = diag(13/12, 5/6, 5/12) (derived above).
    QTest::newRow("inertia_body") << "inertia_body" << -1
                                  << QList<double>{13.0 / 12.0, 0, 0, 0, 5.0 / 6.0, 0, 0, 0, 5.0 / 12.0} << kRel;
    // R = R(r) for r = (w,x,y,z) = (3, 2, 0, 1)/sqrt14, |.|^2 = 14 (formula as for R0):
    //   1/14 [[9+4-0-1, 2(0-3), 2(2+0)], [2(0+3), 9-4+0-1, 2(0-6)], [2(2-0), 2(0+6), 9-4-0+1]]
    //   = 1/14 [[12, -6, 4], [6, 4, -12], [4, 12, 6]] = 1/7 [[6, -3, 2], [3, 2, -6], [2, 6, 3]].
    QTest::newRow("rotation_matrix") << "rotation_matrix" << -1
                                     << QList<double>{6.0 / 7, -3.0 / 7, 2.0 / 7, 3.0 / 7, 2.0 / 7, -6.0 / 7,
                                                      2.0 / 7, 6.0 / 7, 3.0 / 7}
                                     << kRel;
    // I^-1 = R I0^-1 R^T, entry (i,j) = 1/49 sum_k S_ik S_jk d_k with S = 7R (integers) and
    // d = (12/13, 6/5, 12/5):
    //   (0,0): (36*12/13 + 9*6/5  + 4*12/5)/49  = (432/13 + 102/5)/49 = 3486/65/49 = 498/455
    //   (0,1): (18*12/13 - 6*6/5  - 12*12/5)/49 = (216/13 - 36)/49   = -252/13/49 = -36/91
    //   (0,2): (12*12/13 - 18*6/5 + 6*12/5)/49  = (144/13 - 36/5)/49 = 252/65/49  = 36/455
    //   (1,1): (9*12/13  + 4*6/5  + 36*12/5)/49 = (108/13 + 456/5)/49 = 6468/65/49 = 132/65
    //   (1,2): (6*12/13  + 12*6/5 - 18*12/5)/49 = (72/13 - 144/5)/49 = -1512/65/49 = -216/455
    //   (2,2): (4*12/13  + 36*6/5 + 9*12/5)/49  = (48/13 + 324/5)/49  = 4452/65/49 = 636/455
    //   symmetric, and clearly not diagonal.
    QTest::newRow("inverse_inertia_world")
        << "inverse_inertia_world" << -1
        << QList<double>{498.0 / 455, -36.0 / 91, 36.0 / 455, -36.0 / 91, 132.0 / 65, -216.0 / 455,
                         36.0 / 455, -216.0 / 455, 636.0 / 455}
        << kRel;
    // omega = I^-1 L = R I0^-1 R^T L, evaluated right to left:
    //   R^T L = 1/7 [[6,3,2],[-3,2,6],[2,-6,3]] (-50, -200, -5)/108
    //         = 1/756 (-300-600-10, 150-400-30, -100+1200-15) = 1/756 (-910, -280, 1085)
    //         = (-65/54, -10/27, 155/108)
    //   I0^-1 R^T L = (12/13*(-65/54), 6/5*(-10/27), 12/5*155/108) = (-10/9, -4/9, 31/9)
    //   omega = R (-10, -4, 31)/9 = 1/63 [[6,-3,2],[3,2,-6],[2,6,3]] (-10, -4, 31)
    //         = 1/63 (-60+12+62, -30-8-186, -20-24+93) = 1/63 (14, -224, 49)
    //         = (2/9, -32/9, 7/9).
    QTest::newRow("angular_velocity") << "angular_velocity" << -1
                                      << QList<double>{2.0 / 9.0, -32.0 / 9.0, 7.0 / 9.0} << kRel;

    // --- probes ---
    // Probe 0: p0 = x0 + R0 p_B with R0 p_B = 1/3 (2*1/2 - 1 + 2*3/2, 2*1/2 + 2*1 - 3/2,
    //   -1/2 + 2*1 + 2*3/2) = 1/3 (3, 3/2, 9/2) = (1, 1/2, 3/2), so p0 = (2, -3/2, 9/2).
    //   After the step p = x + R p_B with R p_B = 1/7 (3 - 3 + 3, 3/2 + 2 - 9, 1 + 6 + 9/2)
    //   = (3/7, -11/14, 23/14), so p = (1/2 + 3/7, -1 - 11/14, 4 + 23/14) = (13/14, -25/14, 79/14).
    QTest::newRow("probe_position[0]") << "probe_position" << 0
                                       << QList<double>{13.0 / 14, -25.0 / 14, 79.0 / 14} << kRel;
    // v_p = v + omega x (p - x), with p - x = R p_B = (3/7, -11/14, 23/14) =: r:
    //   (omega x r)_x = omega_y r_z - omega_z r_y = (-32/9)(23/14) - (7/9)(-11/14)
    //                 = (-736 + 77)/126 = -659/126
    //   (omega x r)_y = omega_z r_x - omega_x r_z = (7/9)(3/7) - (2/9)(23/14)
    //                 = 42/126 - 46/126 = -2/63
    //   (omega x r)_z = omega_x r_y - omega_y r_x = (2/9)(-11/14) - (-32/9)(3/7)
    //                 = -22/126 + 192/126 = 85/63
    //   v_p = (-2 - 659/126, 5/2 - 2/63, 1 + 85/63) = (-911/126, 311/126, 148/63).
    QTest::newRow("point_velocity[0]") << "point_velocity" << 0
                                       << QList<double>{-911.0 / 126, 311.0 / 126, 148.0 / 63} << kRel;
    // Probe 1 sits at the centre: p_B = R0^T (x0 - x0) = 0, so p = x = (1/2, -1, 4) and
    // v_p = v + omega x 0 = v = (-2, 5/2, 1), both exactly.
    QTest::newRow("probe_position[1]") << "probe_position" << 1 << QList<double>{0.5, -1, 4} << kExact;
    QTest::newRow("point_velocity[1]") << "point_velocity" << 1 << QList<double>{-2, 2.5, 1} << kExact;
}

void TestCustomStep::traceQuantity()
{
    QFETCH(QString, id);
    QFETCH(int, index);
    QFETCH(QList<double>, expected);
    QFETCH(double, relTol);

    rbw::World world(customScene());
    rbw::StepTrace trace;
    const rbw::StepStatus status = world.step(&trace);
    QVERIFY2(status.ok, status.message.c_str());
    QCOMPARE(trace.step, 0L);
    QCOMPARE(trace.time, 0.5);

    const rbw::TraceEntry* entry = trace.find(id.toStdString(), 0, index);
    QVERIFY2(entry != nullptr, qPrintable(QStringLiteral("no trace entry %1[%2]").arg(id).arg(index)));
    const QString why = mismatch(flatten(entry->value), expected, relTol);
    QVERIFY2(why.isEmpty(), qPrintable(id + QStringLiteral(": ") + why));
}

void TestCustomStep::quaternionUpdate()
{
    // r <- normalise(r0 + (h/2)(0, omega_old) r0), omega_old = omega0 = (4/3, -2/3, -2/3).
    // Work with the unnormalised r0' = sqrt12 r0 = (s, u) = (3, (1, 1, 1)) and
    // a = (h/2) omega0 = 1/4 (4/3, -2/3, -2/3) = (1/3, -1/6, -1/6).
    // Quaternion product (0, a)(s, u) = (-a.u, s a + a x u):
    //   -a.u   = -(1/3 - 1/6 - 1/6) = 0
    //   s a    = (1, -1/2, -1/2)
    //   a x u  = (a_y u_z - a_z u_y, a_z u_x - a_x u_z, a_x u_y - a_y u_x)
    //          = (-1/6 + 1/6, -1/6 - 1/3, 1/3 + 1/6) = (0, -1/2, 1/2)
    //   (0, a) r0' = (0, 1, -1, 0)
    // r0' + (0, a) r0' = (3, 2, 0, 1); |.|^2 = 14 -> r = (3, 2, 0, 1)/sqrt14.
    //
    // Guards: the other product order r0 (0, a) = (0, s a + u x a) = (0, 1, 0, -1) would
    // give (3, 2, 1, 0)/sqrt14; the new omega (2/9, -32/9, 7/9) would give yet another r;
    // and omega = 0 (forgetting omega0) would leave r = r0.
    const double r14 = std::sqrt(14.0);
    const QList<double> expected{3.0 / r14, 2.0 / r14, 0.0, 1.0 / r14};

    rbw::World world(customScene());
    const Quat r0 = world.states()[0].q_WB;
    rbw::StepTrace trace;
    QVERIFY(world.step(&trace).ok);
    const rbw::TraceEntry* entry = trace.find("orientation", 0);
    QVERIFY(entry != nullptr);
    const Quat r = std::get<Quat>(entry->value);
    QString why = mismatch(flat(r), expected, kRel);
    QVERIFY2(why.isEmpty(), qPrintable(QStringLiteral("r: ") + why));
    // r stays a unit quaternion (renormalised): |r| = 1 to 1e-15.
    RBW_COMPARE_NEAR(r.norm(), 1.0, 1e-15);
    // The orientation really moved: the angle between r0 and r is not zero,
    // r0 . r = (3*3 + 1*2 + 1*0 + 1*1)/(sqrt12 sqrt14) = 12/sqrt168 = 0.9258201.
    RBW_COMPARE_NEAR(r0.dot(r), 12.0 / std::sqrt(168.0), 1e-12);
}

void TestCustomStep::worldStateMatchesTrace()
{
    // The world keeps exactly the state the trace reports (one source of truth).
    rbw::World world(customScene());
    rbw::StepTrace trace;
    QVERIFY(world.step(&trace).ok);
    const rbw::BodyState& s = world.states()[0];
    QCOMPARE(flat(s.x_W), flatten(trace.find("position", 0)->value));
    QCOMPARE(flat(s.v_W), flatten(trace.find("linear_velocity", 0)->value));
    QCOMPARE(flat(s.q_WB), flatten(trace.find("orientation", 0)->value));
    QCOMPARE(flat(s.L_W), flatten(trace.find("angular_momentum", 0)->value));
    QCOMPARE(flat(s.omega_W), flatten(trace.find("angular_velocity", 0)->value));
    // Diagnostics after the step: P = M v = (-2, 5/2, 1) exactly (M = 1).
    QCOMPARE(trace.diagnostics.P_W, Vec3(-2.0, 2.5, 1.0));
}

QTEST_APPLESS_MAIN(TestCustomStep)
#include "tst_custom_step.moc"
