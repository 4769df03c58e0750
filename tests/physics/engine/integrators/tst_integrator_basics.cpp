// What every integrator must do regardless of accuracy: the registry, a body at rest
// or in uniform motion, a constant force (closed forms), fixed bodies, the trace rows
// of each method, the drift of the un-orthonormalised rotation matrix, and skipping
// the gyroscopic work where it is exactly zero.

#include <QtTest>

#include "tests/physics/engine/integrators/integrator_harness.h"
#include "physics/engine/integrators/implicit_gyroscopic.h"
#include "physics/engine/integrators/implicit_midpoint.h"
#include "physics/engine/integrators/rotation_matrix.h"
#include "physics/engine/scene.h"
#include "physics/engine/world.h"
#include "tests/test_support.h"

#include <cmath>
#include <cstring>

Q_DECLARE_METATYPE(rbw::Vec3)

using namespace rbw::test;

namespace {

const Quat kTilted(Eigen::AngleAxisd(0.9, Vec3(-1, 2, 0.5).normalized()));

void addIntegratorRows()
{
    QTest::addColumn<QString>("name");
    for (const rbw::IntegratorInfo& info : rbw::integratorCatalogue()) {
        QTest::newRow(info.name) << QString::fromLatin1(info.name);
    }
}

bool hasRow(const StepTrace& t, const char* id, int index = -1) { return t.find(id, 0, index) != nullptr; }

} // namespace

class TestIntegratorBasics : public QObject {
    Q_OBJECT

private slots:
    void registry();
    void restStaysAtRest_data() { addIntegratorRows(); }
    void restStaysAtRest();
    void uniformMotion_data() { addIntegratorRows(); }
    void uniformMotion();
    void constantForce_data();
    void constantForce();
    void fixedBodyUntouched_data() { addIntegratorRows(); }
    void fixedBodyUntouched();
    void traceRows_data();
    void traceRows();
    void newtonSolvesToMachinePrecision();
    void rotationMatrixDrifts();
    void orthonormalisedStaysOrthonormal();
    void isotropicSkipChangesNothing_data();
    void isotropicSkipChangesNothing();
    void worldRunsEveryIntegrator_data() { addIntegratorRows(); }
    void worldRunsEveryIntegrator();
};

// Every catalogue entry builds an integrator of that name, with a summary and an
// order; names are unique; an unknown name gives nullptr (the loader reports it).
void TestIntegratorBasics::registry()
{
    QStringList names;
    for (const rbw::IntegratorInfo& info : rbw::integratorCatalogue()) {
        const std::unique_ptr<Integrator> in = rbw::makeIntegrator(info.name);
        QVERIFY2(in, info.name);
        QCOMPARE(QString::fromLatin1(in->name()), QString::fromLatin1(info.name));
        QVERIFY(std::strlen(info.summary) > 20);
        QVERIFY(info.order >= 1 && info.order <= 4);
        QVERIFY(!names.contains(QString::fromLatin1(info.name)));
        names << QString::fromLatin1(info.name);
    }
    QCOMPARE(names.size(), 8);
    QCOMPARE(names.first(), QStringLiteral("explicit-euler"));
    QVERIFY(rbw::makeIntegrator("rk5") == nullptr);
    QVERIFY(rbw::makeIntegrator("") == nullptr);
    QVERIFY(QString::fromStdString(rbw::integratorNames()).contains(QStringLiteral("implicit-midpoint")));
}

// A body at rest (v = 0, L = 0, no load) stays exactly where it is: every update adds
// h*0 = +0 to x, v, L, the rotation is by the zero vector (r + 0, c = (1, 0), R + 0),
// and r / |r| with |r| = 1 to the last bit for the identity. With a tilted r0 the
// renormalisation may move r by an ulp per step: tolerance 4u per step on r.
void TestIntegratorBasics::restStaysAtRest()
{
    QFETCH(QString, name);
    const std::unique_ptr<Integrator> integrator = integratorNamed(name);
    for (const Quat& q0 : {Quat::Identity(), kTilted}) {
        OneBody b = freeBody(Vec3(1, 2, 3), q0, Vec3::Zero(), Vec3(1, -2, 3));
        const rbw::BodyState s0 = b.s();
        const int steps = 100;
        run(*integrator, b, 0.1, steps);
        QVERIFY(b.s().x_W == s0.x_W);
        QVERIFY(b.s().v_W == Vec3::Zero());
        QVERIFY(b.s().L_W == Vec3::Zero());
        QVERIFY(b.s().omega_W == Vec3::Zero());
        QVERIFY2(angleBetween(b.s().q_WB, s0.q_WB) <= 4 * u * steps, qPrintable(name));
    }
}

// Uniform motion: x_n = x0 + n h v, exactly in arithmetic; in doubles each step rounds
// h v and the sum (<= u (h|v| + |x_k|)): tolerance n u (h|v| + X), X = max |x_k|.
void TestIntegratorBasics::uniformMotion()
{
    QFETCH(QString, name);
    const std::unique_ptr<Integrator> integrator = integratorNamed(name);
    const Vec3 x0(1, -2, 3);
    const Vec3 v0(0.5, 0.25, -1.5);
    OneBody b = freeBody(Vec3(1, 2, 3), kTilted, Vec3::Zero(), x0, v0);
    const int n = 1000;
    const double h = 0.01;
    run(*integrator, b, h, n);
    const Vec3 exact = x0 + (n * h) * v0;
    const double X = std::max(x0.norm(), exact.norm()) + n * h * v0.norm();
    RBW_COMPARE_NEAR(b.s().x_W, exact, n * u * (h * v0.norm() + X), name);
    QVERIFY(b.s().v_W == v0);
}

// Constant force F on mass M = 2 (a = F/M), omega = 0. Closed form x0 + v0 t + 1/2 a t^2,
// and each method's exact discrete solution, summed by hand over n steps:
//   explicit Euler (x with the old v):  x_n = x0 + v0 t + a h^2 n(n-1)/2 = exact - 1/2 a h t
//   symplectic Euler (x with the new v): x_n = x0 + v0 t + a h^2 n(n+1)/2 = exact + 1/2 a h t
//   midpoint, RK4, velocity Verlet (implicit-midpoint): exact for a quadratic
// so x_n = exact + c a h t with c = -1/2, +1/2 or 0; v_n = v0 + a t for all.
// Tolerance: rounding of ~n additions of size ~|x|: 4 n u max|x|.
void TestIntegratorBasics::constantForce_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<double>("c");
    QTest::newRow("explicit-euler") << "explicit-euler" << -0.5;
    QTest::newRow("symplectic-euler") << "symplectic-euler" << 0.5;
    QTest::newRow("midpoint") << "midpoint" << 0.0;
    QTest::newRow("rk4") << "rk4" << 0.0;
    QTest::newRow("implicit-gyroscopic") << "implicit-gyroscopic" << 0.5;   // Box2D order: v, then x
    QTest::newRow("implicit-midpoint") << "implicit-midpoint" << 0.0;
    QTest::newRow("rotation-matrix") << "rotation-matrix" << -0.5;   // TUM order
    QTest::newRow("rotation-matrix-orthonormalised") << "rotation-matrix-orthonormalised" << -0.5;
}

void TestIntegratorBasics::constantForce()
{
    QFETCH(QString, name);
    QFETCH(double, c);
    const std::unique_ptr<Integrator> integrator = integratorNamed(name);
    const Vec3 x0(0, 10, 0);
    const Vec3 v0(3, 4, 0);
    const double M = 2.0;
    const Vec3 F(1, -19.62, 0.5);
    const Vec3 a = F / M;
    OneBody b = freeBody(Vec3(1, 2, 3), Quat::Identity(), Vec3::Zero(), x0, v0, rbw::InertiaConvention::Standard, M);
    b.loads[0].F_W = F;
    const int n = 200;
    const double h = 0.01;
    run(*integrator, b, h, n);
    const double t = n * h;
    const Vec3 expected = x0 + t * v0 + (0.5 * t * t) * a + (c * h * t) * a;
    const double X = expected.norm() + x0.norm() + t * v0.norm() + t * t * a.norm();
    RBW_COMPARE_NEAR(b.s().x_W, expected, 4 * n * u * X, name);
    RBW_COMPARE_NEAR(b.s().v_W, (v0 + t * a), 4 * n * u * (v0.norm() + t * a.norm()));
    // the exact answer, to show the offset is really there for the Euler orders
    const Vec3 exact = x0 + t * v0 + (0.5 * t * t) * a;
    QCOMPARE((b.s().x_W - exact).norm() > 1e-3, c != 0.0);
}

// A fixed body is skipped: its state is bit-for-bit unchanged, even with a load.
void TestIntegratorBasics::fixedBodyUntouched()
{
    QFETCH(QString, name);
    const std::unique_ptr<Integrator> integrator = integratorNamed(name);
    OneBody b = freeBody(Vec3(1, 2, 3), kTilted, Vec3(0.1, 0.2, 0.3), Vec3(1, 1, 1), Vec3(1, 0, 0));
    b.defs[0].fixed = true;
    b.loads[0].F_W = Vec3(1, 2, 3);
    b.loads[0].q_W = Vec3(-1, 0, 1);
    const rbw::BodyState s0 = b.s();
    run(*integrator, b, 0.1, 10);
    QVERIFY(b.s().x_W == s0.x_W && b.s().v_W == s0.v_W && b.s().L_W == s0.L_W);
    QVERIFY(b.s().q_WB.coeffs() == s0.q_WB.coeffs() && b.s().R_WB == s0.R_WB);
}

// Every method writes the final x, v, r, L, R, I^-1, omega like explicit Euler, plus
// its own intermediate quantities.
void TestIntegratorBasics::traceRows_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QStringList>("ownRows");   // "id" or "id#index"
    QTest::newRow("explicit-euler") << "explicit-euler" << QStringList{};
    QTest::newRow("symplectic-euler") << "symplectic-euler" << QStringList{"update_angular_velocity"};
    QTest::newRow("midpoint") << "midpoint"
                              << QStringList{"stage_angular_velocity#1", "stage_angular_velocity#2", "stage_torque#1",
                                             "stage_torque#2", "stage_orientation_rate#2", "stage_velocity#1"};
    QTest::newRow("rk4") << "rk4"
                         << QStringList{"stage_angular_velocity#1", "stage_angular_velocity#4", "stage_torque#1",
                                        "stage_torque#4", "stage_orientation_rate#3", "stage_velocity#2"};
    QTest::newRow("implicit-gyroscopic")
        << "implicit-gyroscopic"
        << QStringList{"body_angular_velocity", "gyroscopic_jacobian", "body_angular_velocity_new",
                       "newton_iterations", "newton_residual", "update_angular_velocity"};
    QTest::newRow("implicit-midpoint") << "implicit-midpoint"
                                       << QStringList{"body_angular_momentum", "body_angular_momentum_new",
                                                      "newton_iterations", "newton_residual",
                                                      "midpoint_angular_velocity", "cayley_rotation"};
    QTest::newRow("rotation-matrix") << "rotation-matrix"
                                     << QStringList{"rotation_matrix_update", "orthonormality_error",
                                                    "rotation_determinant"};
    QTest::newRow("rotation-matrix-orthonormalised")
        << "rotation-matrix-orthonormalised"
        << QStringList{"rotation_matrix_update", "orthonormality_error_before", "orthonormality_error",
                       "rotation_determinant"};
}

void TestIntegratorBasics::traceRows()
{
    QFETCH(QString, name);
    QFETCH(QStringList, ownRows);
    const std::unique_ptr<Integrator> integrator = integratorNamed(name);
    OneBody b = freeBody(Vec3(1, 2, 3), kTilted, Vec3(0.3, -0.2, 0.5));
    b.loads[0].F_W = Vec3(0, -1, 0);
    b.loads[0].q_W = Vec3(0.1, 0, 0);
    StepTrace trace;
    step(*integrator, b, 0.05, &trace);
    for (const char* id : {"position", "linear_velocity", "orientation", "angular_momentum", "rotation_matrix",
                           "inverse_inertia_world", "angular_velocity"}) {
        QVERIFY2(hasRow(trace, id), id);
    }
    // the recorded final values are the state's
    QVERIFY(std::get<Vec3>(trace.find("angular_velocity", 0)->value) == b.s().omega_W);
    QVERIFY(std::get<Vec3>(trace.find("angular_momentum", 0)->value) == b.s().L_W);
    for (const QString& row : ownRows) {
        const QStringList parts = row.split(QLatin1Char('#'));
        const int index = parts.size() > 1 ? parts[1].toInt() : -1;
        QVERIFY2(hasRow(trace, qPrintable(parts[0]), index), qPrintable(row));
    }
    // with the trace off nothing is recorded and the result is the same
    OneBody b2 = freeBody(Vec3(1, 2, 3), kTilted, Vec3(0.3, -0.2, 0.5));
    b2.loads = b.loads;
    step(*integrator, b2, 0.05, nullptr);
    QVERIFY(b2.s().x_W == b.s().x_W && b2.s().L_W == b.s().L_W && b2.s().q_WB.coeffs() == b.s().q_WB.coeffs());
}

// The implicit midpoint's Newton iteration reaches rounding level (|G| <= 8 u |L|)
// within a few iterations (quadratic convergence from an explicit predictor), and
// the RK4 stage rows hold what the formula says (k_L,i = q).
void TestIntegratorBasics::newtonSolvesToMachinePrecision()
{
    const std::unique_ptr<Integrator> integrator = integratorNamed(QStringLiteral("implicit-midpoint"));
    OneBody b = freeBody(Vec3(3, 5, 9), kTilted, Vec3(0.3, 2, 1));
    StepTrace trace;
    for (double h : {0.01, 0.1, 0.5}) {
        step(*integrator, b, h, &trace);
        const double residual = std::get<double>(trace.find("newton_residual", 0)->value);
        const double iterations = std::get<double>(trace.find("newton_iterations", 0)->value);
        QVERIFY2(residual <= 8 * u * b.s().L_W.norm(), qPrintable(QString::number(residual)));
        QVERIFY2(iterations >= 1 && iterations <= 6, qPrintable(QString::number(iterations)));
        trace.clear();
    }
    const std::unique_ptr<Integrator> rk4 = integratorNamed(QStringLiteral("rk4"));
    b.loads[0].q_W = Vec3(0.5, -1, 2);
    step(*rk4, b, 0.1, &trace);
    for (int i = 1; i <= 4; ++i) {
        QVERIFY(std::get<Vec3>(trace.find("stage_torque", 0, i)->value) == Vec3(0.5, -1, 2));
    }
}

// R <- R + h [omega]x R without orthonormalisation: R_{n+1}^T R_{n+1} =
// R_n^T (E + h^2 [omega]x^T [omega]x) R_n, so ||R^T R - E||_F grows at every step (by
// ~2 h^2 |omega|^2 at first) and det R > 1 grows too. Asserted: monotone growth over
// 500 steps and a drift far above rounding (> 1e-3) at the end.
void TestIntegratorBasics::rotationMatrixDrifts()
{
    const std::unique_ptr<Integrator> integrator = integratorNamed(QStringLiteral("rotation-matrix"));
    OneBody b = freeBody(Vec3(1, 2, 3), kTilted, Vec3(0.5, 1, 1.5));
    StepTrace trace;
    double prevDrift = rbw::orthonormalityError(b.s().R_WB);
    double prevDet = b.s().R_WB.determinant();
    for (int k = 0; k < 500; ++k) {
        trace.clear();
        step(*integrator, b, 0.01, &trace);
        const double drift = std::get<double>(trace.find("orthonormality_error", 0)->value);
        const double det = std::get<double>(trace.find("rotation_determinant", 0)->value);
        QVERIFY2(drift > prevDrift && det > prevDet, qPrintable(QString::number(k)));
        QCOMPARE(drift, rbw::orthonormalityError(b.s().R_WB));
        prevDrift = drift;
        prevDet = det;
    }
    QVERIFY2(prevDrift > 1e-3, qPrintable(QString::number(prevDrift)));
    // I^-1 is built from the drifted R: R I0^-1 R^T with the state's R
    const Mat3 expected = b.s().R_WB * b.mass[0].I0inv_B * b.s().R_WB.transpose();
    RBW_COMPARE_NEAR(b.s().Iinv_W, expected, 16 * u * expected.norm());
}

// With the polar projection R stays a rotation: ||R^T R - E||_F <= 1e-12 at every step
// (the SVD's U, V are orthogonal to ~10 u) and det R = 1 to the same level.
void TestIntegratorBasics::orthonormalisedStaysOrthonormal()
{
    const std::unique_ptr<Integrator> integrator = integratorNamed(QStringLiteral("rotation-matrix-orthonormalised"));
    OneBody b = freeBody(Vec3(1, 2, 3), kTilted, Vec3(0.5, 1, 1.5));
    for (int k = 0; k < 2000; ++k) {
        step(*integrator, b, 0.01);
        QVERIFY2(rbw::orthonormalityError(b.s().R_WB) <= 1e-12, qPrintable(QString::number(k)));
        RBW_COMPARE_NEAR(b.s().R_WB.determinant(), 1.0, 1e-12);
    }
}

// "Model only what a scene requires": for a cube (I0 = k E) omega x I0 omega = 0, so the
// implicit methods skip their gyroscopic solve. Skipped and forced runs are the same
// in exact arithmetic; in doubles the forced path rounds R^T omega and back (and the
// Newton step on a zero right-hand side of rounding size), a few u per step:
// tolerance 16 u |.| per step, over 200 steps. The skipped run says so in the trace.
void TestIntegratorBasics::isotropicSkipChangesNothing_data()
{
    QTest::addColumn<bool>("midpoint");
    QTest::newRow("implicit-gyroscopic") << false;
    QTest::newRow("implicit-midpoint") << true;
}

void TestIntegratorBasics::isotropicSkipChangesNothing()
{
    QFETCH(bool, midpoint);
    std::unique_ptr<Integrator> skipping;
    std::unique_ptr<Integrator> forced;
    if (midpoint) {
        skipping = std::make_unique<rbw::ImplicitMidpoint>(true);
        forced = std::make_unique<rbw::ImplicitMidpoint>(false);
    } else {
        skipping = std::make_unique<rbw::ImplicitGyroscopic>(true);
        forced = std::make_unique<rbw::ImplicitGyroscopic>(false);
    }
    const Vec3 cube(0.5, 0.5, 0.5);
    OneBody a = freeBody(cube, kTilted, Vec3(0.4, -1, 0.7));
    OneBody b = a;
    a.loads[0].q_W = b.loads[0].q_W = Vec3(0.05, 0, -0.02);
    StepTrace trace;
    step(*skipping, a, 0.01, &trace);
    QVERIFY(hasRow(trace, "gyroscopic_skipped"));
    QVERIFY(!hasRow(trace, "newton_iterations"));
    step(*forced, b, 0.01);
    const int steps = 200;
    for (int k = 1; k < steps; ++k) {
        step(*skipping, a, 0.01);
        step(*forced, b, 0.01);
    }
    const double L = a.s().L_W.norm();
    RBW_COMPARE_NEAR(a.s().L_W, b.s().L_W, 16 * u * steps * L);
    QVERIFY(angleBetween(a.s().q_WB, b.s().q_WB) <= 16 * u * steps);
    // and an anisotropic body is NOT skipped
    OneBody c = freeBody(Vec3(0.5, 0.5, 0.6), kTilted, Vec3(0.4, -1, 0.7));
    trace.clear();
    step(*skipping, c, 0.01, &trace);
    QVERIFY(!hasRow(trace, "gyroscopic_skipped"));
}

// Each integrator runs inside a World from a scene (by name, as scene files choose
// it): three boxes with a force, gravity and spin, 500 steps, no blow-up, and the
// trace's final angular velocity is the world state's.
void TestIntegratorBasics::worldRunsEveryIntegrator()
{
    QFETCH(QString, name);
    rbw::SceneDef scene;
    scene.name = "integrators";
    scene.dt = 0.01;
    scene.integrator = name.toStdString();
    scene.g_W = Vec3(0, -9.81, 0);
    scene.boxCollisions = false;
    for (int i = 0; i < 3; ++i) {
        rbw::BodyDef d;
        d.name = "b";
        d.name += std::to_string(i);
        d.size = Vec3(1.0, 0.6 + 0.1 * i, 0.5);
        d.mass = 1.0 + i;
        d.x0_W = Vec3(3.0 * i, 0, 0);
        d.q0_WB = kTilted;
        d.omega0_W = Vec3(0.5, -1.0 + i, 2.0);
        scene.bodies.push_back(d);
    }
    rbw::ForceDef f;
    f.body = 1;
    f.p_W = Vec3(3.3, 0.5, 0.25);
    f.f_W = Vec3(1, 1, 0);
    f.toStep = 50;
    scene.forces.push_back(f);
    QVERIFY(rbw::validate(scene).empty());
    rbw::World world(scene);
    QCOMPARE(QString::fromLatin1(world.integrator().name()), name);
    StepTrace trace;
    for (int k = 0; k < 500; ++k) {
        QVERIFY(world.step(k == 499 ? &trace : nullptr).ok);
    }
    QVERIFY(std::get<Vec3>(trace.find("angular_velocity", 1)->value) == world.states()[1].omega_W);
}

QTEST_APPLESS_MAIN(TestIntegratorBasics)
#include "tst_integrator_basics.moc"
