// Every integrator against the exact references (physics/workbook/reference/): measured orders
// of convergence, conservation over long runs, the Dzhanibekov flip, explicit Euler's
// energy growth, and a negative control. Measured numbers: docs/integrators.md.

#include <QtTest>

#include "tests/physics/engine/integrators/integrator_harness.h"
#include "physics/engine/integrators/rk4.h"
#include "physics/engine/integrators/rotation_matrix.h"
#include "physics/workbook/reference/dzhanibekov.h"
#include "physics/workbook/reference/symmetric_top.h"
#include "tests/test_support.h"

#include <cmath>

Q_DECLARE_METATYPE(rbw::Vec3)

using namespace rbw::test;
namespace ref = rbw::reference;

namespace {

// The symmetric top of the order test: the worked case I = (3, 3, 9), L_B = (0, 5, 7)
// (|omega| ~ 2.9 rad/s), with a tilted q0 so no axis is special in the world.
const Quat kTopQ0(Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()));
constexpr double kTopEnd = 2.0;   // T: about one turn of the precession (sqrt(74)/3 * 2 = 5.7 rad)

// Error at t = T against the exact symmetric top: the larger of the orientation
// angle error and the relative error of L_B (which also measures omega_B = I0^-1 L_B).
double topError(const Integrator& integrator, int steps)
{
    std::string error;
    const ref::SymmetricTop top = *ref::SymmetricTop::make(3.0, 9.0, kTopQ0, Vec3(0, 5, 7), error);
    OneBody b = freeBody(top.inertia(), kTopQ0, Vec3(0, 5, 7));
    run(integrator, b, kTopEnd / steps, steps);
    const double angle = angleBetween(b.s().q_WB, top.orientation(kTopEnd));
    const double dL = (bodyL(b.s()) - top.L_B(kTopEnd)).norm() / std::sqrt(74.0);
    return std::max(angle, dL);
}

// RK4 with the sign of the rotation wrong (r' = -1/2 (0, omega) r): a deliberately
// broken integrator for the negative control. It runs the real RK4 update on the body
// with L and omega negated, so the turn of r is reversed, then restores L (the base
// then derives omega = I^-1 L from it).
class BackwardsRk4 final : public rbw::Rk4 {
public:
    const char* name() const override { return "broken-rk4"; }

protected:
    void advance(const rbw::BodyStep& step, rbw::BodyState& s) const override
    {
        s.L_W = -s.L_W;
        s.omega_W = -s.omega_W;
        rbw::Rk4::advance(step, s);
        s.L_W = -s.L_W;
    }
};

// Dzhanibekov run: max |dE|/E and max |d|L||/|L| over the run, and the times at which
// L_B,y changed sign (linear interpolation between steps).
struct DzhanibekovRun {
    double maxEnergyDrift = 0.0;
    double maxMomentumDrift = 0.0;
    std::vector<double> flips;
};

DzhanibekovRun runDzhanibekov(const Integrator& integrator, double h, double tEnd)
{
    OneBody b = freeBody(ref::dzhanibekovInertia(), Quat::Identity(), ref::dzhanibekovL0_B());
    const double E0 = energy(b.s());
    const double L0 = b.s().L_W.norm();
    DzhanibekovRun r;
    double prevY = bodyL(b.s()).y();
    const long steps = std::lround(tEnd / h);
    for (long k = 1; k <= steps; ++k) {
        step(integrator, b, h);
        r.maxEnergyDrift = std::max(r.maxEnergyDrift, std::abs(energy(b.s()) - E0) / E0);
        r.maxMomentumDrift = std::max(r.maxMomentumDrift, std::abs(b.s().L_W.norm() - L0) / L0);
        const double y = bodyL(b.s()).y();
        if ((prevY > 0.0) != (y > 0.0)) {
            r.flips.push_back(h * (double(k - 1) + prevY / (prevY - y)));
        }
        prevY = y;
    }
    return r;
}

} // namespace

class TestIntegratorAccuracy : public QObject {
    Q_OBJECT

private slots:
    void convergenceOrder_data();
    void convergenceOrder();
    void wrongSignFailsTheOrderTest();
    void dzhanibekovConservation_data();
    void dzhanibekovConservation();
    void dzhanibekovFlips_data();
    void dzhanibekovFlips();
    void explicitEulerEnergyGrows();
    void rotationMatrixBodyMomentumGrows();
    void courseTemplateConverges_data();
    void courseTemplateConverges();
};

// ---------------------------------------------------------------------------------
// Measured order p = log2(e(h)/e(h/2)) against the exact symmetric top, for h = T/80
// and T/160 (|omega| h ~ 0.07 and 0.04: in the asymptotic range, and RK4's error at
// T/160 is still ~1e-8, far above rounding). Tolerance +-0.2 (the issue's), which
// covers the O(h) correction to the leading term seen between h = T/40 and T/320
// (orders 1.01-1.09 for the first-order methods, docs/integrators.md).
void TestIntegratorAccuracy::convergenceOrder_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<double>("expectedOrder");
    QTest::newRow("explicit-euler") << "explicit-euler" << 1.0;
    QTest::newRow("midpoint") << "midpoint" << 2.0;
    QTest::newRow("rk4") << "rk4" << 4.0;
    // measured: 1.02, 0.99, 2.00, 1.05, 1.01 (docs/integrators.md)
    QTest::newRow("symplectic-euler") << "symplectic-euler" << 1.0;
    QTest::newRow("implicit-gyroscopic") << "implicit-gyroscopic" << 1.0;
    QTest::newRow("implicit-midpoint") << "implicit-midpoint" << 2.0;
    QTest::newRow("rotation-matrix") << "rotation-matrix" << 1.0;
    QTest::newRow("rotation-matrix-orthonormalised") << "rotation-matrix-orthonormalised" << 1.0;
}

void TestIntegratorAccuracy::convergenceOrder()
{
    QFETCH(QString, name);
    QFETCH(double, expectedOrder);
    const std::unique_ptr<Integrator> integrator = integratorNamed(name);
    QVERIFY(integrator);
    const double e1 = topError(*integrator, 80);
    const double e2 = topError(*integrator, 160);
    const double p = std::log2(e1 / e2);
    RBW_COMPARE_NEAR(p, expectedOrder, 0.2, QStringLiteral("%1: the measured order (errors %2, %3)").arg(name).arg(e1).arg(e2));
}

// Negative control: RK4 turning the wrong way has an O(1) error that does not shrink
// with h (the order is ~0, not 4), so the same check rejects it.
void TestIntegratorAccuracy::wrongSignFailsTheOrderTest()
{
    const BackwardsRk4 broken;
    const double e1 = topError(broken, 80);
    const double e2 = topError(broken, 160);
    const double p = std::log2(e1 / e2);
    QVERIFY2(std::abs(p - 4.0) > 0.2, qPrintable(QString::number(p)));
    QVERIFY(e2 > 0.1);
}

// ---------------------------------------------------------------------------------
// Dzhanibekov, 100 s at h = 0.01 (10^4 steps), max |dE|/E and max |d|L||/|L|:
// - implicit-midpoint conserves both exactly in exact arithmetic (header of
//   implicit_midpoint.h); in doubles each step adds a rounding of a few u to r and
//   L_B, a random walk of sqrt(10^4) * few u ~ 1e-14: bound 1e-12 (the issue's).
// - rk4: energy error O(h^4) per unit time; measured 1.1e-12; bound 1e-11 (issue).
// - L_W is untouched by a torque-free step of every method except implicit-gyroscopic
//   (which writes L = I(r_{n+1}) omega'): |d|L||/|L| == 0 exactly for them.
// - explicit-euler, implicit-gyroscopic: first order, drift ~1e-2 at h = 0.01
//   (docs/references.md §5); asserted as a band [1e-3, 1e-1] so a change is noticed.
void TestIntegratorAccuracy::dzhanibekovConservation_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<double>("energyMin");
    QTest::addColumn<double>("energyMax");
    QTest::addColumn<double>("momentumMax");
    QTest::newRow("implicit-midpoint") << "implicit-midpoint" << 0.0 << 1e-12 << 0.0;
    QTest::newRow("rk4") << "rk4" << 0.0 << 1e-11 << 0.0;
    QTest::newRow("midpoint") << "midpoint" << 1e-9 << 1e-7 << 0.0;
    QTest::newRow("explicit-euler") << "explicit-euler" << 1e-3 << 1e-1 << 0.0;
    QTest::newRow("implicit-gyroscopic") << "implicit-gyroscopic" << 1e-3 << 1e-1 << 1e-1;
}

void TestIntegratorAccuracy::dzhanibekovConservation()
{
    QFETCH(QString, name);
    QFETCH(double, energyMin);
    QFETCH(double, energyMax);
    QFETCH(double, momentumMax);
    const std::unique_ptr<Integrator> integrator = integratorNamed(name);
    const DzhanibekovRun r = runDzhanibekov(*integrator, 0.01, 100.0);
    const QString what = QStringLiteral("%1: max |dE|/E = %2, max |d|L||/|L| = %3")
                             .arg(name)
                             .arg(r.maxEnergyDrift, 0, 'g', 3)
                             .arg(r.maxMomentumDrift, 0, 'g', 3);
    qInfo().noquote() << what;
    QVERIFY2(r.maxEnergyDrift >= energyMin && r.maxEnergyDrift <= energyMax, qPrintable(what));
    QVERIFY2(r.maxMomentumDrift <= momentumMax, qPrintable(what));
}

// The flip happens, at the times the exact solution gives, at equal intervals:
// 300 s at h = 0.01 (five flips, reference times 29.53, 88.58, ... s, 2K/lambda = 59.06 s
// apart). Tolerance 0.05 s on each time: near the separatrix the flip time is
// sensitive to the phase, and a 2nd/4th-order error in L_B of ~1e-6 shifts it by
// ~log-sensitivity * 1e-6 / lambda; measured shifts are below 0.01 s.
void TestIntegratorAccuracy::dzhanibekovFlips_data()
{
    QTest::addColumn<QString>("name");
    QTest::newRow("implicit-midpoint") << "implicit-midpoint";
    QTest::newRow("rk4") << "rk4";
}

void TestIntegratorAccuracy::dzhanibekovFlips()
{
    QFETCH(QString, name);
    const std::unique_ptr<Integrator> integrator = integratorNamed(name);
    const DzhanibekovRun r = runDzhanibekov(*integrator, 0.01, 300.0);
    const std::vector<double> exact = ref::dzhanibekov().signChangesOfOmega2(300.0);
    QCOMPARE(r.flips.size(), exact.size());
    QVERIFY(exact.size() >= 5);
    for (size_t i = 0; i < exact.size(); ++i) {
        RBW_COMPARE_NEAR(r.flips[i], exact[i], 0.05, QStringLiteral("flip %1").arg(i));
    }
    const double interval = r.flips[1] - r.flips[0];
    for (size_t i = 2; i < r.flips.size(); ++i) {
        RBW_COMPARE_NEAR((r.flips[i] - r.flips[i - 1]), interval, 0.05);
    }
}

// ---------------------------------------------------------------------------------
// Explicit Euler in the TUM order keeps L_W exactly (L <- L + h*0), so |L| does not
// grow in the world frame; what grows is the energy. One step turns the body about
// the world omega by theta = 2 atan(h|omega|/2) (normalise(r + h/2 (0,omega) r) =
// normalise((1, h omega/2)) r), so in the body frame L_B' = Rot(omega_B, -theta) L_B =
// L_B + h L_B x omega_B + (second-order term along L_B - (L_B.w)w, w = omega_B/|omega_B|)
// + O(h^3). With 2T = L_B . I0^-1 L_B and I0^-1 L_B = omega_B, the first-order term gives
// 2h omega_B.(L_B x omega_B) = 0 and the second-order term gives -h^2|omega|^2 (omega.L -
// omega.L) = 0, leaving
//   2T' - 2T = h^2 (L_B x omega_B) . I0^-1 (L_B x omega_B) + O(h^3) > 0:
// the body-frame form's |L|-growth identity, moved into the energy. So T grows at
// every step for a free asymmetric body (I = (3,5,9), L = (0.3, 2, 1), far from the
// axes, h = 0.01, 2000 steps), and L_W stays bit-for-bit constant.
void TestIntegratorAccuracy::explicitEulerEnergyGrows()
{
    const std::unique_ptr<Integrator> integrator = integratorNamed(QStringLiteral("explicit-euler"));
    OneBody b = freeBody(Vec3(3, 5, 9), kTopQ0, Vec3(0.3, 2, 1));
    const Vec3 L0_W = b.s().L_W;
    double T = energy(b.s());
    const double T0 = T;
    for (int k = 0; k < 2000; ++k) {
        step(*integrator, b, 0.01);
        const double Tn = energy(b.s());
        QVERIFY2(Tn > T, qPrintable(QStringLiteral("step %1: T %2 -> %3").arg(k).arg(T, 0, 'g', 17).arg(Tn, 0, 'g', 17)));
        T = Tn;
        QVERIFY(b.s().L_W == L0_W);
    }
    QVERIFY(T > T0 * (1.0 + 1e-4));
}

// Napier's R <- R + h [omega]x R is where the textbook body-frame identity shows:
// L_B,n+1 = R_{n+1}^T L = R_n^T (E - h[omega]x) L = R_n^T (L - h omega x L), so for an
// orthogonal R_n: |L_B,n+1|^2 = |L|^2 + h^2 |omega x L|^2 (L.(omega x L) = 0), i.e. |L_B|
// grows; the drift of R keeps it growing. First step: exact identity up to rounding
// (R_0 is orthogonal to ~u, the products cost a few u: tolerance 64 u |L|^2).
void TestIntegratorAccuracy::rotationMatrixBodyMomentumGrows()
{
    const std::unique_ptr<Integrator> integrator = integratorNamed(QStringLiteral("rotation-matrix"));
    const double h = 0.01;
    OneBody b = freeBody(Vec3(3, 5, 9), kTopQ0, Vec3(0.3, 2, 1));
    const Vec3 L = b.s().L_W;
    const Vec3 omega0 = b.s().omega_W;
    step(*integrator, b, h);
    const double expected = L.squaredNorm() + h * h * omega0.cross(L).squaredNorm();
    RBW_COMPARE_NEAR(bodyL(b.s()).squaredNorm(), expected, 64 * u * L.squaredNorm());
    double prev = bodyL(b.s()).norm();
    for (int k = 0; k < 2000; ++k) {
        step(*integrator, b, h);
        const double now = bodyL(b.s()).norm();
        QVERIFY2(now > prev, qPrintable(QString::number(k)));
        prev = now;
    }
}

// ---------------------------------------------------------------------------------
// Course-template convention (I^-1 = R^T I0^-1 R): no closed form, so every
// integrator is compared with RK4 at h = 1e-3 (error ~1e-12) after 1 s of an
// asymmetric body (I = (1, 2, 3.5), tilted start). Each must converge to the same
// solution: the error at h = 0.01 is below 0.05 and shrinks when h is halved by at
// least 2^(order) / 1.5 (a first-order method by 1.33x, second order by 2.7x).
void TestIntegratorAccuracy::courseTemplateConverges_data()
{
    QTest::addColumn<QString>("name");
    for (const rbw::IntegratorInfo& info : rbw::integratorCatalogue()) {
        QTest::newRow(info.name) << QString::fromLatin1(info.name);
    }
}

void TestIntegratorAccuracy::courseTemplateConverges()
{
    QFETCH(QString, name);
    const std::unique_ptr<Integrator> integrator = integratorNamed(name);
    const rbw::InertiaConvention tmpl = rbw::InertiaConvention::CourseTemplate;
    const Vec3 I(1, 2, 3.5);
    const Vec3 L0(0.4, -0.7, 1.5);
    auto finalState = [&](const Integrator& in, int steps) {
        OneBody b = freeBody(I, kTopQ0, L0, Vec3::Zero(), Vec3::Zero(), tmpl);
        run(in, b, 1.0 / steps, steps);
        return b.s();
    };
    const rbw::BodyState exact = finalState(rbw::Rk4(), 1000);
    auto err = [&](int steps) {
        const rbw::BodyState s = finalState(*integrator, steps);
        return std::max(angleBetween(s.q_WB, exact.q_WB), (s.omega_W - exact.omega_W).norm() / exact.omega_W.norm());
    };
    const double e1 = err(100);
    const double e2 = err(200);
    int order = 1;
    for (const rbw::IntegratorInfo& info : rbw::integratorCatalogue()) {
        if (name == QLatin1String(info.name)) order = info.order;
    }
    const QString what = QStringLiteral("%1: errors %2 (h=0.01), %3 (h=0.005)").arg(name).arg(e1).arg(e2);
    QVERIFY2(e1 < 0.05, qPrintable(what));
    QVERIFY2(e1 / e2 >= std::pow(2.0, order) / 1.5, qPrintable(what));
}

QTEST_APPLESS_MAIN(TestIntegratorAccuracy)
#include "tst_integrator_accuracy.moc"
