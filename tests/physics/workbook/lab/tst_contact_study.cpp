// The contact problems and the contact study (physics/workbook/lab/contact_problems.h,
// contact_study.h): the measure against hand-placed boxes, the problems' scenes, the
// runner's rows, and what the study is for: a resting box that the course model lets
// slide and the manifold model holds still.
#include "physics/workbook/lab/contact_study.h"
#include "physics/engine/world.h"
#include "tests/test_support.h"

#include <QtTest>

#include <cmath>

using namespace rbw;
using namespace rbw::lab;

namespace {

// Two unit boxes, axis-aligned, and a ground plane y = 0.
SceneDef twoBoxes(const Vec3& xA, const Vec3& xB)
{
    SceneDef s = contactProblemScene(ContactProblem::RestingBox, ContactModel::Course);
    s.bodies[0].x0_W = xA;
    BodyDef b = s.bodies[0];
    b.name = "other";
    b.x0_W = xB;
    s.bodies.push_back(b);
    return s;
}

} // namespace

class TestContactStudy : public QObject {
    Q_OBJECT
private slots:
    void measure_data();
    void measure();
    void problemScenes();
    void validation_data();
    void validation();
    void rowsInOrder();
    void restingBoxCourseSlidesManifoldHolds();
};

void TestContactStudy::measure_data()
{
    QTest::addColumn<Vec3>("xA");
    QTest::addColumn<Vec3>("xB");
    QTest::addColumn<Vec3>("vA");
    QTest::addColumn<double>("overlap");
    QTest::addColumn<double>("below");
    QTest::addColumn<double>("kinetic");
    QTest::addColumn<int>("moving");
    // Unit boxes 0.9 apart along x overlap by 1 - 0.9 = 0.1 (the SAT's least overlap);
    // A's centre at y = 0.45 puts its lower corners 0.05 below the ground; A moving at
    // 1 m/s: T = 1/2 M |v|^2 = 0.5 J, one body faster than 0.01 m/s.
    QTest::newRow("overlap 0.1, 0.05 below") << Vec3(0, 0.45, 0) << Vec3(0.9, 0.5, 0) << Vec3(1, 0, 0) << 0.1 << 0.05
                                             << 0.5 << 1;
    // Negative control: 1.1 apart and resting on the ground: nothing overlaps.
    QTest::newRow("apart, on the ground") << Vec3(0, 0.5, 0) << Vec3(1.1, 0.5, 0) << Vec3(0, 0, 0) << 0.0 << 0.0 << 0.0
                                          << 0;
    // 0.005 m/s is not moving (the threshold is 0.01 m/s): T = 1/2 * 0.005^2 = 1.25e-5 J.
    QTest::newRow("creeping") << Vec3(0, 0.5, 0) << Vec3(3, 0.5, 0) << Vec3(0.005, 0, 0) << 0.0 << 0.0 << 1.25e-5 << 0;
}

void TestContactStudy::measure()
{
    QFETCH(Vec3, xA);
    QFETCH(Vec3, xB);
    QFETCH(Vec3, vA);
    QFETCH(double, overlap);
    QFETCH(double, below);
    QFETCH(double, kinetic);
    QFETCH(int, moving);
    SceneDef s = twoBoxes(xA, xB);
    s.bodies[0].v0_W = vA;
    const World w(s);
    const ContactMeasure m = measureContacts(s, w.massProperties(), w.states());
    RBW_COMPARE_NEAR_STRICT(m.deepestOverlap, overlap, 1e-12);
    RBW_COMPARE_NEAR_STRICT(m.deepestBelow, below, 1e-12);
    RBW_COMPARE_NEAR_STRICT(m.kineticEnergy, kinetic, 1e-15);
    QCOMPARE(m.moving, moving);
}

void TestContactStudy::problemScenes()
{
    // The scenes are valid in both models, and as the header describes them.
    for (ContactProblem p : {ContactProblem::RestingBox, ContactProblem::Tower, ContactProblem::Rain}) {
        for (ContactModel model : {ContactModel::Course, ContactModel::Manifold}) {
            const SceneDef s = contactProblemScene(p, model, 250);
            QVERIFY2(validate(s).empty(), contactProblemName(p));
            QCOMPARE(s.steps, 600L);
            QCOMPARE(s.contactModel, model);
        }
        QCOMPARE(contactProblemFromName(contactProblemName(p)), std::optional<ContactProblem>(p));
    }
    QCOMPARE(contactProblemScene(ContactProblem::Tower, ContactModel::Course).bodies.size(), size_t(10));
    const SceneDef rain = contactProblemScene(ContactProblem::Rain, ContactModel::Course, 250);
    QCOMPARE(rain.bodies.size(), size_t(250));
    // Box 249 is k = 49 of layer 2: x = 1.5 (9 - 4.5), y = 3 + 1.5 * 2, z = 1.5 (4 - 4.5).
    RBW_COMPARE_NEAR_STRICT(rain.bodies[249].x0_W, Vec3(6.75, 6.0, -0.75), 1e-15);
    QVERIFY(!contactProblemFromName("pile").has_value());
    // At rest as placed: nothing overlaps at the start of the tower.
    const SceneDef tower = contactProblemScene(ContactProblem::Tower, ContactModel::Course);
    const World w(tower);
    QVERIFY(measureContacts(tower, w.massProperties(), w.states()).deepestOverlap < 1e-12);
}

void TestContactStudy::validation_data()
{
    QTest::addColumn<QString>("field");
    QTest::addColumn<int>("which");
    QTest::newRow("iterations 0") << "iterations" << 0;
    QTest::newRow("no model") << "iterations" << 1;
    QTest::newRow("dt negative") << "dt" << 2;
    QTest::newRow("too many steps") << "dt" << 3;
    QTest::newRow("t_end 0") << "t_end" << 4;
    QTest::newRow("rain of 0 boxes") << "boxes" << 5;
}

void TestContactStudy::validation()
{
    QFETCH(QString, field);
    QFETCH(int, which);
    ContactStudyConfig c;
    QVERIFY(validateContactStudy(c).empty());   // the defaults run
    switch (which) {
    case 0: c.iterations = {4, 0}; break;
    case 1: c.iterations.clear(); c.course = false; c.softStep = false; break;
    case 2: c.dts = {0.01, -0.01}; break;
    case 3: c.dts = {1e-9}; break;
    case 4: c.tEnd = 0.0; break;
    case 5: c.problem = ContactProblem::Rain; c.rainBoxes = 0; break;
    }
    const std::vector<SceneIssue> issues = validateContactStudy(c);
    QCOMPARE(issues.size(), size_t(1));
    QCOMPARE(QString::fromStdString(issues[0].path), field);
}

void TestContactStudy::rowsInOrder()
{
    ContactStudyConfig c;
    c.problem = ContactProblem::Rain;
    c.rainBoxes = 4;
    c.iterations = {1, 4};
    c.dts = {1.0 / 60.0, 1.0 / 30.0};
    c.tEnd = 0.5;
    int calls = 0;
    const ContactStudyResult r = runContactStudy(c, [&calls](int done, int total) {
        ++calls;
        QCOMPARE(total, 8);
        QCOMPARE(done, calls);
    });
    QCOMPARE(r.runsPlanned, 8);
    QCOMPARE(r.rows.size(), size_t(8));
    QCOMPARE(calls, 8);
    // course at each h, the soft step (its 5 substeps) at each h, then the sequential
    // impulses by iterations, each at each h: three solvers
    const char* models[] = {"course", "course", "soft-step", "soft-step", "manifold", "manifold", "manifold", "manifold"};
    const int iterations[] = {0, 0, 5, 5, 1, 1, 4, 4};
    const long steps[] = {30, 15, 30, 15, 30, 15, 30, 15};   // T/h = 0.5 * 60, 0.5 * 30
    for (int i = 0; i < 8; ++i) {
        QCOMPARE(QString::fromStdString(r.rows[i].model), QString::fromLatin1(models[i]));
        QCOMPARE(r.rows[i].iterations, iterations[i]);
        QCOMPARE(r.rows[i].steps, steps[i]);
        QCOMPARE(r.rows[i].status, RunStatus::Ok);
        QVERIFY(!r.rows[i].drift.has_value());   // the rain falls: no drift
        QVERIFY(r.rows[i].nsPerStep > 0.0);
        // Free fall for 0.5 s from 3 m: nothing lands, nothing overlaps, all 4 move.
        QCOMPARE(r.rows[i].deepestOverlap, 0.0);
        QCOMPARE(r.rows[i].movingEnd, 4);
    }
}

void TestContactStudy::restingBoxCourseSlidesManifoldHolds()
{
    // What the study shows (issue 11): a box resting on the ground for 2 s at h = 1/60.
    // The manifold model holds it within 1 mm, and its energy never rises by more than
    // the potential energy of a 10 micrometre lift, M g 1e-5 m = 9.81e-5 J (its position
    // fix moves the box by fractions of a micrometre). The course model's single-point
    // impulses let it creep (the issue measured about 5 cm/s) and bounce: the negative
    // controls that make the first checks mean something.
    ContactStudyConfig c;
    c.problem = ContactProblem::RestingBox;
    c.iterations = {10};
    c.dts = {1.0 / 60.0};
    c.tEnd = 2.0;
    const ContactStudyResult r = runContactStudy(c);
    QCOMPARE(r.rows.size(), size_t(3));
    const ContactStudyRow& course = r.rows[0];
    const ContactStudyRow& soft = r.rows[1];
    const ContactStudyRow& manifold = r.rows[2];
    QCOMPARE(QString::fromStdString(soft.model), QStringLiteral("soft-step"));
    // The soft step holds it too: within 1 mm, no energy above the same 10 micrometre lift
    QVERIFY2(*soft.drift < 1e-3, qPrintable(QString::number(*soft.drift)));
    QVERIFY2(*manifold.drift < 1e-3, qPrintable(QString::number(*manifold.drift)));
    const double lift = 1.0 * 9.81 * 1e-5;
    QVERIFY2(manifold.energyGained < lift, qPrintable(QString::number(manifold.energyGained)));
    QVERIFY2(soft.energyGained < lift, qPrintable(QString::number(soft.energyGained)));
    QVERIFY2(*course.drift > 1e-2, qPrintable(QString::number(*course.drift)));
    QVERIFY2(course.energyGained > lift, qPrintable(QString::number(course.energyGained)));
}

QTEST_GUILESS_MAIN(TestContactStudy)
#include "tst_contact_study.moc"
