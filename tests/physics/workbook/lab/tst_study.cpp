// The accuracy study runner (physics/workbook/lab/study.h) on the lesson-10 problems: its own
// numbers against closed forms (constant spin, the projectile), measured orders of
// convergence (symmetric and asymmetric top), conservation, refusals with their
// reasons, cancellation, and a blown-up run reported without numbers.
#include "physics/workbook/lab/study.h"
#include "tests/test_support.h"

#include <QtTest>

#include <cmath>

using rbw::SceneDef;
using rbw::lab::RunStatus;
using rbw::lab::StudyConfig;
using rbw::lab::StudyResult;
using rbw::lab::StudyRow;
using rbw::test::lessonScene;

namespace {

SceneDef problem(const QString& file) { return lessonScene("10-accuracy-lab/" + file); }

// A study with a tiny timing budget: the tests check numbers, not speed.
StudyConfig config(const QStringList& integrators, const std::vector<double>& dts, double tEnd)
{
    StudyConfig c;
    for (const QString& name : integrators) c.integrators.push_back(name.toStdString());
    c.dts = dts;
    c.tEnd = tEnd;
    c.timingBudgetSeconds = 0.0;
    c.timingStepsPerRepeat = 50;
    return c;
}

StudyResult study(const SceneDef& scene, const StudyConfig& c)
{
    const std::vector<rbw::SceneIssue> issues = rbw::lab::validateStudy(scene, c);
    if (!issues.empty()) qFatal("study refused: %s: %s", issues[0].path.c_str(), issues[0].reason.c_str());
    return rbw::lab::runStudy(scene, c);
}

bool hasNoNumbers(const StudyRow& r)
{
    return !r.positionError && !r.orientationError && !r.omegaError && !r.energyDrift && !r.momentumDrift &&
           !r.nsPerStep;
}

} // namespace

class TestStudy : public QObject {
    Q_OBJECT
private slots:
    void constantSpinClosedForm_data();
    void constantSpinClosedForm();
    void projectilePositionClosedForm();
    void convergenceOrder_data();
    void convergenceOrder();
    void implicitMidpointConservesEnergy_data();
    void implicitMidpointConservesEnergy();
    void refusedWithReason_data();
    void refusedWithReason();
    void cancellationStopsEarly();
    void blownUpRunHasNoNumbers();
    void rowsAndTiming();
};

// ---------------------------------------------------------------------------------
// Constant spin (constant-spin.json): |omega| = 3 rad/s about a principal axis n, so
// omega and L stay exact for every integrator and only the turn per step is wrong.
// With w = (0, omega) (w^2 = -|omega|^2) and a = h|omega|/2, one step multiplies q by
//   explicit Euler, normalised:  1 + (h/2) w                 -> turn 2 atan(a)
//   implicit midpoint (Cayley):  (1, (h/2) omega)/norm       -> turn 2 atan(a)
//   midpoint: 1 + (h/2) w + (h^2/8) w^2 = (1 - a^2/2, a n)   -> turn 2 atan(a / (1 - a^2/2))
//   RK4: sum_{j<=4} ((h/2) w)^j / j! = (1 - a^2/2 + a^4/24, (a - a^3/6) n)
//                                                            -> turn 2 atan((a - a^3/6)/(1 - a^2/2 + a^4/24))
// all about n, so after N = T/h steps the orientation error is |N turn - |omega| T|.
// (For explicit Euler this is O(h^2), not O(h): about a fixed axis the first-order
// error cancels. The orders 1, 2, 4 are measured on the tops below.)
void TestStudy::constantSpinClosedForm_data()
{
    QTest::addColumn<QString>("integrator");
    QTest::addColumn<double>("dt");
    for (double dt : {0.1, 0.02, 0.005}) {
        for (const char* name : {"explicit-euler", "implicit-midpoint", "midpoint", "rk4"}) {
            QTest::addRow("%s h=%g", name, dt) << QString(name) << dt;
        }
    }
}

void TestStudy::constantSpinClosedForm()
{
    QFETCH(QString, integrator);
    QFETCH(double, dt);
    const double T = 2.0;
    const double w = 3.0;
    const StudyResult r = study(problem("constant-spin.json"), config({integrator}, {dt}, T));
    QCOMPARE(int(r.rows.size()), 1);
    const StudyRow& row = r.rows[0];
    QCOMPARE(row.status, RunStatus::Ok);
    const long N = std::lround(T / dt);
    QCOMPARE(row.steps, N);
    const double a = dt * w / 2.0;
    double turn = 2.0 * std::atan(a);
    if (integrator == "midpoint") turn = 2.0 * std::atan(a / (1.0 - a * a / 2.0));
    if (integrator == "rk4") turn = 2.0 * std::atan((a - a * a * a / 6.0) / (1.0 - a * a / 2.0 + std::pow(a, 4) / 24.0));
    const double expected = std::abs(double(N) * turn - w * T);
    QVERIFY(row.orientationError.has_value());
    // rounding: about 1e-16 per step in the quaternion, and the angle itself
    RBW_COMPARE_NEAR(*row.orientationError, expected, 1e-13 + double(N) * 1e-15);
    QVERIFY(*row.omegaError <= 1e-13);
    QCOMPARE(*row.positionError, 0.0);   // at rest at the origin, exactly
    QVERIFY(*row.energyDrift <= 1e-14);
}

// The projectile (projectile.json, g = (0, -9.81, 0), T = 2): explicit Euler moves x
// with the old v, x_N = x0 + h sum_{k<N} (v0 + k h g) = x0 + v0 T + 1/2 g T^2 - 1/2 g h T,
// so its position error is exactly 1/2 |g| h T (order 1). Midpoint and RK4 integrate
// a quadratic exactly: their error is rounding.
void TestStudy::projectilePositionClosedForm()
{
    const double T = 2.0;
    const StudyResult r = study(problem("projectile.json"), config({"explicit-euler", "midpoint", "rk4"}, {0.1, 0.01}, T));
    QCOMPARE(int(r.rows.size()), 6);
    for (const StudyRow& row : r.rows) {
        QVERIFY(row.positionError.has_value());
        if (row.integrator == "explicit-euler") {
            const double expected = 0.5 * 9.81 * row.dt * T;
            RBW_COMPARE_NEAR(*row.positionError, expected, 1e-12);
        } else {
            QVERIFY2(*row.positionError <= 1e-12, qPrintable(QString::number(*row.positionError)));
        }
    }
}

// ---------------------------------------------------------------------------------
// Measured order p = log2(e(h)/e(h/2)) of the orientation error and of the omega error
// at T = 2 s, on the study's own numbers. h is chosen in each method's asymptotic
// range: rk4 and midpoint at h = 0.01/0.005 (|omega| h <= 0.07); explicit Euler needs
// smaller steps on the tumbling book (|omega| = 6.8 rad/s; at h = 0.01/0.005 it still
// measures 1.4), so h = 0.002/0.001 there. Expected p: 1, 2, 4 +- 0.3.
void TestStudy::convergenceOrder_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("integrator");
    QTest::addColumn<double>("h");
    QTest::addColumn<double>("order");
    for (const char* file : {"symmetric-top.json", "scene.json"}) {
        QTest::addRow("%s explicit-euler", file) << QString(file) << "explicit-euler" << 0.002 << 1.0;
        QTest::addRow("%s midpoint", file) << QString(file) << "midpoint" << 0.01 << 2.0;
        QTest::addRow("%s rk4", file) << QString(file) << "rk4" << 0.01 << 4.0;
        QTest::addRow("%s implicit-midpoint", file) << QString(file) << "implicit-midpoint" << 0.01 << 2.0;
    }
}

void TestStudy::convergenceOrder()
{
    QFETCH(QString, file);
    QFETCH(QString, integrator);
    QFETCH(double, h);
    QFETCH(double, order);
    const StudyResult r = study(problem(file), config({integrator}, {h, h / 2.0}, 2.0));
    QCOMPARE(int(r.rows.size()), 2);
    const double pq = std::log2(*r.rows[0].orientationError / *r.rows[1].orientationError);
    const double pw = std::log2(*r.rows[0].omegaError / *r.rows[1].omegaError);
    RBW_COMPARE_NEAR(pq, order, 0.3, "the orientation error's order");
    RBW_COMPARE_NEAR(pw, order, 0.3, "the omega error's order");
}

// ---------------------------------------------------------------------------------
// Implicit midpoint keeps T and L of a free body to rounding (docs/integrators.md);
// with gravity E = T + V, and V is integrated exactly by its half kicks. Negative
// control: explicit Euler's drift on the same runs is far above the bound.
void TestStudy::implicitMidpointConservesEnergy_data()
{
    QTest::addColumn<QString>("file");
    QTest::newRow("symmetric top") << "symmetric-top.json";
    QTest::newRow("tumbling book, gravity") << "scene.json";
}

void TestStudy::implicitMidpointConservesEnergy()
{
    QFETCH(QString, file);
    const StudyResult r = study(problem(file), config({"implicit-midpoint", "explicit-euler"}, {0.1, 0.01}, 2.0));
    QCOMPARE(int(r.rows.size()), 4);
    for (const StudyRow& row : r.rows) {
        QVERIFY(row.energyDrift.has_value());
        if (row.integrator == "implicit-midpoint") {
            QVERIFY2(*row.energyDrift <= 1e-12, qPrintable(QString::number(*row.energyDrift)));
        } else {
            QVERIFY2(*row.energyDrift > 1e-3, qPrintable(QString::number(*row.energyDrift)));
        }
    }
}

// ---------------------------------------------------------------------------------
void TestStudy::refusedWithReason_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::addColumn<QString>("integrators");
    QTest::addColumn<QString>("dts");
    QTest::addColumn<double>("tEnd");
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("reasonPart");
    const QString spin = "10-accuracy-lab/constant-spin.json";
    QTest::newRow("two bodies") << "03-two-box-collision/scene.json" << "" << "0.1" << 1.0 << "bodies"
                                << "exactly one body";
    QTest::newRow("planes") << "one body on a plane" << "" << "0.1" << 1.0 << "planes" << "plane(s)";
    QTest::newRow("unknown integrator") << spin << "rk5" << "0.1" << 1.0 << "integrators"
                                        << "unknown integrator \"rk5\"";
    QTest::newRow("dt <= 0") << spin << "" << "-0.1" << 1.0 << "dt" << "must be a finite number > 0";
    QTest::newRow("dt zero") << spin << "" << "0" << 1.0 << "dt" << "must be a finite number > 0";
    QTest::newRow("dt not dividing T") << spin << "" << "0.03" << 1.0 << "dt" << "does not divide";
    QTest::newRow("t_end <= 0") << spin << "" << "0.1" << 0.0 << "t_end" << "must be a finite number > 0";
    QTest::newRow("too many steps") << spin << "" << "1e-9" << 1.0 << "dt" << "more than the limit";
}

void TestStudy::refusedWithReason()
{
    QFETCH(QString, lesson);
    QFETCH(QString, integrators);
    QFETCH(QString, dts);
    QFETCH(double, tEnd);
    QFETCH(QString, path);
    QFETCH(QString, reasonPart);
    SceneDef scene;
    if (lesson == "one body on a plane") {
        scene = lessonScene("06-box-on-plane/scene.json");
        scene.bodies.resize(1);
        scene.pairs.clear();
        scene.probes.clear();
    } else {
        scene = lessonScene(lesson);
    }
    const StudyConfig c = config(integrators.isEmpty() ? QStringList{} : integrators.split(','),
                                 {dts.toDouble()}, tEnd);
    const std::vector<rbw::SceneIssue> issues = rbw::lab::validateStudy(scene, c);
    QVERIFY(!issues.empty());
    bool found = false;
    for (const rbw::SceneIssue& i : issues) {
        found = found || (QString::fromStdString(i.path) == path && QString::fromStdString(i.reason).contains(reasonPart));
    }
    QVERIFY2(found, qPrintable(QString::fromStdString(issues[0].path + ": " + issues[0].reason)));
}

// Cancel from the progress callback after the first run: the study stops there.
void TestStudy::cancellationStopsEarly()
{
    const SceneDef scene = problem("scene.json");
    const StudyConfig c = config({"explicit-euler", "rk4"}, {0.01, 0.005, 0.002}, 2.0);
    std::atomic<bool> cancel{false};
    int calls = 0;
    const StudyResult r = rbw::lab::runStudy(
        scene, c,
        [&](int done, int total) {
            ++calls;
            QCOMPARE(total, 6);
            if (done == 1) cancel = true;
        },
        &cancel);
    QVERIFY(r.cancelled);
    QCOMPARE(r.runsPlanned, 6);
    QCOMPARE(int(r.rows.size()), 1);
    QCOMPARE(calls, 1);
    // Negative control: the same study without cancelling runs all six.
    const StudyResult full = rbw::lab::runStudy(scene, c);
    QVERIFY(!full.cancelled);
    QCOMPARE(int(full.rows.size()), 6);
    // Cancelled before it starts: no run at all.
    std::atomic<bool> early{true};
    QCOMPARE(int(rbw::lab::runStudy(scene, c, {}, &early).rows.size()), 0);
}

// The rotation-matrix update without orthonormalisation at h = 0.1 on the tumbling
// book (|omega| h = 0.68): R grows by sqrt(1 + h^2 |omega|^2) per step and omega = R
// I0^-1 R^T L with it, so it overflows within a few steps. The row says where, and has
// no numbers; the other runs of the study are unaffected.
void TestStudy::blownUpRunHasNoNumbers()
{
    const StudyResult r = study(problem("scene.json"), config({"rotation-matrix", "rk4"}, {0.1}, 2.0));
    QCOMPARE(int(r.rows.size()), 2);
    const StudyRow& bad = r.rows[0];
    QCOMPARE(bad.status, RunStatus::BlownUp);
    QVERIFY(bad.blowUpStep >= 0 && bad.blowUpStep < 20);
    QCOMPARE(QString::fromStdString(bad.statusText()), QString("blown up at step %1").arg(bad.blowUpStep));
    QVERIFY(hasNoNumbers(bad));
    QVERIFY(!bad.totalNs().has_value());
    QVERIFY(!bad.blowUpMessage.empty());
    const StudyRow& good = r.rows[1];
    QCOMPARE(good.status, RunStatus::Ok);
    QVERIFY(good.orientationError.has_value() && std::isfinite(*good.orientationError));
}

// Rows: integrator-major, N = T/h, the same T; every ok row has a positive wall time.
void TestStudy::rowsAndTiming()
{
    StudyConfig c = config({"midpoint", "explicit-euler"}, {0.1, 0.05}, 1.0);
    c.timingBudgetSeconds = 0.001;
    const StudyResult r = study(problem("symmetric-top.json"), c);
    QCOMPARE(int(r.rows.size()), 4);
    const char* names[] = {"midpoint", "midpoint", "explicit-euler", "explicit-euler"};
    const double dts[] = {0.1, 0.05, 0.1, 0.05};
    const long steps[] = {10, 20, 10, 20};
    for (int i = 0; i < 4; ++i) {
        QCOMPARE(QString::fromStdString(r.rows[i].integrator), QString(names[i]));
        QCOMPARE(r.rows[i].dt, dts[i]);
        QCOMPARE(r.rows[i].steps, steps[i]);
        QCOMPARE(r.rows[i].tEnd, 1.0);
        QVERIFY(r.rows[i].nsPerStep.has_value() && *r.rows[i].nsPerStep > 0.0);
        QCOMPARE(QString::fromStdString(r.rows[i].statusText()), QString("ok"));
    }
    QVERIFY(QString::fromStdString(r.reference).startsWith("symmetric top"));
}

QTEST_APPLESS_MAIN(TestStudy)
#include "tst_study.moc"
