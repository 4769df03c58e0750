// How deep a column of boxes sinks into itself with the soft step (issue 19): a soft
// contact is a spring, and under the weight a contact carries it settles where the
// solve pass changes nothing. Per point k, with v_n = 0 after the warm start and the
// relax, that is -m_k s_m (beta_s s_k) = s_i lambda_k (soft_step_solver.h), and with
// s_i / (s_m beta_s) = 1 / (h_s omega^2) and lambda_k = F_k h_s:
//
//   s_k = -F_k / (m_k omega^2)        omega = 2 pi f,  f = 1 / (8 h_s)
//
// A column of ten unit cubes (M = 1 kg, I = M/6 E), aligned, standing on the ground:
// the contact between box j-1 and box j carries the 10 - j boxes above it on its four
// corners, F_k = (10 - j) M g / 4, and a corner's normal mass is m_k = 1/K,
// K = 1/M + 1/M + (r x n) . I^-1 (r x n) twice = 1 + 1 + 6 (0.5) + 6 (0.5) = 8 (r the
// corner's lever arm (+-0.5, 0.5, +-0.5), |r x n|^2 = 0.5). So the centres are
//
//   y_j - y_{j-1} = 1 - 2 (10 - j) g / omega^2
//
// and the lowest box-box contact sinks 18 g / omega^2: 4.97 mm at 4 substeps (30 Hz),
// 3.18 mm at 5 (37.5 Hz, the default), 1.24 mm at 8 (60 Hz), so the stiffness set
// relative to the substep rate is what keeps the rain's columns of ten within 1 cm.
// The ground (static, twice f) carries all ten on corners of K = 1 + 3 = 4:
// y_0 = 0.5 - 10 g / (4 omega^2).
//
// Sleeping is off so the column keeps being solved; after 5 s it has settled (the
// slowest mode of the over-damped springs, zeta = 10, decays in well under a second).
#include "tests/test_support.h"

#include "physics/engine/manifold/settings.h"
#include "physics/engine/manifold/soft_step_solver.h"
#include "physics/engine/world.h"

#include <QtTest>

#include <cmath>
#include <string>

using namespace rbw;

namespace {

constexpr double kH = 1.0 / 60.0;
constexpr double kG = 9.81;
constexpr double kPi = 3.14159265358979323846;
constexpr int kBoxes = 10;

SceneDef column(int substeps)
{
    SceneDef s;
    s.dt = kH;
    s.steps = 300;
    s.integrator = "symplectic-euler";
    s.g_W = Vec3(0.0, -kG, 0.0);
    s.restitution = 0.0;
    s.friction = 0.5;
    s.contactModel = ContactModel::Manifold;
    s.solver = ManifoldSolver::SoftStep;
    s.substeps = substeps;
    s.sleep = false;
    PlaneDef ground;
    ground.name = "ground";
    s.planes.push_back(ground);
    for (int j = 0; j < kBoxes; ++j) {
        BodyDef b;
        b.name = "b" + std::to_string(j);
        b.mass = 1.0;
        b.x0_W = Vec3(0.0, 0.5 + j, 0.0);
        s.bodies.push_back(b);
    }
    return s;
}

} // namespace

class TestSoftColumn : public QObject {
    Q_OBJECT

private slots:
    void columnSinksAsItsSprings_data()
    {
        QTest::addColumn<int>("substeps");
        QTest::newRow("4 substeps (30 Hz)") << 4;
        QTest::newRow("5 substeps (37.5 Hz, the default)") << 5;
        QTest::newRow("8 substeps (60 Hz)") << 8;
    }

    void columnSinksAsItsSprings()
    {
        QFETCH(int, substeps);
        World w(column(substeps));
        for (int k = 0; k < 300; ++k) QVERIFY(w.step().ok);
        const double h_s = kH / substeps;
        const double omega = 2.0 * kPi * softContactHertz(ManifoldSettings{}.contactHertzPerSubstepRate, h_s);
        RBW_COMPARE_NEAR_STRICT(omega, 2.0 * kPi / (8.0 * h_s), 1e-9);
        // y_0 = 0.5 - 10 g / (4 omega^2)  (the ground, 2 f)
        const double ground = 10.0 * kG / (4.0 * omega * omega);
        RBW_COMPARE_NEAR_STRICT(0.5 - w.states()[0].x_W.y(), ground, 0.05 * ground);
        for (int j = 1; j < kBoxes; ++j) {
            // 1 - (y_j - y_{j-1}) = 2 (10 - j) g / omega^2, within 5 % (the corners' rows couple)
            const double sink = 2.0 * (kBoxes - j) * kG / (omega * omega);
            const double measured = 1.0 - (w.states()[static_cast<std::size_t>(j)].x_W.y() -
                                           w.states()[static_cast<std::size_t>(j - 1)].x_W.y());
            QVERIFY2(std::abs(measured - sink) <= 0.05 * sink,
                     qPrintable(QStringLiteral("contact %1: %2 m, expected %3 m").arg(j).arg(measured).arg(sink)));
        }
    }

    // The default's f = 1/(8 h_s) keeps the lowest contact of a column of ten under the
    // 5 mm slop at h = 1/60 s; Box2D's fixed 30 Hz does not scale with the substeps
    // (control: at 4 substeps, 30 Hz, it is 4.97 mm, at the slop).
    void defaultColumnWithinTheSlop()
    {
        const ManifoldSettings defaults;
        QCOMPARE(defaults.substeps, 5);
        const double omega = 2.0 * kPi * softContactHertz(defaults.contactHertzPerSubstepRate, kH / defaults.substeps);
        QVERIFY(18.0 * kG / (omega * omega) < defaults.slop);
        const double omega30 = 2.0 * kPi * 30.0;
        QVERIFY(18.0 * kG / (omega30 * omega30) > 0.99 * defaults.slop);
    }
};

QTEST_APPLESS_MAIN(TestSoftColumn)
#include "tst_soft_column.moc"
