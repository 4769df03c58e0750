// The impulse response of docs/references.md §3, with friction, against hand
// derivations and conservation laws. Contacts are built directly (not detected), so
// these tests pin down the response alone.
#include "physics/engine/body.h"
#include "physics/engine/course/impulse.h"
#include "physics/engine/diagnostics.h"
#include "tests/test_support.h"

#include <QtTest>

using namespace rbw;

namespace {

constexpr double kExact = 1e-14;   // hand values are exact fractions: only rounding remains

struct Body {
    BodyDef def;
    MassProperties mp;
    BodyState s;
};

Body makeBody(const Vec3& size, double mass, const Vec3& x, const Vec3& v, const Vec3& omega = Vec3::Zero(),
              const Quat& q = Quat::Identity(), bool fixed = false)
{
    Body b;
    b.def.size = size;
    b.def.mass = mass;
    b.def.fixed = fixed;
    b.def.x0_W = x;
    b.def.v0_W = v;
    b.def.omega0_W = omega;
    b.def.q0_WB = q;
    b.mp = massProperties(b.def);
    b.s = initialState(b.def, b.mp, InertiaConvention::Standard);
    return b;
}

ContactGeometry contactAt(const Vec3& p, const Vec3& n)
{
    ContactGeometry g;
    g.p_W = p;
    g.n_W = n;
    return g;
}

bool near(const Vec3& a, const Vec3& b, double tol) { return (a - b).cwiseAbs().maxCoeff() <= tol; }

Diagnostics pairDiagnostics(const Body& a, const Body& b)
{
    return computeDiagnostics({a.mp, b.mp}, {a.s, b.s}, Vec3::Zero());
}

} // namespace

class TestImpulse : public QObject {
    Q_OBJECT
private slots:
    void bothBodiesRotate();
    void fixedBodyIsInfiniteMass();
    void separatingPairGetsNoImpulse();
    void conservation_data();
    void conservation();
    void centralImpactEnergyLoss_data();
    void centralImpactEnergyLoss();
    void friction_data();
    void friction();
    void particleResponseLeavesSpinAlone();
};

void TestImpulse::bothBodiesRotate()
{
    // Two unit cubes, M = 1: I0 = 1/12 (1 + 1) = 1/6 about every axis, so I^-1 = 6 * Id in
    // any orientation. A at (-0.5, -0.25, 0) moving +x, B at (0.5, 0.25, 0) moving -x,
    // contact at p = 0 with n = (-1, 0, 0) (from B to A), c = 0.5.
    Body A = makeBody(Vec3::Ones(), 1, Vec3(-0.5, -0.25, 0), Vec3(1, 0, 0));
    Body B = makeBody(Vec3::Ones(), 1, Vec3(0.5, 0.25, 0), Vec3(-1, 0, 0));
    const ImpulseResult r = applyContactImpulse(contactAt(Vec3::Zero(), Vec3(-1, 0, 0)), {&A.s, &A.mp},
                                                {&B.s, &B.mp}, 0.5, 0.0);
    // x_a = p - x_A = (0.5, 0.25, 0), x_b = (-0.5, -0.25, 0)
    QVERIFY(near(r.x_a, Vec3(0.5, 0.25, 0), kExact));
    QVERIFY(near(r.x_b, Vec3(-0.5, -0.25, 0), kExact));
    // v_rel = (1,0,0) - (-1,0,0) = (2,0,0); v_rel . n = -2
    QCOMPARE(r.v_rel_n, -2.0);
    // numerator = -(1 + 0.5)(-2) = 3
    QCOMPARE(r.numerator, 3.0);
    // x_a x n = (0.5,0.25,0) x (-1,0,0) = (0, 0, 0.25); I^-1 (.) = (0, 0, 1.5);
    // (0,0,1.5) x x_a = (-0.375, 0.75, 0); . n = 0.375.  B: x_b x n = (0,0,-0.25) ->
    // (0,0,-1.5) x x_b = (-0.375, 0.75, 0); . n = 0.375.
    RBW_COMPARE_NEAR_STRICT(r.rotationalA, 0.375, kExact);
    RBW_COMPARE_NEAR_STRICT(r.rotationalB, 0.375, kExact);
    // denominator = 1 + 1 + 0.375 + 0.375 = 2.75;  J = 3 / 2.75 = 12/11
    RBW_COMPARE_NEAR_STRICT(r.denominator, 2.75, kExact);
    RBW_COMPARE_NEAR_STRICT(r.J, 12.0 / 11.0, kExact);
    // v_A' = 1 - 12/11 = -1/11, v_B' = -1 + 12/11 = 1/11
    QVERIFY(near(A.s.v_W, Vec3(-1.0 / 11, 0, 0), kExact));
    QVERIFY(near(B.s.v_W, Vec3(1.0 / 11, 0, 0), kExact));
    // L_A' = x_a x J n = 12/11 (0,0,0.25) = (0,0,3/11); omega_A' = 6 L = (0,0,18/11).
    // L_B' = -x_b x J n = -12/11 (0,0,-0.25) = (0,0,3/11); omega_B' = (0,0,18/11): both rotate.
    QVERIFY(near(A.s.L_W, Vec3(0, 0, 3.0 / 11), kExact));
    QVERIFY(near(B.s.L_W, Vec3(0, 0, 3.0 / 11), kExact));
    QVERIFY(near(A.s.omega_W, Vec3(0, 0, 18.0 / 11), 1e-13));
    QVERIFY(near(B.s.omega_W, Vec3(0, 0, 18.0 / 11), 1e-13));
    // Check of the whole: after the impulse v_rel . n = -c (v_rel . n before) = 1.
    const Vec3 vA = A.s.v_W + A.s.omega_W.cross(r.x_a);
    const Vec3 vB = B.s.v_W + B.s.omega_W.cross(r.x_b);
    RBW_COMPARE_NEAR_STRICT((vA - vB).dot(Vec3(-1, 0, 0)), 1.0, 1e-13);
}

void TestImpulse::fixedBodyIsInfiniteMass()
{
    // Same A as above against a fixed B: 1/M_B = 0 and I_B^-1 = 0, so
    // J = -(1 + c) v_rel.n / (1/M_A + [.]_A) = 3 / (1 + 0.375) = 24/11, and B does not move.
    Body A = makeBody(Vec3::Ones(), 1, Vec3(-0.5, -0.25, 0), Vec3(2, 0, 0));
    Body B = makeBody(Vec3::Ones(), 1, Vec3(0.5, 0.25, 0), Vec3::Zero(), Vec3::Zero(), Quat::Identity(), true);
    const ImpulseResult r = applyContactImpulse(contactAt(Vec3::Zero(), Vec3(-1, 0, 0)), {&A.s, &A.mp},
                                                {&B.s, &B.mp}, 0.5, 0.0);
    QCOMPARE(r.invMassB, 0.0);
    QCOMPARE(r.rotationalB, 0.0);
    RBW_COMPARE_NEAR_STRICT(r.J, 24.0 / 11.0, kExact);
    QCOMPARE(B.s.v_W, Vec3::Zero().eval());
    QCOMPARE(B.s.L_W, Vec3::Zero().eval());
    // v_A' = 2 - 24/11 = -2/11
    QVERIFY(near(A.s.v_W, Vec3(-2.0 / 11, 0, 0), kExact));
}

void TestImpulse::separatingPairGetsNoImpulse()
{
    // v_rel . n = ((-1) - 0) * (-1) = 1 > 0: separating, no impulse, nothing changes.
    Body A = makeBody(Vec3::Ones(), 1, Vec3(-0.5, 0, 0), Vec3(-1, 0, 0));
    Body B = makeBody(Vec3::Ones(), 1, Vec3(0.5, 0, 0), Vec3::Zero());
    const BodyState before = A.s;
    const ImpulseResult r = applyContactImpulse(contactAt(Vec3::Zero(), Vec3(-1, 0, 0)), {&A.s, &A.mp},
                                                {&B.s, &B.mp}, 1.0, 0.5);
    QVERIFY(r.separating);
    QCOMPARE(r.J, 0.0);
    QCOMPARE(A.s.v_W, before.v_W);
    QCOMPARE(A.s.L_W, before.L_W);
    QCOMPARE(B.s.v_W, Vec3::Zero().eval());
    // Negative control: the same pair approaching does get an impulse.
    A.s.v_W = Vec3(1, 0, 0);
    QVERIFY(!applyContactImpulse(contactAt(Vec3::Zero(), Vec3(-1, 0, 0)), {&A.s, &A.mp}, {&B.s, &B.mp}, 1.0, 0.0)
                     .separating);
}

void TestImpulse::conservation_data()
{
    QTest::addColumn<double>("c");
    QTest::addColumn<double>("mu");
    QTest::newRow("elastic") << 1.0 << 0.0;
    QTest::newRow("c = 0.5") << 0.5 << 0.0;
    QTest::newRow("plastic") << 0.0 << 0.0;
    QTest::newRow("c = 0.7, friction 0.4") << 0.7 << 0.4;
}

void TestImpulse::conservation()
{
    // Two spinning, rotated, unequal boxes; an off-centre contact. An impulse pair +P on
    // A and -P on B at the same point conserves total P and L about the origin:
    //   dP = P - P = 0;  dL_O = (x_A x P + x_a x P) - (x_B x P + x_b x P) = p x P - p x P = 0.
    QFETCH(double, c);
    QFETCH(double, mu);
    Body A = makeBody(Vec3(1, 0.6, 0.5), 2, Vec3(-0.4, 0.1, 0.2), Vec3(1.5, -0.2, 0.3), Vec3(0.3, -1, 2),
                      Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized())));
    Body B = makeBody(Vec3(0.8, 1.2, 0.4), 3.5, Vec3(0.6, -0.3, 0.1), Vec3(-1, 0.4, 0), Vec3(-2, 0.5, 1),
                      Quat(Eigen::AngleAxisd(-1.1, Vec3(3, -1, 2).normalized())));
    const Vec3 n = Vec3(-1, 0.2, 0.1).normalized();
    const Diagnostics before = pairDiagnostics(A, B);
    const ImpulseResult r = applyContactImpulse(contactAt(Vec3(0.1, -0.05, 0.15), n), {&A.s, &A.mp}, {&B.s, &B.mp},
                                                c, mu);
    QVERIFY(!r.separating);
    QVERIFY(r.J > 0.0);
    const Diagnostics after = pairDiagnostics(A, B);
    QVERIFY2(near(after.P_W, before.P_W, 1e-12), "total linear momentum changed");
    QVERIFY2(near(after.L_O_W, before.L_O_W, 1e-12), "angular momentum about the origin changed");
    if (c == 1.0 && mu == 0.0) {
        RBW_COMPARE_NEAR(after.kinetic, before.kinetic, 1e-12 * before.kinetic);
    } else {
        QVERIFY(after.kinetic < before.kinetic);
    }
    QCOMPARE(r.kineticBefore, before.kinetic);
}

void TestImpulse::centralImpactEnergyLoss_data()
{
    QTest::addColumn<double>("m1");
    QTest::addColumn<double>("m2");
    QTest::addColumn<double>("c");
    QTest::newRow("equal masses, c = 0.5") << 1.0 << 1.0 << 0.5;
    QTest::newRow("2:3, c = 0.8") << 2.0 << 3.0 << 0.8;
    QTest::newRow("plastic") << 1.5 << 4.0 << 0.0;
    QTest::newRow("elastic (no loss)") << 1.0 << 2.0 << 1.0;
}

void TestImpulse::centralImpactEnergyLoss()
{
    // Central impact: p on the line through both centres, so x_a, x_b are parallel to n
    // and both rotational terms vanish. With approach speed u = -v_rel.n and reduced mass
    // mu = m1 m2 / (m1 + m2):  J = (1 + c) mu u, and the kinetic energy lost is
    //   dT = J (v_rel.n_before + v_rel.n_after)/2 ... = 1/2 mu (1 - c^2) u^2.
    QFETCH(double, m1);
    QFETCH(double, m2);
    QFETCH(double, c);
    const double u = 3.0;   // A at -1 moving +2, B at +1 moving -1: u = 3
    Body A = makeBody(Vec3::Ones(), m1, Vec3(-1, 0, 0), Vec3(2, 0, 0));
    Body B = makeBody(Vec3::Ones(), m2, Vec3(1, 0, 0), Vec3(-1, 0, 0));
    const double before = pairDiagnostics(A, B).kinetic;
    const ImpulseResult r = applyContactImpulse(contactAt(Vec3::Zero(), Vec3(-1, 0, 0)), {&A.s, &A.mp},
                                                {&B.s, &B.mp}, c, 0.0);
    const double reduced = m1 * m2 / (m1 + m2);
    RBW_COMPARE_NEAR_STRICT(r.J, (1 + c) * reduced * u, 1e-13);
    const double lost = before - pairDiagnostics(A, B).kinetic;
    RBW_COMPARE_NEAR_STRICT(lost, 0.5 * reduced * (1 - c * c) * u * u, 1e-13);
}

void TestImpulse::friction_data()
{
    QTest::addColumn<double>("mu");
    QTest::addColumn<double>("expectedJt");
    QTest::addColumn<bool>("clamped");
    // Unit cube (M = 1, I^-1 = 6) sliding at v = (2, -1, 0) onto a fixed floor, contact
    // p = x + (0, -0.5, 0), n = (0, 1, 0), c = 0.
    //   Normal: x_a x n = 0, so J = -(1)(-1) / 1 = 1 and v' = (2, 0, 0).
    //   Tangent t = (-1, 0, 0) against the sliding; x_a x t = (0, 0, -0.5),
    //   I^-1(.) x x_a = (0,0,-3) x (0,-0.5,0) = (-1.5, 0, 0), . t = 1.5; k_t = 1 + 1.5 = 2.5.
    //   Stopping impulse J_t* = 2 / 2.5 = 0.8.
    QTest::newRow("mu = 0.2 slides: J_t = mu J = 0.2") << 0.2 << 0.2 << true;
    QTest::newRow("mu = 1 sticks: J_t = J_t* = 0.8") << 1.0 << 0.8 << false;
}

void TestImpulse::friction()
{
    QFETCH(double, mu);
    QFETCH(double, expectedJt);
    QFETCH(bool, clamped);
    Body A = makeBody(Vec3::Ones(), 1, Vec3(0, 0.5, 0), Vec3(2, -1, 0));
    const ImpulseResult r = applyContactImpulse(contactAt(Vec3(0, 0, 0), Vec3(0, 1, 0)), {&A.s, &A.mp},
                                                ResponseBody{}, 0.0, mu);
    RBW_COMPARE_NEAR_STRICT(r.J, 1.0, kExact);
    RBW_COMPARE_NEAR_STRICT(r.J_t, expectedJt, kExact);
    QCOMPARE(r.frictionClamped, clamped);
    QVERIFY(near(r.t_W, Vec3(-1, 0, 0), kExact));
    // v'' = (2 - J_t, 0, 0); L = x_a x (-J_t, 0, 0) = (0, 0, -0.5 J_t); omega_z = -3 J_t
    QVERIFY(near(A.s.v_W, Vec3(2 - expectedJt, 0, 0), kExact));
    QVERIFY(near(A.s.omega_W, Vec3(0, 0, -3 * expectedJt), 1e-13));
    // Sticking leaves the contact point at rest: 1.2 + (-2.4)(0.5) = 0.
    const double slip = (A.s.v_W + A.s.omega_W.cross(r.x_a)).x();
    if (!clamped) {
        RBW_COMPARE_NEAR_STRICT(slip, 0.0, 1e-13);
    } else {
        QVERIFY(slip > 0.0);   // still sliding in the same direction, slower
    }
}

void TestImpulse::particleResponseLeavesSpinAlone()
{
    // Angular response off (Napier "bounce as a particle"): no rotational terms, L unchanged,
    // J = -(1 + c) v_n / (1/M) for a fixed floor: c = 1, v_n = -2 -> J = 4 M.
    Body A = makeBody(Vec3(1, 2, 1), 1, Vec3(0, 1, 0), Vec3(0, -2, 0), Vec3(0, 0, 1.5));
    const Vec3 L0 = A.s.L_W;
    const ImpulseResult r = applyContactImpulse(contactAt(Vec3(0.4, 0, 0.3), Vec3(0, 1, 0)),
                                                {&A.s, &A.mp, false}, ResponseBody{}, 1.0, 0.0);
    QCOMPARE(r.rotationalA, 0.0);
    RBW_COMPARE_NEAR_STRICT(r.J, 4.0, kExact);
    QCOMPARE(A.s.L_W, L0);
    QVERIFY(near(A.s.v_W, Vec3(0, 2, 0), kExact));
}

QTEST_APPLESS_MAIN(TestImpulse)
#include "tst_impulse.moc"
