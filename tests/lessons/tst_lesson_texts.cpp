// The lesson texts say what the app shows (issue 12): every number or behaviour a
// lesson.md or a variant's own text (NAME.md beside NAME.json) states about a run is
// checked here against the physics the app runs, and the text is checked to still
// state it, so neither can drift from the other. The numbers were read off the real
// rbw binary; each is rounded in the text as written there, and checked to that
// rounding (or exactly, where the text says "exactly" or "to the last bit").
#include "app/core/lesson_catalogue.h"
#include "physics/engine/quantities.h"
#include "physics/engine/world.h"
#include "tests/test_support.h"

#include <QFile>
#include <QFileInfo>
#include <QtTest>

#include <cmath>

using namespace rbw;
using rbw::test::lessonScene;

namespace {

QString lessonText(const QString& relative)
{
    QFile f(QStringLiteral(RBW_SOURCE_DIR "/lessons/") + relative);
    if (!f.open(QIODevice::ReadOnly)) qFatal("cannot read lessons/%s", qPrintable(relative));
    return QString::fromUtf8(f.readAll());
}

// value, rounded to `decimals` places, is the number the text writes.
bool rounds(double value, double written, int decimals)
{
    return std::abs(value - written) <= 0.5 * std::pow(10.0, -decimals) * (1 + 1e-9);
}

void stepN(World& w, int n, StepTrace* trace = nullptr)
{
    for (int k = 0; k < n; ++k) {
        const StepStatus s = w.step(trace);
        if (!s.ok) qFatal("step %d failed: %s", k, s.message.c_str());
    }
}

const TraceEntry* entry(const StepTrace& t, const char* id, int body)
{
    for (const TraceEntry& e : t.entries) {
        if (e.body == body && std::strcmp(e.info->id, id) == 0) return &e;
    }
    return nullptr;
}

int bodyIndex(const World& w, const char* name)
{
    for (int b = 0; b < static_cast<int>(w.scene().bodies.size()); ++b) {
        if (w.scene().bodies[static_cast<size_t>(b)].name == name) return b;
    }
    qFatal("no body %s", name);
    return -1;
}

} // namespace

class TestLessonTexts : public QObject {
    Q_OBJECT
private slots:
    void lesson1TableIsOnTheRight();
    void lesson2TorqueIsConstant();
    void lesson2LIsConstantEnergyGrows();
    void lesson7SaysTheAppOpensScenes();
    void everyVariantHasItsOwnText_data();
    void everyVariantHasItsOwnText();
    void impulseExperiments();
    void projectile();
    void constantSpin();
    void symmetricTop();
    void fiftyBoxesEnergy();
};

void TestLessonTexts::lesson1TableIsOnTheRight()
{
    const QString text = lessonText("01-one-step/lesson.md");
    QVERIFY(text.contains("quantities table on the right"));
    QVERIFY(!text.contains("table above"));   // the table is a dock on the right (tst_window_controls)
}

// "q = (−0.25, 0.25, −0.2) in all 200 steps" although the lever arm changes; L after
// them is lesson 1's, ω is not.
void TestLessonTexts::lesson2TorqueIsConstant()
{
    const QString text = lessonText("02-single-body/lesson.md");
    QVERIFY(text.contains("q = (−0.25, 0.25, −0.2) in all\n   200 steps"));
    QVERIFY(text.contains("(−4.841, 2.022, −2.549)"));
    QVERIFY(text.contains("(−0.685, −0.485,\n   0.25)"));
    World w(lessonScene("02-single-body/scene.json"));
    StepTrace t;
    const Vec3 q0(-0.25, 0.25, -0.2);
    Vec3 firstLever = Vec3::Zero();
    Vec3 lastLever = Vec3::Zero();
    for (int k = 0; k < 200; ++k) {
        QVERIFY(w.step(&t).ok);
        const TraceEntry* q = entry(t, "torque", 0);
        QVERIFY(q != nullptr);
        const Vec3 qk = std::get<Vec3>(q->value);
        // Round-off of the cross product of numbers of size 1: a few 1e-17.
        QVERIFY2((qk - q0).cwiseAbs().maxCoeff() <= 1e-15, qPrintable(QString::number(k)));
        const Vec3 lever = std::get<Vec3>(entry(t, "lever_arm", 0)->value);
        if (k == 0) firstLever = lever;
        lastLever = lever;
    }
    // Negative control: the lever arm did change, by about (1, 1, 0).
    QVERIFY((firstLever - lastLever).norm() > 1.0);
    QVERIFY(rounds(lastLever.x(), -0.685, 3) && rounds(lastLever.y(), -0.485, 3) && lastLever.z() == 0.25);
    const BodyState& s = w.states()[0];
    QVERIFY((s.L_W - Vec3(-0.5, 0.5, -0.4)).cwiseAbs().maxCoeff() <= 1e-15);
    QVERIFY(rounds(s.omega_W.x(), -4.841, 3) && rounds(s.omega_W.y(), 2.022, 3) && rounds(s.omega_W.z(), -2.549, 3));
    QVERIFY(s.x_W.isApprox(Vec3(0.995, 0.995, 0), 1e-12));   // "(0.995, 0.995, 0)"
}

// "L stays constant ... to the last bit", |L| flat at 0.812404, T_rot 2.2257 J -> 2.7487 J.
void TestLessonTexts::lesson2LIsConstantEnergyGrows()
{
    const QString text = lessonText("02-single-body/lesson.md");
    QVERIFY(text.contains("0.812404"));
    QVERIFY(text.contains("2.2257 J") && text.contains("2.7487 J after 1000 steps"));
    QVERIFY(!text.contains("creep"));   // the old, wrong statement
    World w(lessonScene("02-single-body/scene.json"));
    StepTrace t;
    stepN(w, 200, &t);
    const Vec3 L200 = w.states()[0].L_W;
    const double T200 = t.diagnostics.bodies[0].kineticRotational;
    QVERIFY(rounds(t.diagnostics.bodies[0].L_norm, 0.812404, 6));
    QVERIFY(rounds(T200, 2.2257, 4));
    double previous = T200;
    for (int k = 200; k < 1000; ++k) {
        QVERIFY(w.step(&t).ok);
        QVERIFY(w.states()[0].L_W == L200);   // bit for bit
        const double T = t.diagnostics.bodies[0].kineticRotational;
        QVERIFY2(T > previous, qPrintable(QString("T_rot did not grow in step %1").arg(k)));
        previous = T;
    }
    QVERIFY(rounds(previous, 2.7487, 4));
    QVERIFY(rounds(100.0 * (previous / T200 - 1.0), 23.0, 0));   // "+23 %"
}

void TestLessonTexts::lesson7SaysTheAppOpensScenes()
{
    const QString text = lessonText("07-bounce/lesson.md");
    QVERIFY(!text.contains("cannot open"));
    QVERIFY(text.contains("**File → Open**"));
}

void TestLessonTexts::everyVariantHasItsOwnText_data()
{
    QTest::addColumn<QString>("id");
    QTest::addColumn<QString>("textPath");
    QTest::addColumn<QString>("parentText");
    const QList<Lesson> lessons = lessonCatalogue(QStringLiteral(RBW_SOURCE_DIR "/lessons"));
    int variants = 0;
    for (const Lesson& l : lessons) {
        if (!l.variant) continue;
        ++variants;
        const QString parent = QFileInfo(l.scenePath).absolutePath() + "/lesson.md";
        QTest::newRow(qPrintable(l.id)) << l.id << l.textPath << parent;
    }
    QVERIFY(variants >= 5);   // fifty-boxes, impulses and the three accuracy-lab problems
}

void TestLessonTexts::everyVariantHasItsOwnText()
{
    QFETCH(QString, id);
    QFETCH(QString, textPath);
    QFETCH(QString, parentText);
    QVERIFY2(QFile::exists(textPath), qPrintable(textPath));
    QVERIFY2(QFileInfo(textPath) != QFileInfo(parentText), qPrintable(id + " shows its parent's text"));
    QCOMPARE(QFileInfo(textPath).completeBaseName(), id.section('/', 1));
    QFile f(textPath);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QVERIFY(f.readAll().startsWith("# Lesson "));
}

// impulses.md: J = f h; stop, reverse, ω_z = ∓2.7 rad/s, T = 12.15 J.
void TestLessonTexts::impulseExperiments()
{
    const QString text = lessonText("07-bounce/impulses.md");
    QVERIFY(text.contains("**−2.7 rad/s**") && text.contains("(0, 0, +2.7)") && text.contains("12.15 J"));
    World w(lessonScene("07-bounce/impulses.json"));
    stepN(w, 400);
    RBW_COMPARE_NEAR(w.states()[bodyIndex(w, "stop")].v_W, Vec3::Zero(), 1e-12);
    RBW_COMPARE_NEAR(w.states()[bodyIndex(w, "reverse")].v_W, Vec3(-3, 0, 0), 1e-12);
    const BodyState& cw = w.states()[bodyIndex(w, "spin-clockwise")];
    const BodyState& ccw = w.states()[bodyIndex(w, "spin-anticlockwise")];
    RBW_COMPARE_NEAR(cw.L_W, Vec3(0, 0, -9), 1e-12);
    RBW_COMPARE_NEAR(cw.omega_W, Vec3(0, 0, -2.7), 1e-12);
    RBW_COMPARE_NEAR(ccw.omega_W, Vec3(0, 0, 2.7), 1e-12);
    RBW_COMPARE_NEAR(cw.v_W, Vec3::Zero(), 1e-12);
    QVERIFY(rounds(w.diagnostics().bodies[static_cast<size_t>(bodyIndex(w, "spin-clockwise"))].kinetic, 12.15, 2));
}

// projectile.md: y = −3.5219 m after 200 steps, ½ g h T = 0.0981 m above the parabola.
void TestLessonTexts::projectile()
{
    const QString text = lessonText("10-accuracy-lab/projectile.md");
    QVERIFY(text.contains("**y = −3.5219 m**") && text.contains("**0.0981 m**") && text.contains("(3, −11.62, 0)"));
    World w(lessonScene("10-accuracy-lab/projectile.json"));
    stepN(w, 200);
    const BodyState& s = w.states()[0];
    QVERIFY(rounds(s.x_W.y(), -3.5219, 4));
    const double exact = 8.0 * 2.0 - 0.5 * 9.81 * 4.0;
    RBW_COMPARE_NEAR((s.x_W.y() - exact), 0.5 * 9.81 * 0.01 * 2.0, 1e-12);
    RBW_COMPARE_NEAR(s.v_W, Vec3(3, -11.62, 0), 1e-12);
}

// constant-spin.md: ω stays (0, −1.5, 2.598) within 2e-15, T = 1.02 J, lag 4.5e-4 rad.
void TestLessonTexts::constantSpin()
{
    const QString text = lessonText("10-accuracy-lab/constant-spin.md");
    QVERIFY(text.contains("4.5·10⁻⁴ rad") && text.contains("1.02 J") && text.contains("within 2·10⁻¹⁵"));
    World w(lessonScene("10-accuracy-lab/constant-spin.json"));
    const Vec3 omega0 = w.states()[0].omega_W;
    StepTrace t;
    for (int k = 0; k < 200; ++k) {
        QVERIFY(w.step(&t).ok);
        QVERIFY((w.states()[0].omega_W - omega0).cwiseAbs().maxCoeff() <= 2e-15);
        RBW_COMPARE_NEAR(t.diagnostics.kinetic, 1.02, 1e-15);
    }
    QVERIFY(rounds(std::abs(200 * 2 * std::atan(0.015) - 6.0), 4.5e-4, 5));
}

// symmetric-top.md: L constant, |L| = 0.5267; T 0.932145 J -> 0.954654 J (+2.4 %).
void TestLessonTexts::symmetricTop()
{
    const QString text = lessonText("10-accuracy-lab/symmetric-top.md");
    QVERIFY(text.contains("0.932145 J") && text.contains("0.954654 J") && text.contains("0.5267"));
    World w(lessonScene("10-accuracy-lab/symmetric-top.json"));
    QVERIFY(rounds(w.diagnostics().kinetic, 0.932145, 6));
    const Vec3 L0 = w.states()[0].L_W;
    QVERIFY(rounds(L0.norm(), 0.5267, 4));
    stepN(w, 200);
    QVERIFY(w.states()[0].L_W == L0);
    const double T = w.diagnostics().kinetic;
    QVERIFY(rounds(T, 0.954654, 6));
    QVERIFY(rounds(100.0 * (T / 0.932145 - 1.0), 2.4, 1));
    // Implicit midpoint keeps it (the text: "T stays 0.932145 J").
    SceneDef im = lessonScene("10-accuracy-lab/symmetric-top.json");
    im.integrator = "implicit-midpoint";
    World m(im);
    stepN(m, 200);
    QVERIFY(rounds(m.diagnostics().kinetic, 0.932145, 6));
}

// fifty-boxes.md: E from 752.49 J to 138.18 J, rising by at most a few hundredths in a step.
void TestLessonTexts::fiftyBoxesEnergy()
{
    const QString text = lessonText("04-many-boxes/fifty-boxes.md");
    QVERIFY(text.contains("752.49 J to 138.18 J"));
    World w(lessonScene("04-many-boxes/fifty-boxes.json"));
    QCOMPARE(int(w.scene().bodies.size()), 50);
    QVERIFY(rounds(w.diagnostics().total, 752.49, 2));
    double previous = w.diagnostics().total;
    double largestRise = 0.0;
    for (int k = 0; k < 1000; ++k) {
        QVERIFY(w.step().ok);
        const double E = w.diagnostics().total;
        largestRise = std::max(largestRise, E - previous);
        previous = E;
    }
    QVERIFY(rounds(previous, 138.18, 2));
    QVERIFY(largestRise > 0.0 && largestRise < 0.1);   // "a few hundredths of a joule"
}

QTEST_GUILESS_MAIN(TestLessonTexts)
#include "tst_lesson_texts.moc"
