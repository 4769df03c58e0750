// The exact reference solutions (physics/workbook/reference/) checked against their own
// invariants and against the ODE they claim to solve, before they judge any
// integrator. Every tolerance is stated with its reason.
//
// Finite differences: for a smooth f, the central difference (f(t+d) - f(t-d))/(2d)
// differs from f'(t) by d^2/6 |f'''| (truncation) plus about u |f| / d (rounding,
// u = 2^-53). With d = 1e-4 and the rates here (|omega| <= 3 rad/s, so |f'''| <=
// 27 |f|), truncation <= 1e-8/6 * 27 |f| = 4.5e-8 |f| and rounding ~ 1e-12 |f|:
// tolerance 1e-7 |f| for the residual of each ODE.

#include <QtTest>

#include "tests/physics/engine/integrators/integrator_harness.h"
#include "physics/workbook/reference/asymmetric_top.h"
#include "physics/workbook/reference/constant_spin.h"
#include "physics/workbook/reference/dzhanibekov.h"
#include "physics/workbook/reference/projectile.h"
#include "physics/workbook/reference/symmetric_top.h"
#include "tests/test_support.h"

#include <cmath>

Q_DECLARE_METATYPE(rbw::Vec3)
Q_DECLARE_METATYPE(rbw::Quat)

using namespace rbw::test;
namespace ref = rbw::reference;

namespace {

constexpr double kFdStep = 1e-4;   // d, see the file comment
constexpr double kFdTol = 1e-7;    // relative FD residual, see the file comment

// (q(t+d) - q(t-d)) / (2d), as a 4-vector [w, x, y, z]
template <class F>
Eigen::Vector4d quatRateFd(const F& q, double t)
{
    const Quat a = q(t + kFdStep);
    const Quat b = q(t - kFdStep);
    const Eigen::Vector4d va(a.w(), a.x(), a.y(), a.z());
    const Eigen::Vector4d vb(b.w(), b.x(), b.y(), b.z());
    return (va - vb) / (2.0 * kFdStep);
}

// 1/2 (0, omega_W) q as [w, x, y, z]
Eigen::Vector4d quatRate(const Vec3& omega_W, const Quat& q)
{
    const Quat r = Quat(0.0, omega_W.x(), omega_W.y(), omega_W.z()) * q;
    return 0.5 * Eigen::Vector4d(r.w(), r.x(), r.y(), r.z());
}

// |FD(L_B)' - L_B x omega_B| relative to |L||omega|, the body-frame Euler equation
// L_B' = L_B x omega_B  (equivalently I0 omega_B' + omega_B x I0 omega_B = 0).
template <class F>
double eulerResidual(const F& L_B, const Vec3& I, double t)
{
    const Vec3 fd = (L_B(t + kFdStep) - L_B(t - kFdStep)) / (2.0 * kFdStep);
    const Vec3 L = L_B(t);
    const Vec3 omega = L.cwiseQuotient(I);
    return (fd - L.cross(omega)).norm() / (L.norm() * omega.norm());
}

} // namespace

class TestReferences : public QObject {
    Q_OBJECT

private slots:
    void constantSpin_data();
    void constantSpin();
    void constantSpinRejectsOffAxis();
    void projectile();
    void symmetricTopWorkedCase();
    void symmetricTop_data();
    void symmetricTop();
    void asymmetricTop_data();
    void asymmetricTop();
    void asymmetricTopRejectsBadInput();
    void dzhanibekovCase();
    void wrongReferenceIsCaught();
};

// ---------------------------------------------------------------------------------
// Constant spin about a principal axis: q(t) = exp(1/2 omega t) q0 must satisfy
// q' = 1/2 (0, omega) q (FD, tolerance above), stay unit (|q| = 1 to 4u: a product
// of unit quaternions), and start at q0 exactly.
void TestReferences::constantSpin_data()
{
    QTest::addColumn<Vec3>("I");
    QTest::addColumn<Quat>("q0");
    QTest::addColumn<Vec3>("axis_B");   // principal axis in the body frame
    QTest::addColumn<double>("rate");
    const Quat tilted(Eigen::AngleAxisd(0.7, Vec3(1, -2, 0.5).normalized()));
    QTest::newRow("x axis, identity") << Vec3(1, 2, 3) << Quat::Identity() << Vec3(1, 0, 0) << 2.0;
    QTest::newRow("y axis, tilted") << Vec3(1, 2, 3) << tilted << Vec3(0, 1, 0) << -1.5;
    QTest::newRow("z axis, tilted, fast") << Vec3(0.2, 0.5, 0.6) << tilted << Vec3(0, 0, 1) << 3.0;
}

void TestReferences::constantSpin()
{
    QFETCH(Vec3, I);
    QFETCH(Quat, q0);
    QFETCH(Vec3, axis_B);
    QFETCH(double, rate);
    const Vec3 omega_W = q0 * (rate * axis_B);
    std::string error;
    const std::optional<ref::ConstantSpin> spin = ref::ConstantSpin::make(I, q0, omega_W, error);
    QVERIFY2(spin, error.c_str());
    QCOMPARE(angleBetween(spin->orientation(0.0), q0), 0.0);
    for (double t : {0.3, 1.0, 2.7}) {
        const Eigen::Vector4d fd = quatRateFd([&](double s) { return spin->orientation(s); }, t);
        const Eigen::Vector4d exact = quatRate(omega_W, spin->orientation(t));
        RBW_COMPARE_NEAR(fd, exact, kFdTol * std::abs(rate), QStringLiteral("t = %1").arg(t));
        RBW_COMPARE_NEAR(spin->orientation(t).norm(), 1.0, 4 * u);
    }
    // L = R0 I0 R0^T omega = rate * I_axis * (q0 axis_B): parallel to omega
    const double Iaxis = I.dot(axis_B.cwiseAbs());
    RBW_COMPARE_NEAR(spin->L_W(), Iaxis * omega_W, 8 * u * Iaxis * std::abs(rate));
}

// Negative control: a spin off the principal axes does not stay constant, and the
// reference refuses it with a message instead of returning a wrong "exact" answer.
void TestReferences::constantSpinRejectsOffAxis()
{
    std::string error;
    QVERIFY(!ref::ConstantSpin::make(Vec3(1, 2, 3), Quat::Identity(), Vec3(1, 1, 0), error));
    QVERIFY(error.find("principal axis") != std::string::npos);
}

// ---------------------------------------------------------------------------------
// Projectile: x(t) = x0 + v0 t + 1/2 g t^2. Hand check at t = 2 for x0 = (1, 2, 3),
// v0 = (4, 5, 0), g = (0, -9.81, 0): x = (1 + 8, 2 + 10 - 19.62, 3) = (9, -7.62, 3),
// v = (4, 5 - 19.62, 0) = (4, -14.62, 0). Energy per mass 1/2|v|^2 - g.x is constant:
// at t = 0: 1/2 (16 + 25) + 9.81 * 2 = 40.12; at t = 2: 1/2 (16 + 213.7444) + 9.81 * (-7.62)
// = 114.8722 - 74.7522 = 40.12. Tolerances: a few u of the magnitudes involved.
void TestReferences::projectile()
{
    std::string error;
    const std::optional<ref::ConstantSpin> spin =
        ref::ConstantSpin::make(Vec3(1, 2, 3), Quat::Identity(), Vec3(0, 0, 1.5), error);
    QVERIFY2(spin, error.c_str());
    const ref::Projectile p(Vec3(1, 2, 3), Vec3(4, 5, 0), Vec3(0, -9.81, 0), *spin);
    const ref::ExactState s = p.at(2.0);
    RBW_COMPARE_NEAR(s.x_W, Vec3(9, -7.62, 3), 64 * u);
    RBW_COMPARE_NEAR(s.v_W, Vec3(4, -14.62, 0), 64 * u);
    for (double t : {0.0, 0.5, 2.0, 3.3}) {
        const double e = 0.5 * p.velocity(t).squaredNorm() - Vec3(0, -9.81, 0).dot(p.position(t));
        RBW_COMPARE_NEAR(e, 40.12, 1e-13 * 40.12);
    }
    // x'' = g by FD (second difference; exact for a quadratic up to rounding u|x|/d^2)
    const double d = 1e-2;
    const Vec3 acc = (p.position(1.0 + d) - 2.0 * p.position(1.0) + p.position(1.0 - d)) / (d * d);
    RBW_COMPARE_NEAR(acc, Vec3(0, -9.81, 0), 1e-9);
    QCOMPARE(angleBetween(s.q_WB, spin->orientation(2.0)), 0.0);
}

// ---------------------------------------------------------------------------------
// Symmetric top, the worked case of docs/references.md §5: I = (3, 3, 9), L_B(0) = (0, 5, 7).
// Omega = L3 (I1 - I3)/(I1 I3) = 7 (3 - 9)/27 = -42/27 = -14/9. L_perp = 5, phi0 = 0, so
// L_B(t) = (5 sin(-14t/9), 5 cos(-14t/9), 7); at t = 9 pi/28 (a quarter turn of L_B):
// L_B = (5 sin(-pi/2), 5 cos(-pi/2), 7) = (-5, 0, 7). Precession rate |L|/I1 = sqrt(74)/3.
void TestReferences::symmetricTopWorkedCase()
{
    std::string error;
    const std::optional<ref::SymmetricTop> top =
        ref::SymmetricTop::make(3.0, 9.0, Quat::Identity(), Vec3(0, 5, 7), error);
    QVERIFY2(top, error.c_str());
    RBW_COMPARE_NEAR(top->Omega(), (-14.0 / 9.0), 4 * u * 14.0 / 9.0);
    RBW_COMPARE_NEAR(top->precessionRate(), std::sqrt(74.0) / 3.0, 4 * u * 3.0);
    const double tQuarter = 9.0 * M_PI / 28.0;
    RBW_COMPARE_NEAR(top->L_B(tQuarter), Vec3(-5, 0, 7), 1e-14 * 7.0);
    // T = 1/2 (25/3 + 49/9) = 1/2 (75 + 49)/9 = 62/9
    RBW_COMPARE_NEAR(top->kineticEnergy(), 62.0 / 9.0, 4 * u * 62.0 / 9.0);
}

// Invariants and ODEs for several tops: |L_B(t)| = |L|, T constant (rounding of a
// sin/cos evaluation: 1e-14 relative), the body-frame Euler equation by FD, the
// orientation's q' = 1/2 (0, omega_W) q by FD, and R(t)^T L_W = L_B(t) (the
// orientation and the body-frame formula agree; rounding of a few rotations: 1e-13).
void TestReferences::symmetricTop_data()
{
    QTest::addColumn<double>("I1");
    QTest::addColumn<double>("I3");
    QTest::addColumn<Quat>("q0");
    QTest::addColumn<Vec3>("L0_B");
    QTest::newRow("worked (3,3,9), L=(0,5,7), q0 tilted")
        << 3.0 << 9.0 << Quat(Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized())) << Vec3(0, 5, 7);
    QTest::newRow("prolate (2,2,1), L=(1,-2,0.5)")
        << 2.0 << 1.0 << Quat(Eigen::AngleAxisd(-1.1, Vec3(0, 1, 1).normalized())) << Vec3(1, -2, 0.5);
    QTest::newRow("oblate (1,1,1.8), L=(-0.3,0.2,-2)") << 1.0 << 1.8 << Quat::Identity() << Vec3(-0.3, 0.2, -2);
}

void TestReferences::symmetricTop()
{
    QFETCH(double, I1);
    QFETCH(double, I3);
    QFETCH(Quat, q0);
    QFETCH(Vec3, L0_B);
    std::string error;
    const std::optional<ref::SymmetricTop> top = ref::SymmetricTop::make(I1, I3, q0, L0_B, error);
    QVERIFY2(top, error.c_str());
    const Vec3 I(I1, I1, I3);
    const double L = L0_B.norm();
    const double T0 = top->kineticEnergy();
    RBW_COMPARE_NEAR(top->L_B(0.0), L0_B, 1e-15 * 4 * L);
    for (double t : {0.1, 0.77, 2.0, 5.5}) {
        const QByteArray at = QByteArray::number(t);
        RBW_COMPARE_NEAR(top->L_B(t).norm(), L, 1e-14 * L, at);
        const Vec3 Lb = top->L_B(t);
        RBW_COMPARE_NEAR(0.5 * Lb.dot(Lb.cwiseQuotient(I)), T0, 1e-14 * T0, at);
        QVERIFY2(eulerResidual([&](double s) { return top->L_B(s); }, I, t) <= kFdTol, at);
        const ref::ExactState st = top->at(t);
        const Eigen::Vector4d fd = quatRateFd([&](double s) { return top->orientation(s); }, t);
        RBW_COMPARE_NEAR(fd, quatRate(st.omega_W, st.q_WB), kFdTol * st.omega_W.norm(), at);
        RBW_COMPARE_NEAR(st.q_WB.conjugate() * top->L_W(), Lb, 1e-13 * L, at);
    }
}

// ---------------------------------------------------------------------------------
// Asymmetric top (Boost's sn, cn, dn): both branches (L^2 > 2T I2 and < 2T I2) and
// both signs of every component. Checks: omega_B(0) reproduces the initial condition
// (the phase tau0 and the signs; F and sn are accurate to ~1e-15, tolerance 1e-12);
// |L_B| and T constant (1e-12: Boost's elliptic functions are accurate to a few
// ulps, so the invariants hold to ~1e-14; 1e-12 leaves room near k -> 1); and the
// body-frame Euler equation by FD at a spread of times.
void TestReferences::asymmetricTop_data()
{
    QTest::addColumn<Vec3>("I");
    QTest::addColumn<Vec3>("L0_B");
    QTest::addColumn<bool>("circlesAxis3");
    // L^2 = 4.13, 2T = 0.04 + 0.045 + 1.3333 = 1.41833; 2T I2 = 2.8367 < L^2: axis 3
    QTest::newRow("(1,2,3) near axis 3") << Vec3(1, 2, 3) << Vec3(0.2, 0.3, 2) << true;
    QTest::newRow("(1,2,3) near axis 3, signs") << Vec3(1, 2, 3) << Vec3(-0.5, 0.7, -1.8) << true;
    // L^2 = 4.13, 2T = 4 + 0.045 + 0.01333 = 4.0583; 2T I2 = 8.117 > L^2: axis 1
    QTest::newRow("(1,2,3) near axis 1") << Vec3(1, 2, 3) << Vec3(2, 0.3, 0.2) << false;
    QTest::newRow("(1,2,3) near axis 1, signs") << Vec3(1, 2, 3) << Vec3(1.5, -0.4, -0.3) << false;
    QTest::newRow("(1,2,3) near axis 1, negative") << Vec3(1, 2, 3) << Vec3(-1.5, -0.4, 0.3) << false;
    QTest::newRow("Dzhanibekov (3,5,9)") << Vec3(3, 5, 9) << Vec3(0, 2, 0.01) << true;
}

void TestReferences::asymmetricTop()
{
    QFETCH(Vec3, I);
    QFETCH(Vec3, L0_B);
    QFETCH(bool, circlesAxis3);
    std::string error;
    const std::optional<ref::AsymmetricTop> top = ref::AsymmetricTop::make(I, L0_B, error);
    QVERIFY2(top, error.c_str());
    QCOMPARE(top->circlesAxis3(), circlesAxis3);
    const double L = L0_B.norm();
    const double T0 = 0.5 * L0_B.dot(L0_B.cwiseQuotient(I));
    RBW_COMPARE_NEAR(top->L_B(0.0), L0_B, 1e-12 * L);
    RBW_COMPARE_NEAR(top->kineticEnergy(), T0, 1e-14 * T0);
    const double P = top->period();
    for (int i = 1; i <= 20; ++i) {
        const double t = 0.137 * i * P;   // spread over almost three periods
        const QByteArray at = QByteArray::number(t);
        const Vec3 Lb = top->L_B(t);
        RBW_COMPARE_NEAR(Lb.norm(), L, 1e-12 * L, at);
        RBW_COMPARE_NEAR(0.5 * Lb.dot(Lb.cwiseQuotient(I)), T0, 1e-12 * T0, at);
        QVERIFY2(eulerResidual([&](double s) { return top->L_B(s); }, I, t) <= kFdTol, at);
    }
    // periodic: omega_B(t + P) = omega_B(t)
    RBW_COMPARE_NEAR(top->L_B(0.3 + P), top->L_B(0.3), 1e-10 * L);
}

void TestReferences::asymmetricTopRejectsBadInput()
{
    std::string error;
    // I not ordered
    QVERIFY(!ref::AsymmetricTop::make(Vec3(2, 1, 3), Vec3(1, 1, 1), error));
    QVERIFY(error.find("I1 < I2 < I3") != std::string::npos);
    // separatrix: I = (1,2,3), L = (0,1,0): L^2 = 1, 2T = 1/2, 2T I2 = 1 = L^2
    QVERIFY(!ref::AsymmetricTop::make(Vec3(1, 2, 3), Vec3(0, 1, 0), error));
    QVERIFY(error.find("separatrix") != std::string::npos);
    QVERIFY(!ref::AsymmetricTop::make(Vec3(1, 2, 3), Vec3::Zero(), error));
}

// The Dzhanibekov case by hand: L^2 = 4.0001, 2T = 0.8 + 0.0001/9 = 0.80001111...
//   k^2 = (I2 - I1)(2T I3 - L^2)/((I3 - I2)(L^2 - 2T I1)) = 2 (7.2001 - 4.0001)/(4 (4.0001 - 2.40003333))
//       = 6.4 / 6.40026667 = 0.99995833...
//   lambda = sqrt(4 * 1.60006667 / 135) = 0.2177...
// omega1(0) = 0 and omega2(0) > 0 give tau0 = K, so omega2 = A2 sn(tau) changes sign at
// tau = 2mK: t = K/lambda, 3K/lambda, ... equally spaced by 2K/lambda, and the
// sampled reference really changes sign there (a sign check 0.05 s either side).
void TestReferences::dzhanibekovCase()
{
    const ref::AsymmetricTop top = ref::dzhanibekov();
    const double twoT = 0.8 + 0.0001 / 9.0;
    const double k2 = 2.0 * (9.0 * twoT - 4.0001) / (4.0 * (4.0001 - 3.0 * twoT));
    RBW_COMPARE_NEAR(top.modulus() * top.modulus(), k2, 1e-14);
    RBW_COMPARE_NEAR(top.lambda(), std::sqrt(4.0 * (4.0001 - 3.0 * twoT) / 135.0), 1e-15);
    const std::vector<double> flips = top.signChangesOfOmega2(300.0);
    QVERIFY(flips.size() >= 5);
    const double K = top.quarterPeriod();
    RBW_COMPARE_NEAR(flips[0], K / top.lambda(), 1e-9);
    for (size_t i = 0; i < flips.size(); ++i) {
        if (i > 0) {
            RBW_COMPARE_NEAR((flips[i] - flips[i - 1]), 2.0 * K / top.lambda(), 1e-9);
        }
        QVERIFY(top.L_B(flips[i] - 0.05).y() * top.L_B(flips[i] + 0.05).y() < 0.0);
    }
}

// Negative control: the same elliptic solution with one sign wrong (omega2 -> -omega2,
// i.e. s1 s2 s3 = -1) keeps |L| and T (they are even in each component) but fails the
// FD check of Euler's equation by far: the residual check can fail.
void TestReferences::wrongReferenceIsCaught()
{
    const Vec3 I(1, 2, 3);
    std::string error;
    const std::optional<ref::AsymmetricTop> top = ref::AsymmetricTop::make(I, Vec3(0.2, 0.3, 2), error);
    QVERIFY2(top, error.c_str());
    auto wrong = [&](double t) {
        Vec3 L = top->L_B(t);
        L.y() = -L.y();
        return L;
    };
    const double t = 0.4 * top->period();
    QVERIFY(eulerResidual([&](double s) { return top->L_B(s); }, I, t) <= kFdTol);
    QVERIFY(eulerResidual(wrong, I, t) > 1e3 * kFdTol);
}

QTEST_APPLESS_MAIN(TestReferences)
#include "tst_references.moc"
