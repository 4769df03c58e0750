// Table 2.1 of the TUM exercise (docs/references.md §1): one explicit Euler step of
// h = 2 for a box of size (1, 0.6, 0.5), mass 2, rotated 90 degrees about z, pushed by
// f = (1, 1, 0) at p = (0.3, 0.5, 0.25). Every intermediate quantity of the trace is
// checked against a value derived by hand below, written as an exact fraction.
//
// Tolerance. Unless a row says otherwise, a traced value a is accepted when
//   |a_i - e_i| <= 1e-12 * max_j |e_j|
// for every component i, i.e. 1e-12 relative to the largest entry of the expected
// quantity e. The hand values are exact fractions; the only differences are double
// rounding (a few 1e-16 relative), so 1e-12 leaves four orders of magnitude of
// headroom without hiding any real mistake (a wrong formula, e.g. the new v in the
// position update or the new omega in the orientation update, changes these values
// by 1e-1 or more). Entries that are exactly zero in the
// hand derivation (e.g. off-diagonals of R = Rz(90)) thus get an absolute tolerance
// of 1e-12 times the quantity's scale: the code computes them from cos 45 and
// sin 45 rounded to doubles, so they come out as ~1e-16, not 0.
//
// Every hand fraction is also checked against the 6-decimal numbers printed in
// Table 2.1 (to +-5e-7) where the table prints one, so a slip in a derivation below
// cannot pass silently.

#include "tests/test_support.h"

#include <QtTest>

#include "app/scene/scene_loader.h"
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


// The scene of Table 2.1, built in code.
rbw::SceneDef table21Scene()
{
    rbw::SceneDef s;
    s.name = "Table 2.1";
    s.dt = 2.0;   // h = 2
    s.steps = 1;
    rbw::BodyDef box;
    box.name = "box";
    box.size = Vec3(1.0, 0.6, 0.5);
    box.mass = 2.0;
    box.x0_W = Vec3::Zero();
    box.q0_WB = Quat(Eigen::AngleAxisd(std::numbers::pi / 2.0, Vec3::UnitZ()));
    box.v0_W = Vec3::Zero();
    box.omega0_W = Vec3::Zero();
    s.bodies.push_back(box);

    rbw::ForceDef f;
    f.body = 0;
    f.p_W = Vec3(0.3, 0.5, 0.25);
    f.f_W = Vec3(1.0, 1.0, 0.0);
    f.fromStep = 0;   // acts in step 0 only
    f.toStep = 1;
    s.forces.push_back(f);

    s.probes.push_back(rbw::ProbeDef{0, Vec3(-0.3, -0.5, -0.25)});
    s.probes.push_back(rbw::ProbeDef{0, Vec3(0.3, 0.5, 0.25)});
    return s;
}

constexpr double kRel = 1e-12;   // see the header comment

} // namespace

class TestTable21 : public QObject {
    Q_OBJECT

private slots:
    void sceneIsValid();
    void traceQuantity_data();
    void traceQuantity();
    void orientationUnchanged();
    void positionStaysAtOrigin();
    void lessonFileGivesSameOmega();
};

void TestTable21::sceneIsValid()
{
    const auto issues = rbw::validate(table21Scene());
    QVERIFY2(issues.empty(), issues.empty() ? "" : issues.front().reason.c_str());
}

void TestTable21::traceQuantity_data()
{
    QTest::addColumn<QString>("id");
    QTest::addColumn<int>("index");          // force / probe index, -1 for none
    QTest::addColumn<QList<double>>("expected");
    QTest::addColumn<QList<double>>("printed");   // Table 2.1's 6-decimal values, or empty

    const QList<double> none;

    // --- forces stage (algorithm step 1) ---
    // The one force, index 0, is recorded as given: f_0 = (1, 1, 0).
    QTest::newRow("applied_force") << "applied_force" << 0 << QList<double>{1.0, 1.0, 0.0} << none;
    // Its application point as given: p_0 = (0.3, 0.5, 0.25).
    QTest::newRow("application_point") << "application_point" << 0
                                       << QList<double>{0.3, 0.5, 0.25} << none;
    // Lever arm x_0 = p_0 - x = (0.3, 0.5, 0.25) - (0, 0, 0) = (0.3, 0.5, 0.25).
    QTest::newRow("lever_arm") << "lever_arm" << 0 << QList<double>{0.3, 0.5, 0.25} << none;
    // Total force F = sum f_i = f_0 = (1, 1, 0)  (no gravity in this scene).
    QTest::newRow("force") << "force" << -1 << QList<double>{1.0, 1.0, 0.0} << none;
    // Torque q = x_0 x f_0 = (0.3, 0.5, 0.25) x (1, 1, 0)
    //   q_x = 0.5*0   - 0.25*1 = -1/4
    //   q_y = 0.25*1  - 0.3*0  =  1/4
    //   q_z = 0.3*1   - 0.5*1  = -1/5
    // Table 2.1: q = (-0.25, 0.25, -0.2).
    QTest::newRow("torque") << "torque" << -1 << QList<double>{-1.0 / 4.0, 1.0 / 4.0, -1.0 / 5.0}
                            << QList<double>{-0.25, 0.25, -0.2};

    // --- integration stage (algorithm steps 2-7) ---
    // x <- x + h v_old = (0,0,0) + 2*(0,0,0) = (0,0,0): the OLD v (zero) is used.
    QTest::newRow("position") << "position" << -1 << QList<double>{0.0, 0.0, 0.0}
                              << QList<double>{0.0, 0.0, 0.0};
    // v <- v + h F / M = (0,0,0) + 2*(1,1,0)/2 = (1, 1, 0).   Table 2.1: v = (1, 1, 0).
    QTest::newRow("linear_velocity") << "linear_velocity" << -1 << QList<double>{1.0, 1.0, 0.0}
                                     << QList<double>{1.0, 1.0, 0.0};
    // r <- normalise(r + (h/2)(0, omega_old) r) with omega_old = 0: r is unchanged,
    // r = (cos 45, 0, 0, sin 45) = (1/sqrt2, 0, 0, 1/sqrt2)  [w, x, y, z].
    QTest::newRow("orientation") << "orientation" << -1
                                 << QList<double>{1.0 / std::sqrt(2.0), 0.0, 0.0, 1.0 / std::sqrt(2.0)}
                                 << none;
    // L <- L + h q = (0,0,0) + 2*(-1/4, 1/4, -1/5) = (-1/2, 1/2, -2/5).
    // Table 2.1: L = (-0.5, 0.5, -0.4).
    QTest::newRow("angular_momentum") << "angular_momentum" << -1
                                      << QList<double>{-1.0 / 2.0, 1.0 / 2.0, -2.0 / 5.0}
                                      << QList<double>{-0.5, 0.5, -0.4};
    // I0 = M/12 diag(b^2+c^2, a^2+c^2, a^2+b^2) with (a,b,c) = (1, 0.6, 0.5), M = 2:
    //    = 2/12 diag(0.36+0.25, 1+0.25, 1+0.36) = 1/6 diag(0.61, 1.25, 1.36)
    //    = diag(61/600, 5/24, 17/75) = diag(0.101667, 0.208333, 0.226667)   (Table 2.1).
    QTest::newRow("inertia_body") << "inertia_body" << -1
                                  << QList<double>{61.0 / 600.0, 0, 0, 0, 5.0 / 24.0, 0, 0, 0, 17.0 / 75.0}
                                  << QList<double>{0.101667, 0, 0, 0, 0.208333, 0, 0, 0, 0.226667};
    // R = R(r) = Rz(90): columns are the images of the body axes,
    //   R e_x = e_y, R e_y = -e_x, R e_z = e_z   ->   R = [[0,-1,0],[1,0,0],[0,0,1]].
    QTest::newRow("rotation_matrix") << "rotation_matrix" << -1
                                     << QList<double>{0, -1, 0, 1, 0, 0, 0, 0, 1} << none;
    // I0^-1 = diag(600/61, 24/5, 75/17) = diag(9.836066, 4.8, 4.411765).
    // I^-1 = R I0^-1 R^T. For R = Rz(90) the world x axis is the body's -y axis and the
    // world y axis is the body's x axis, so the x and y entries swap:
    //   I^-1 = diag(24/5, 600/61, 75/17) = diag(4.8, 9.836066, 4.411765), no off-diagonals.
    QTest::newRow("inverse_inertia_world")
        << "inverse_inertia_world" << -1
        << QList<double>{24.0 / 5.0, 0, 0, 0, 600.0 / 61.0, 0, 0, 0, 75.0 / 17.0}
        << QList<double>{4.8, 0, 0, 0, 9.836066, 0, 0, 0, 4.411765};
    // omega = I^-1 L (diagonal, so component by component):
    //   omega_x = 24/5   * (-1/2) = -12/5  = -2.4
    //   omega_y = 600/61 * ( 1/2) = 300/61 = 60/12.2 = 4.918033
    //   omega_z = 75/17  * (-2/5) = -30/17 = -1.764706
    // Table 2.1: omega = (-2.4, 4.918033, -1.764706).
    QTest::newRow("angular_velocity") << "angular_velocity" << -1
                                      << QList<double>{-12.0 / 5.0, 300.0 / 61.0, -30.0 / 17.0}
                                      << QList<double>{-2.4, 4.918033, -1.764706};

    // --- probes (algorithm step 8) ---
    // A probe moves with its body: p = x + R p_B with p_B = R0^T (p0 - x0). Here x = x0 = 0
    // and R = R0 (omega_old = 0), so p = R0 R0^T p0 = p0.
    QTest::newRow("probe_position[0]") << "probe_position" << 0
                                       << QList<double>{-0.3, -0.5, -0.25} << none;
    QTest::newRow("probe_position[1]") << "probe_position" << 1
                                       << QList<double>{0.3, 0.5, 0.25} << none;
    // v_p = v + omega x (p - x), with v = (1,1,0), x = 0, omega = (-12/5, 300/61, -30/17).
    // Probe 0, p = (-3/10, -1/2, -1/4):
    //   (omega x p)_x = omega_y p_z - omega_z p_y = (300/61)(-1/4) - (-30/17)(-1/2)
    //                 = -75/61 - 15/17 = -(75*17 + 15*61)/1037 = -2190/1037
    //   (omega x p)_y = omega_z p_x - omega_x p_z = (-30/17)(-3/10) - (-12/5)(-1/4)
    //                 = 9/17 - 3/5 = (45 - 51)/85 = -6/85
    //   (omega x p)_z = omega_x p_y - omega_y p_x = (-12/5)(-1/2) - (300/61)(-3/10)
    //                 = 6/5 + 90/61 = (366 + 450)/305 = 816/305
    //   v_p = (1 - 2190/1037, 1 - 6/85, 0 + 816/305) = (-1153/1037, 79/85, 816/305)
    //       = (-1.111861, 0.929412, 2.675410)   (Table 2.1).
    QTest::newRow("point_velocity[0]") << "point_velocity" << 0
                                       << QList<double>{-1153.0 / 1037.0, 79.0 / 85.0, 816.0 / 305.0}
                                       << QList<double>{-1.111861, 0.929412, 2.675410};
    // Probe 1, p = (3/10, 1/2, 1/4) = -(probe 0), so omega x p flips sign:
    //   v_p = (1 + 2190/1037, 1 + 6/85, 0 - 816/305) = (3227/1037, 91/85, -816/305)
    //       = (3.111861, 1.070588, -2.675410)   (Table 2.1).
    QTest::newRow("point_velocity[1]") << "point_velocity" << 1
                                       << QList<double>{3227.0 / 1037.0, 91.0 / 85.0, -816.0 / 305.0}
                                       << QList<double>{3.111861, 1.070588, -2.675410};
}

void TestTable21::traceQuantity()
{
    QFETCH(QString, id);
    QFETCH(int, index);
    QFETCH(QList<double>, expected);
    QFETCH(QList<double>, printed);

    // First the derivation against the printed table: the 6-decimal values are
    // rounded, so they agree with the exact fractions to within 5e-7.
    if (!printed.isEmpty()) {
        QCOMPARE(printed.size(), expected.size());
        for (int i = 0; i < printed.size(); ++i) {
            RBW_COMPARE_NEAR(printed[i], expected[i], 5e-7, "Table 2.1's printed value against the hand value");
        }
    }

    rbw::World world(table21Scene());
    rbw::StepTrace trace;
    const rbw::StepStatus status = world.step(&trace);
    QVERIFY2(status.ok, status.message.c_str());
    QCOMPARE(trace.step, 0L);
    QCOMPARE(trace.time, 2.0);   // t_1 = 1 * h

    const rbw::TraceEntry* entry = trace.find(id.toStdString(), 0, index);
    QVERIFY2(entry != nullptr, qPrintable(QStringLiteral("no trace entry %1[%2]").arg(id).arg(index)));
    const QString why = mismatch(flatten(entry->value), expected, kRel);
    QVERIFY2(why.isEmpty(), qPrintable(id + QStringLiteral(": ") + why));
}

void TestTable21::orientationUnchanged()
{
    rbw::World world(table21Scene());
    const Quat r0 = world.states()[0].q_WB;
    rbw::StepTrace trace;
    QVERIFY(world.step(&trace).ok);
    const rbw::TraceEntry* entry = trace.find("orientation", 0);
    QVERIFY(entry != nullptr);
    const Quat r1 = std::get<Quat>(entry->value);
    // omega_old = I^-1(r0) L0 with L0 = I(r0) * 0 = 0, so (h/2)(0, omega_old) r = 0 exactly
    // and r + 0 = r exactly. The only arithmetic left is the renormalisation r/|r| of an
    // already unit quaternion, which can move each coefficient by at most a couple of
    // units in the last place: tolerance 4 * 2^-53 ~ 4.4e-16 per coefficient.
    const double tol = 4.0 * std::ldexp(1.0, -53);
    RBW_COMPARE_NEAR(r1.w(), r0.w(), tol, "r changed");
    RBW_COMPARE_NEAR(r1.x(), r0.x(), tol, "r changed");
    RBW_COMPARE_NEAR(r1.y(), r0.y(), tol, "r changed");
    RBW_COMPARE_NEAR(r1.z(), r0.z(), tol, "r changed");
    // And the state the world keeps is the traced one.
    QCOMPARE(world.states()[0].q_WB.coeffs(), r1.coeffs());
}

void TestTable21::positionStaysAtOrigin()
{
    rbw::World world(table21Scene());
    rbw::StepTrace trace;
    QVERIFY(world.step(&trace).ok);
    // x <- x + h v_old = 0 + 2 * 0 = 0 exactly: the OLD velocity (zero) is used, not the
    // new v = (1, 1, 0), which would give x = (2, 2, 0). Compared exactly.
    const rbw::TraceEntry* entry = trace.find("position", 0);
    QVERIFY(entry != nullptr);
    QCOMPARE(std::get<Vec3>(entry->value), Vec3(Vec3::Zero()));
    QCOMPARE(world.states()[0].x_W, Vec3(Vec3::Zero()));
    // The velocity did change: v = h F / M = (1, 1, 0), exact in binary.
    QCOMPARE(world.states()[0].v_W, Vec3(1.0, 1.0, 0.0));
}

void TestTable21::lessonFileGivesSameOmega()
{
    const QString path = QStringLiteral(RBW_SOURCE_DIR "/lessons/01-one-step/scene.json");
    const rbw::SceneLoadResult loaded = rbw::loadSceneFile(path);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errors.join(QLatin1Char('\n'))));

    rbw::World fromFile(*loaded.scene);
    rbw::World fromCode(table21Scene());
    rbw::StepTrace traceFile;
    rbw::StepTrace traceCode;
    QVERIFY(fromFile.step(&traceFile).ok);
    QVERIFY(fromCode.step(&traceCode).ok);

    // The file gives the orientation as 90 degrees about z, converted as
    // 90 * pi / 180; the code uses pi / 2. The two may differ in the last bit, so the
    // results agree to the same 1e-12 relative as the hand values, not exactly.
    const rbw::TraceEntry* wFile = traceFile.find("angular_velocity", 0);
    const rbw::TraceEntry* wCode = traceCode.find("angular_velocity", 0);
    QVERIFY(wFile != nullptr && wCode != nullptr);
    QString why = mismatch(flatten(wFile->value), flatten(wCode->value), kRel);
    QVERIFY2(why.isEmpty(), qPrintable(QStringLiteral("omega: ") + why));
    // Both equal the hand value omega = (-12/5, 300/61, -30/17) (see traceQuantity).
    why = mismatch(flatten(wFile->value), {-12.0 / 5.0, 300.0 / 61.0, -30.0 / 17.0}, kRel);
    QVERIFY2(why.isEmpty(), qPrintable(QStringLiteral("omega from file: ") + why));

    // The file names the same two probes; their velocities agree too.
    for (int i = 0; i < 2; ++i) {
        const rbw::TraceEntry* pFile = traceFile.find("point_velocity", 0, i);
        const rbw::TraceEntry* pCode = traceCode.find("point_velocity", 0, i);
        QVERIFY(pFile != nullptr && pCode != nullptr);
        why = mismatch(flatten(pFile->value), flatten(pCode->value), kRel);
        QVERIFY2(why.isEmpty(), qPrintable(QStringLiteral("v_p[%1]: ").arg(i) + why));
    }
}

QTEST_APPLESS_MAIN(TestTable21)
#include "tst_table21.moc"
