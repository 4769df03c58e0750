// Multi-step invariants of the explicit Euler world (docs/references.md §1 and §5),
// each derived in a comment above its test, with the tolerance stated and justified.
//
// Notation: u = 2^-53 is the unit roundoff of double (half the machine epsilon).

#include <QtTest>

#include "physics/engine/diagnostics.h"
#include "physics/engine/scene.h"
#include "physics/engine/trace.h"
#include "physics/engine/world.h"
#include "tests/test_support.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

Q_DECLARE_METATYPE(rbw::Vec3)

namespace {

using rbw::Quat;
using rbw::Vec3;

const double u = std::ldexp(1.0, -53);

QString vecText(const Vec3& v)
{
    return QStringLiteral("(%1, %2, %3)")
        .arg(v.x(), 0, 'g', 17)
        .arg(v.y(), 0, 'g', 17)
        .arg(v.z(), 0, 'g', 17);
}

using rbw::test::boxDef;

Quat axisAngle(double angle, const Vec3& axis)
{
    return Quat(Eigen::AngleAxisd(angle, axis.normalized()));
}

// Three free boxes with different sizes, masses, positions, orientations, linear and
// angular velocities; no forces, no gravity. They never touch, so no contact impulse
// can act either: the centres move on straight lines c(t) = x0 + t v, and the smallest
// centre distance over t >= 0 is
//   A-B: d(t) = (-4 - 0.8t, 3 + 1.45t, 1.5 - 0.8t), d.d' > 0 at t = 0 -> min |d(0)| = 5.2
//   A-C: d(t) = (-1 - 0.3t, 2 + 1.2t, -4.5 + 1.2t), min at t = 2.7/2.97: |d| = 4.77
//   B-C: d(t) = (3 + 0.5t, -1 - 0.25t, -6 + 2t),     min at t = 10.25/4.3125: |d| = 4.65
// while the bounding spheres (half-diagonals) are A sqrt(0.25+1+2.25) = 1.87,
// B sqrt(0.0625+0.0625+1) = 1.06, C sqrt(1+0.25+0.25) = 1.22: every pair sum < 3.1.
rbw::SceneDef freeBodies(double dt)
{
    rbw::SceneDef s;
    s.name = "free bodies";
    s.dt = dt;
    s.bodies.push_back(boxDef("A", Vec3(1, 2, 3), 1.5, Vec3(1, -2, 0.5), axisAngle(0.7, Vec3(1, 2, 2)),
                           Vec3(0.3, -1.2, 0.8), Vec3(1.1, -0.4, 2.3)));
    s.bodies.push_back(boxDef("B", Vec3(0.5, 0.5, 2), 4.0, Vec3(-3, 1, 2), Quat::Identity(),
                           Vec3(-0.5, 0.25, 0), Vec3(0, 3, 0.2)));
    s.bodies.push_back(boxDef("C", Vec3(2, 1, 1), 0.8, Vec3(0, 0, -4), axisAngle(2.0, Vec3(0, 1, 0)),
                           Vec3(0, 0, 2), Vec3(-5, 0.1, 0.1)));
    return s;
}

// The blow-up scene: body 0 "calm", a unit cube at rest at (5, 0, 0), and body 1
// "spinner", a cube of edge 1 and mass 6, so I0 = 6/12 * diag(1+1, 1+1, 1+1) = identity,
// starting at the origin with r0 = identity and the given v0 and omega0. The calm cube
// is 5 away and the spinner only spins or flies off along +x in jumps far past it, so
// the two never touch: whatever happens to the spinner, the calm body must stay as it
// is and must never be named in a blow-up.
rbw::SceneDef blowUpScene(double dt, const Vec3& v0, const Vec3& omega0)
{
    rbw::SceneDef s;
    s.name = "blow-up";
    s.dt = dt;
    s.bodies.push_back(boxDef("calm", Vec3(1, 1, 1), 1.0, Vec3(5, 0, 0), Quat::Identity(), Vec3::Zero(),
                           Vec3::Zero()));
    s.bodies.push_back(boxDef("spinner", Vec3(1, 1, 1), 6.0, Vec3::Zero(), Quat::Identity(), v0, omega0));
    return s;
}

} // namespace

class TestInvariants : public QObject {
    Q_OBJECT

private slots:
    void noForcesConservesMomenta_data();
    void noForcesConservesMomenta();
    void pureTranslationKeepsKineticEnergy_data();
    void pureTranslationKeepsKineticEnergy();
    void quaternionStaysUnit_data();
    void quaternionStaysUnit();
    void forceWindowGivesImpulse_data();
    void forceWindowGivesImpulse();
    void blowUpIsReported_data();
    void blowUpIsReported();
    void blowUpControlSmallDt_data();
    void blowUpControlSmallDt();
    void orientationOverflowIsNotSilent();
};

// ---------------------------------------------------------------------------------
// No forces: P and L_O are conserved.
//
// With no force and no torque, each step does v <- v + h*0/M and L <- L + h*0. Both
// additions add an exact zero, so v and L_W are bit-for-bit constant, and so is
// P = sum M v (the same products summed in the same order): compared with ==.
// (Explicit Euler is known to grow |L| when Euler's equations are integrated in the
// body frame, |L_{n+1}|^2 = |L_n|^2 + h^2 |omega x L_n|^2; this world integrates L in
// the WORLD frame, where the torque-free update is L <- L + h*0: exactly constant.)
//
// L_O = sum (x x P + L). In exact arithmetic one step changes x x P by
// (h v) x (M v) = 0, so L_O is constant too. In doubles x drifts from x0 + n h v by the
// roundings of fl(h v) (componentwise, <= u h|v|) and of each addition (<= u |x_k|):
//   |x_n - (x0 + n h v)| <= n u (h|v| + X),   X = max_k |x_k|,
// and since (n h v) x P = 0 the computed L_O moves by at most that times |P|, plus the
// rounding of evaluating x x P + L once at the start and once now (a few u each,
// bounded by 8 u (X |P| + |L|)). Tolerance on |L_O,n - L_O,0|:
//   tol = sum over bodies of (n + 8) u ((h|v| + X)|P| + |L|).
void TestInvariants::noForcesConservesMomenta_data()
{
    QTest::addColumn<double>("dt");
    QTest::addColumn<int>("steps");
    QTest::newRow("h=0.001") << 0.001 << 5000;
    QTest::newRow("h=0.01") << 0.01 << 5000;
    QTest::newRow("h=0.1") << 0.1 << 5000;
    QTest::newRow("h=1") << 1.0 << 2000;
}

void TestInvariants::noForcesConservesMomenta()
{
    QFETCH(double, dt);
    QFETCH(int, steps);

    rbw::World world(freeBodies(dt));
    const int nBodies = static_cast<int>(world.states().size());
    const rbw::Diagnostics d0 = world.diagnostics();
    std::vector<Vec3> v0;
    std::vector<Vec3> L0;
    std::vector<double> X(nBodies, 0.0);
    for (const rbw::BodyState& s : world.states()) {
        v0.push_back(s.v_W);
        L0.push_back(s.L_W);
    }
    for (int b = 0; b < nBodies; ++b) {
        X[b] = world.states()[b].x_W.norm();
    }

    for (int k = 0; k < steps; ++k) {
        const rbw::StepStatus st = world.step();
        QVERIFY2(st.ok, st.message.c_str());
        for (int b = 0; b < nBodies; ++b) {
            const rbw::BodyState& s = world.states()[b];
            X[b] = std::max(X[b], s.x_W.norm());
            // v and L_W: bit-for-bit constant (an exact zero is added each step).
            if (s.v_W != v0[b] || s.L_W != L0[b]) {
                QFAIL(qPrintable(QStringLiteral("step %1 body %2: v %3 (was %4), L %5 (was %6)")
                                     .arg(k)
                                     .arg(b)
                                     .arg(vecText(s.v_W), vecText(v0[b]), vecText(s.L_W), vecText(L0[b]))));
            }
        }
        const rbw::Diagnostics d = world.diagnostics();
        if (d.P_W != d0.P_W) {
            QFAIL(qPrintable(QStringLiteral("step %1: P %2, was %3").arg(k).arg(vecText(d.P_W), vecText(d0.P_W))));
        }
    }

    double tol = 0.0;
    for (int b = 0; b < nBodies; ++b) {
        const double M = world.massProperties()[b].M;
        const double P = M * v0[b].norm();
        tol += (steps + 8) * u * ((dt * v0[b].norm() + X[b]) * P + L0[b].norm());
    }
    const Vec3 LO = world.diagnostics().L_O_W;
    const double drift = (LO - d0.L_O_W).norm();
    QVERIFY2(drift <= tol, qPrintable(QStringLiteral("L_O drifted by %1 > tol %2: %3 -> %4")
                                          .arg(drift, 0, 'g', 3)
                                          .arg(tol, 0, 'g', 3)
                                          .arg(vecText(d0.L_O_W), vecText(LO))));
    // The bodies really moved and turned: x changed by n h v, and omega (which depends
    // on the orientation) is no longer omega0 for the asymmetric box A.
    QVERIFY((world.states()[0].x_W - freeBodies(dt).bodies[0].x0_W).norm() > 0.1 * steps * dt);
}

// ---------------------------------------------------------------------------------
// Pure translation keeps its kinetic energy exactly.
//
// With omega0 = 0, L0 = I(r0) * 0 = 0 exactly (every product is 0). No torque keeps
// L = 0 + h*0 = 0 and omega = I^-1 * 0 = 0 exactly, so T_rot = 1/2 omega.L = 0 exactly.
// No force keeps v bit-for-bit (v + h*0/M = v), so T_trans = 1/2 M |v|^2 is computed
// from the same bits every step: T is constant with ==, whatever the orientation.
// The hand values of T: rows 1-3 are dyadic, so T is exact and compared with ==:
//   M = 2,   v = (3/2, -2, 6):      |v|^2 = 9/4 + 4 + 36 = 169/4,          T = 169/4
//   M = 1/2, v = (1/4, -1/2, 1):    |v|^2 = 1/16 + 1/4 + 1 = 21/16,        T = 21/64
//   M = 8,   v = (0, 0, -3/8):      |v|^2 = 9/64,                          T = 9/16
// Row 4, M = 3, v = (0.1, 0.2, -0.3): |v|^2 = 0.14, T = 0.21, which doubles cannot hold
// exactly: T_0 is compared with 0.21 to 8u relative (the three decimal inputs and about
// six roundings), and every later T with T_0 by ==.
void TestInvariants::pureTranslationKeepsKineticEnergy_data()
{
    QTest::addColumn<double>("dt");
    QTest::addColumn<double>("mass");
    QTest::addColumn<Vec3>("v0");
    QTest::addColumn<double>("angle");   // r0 = angle about (1, 2, 2)/3
    QTest::addColumn<double>("T");
    QTest::addColumn<double>("relTolT0");

    QTest::newRow("M=2 h=0.01") << 0.01 << 2.0 << Vec3(1.5, -2, 6) << 0.0 << 169.0 / 4.0 << 0.0;
    QTest::newRow("M=1/2 h=0.37 rotated") << 0.37 << 0.5 << Vec3(0.25, -0.5, 1) << 1.2 << 21.0 / 64.0 << 0.0;
    QTest::newRow("M=8 h=1e-3 rotated") << 1e-3 << 8.0 << Vec3(0, 0, -0.375) << 2.5 << 9.0 / 16.0 << 0.0;
    QTest::newRow("M=3 h=0.05 decimal v") << 0.05 << 3.0 << Vec3(0.1, 0.2, -0.3) << 0.4 << 0.21 << 8 * u;
}

void TestInvariants::pureTranslationKeepsKineticEnergy()
{
    QFETCH(double, dt);
    QFETCH(double, mass);
    QFETCH(Vec3, v0);
    QFETCH(double, angle);
    QFETCH(double, T);
    QFETCH(double, relTolT0);

    rbw::SceneDef s;
    s.name = "translation";
    s.dt = dt;
    s.bodies.push_back(boxDef("slider", Vec3(1, 2, 3), mass, Vec3(1, 1, 1), axisAngle(angle, Vec3(1, 2, 2)),
                           v0, Vec3::Zero()));
    rbw::World world(s);
    const double T0 = world.diagnostics().kinetic;
    if (relTolT0 == 0.0) {
        QCOMPARE(T0, T);
    } else {
        RBW_COMPARE_NEAR(T0, T, relTolT0 * T);
    }
    for (int k = 0; k < 10000; ++k) {
        QVERIFY(world.step().ok);
        const rbw::Diagnostics d = world.diagnostics();
        if (d.kinetic != T0 || d.kineticRotational != 0.0 || world.states()[0].omega_W != Vec3::Zero()) {
            QFAIL(qPrintable(QStringLiteral("step %1: T = %2 (T0 = %3), T_rot = %4")
                                 .arg(k)
                                 .arg(d.kinetic, 0, 'g', 17)
                                 .arg(T0, 0, 'g', 17)
                                 .arg(d.kineticRotational, 0, 'g', 17)));
        }
    }
}

// ---------------------------------------------------------------------------------
// |r| = 1 after 10^4 steps of a spinning box.
//
// Without renormalisation, r + (h/2)(0, omega) r has norm |r| sqrt(1 + (h|omega|/2)^2)
// (the product (0, omega) r is orthogonal to r in R^4), so |r| would grow by a factor
// (1 + (h|omega|/2)^2)^(n/2): for the gentlest row below (h|omega| ~ 0.01) that is
// exp(10^4 * 1.25e-5 / 2) ~ 1.06 after 10^4 steps, far outside the tolerance. The world
// renormalises every step, so |r| - 1 is the rounding of one division by the norm: a
// few u, and it does not accumulate. Tolerance 1e-12 on | |r| - 1 | at every step.
//
// Also checked along the way, since there is no torque:
//   - L_W is bit-for-bit constant (L + h*0);
//   - |omega| = |R I0^-1 R^T L| <= |L| / I_min (the largest eigenvalue of I^-1 is
//     1/I_min for every R), to 1e-12 relative: even a huge h|omega| cannot make
//     this explicit Euler diverge, because L_W never grows.
void TestInvariants::quaternionStaysUnit_data()
{
    QTest::addColumn<double>("dt");
    QTest::addColumn<Vec3>("omega0");

    // Box (1, 2, 3), M = 1: I0 = diag(13, 10, 5)/12, I_min = 5/12.
    QTest::newRow("h|w|~0.01") << 0.001 << Vec3(3, -8, 4);      // |omega0| = sqrt(89) ~ 9.4
    QTest::newRow("h|w|~1") << 0.1 << Vec3(3, -8, 4);
    QTest::newRow("h|w|~100 tumbling") << 10.0 << Vec3(3, -8, 4);
    QTest::newRow("slow spin about ~y, h=0.01") << 0.01 << Vec3(0.01, 2, 0.01);
}

void TestInvariants::quaternionStaysUnit()
{
    QFETCH(double, dt);
    QFETCH(Vec3, omega0);

    rbw::SceneDef s;
    s.name = "spinner";
    s.dt = dt;
    s.bodies.push_back(boxDef("spinner", Vec3(1, 2, 3), 1.0, Vec3(0, 0, 0), axisAngle(0.3, Vec3(2, -1, 2)),
                           Vec3::Zero(), omega0));
    rbw::World world(s);
    const Vec3 L0 = world.states()[0].L_W;
    const double Imin = 5.0 / 12.0;
    double worstNorm = 0.0;
    for (int k = 0; k < 10000; ++k) {
        const rbw::StepStatus st = world.step();
        QVERIFY2(st.ok, st.message.c_str());
        const rbw::BodyState& b = world.states()[0];
        const double dev = std::abs(b.q_WB.norm() - 1.0);
        worstNorm = std::max(worstNorm, dev);
        if (dev > 1e-12) {
            QFAIL(qPrintable(QStringLiteral("step %1: |r| - 1 = %2").arg(k).arg(dev, 0, 'g', 3)));
        }
        if (b.L_W != L0) {
            QFAIL(qPrintable(QStringLiteral("step %1: L %2, was %3").arg(k).arg(vecText(b.L_W), vecText(L0))));
        }
        if (b.omega_W.norm() > L0.norm() / Imin * (1.0 + 1e-12)) {
            QFAIL(qPrintable(QStringLiteral("step %1: |omega| = %2 > |L|/I_min = %3")
                                 .arg(k)
                                 .arg(b.omega_W.norm(), 0, 'g', 17)
                                 .arg(L0.norm() / Imin, 0, 'g', 17)));
        }
    }
    qDebug("max ||r| - 1| over 10^4 steps: %.3g", worstNorm);
}

// ---------------------------------------------------------------------------------
// A force acting in the steps [from, to) gives the impulse F h (to - from).
//
// In an active step v <- v + (h/M) F, so P = M v changes by h F; outside the window
// v <- v + 0 leaves v (and P) bit-for-bit unchanged. Hence
//   P(k) = P(0)                          for k <= from   (before the window)
//   P(k) = P(0) + F h (k - from)         for from <= k <= to
//   P(k) = P(0) + F h (to - from)        for k >= to     (after the window)
// where P(k) is the momentum after k steps. The application point only adds torque;
// it does not change P.
// Exactness: in the "exact" rows h, M, 1/M, F and v0 are small dyadic rationals, so
// every increment (h/M) F, every partial sum and M v are exact in binary and the
// impulse is compared with ==. In the decimal row (h = 0.01, M = 3) each increment
// d = fl(fl(h fl(1/M)) F) is within 3u|hF/M| of hF/M and each addition rounds by at most
// u|v|, so componentwise
//   |DeltaP - F h n| <= M n u (3|h F_i/M| + V_i) + u (|P_after,i| + |P_before,i|) + 3u |F_i h n|
// with V_i = max_k |v_k,i| and n = to - from (the last two terms: rounding of M v, of
// the subtraction and of the product F h n).
//
// The trace must also show the force only inside the window: applied_force[0] is
// recorded in step k iff from <= k < to.
void TestInvariants::forceWindowGivesImpulse_data()
{
    QTest::addColumn<long>("from");
    QTest::addColumn<long>("to");
    QTest::addColumn<int>("steps");
    QTest::addColumn<double>("dt");
    QTest::addColumn<double>("mass");
    QTest::addColumn<Vec3>("force");
    QTest::addColumn<Vec3>("lever");   // application point relative to x0
    QTest::addColumn<bool>("exact");

    QTest::newRow("step 0 only") << 0L << 1L << 5 << 0.5 << 2.0 << Vec3(1, -2, 4) << Vec3(0, 0, 0) << true;
    QTest::newRow("window [3,7)") << 3L << 7L << 12 << 0.25 << 4.0 << Vec3(3, 0.5, -1.5) << Vec3(0.5, -0.25, 1)
                                  << true;
    QTest::newRow("single late step [5,6)") << 5L << 6L << 9 << 0.125 << 0.5 << Vec3(-8, 2, 1)
                                            << Vec3(-1, 1, 0.5) << true;
    QTest::newRow("long window [2,40)") << 2L << 40L << 50 << 0.0625 << 1.0 << Vec3(0.75, -1.25, 2.5)
                                        << Vec3(0.25, 0.25, -0.5) << true;
    QTest::newRow("decimal [1,101)") << 1L << 101L << 120 << 0.01 << 3.0 << Vec3(0.1, -0.2, 0.3)
                                     << Vec3(0.3, 0.1, -0.2) << false;
}

void TestInvariants::forceWindowGivesImpulse()
{
    QFETCH(long, from);
    QFETCH(long, to);
    QFETCH(int, steps);
    QFETCH(double, dt);
    QFETCH(double, mass);
    QFETCH(Vec3, force);
    QFETCH(Vec3, lever);
    QFETCH(bool, exact);

    const Vec3 x0(1, -1, 2);
    rbw::SceneDef s;
    s.name = "impulse";
    s.dt = dt;
    s.bodies.push_back(boxDef("box", Vec3(1, 2, 3), mass, x0, axisAngle(0.5, Vec3(1, 1, 0)), Vec3(0.5, -1, 0.25),
                           Vec3(0.5, 1, -0.5)));
    rbw::ForceDef f;
    f.body = 0;
    f.p_W = x0 + lever;
    f.f_W = force;
    f.fromStep = from;
    f.toStep = to;
    s.forces.push_back(f);
    QVERIFY(rbw::validate(s).empty());

    rbw::World world(s);
    const Vec3 P0 = world.diagnostics().P_W;
    Vec3 Pbefore = P0;   // P after `from` steps, i.e. just before the window
    Vec3 V = world.states()[0].v_W.cwiseAbs();
    rbw::StepTrace trace;
    for (int k = 0; k < steps; ++k) {
        if (k == from) {
            Pbefore = world.diagnostics().P_W;
        }
        const Vec3 Pprev = world.diagnostics().P_W;
        QVERIFY(world.step(&trace).ok);
        V = V.cwiseMax(world.states()[0].v_W.cwiseAbs());
        const bool active = from <= k && k < to;
        // The force is in the trace exactly in the active steps.
        QVERIFY2((trace.find("applied_force", 0, 0) != nullptr) == active,
                 qPrintable(QStringLiteral("step %1: applied_force present = %2, active = %3")
                                .arg(k)
                                .arg(trace.find("applied_force", 0, 0) != nullptr)
                                .arg(active)));
        // Outside the window the momentum does not change at all.
        if (!active) {
            QVERIFY2(world.diagnostics().P_W == Pprev,
                     qPrintable(QStringLiteral("step %1 outside the window changed P: %2 -> %3")
                                    .arg(k)
                                    .arg(vecText(Pprev), vecText(world.diagnostics().P_W))));
        }
    }
    // Before the window nothing happened.
    QVERIFY(Pbefore == P0);

    const Vec3 Pafter = world.diagnostics().P_W;
    const double n = static_cast<double>(to - from);
    const Vec3 impulse = force * dt * n;   // F h (to - from)
    const Vec3 deltaP = Pafter - Pbefore;
    if (exact) {
        QCOMPARE(deltaP, impulse);
    } else {
        for (int i = 0; i < 3; ++i) {
            const double tol = mass * n * u * (3.0 * std::abs(dt * force[i] / mass) + V[i]) +
                               u * (std::abs(Pafter[i]) + std::abs(Pbefore[i])) +
                               3.0 * u * std::abs(impulse[i]);
            RBW_COMPARE_NEAR(deltaP[i], impulse[i], tol, QStringLiteral("component %1 of DeltaP against F h n").arg(i));
        }
    }
}

// ---------------------------------------------------------------------------------
// A blow-up is reported, named, and the world refuses to go on.
//
// Note on explicit Euler here: this world integrates L in the world frame, so a free
// spin keeps L_W exactly and |omega| <= |L|/I_min (see quaternionStaysUnit), and the
// quaternion is renormalised each step. A torque-free spin therefore never diverges
// the way the body-frame form does (|L_{n+1}|^2 = |L_n|^2 + h^2|omega x L_n|^2); the
// only way to a non-finite state is overflow of a single update. Both rows below
// derive when that happens (DBL_MAX ~ 1.797e308):
//
// "huge spin, huge dt": spinner with I0 = identity, r0 = (1,0,0,0), omega0 = (1e100,0,0),
//   h = 1e210, so L0 = omega0. Step 0: x = 0 + h*0 = 0 and v = 0 stay finite;
//   r + (h/2)(0, omega0) r = (1, 0, 0, 0) + (0, 5e309, 0, 0); 5e309 > DBL_MAX rounds to
//   +inf, |r|^2 = inf, and r/|r| = (1/inf, inf/inf, 0, 0) = (0, NaN, 0, 0).
//   -> reported in step 0, body 1 "spinner", quantity "orientation" (position and
//   velocity are checked first and are finite).
// "runaway velocity": v0 = (1e308, 0, 0), h = 1, omega0 = 0. Step 0: x = 0 + 1e308,
//   finite. Step 1: x = 1e308 + 1e308 = 2e308 > DBL_MAX -> +inf.
//   -> reported in step 1, body 1 "spinner", quantity "position".
void TestInvariants::blowUpIsReported_data()
{
    QTest::addColumn<double>("dt");
    QTest::addColumn<Vec3>("v0");
    QTest::addColumn<Vec3>("omega0");
    QTest::addColumn<long>("expectedStep");
    QTest::addColumn<QString>("expectedQuantity");

    QTest::newRow("huge spin, huge dt") << 1e210 << Vec3(0, 0, 0) << Vec3(1e100, 0, 0) << 0L << "orientation";
    QTest::newRow("runaway velocity") << 1.0 << Vec3(1e308, 0, 0) << Vec3(0, 0, 0) << 1L << "position";
}

void TestInvariants::blowUpIsReported()
{
    QFETCH(double, dt);
    QFETCH(Vec3, v0);
    QFETCH(Vec3, omega0);
    QFETCH(long, expectedStep);
    QFETCH(QString, expectedQuantity);

    const rbw::SceneDef scene = blowUpScene(dt, v0, omega0);
    QVERIFY(rbw::validate(scene).empty());   // every input is finite and valid
    rbw::World world(scene);
    for (long k = 0; k < expectedStep; ++k) {
        const rbw::StepStatus st = world.step();
        QVERIFY2(st.ok, qPrintable(QStringLiteral("step %1 blew up early: %2").arg(k).arg(st.message.c_str())));
    }
    rbw::StepTrace trace;
    const rbw::StepStatus st = world.step(&trace);
    QVERIFY(!st.ok);
    QCOMPARE(st.step, expectedStep);
    QCOMPARE(st.body, 1);
    QCOMPARE(QString::fromStdString(st.bodyName), QStringLiteral("spinner"));
    QCOMPARE(QString::fromStdString(st.quantity), expectedQuantity);
    const QString message = QString::fromStdString(st.message);
    QVERIFY2(message.contains(QStringLiteral("step %1").arg(expectedStep)), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("spinner")), qPrintable(message));
    QVERIFY2(message.contains(expectedQuantity), qPrintable(message));
    QVERIFY(world.status().ok == false);
    // The calm body is untouched: a non-finite spinner must not spread to it (e.g. via
    // a spurious contact with a NaN pose). At rest, no force: x and v exactly as given.
    QCOMPARE(world.states()[0].x_W, Vec3(5, 0, 0));
    QCOMPARE(world.states()[0].v_W, Vec3(Vec3::Zero()));
    QCOMPARE(world.states()[0].L_W, Vec3(Vec3::Zero()));

    // Refuses further steps: the same status comes back and nothing advances.
    const long index = world.stepIndex();
    const double time = world.time();
    QCOMPARE(index, expectedStep + 1);
    for (int i = 0; i < 3; ++i) {
        const rbw::StepStatus again = world.step(&trace);
        QVERIFY(!again.ok);
        QCOMPARE(again.step, st.step);
        QCOMPARE(again.body, st.body);
        QCOMPARE(again.quantity, st.quantity);
        QCOMPARE(again.message, st.message);
        QCOMPARE(world.stepIndex(), index);
        QCOMPARE(world.time(), time);
    }
}

// Negative control: the same scenes with a small dt run 1000 steps (far more than the
// one or two steps the blow-ups above take) with every state finite and |r| = 1:
//   "huge spin, small dt": h = 1e-100, so (h/2)|omega0| = 0.5 per step: a finite
//     rotation of 2 atan(0.5) ~ 53 degrees per step, |r|^2 = 1.25 before renormalising.
//   "runaway velocity, small dt": h = 1e-3, so after n steps x = n * 1e305; for
//     n = 1000 that is 1e308 < DBL_MAX.
void TestInvariants::blowUpControlSmallDt_data()
{
    QTest::addColumn<double>("dt");
    QTest::addColumn<Vec3>("v0");
    QTest::addColumn<Vec3>("omega0");

    QTest::newRow("huge spin, small dt") << 1e-100 << Vec3(0, 0, 0) << Vec3(1e100, 0, 0);
    QTest::newRow("runaway velocity, small dt") << 1e-3 << Vec3(1e308, 0, 0) << Vec3(0, 0, 0);
}

void TestInvariants::blowUpControlSmallDt()
{
    QFETCH(double, dt);
    QFETCH(Vec3, v0);
    QFETCH(Vec3, omega0);

    rbw::World world(blowUpScene(dt, v0, omega0));
    for (int k = 0; k < 1000; ++k) {
        const rbw::StepStatus st = world.step();
        QVERIFY2(st.ok, qPrintable(QStringLiteral("step %1: %2").arg(k).arg(st.message.c_str())));
        const rbw::BodyState& s = world.states()[1];
        QVERIFY(s.x_W.allFinite() && s.v_W.allFinite() && s.L_W.allFinite() && s.omega_W.allFinite());
        RBW_COMPARE_NEAR(s.q_WB.norm(), 1.0, 1e-12, QStringLiteral("|r| after step %1").arg(k));
    }
    QVERIFY(world.status().ok);
}

// ---------------------------------------------------------------------------------
// Between the two regimes above there is a third: (h/2)|omega| finite but above
// sqrt(DBL_MAX) ~ 1.34e154. Spinner as above, omega0 = (1e100, 0, 0), h = 1e60:
//   r + (h/2)(0, omega0) r = (1, 5e159, 0, 0), finite; |r|^2 = 1 + 2.5e319 = inf,
//   so r / |r| = (1/inf, 5e159/inf, 0, 0) = (0, 0, 0, 0).
// That is finite but not a rotation at all (|r| = 0), and R(r) of the zero quaternion
// is the identity, so the box silently stops turning. The step should either keep
// |r| = 1 or report the step as a blow-up ("orientation"); it must not go on silently.
void TestInvariants::orientationOverflowIsNotSilent()
{
    rbw::World world(blowUpScene(1e60, Vec3::Zero(), Vec3(1e100, 0, 0)));
    const rbw::StepStatus st = world.step();
    const double norm = world.states()[1].q_WB.norm();
    // |r|^2 overflows here; the integrator normalises with stableNormalize(), so r stays a
    // unit quaternion (or, failing that, the step must report a blow-up).
    if (st.ok) RBW_COMPARE_NEAR(norm, 1.0, 1e-12, "|r| after a step that did not blow up");
}

QTEST_APPLESS_MAIN(TestInvariants)
#include "tst_invariants.moc"
