// Every lesson's derivation with every integrator (issue 10, item 2): the page names
// the integrator actually used, writes out that integrator's own section (RK4's
// stages, the midpoint rule, implicit midpoint's Newton solve and Cayley rotation,
// symplectic Euler's order, the rotation-matrix update), finds every number it names
// in the trace, and substitutes every start-of-step value (x_n, v_n, r_n, L_n, omega_n,
// R_n, I^-1(r_n)) with its number instead of leaving the symbol.
#include "app/core/focus_filter.h"
#include "app/derivation/derivation_builder.h"
#include "app/derivation/integrator_sections.h"
#include "tests/app/derivation/derivation_test_support.h"
#include "physics/engine/integrator_registry.h"

#include <QDir>
#include <QRegularExpression>
#include <QtTest>

using namespace rbw;
using namespace rbw::test;

namespace {

// A start-of-step symbol left in a substituted cell: x, v, L, omega bare or with the
// index n, r_n, R_n. (Symbols with other subscripts, such as v_A(p) or r_{n+1}, the
// unknown of an implicit rule, are not start-of-step values.)
const QRegularExpression& startSymbol()
{
    static const QRegularExpression re(QStringLiteral(
        R"(\\mathbf\{[xvL]\}(?![_(])|\\mathbf\{[xvL]\}_n|\\boldsymbol\{\\omega\}(?!_)|\\boldsymbol\{\\omega\}_n|(?<![A-Za-z\\])[rR]_n(?![A-Za-z{+]))"));
    return re;
}

// The first step whose trace has a contact, within `limit` steps; -1 if none.
int firstContactStep(const SceneDef& scene, int limit)
{
    World w(scene);
    StepTrace t;
    for (int k = 0; k < limit; ++k) {
        if (!w.step(&t).ok) return -1;
        if (!t.contacts.empty()) return k;
    }
    return -1;
}

SceneDef withIntegrator(SceneDef scene, const char* name)
{
    scene.integrator = name;
    for (BodyDef& b : scene.bodies) b.integrator.clear();
    return scene;
}

SceneDef sceneOf(const QString& lessonScene)
{
    const SceneLoadResult r = loadSceneFile(QStringLiteral(RBW_SOURCE_DIR "/lessons/") + lessonScene);
    if (!r.ok()) qFatal("%s", qPrintable(r.errors.join('\n')));
    return *r.scene;
}

} // namespace

class TestDerivationIntegrators : public QObject {
    Q_OBJECT
private slots:
    void everySectionParses();
    void symbolCheckCatchesSymbols();
    void lessonTimesIntegrator_data();
    void lessonTimesIntegrator();
    void sectionsFormulasHold_data();
    void sectionsFormulasHold();
};

void TestDerivationIntegrators::everySectionParses()
{
    for (const IntegratorInfo& info : integratorCatalogue()) {
        const std::vector<const IntegratorSection*> sections = integratorSections(QString::fromLatin1(info.name));
        QCOMPARE(sections.size(), size_t(2));   // its own, then the shared derived rows
        for (const IntegratorSection* s : sections) {
            QVERIFY2(s->errors.isEmpty(), qPrintable(s->errors.join('\n')));
            QVERIFY(!s->nodes.empty());
        }
        QVERIFY(sections[0]->label.endsWith(QString::fromLatin1(info.name) + QStringLiteral(".md")));
    }
    // An unknown integrator is an error, not an empty section.
    const std::vector<const IntegratorSection*> unknown = integratorSections(QStringLiteral("leapfrog"));
    QCOMPARE(unknown.size(), size_t(1));
    QVERIFY(unknown[0]->errors.join(' ').contains(QStringLiteral("leapfrog")));
}

void TestDerivationIntegrators::symbolCheckCatchesSymbols()
{
    // Negative control: the old lesson 1 rows (symbols at the start of the step) are
    // caught; substituted numbers, function names and other subscripts are not.
    const QStringList caught = {QStringLiteral("\\mathbf{x} + 0.5\\,\\mathbf{v}"), QStringLiteral("\\mathbf{L} + h\\,q"),
                                QStringLiteral("I^{-1}\\,\\boldsymbol{\\omega}"), QStringLiteral("r_n + h k"),
                                QStringLiteral("R_n^T"), QStringLiteral("\\mathbf{v}_n + 1")};
    for (const QString& s : caught) QVERIFY2(startSymbol().match(s).hasMatch(), qPrintable(s));
    const QStringList fine = {QStringLiteral("\\begin{pmatrix} 1 \\\\ 0 \\\\ 0 \\end{pmatrix} + 2"),
                              QStringLiteral("R\\big((1, 0, 0, 0)\\big)"), QStringLiteral("\\mathbf{v}_A(\\mathbf{p})"),
                              QStringLiteral("\\tfrac12(r_{n+1} + 1)"), QStringLiteral("\\boldsymbol{\\omega}_m"),
                              QStringLiteral("\\mathbf{0}")};
    for (const QString& s : fine) QVERIFY2(!startSymbol().match(s).hasMatch(), qPrintable(s));
}

void TestDerivationIntegrators::lessonTimesIntegrator_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::addColumn<QString>("integrator");
    QTest::addColumn<bool>("atContact");
    for (const QString& lesson : lessonScenesWithTemplates()) {
        // The step of the first contact too, for the scenes that have one.
        const bool collides = firstContactStep(sceneOf(lesson), 400) >= 0;
        for (const IntegratorInfo& info : integratorCatalogue()) {
            QTest::addRow("%s/%s/step0", qPrintable(lesson), info.name) << lesson << QString::fromLatin1(info.name) << false;
            if (collides) {
                QTest::addRow("%s/%s/contact", qPrintable(lesson), info.name)
                    << lesson << QString::fromLatin1(info.name) << true;
            }
        }
    }
}

void TestDerivationIntegrators::lessonTimesIntegrator()
{
    QFETCH(QString, lesson);
    QFETCH(QString, integrator);
    QFETCH(bool, atContact);
    const SceneDef scene = withIntegrator(sceneOf(lesson), integrator.toLatin1().constData());
    const std::vector<SceneIssue> problems = validate(scene);
    QVERIFY2(problems.empty(), problems.empty() ? "" : (problems.front().path + ": " + problems.front().reason).c_str());
    int step = 0;
    if (atContact) {
        step = firstContactStep(scene, 400);
        QVERIFY2(step >= 0, "this integrator finds no contact where explicit Euler does");
    }
    const StepTrace trace = traceOfStep(scene, step);
    // As the app builds it: a scene of many bodies writes out one of them (focus_filter.h).
    DerivationOptions options;
    options.focusBody = derivationFocusBody(scene, -1);
    const DerivationDocument doc =
        buildLessonDerivation(trace, scene, lessonDir(lesson.section('/', 0, 0)), options);
    QVERIFY2(!doc.fallback, qPrintable(doc.errors.join('\n')));
    QVERIFY2(doc.errors.isEmpty(), qPrintable(doc.errors.join('\n')));
    // Every placeholder found its number (a row of another integrator would not).
    QVERIFY2(doc.notes.isEmpty(), qPrintable(doc.notes.join('\n')));

    // The integrator actually used is named, and its own section was written out.
    const IntegratorInfo* info = findIntegrator(integrator.toStdString());
    QVERIFY(info != nullptr);
    QVERIFY2(doc.html.contains(htmlEscape(QString::fromUtf8(info->title))), info->title);
    const QString own = QStringLiteral("app/derivation/integrators/%1.md:").arg(integrator);
    int ownRows = 0;
    for (const DerivationRow& row : doc.rows) {
        if (row.where.startsWith(own)) ++ownRows;
        if (row.where.startsWith(QLatin1String("app/derivation/integrators/")) && !row.where.startsWith(own)) {
            const bool shared = row.where.contains(QLatin1String("/derived"));
            QVERIFY2(shared, qPrintable(QStringLiteral("a row of another integrator: ") + row.where));
        }
        // No start-of-step symbol where the trace has the number.
        const QRegularExpressionMatch m = startSymbol().match(row.substituted);
        QVERIFY2(!m.hasMatch(), qPrintable(QStringLiteral("%1: '%2' left as a symbol in %3")
                                                .arg(row.where, m.captured(0), row.substituted)));
    }
    QVERIFY2(ownRows >= 2, qPrintable(QStringLiteral("%1 rows of %2").arg(ownRows).arg(own)));
}

// The rows of each section claim that a formula, with the numbers put in, gives the
// number beside it. Recomputed here from the numbers the page shows (the start of the
// step and the trace's own entries), the claims hold to rounding: the sections write
// out what the integrators compute, not another method.
void TestDerivationIntegrators::sectionsFormulasHold_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::addColumn<QString>("integrator");
    // Lesson 1: a force and its torque (h = 2); lesson 9: a free spinning box.
    for (const char* lesson : {"01-one-step", "09-tennis-racket"}) {
        for (const IntegratorInfo& info : integratorCatalogue()) {
            QTest::addRow("%s/%s", lesson, info.name) << QString::fromLatin1(lesson) << QString::fromLatin1(info.name);
        }
    }
}

namespace {

template <class T>
T valueOf(const StepTrace& t, const char* id, int body, int index = -1)
{
    const TraceEntry* e = t.find(id, body, index);
    if (e == nullptr) qFatal("no %s[%d] for body %d", id, index, body);
    return std::get<T>(e->value);
}

Quat plus(const Quat& a, double w, const Quat& b)
{
    Quat out;
    out.coeffs() = a.coeffs() + w * b.coeffs();
    return out;
}

// r' = 1/2 (0, omega) r
Quat rate(const Vec3& omega, const Quat& r)
{
    Quat out = Quat(0.0, omega.x(), omega.y(), omega.z()) * r;
    out.coeffs() *= 0.5;
    return out;
}

bool near(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b)
{
    return (a - b).norm() <= 1e-12 * std::max(1.0, b.norm());
}

} // namespace

void TestDerivationIntegrators::sectionsFormulasHold()
{
    QFETCH(QString, lesson);
    QFETCH(QString, integrator);
    const SceneDef scene = withIntegrator(lessonScene(lesson), integrator.toLatin1().constData());
    const StepTrace t = traceOfStep(scene, 0);
    const double h = scene.dt;
    const int b = 0;
    const BodyState& s0 = t.start.bodies[b];
    const double M = scene.bodies[b].mass;
    const TraceEntry* forceEntry = t.find("force", b);
    const Vec3 F = forceEntry != nullptr ? std::get<Vec3>(forceEntry->value) : Vec3::Zero();
    const TraceEntry* torqueEntry = t.find("torque", b);
    const Vec3 q = torqueEntry != nullptr ? std::get<Vec3>(torqueEntry->value) : Vec3::Zero();
    const Vec3 x1 = valueOf<Vec3>(t, "position", b);
    const Vec3 v1 = valueOf<Vec3>(t, "linear_velocity", b);
    const Quat r1 = valueOf<Quat>(t, "orientation", b);
    const Vec3 L1 = valueOf<Vec3>(t, "angular_momentum", b);
    auto normalised = [](Quat r) { return r.normalized(); };

    if (integrator == QLatin1String("explicit-euler") || integrator.startsWith(QLatin1String("rotation-matrix"))) {
        QVERIFY(near(x1, s0.x_W + h * s0.v_W));
        QVERIFY(near(v1, s0.v_W + h * F / M));
        QVERIFY(near(L1, s0.L_W + h * q));
        if (integrator == QLatin1String("explicit-euler")) {
            QVERIFY(near(r1.coeffs(), normalised(plus(s0.q_WB, h, rate(s0.omega_W, s0.q_WB))).coeffs()));
        } else {
            const Mat3 update = valueOf<Mat3>(t, "rotation_matrix_update", b);
            QVERIFY(near(update, s0.R_WB + h * skew(s0.omega_W) * s0.R_WB));
        }
    } else if (integrator == QLatin1String("symplectic-euler")) {
        QVERIFY(near(v1, s0.v_W + h * F / M));
        QVERIFY(near(x1, s0.x_W + h * v1));
        QVERIFY(near(L1, s0.L_W + h * q));
        const Vec3 w1 = valueOf<Vec3>(t, "update_angular_velocity", b);
        QVERIFY(near(w1, s0.Iinv_W * L1));
        QVERIFY(near(r1.coeffs(), normalised(plus(s0.q_WB, h, rate(w1, s0.q_WB))).coeffs()));
    } else if (integrator == QLatin1String("midpoint") || integrator == QLatin1String("rk4")) {
        const int n = integrator == QLatin1String("rk4") ? 4 : 2;
        const double a[5] = {0.0, 0.0, 0.5 * h, 0.5 * h, h};   // stage i at y_n + a_i k_{i-1}
        for (int i = 1; i <= n; ++i) {
            QVERIFY(near(valueOf<Vec3>(t, "stage_velocity", b, i), s0.v_W + a[i] * F / M));
            const Vec3 wi = valueOf<Vec3>(t, "stage_angular_velocity", b, i);
            const Quat ri = i == 1 ? s0.q_WB : plus(s0.q_WB, a[i], valueOf<Quat>(t, "stage_orientation_rate", b, i - 1));
            const Vec3 Li = s0.L_W + a[i] * q;
            const Mat3 Ri = ri.normalized().toRotationMatrix();
            // I^-1(r_i) = R_i I0^-1 R_i^T (or R_i^T I0^-1 R_i in the course template's convention)
            const Mat3 I0inv = valueOf<Mat3>(t, "inverse_inertia_body", b);
            const Mat3 IinvI = scene.conventionOf(b) == InertiaConvention::CourseTemplate
                                   ? Mat3(Ri.transpose() * I0inv * Ri)
                                   : Mat3(Ri * I0inv * Ri.transpose());
            QVERIFY2(near(wi, IinvI * Li), qPrintable(QStringLiteral("omega_%1").arg(i)));
            QVERIFY(near(valueOf<Quat>(t, "stage_orientation_rate", b, i).coeffs(), rate(wi, ri).coeffs()));
        }
        if (n == 2) {
            QVERIFY(near(x1, s0.x_W + h * valueOf<Vec3>(t, "stage_velocity", b, 2)));
            QVERIFY(near(r1.coeffs(),
                         normalised(plus(s0.q_WB, h, valueOf<Quat>(t, "stage_orientation_rate", b, 2))).coeffs()));
        } else {
            const Vec3 kx = valueOf<Vec3>(t, "stage_velocity", b, 1) + 2.0 * valueOf<Vec3>(t, "stage_velocity", b, 2) +
                            2.0 * valueOf<Vec3>(t, "stage_velocity", b, 3) + valueOf<Vec3>(t, "stage_velocity", b, 4);
            QVERIFY(near(x1, s0.x_W + h / 6.0 * kx));
            Quat kr = valueOf<Quat>(t, "stage_orientation_rate", b, 1);
            kr = plus(kr, 2.0, valueOf<Quat>(t, "stage_orientation_rate", b, 2));
            kr = plus(kr, 2.0, valueOf<Quat>(t, "stage_orientation_rate", b, 3));
            kr = plus(kr, 1.0, valueOf<Quat>(t, "stage_orientation_rate", b, 4));
            QVERIFY(near(r1.coeffs(), normalised(plus(s0.q_WB, h / 6.0, kr)).coeffs()));
        }
        QVERIFY(near(v1, s0.v_W + h * F / M));
        QVERIFY(near(L1, s0.L_W + h * q));
    } else if (integrator == QLatin1String("implicit-gyroscopic")) {
        QVERIFY(near(v1, s0.v_W + h * F / M));
        QVERIFY(near(x1, s0.x_W + h * v1));
        const Vec3 w1 = valueOf<Vec3>(t, "update_angular_velocity", b);
        if (t.find("body_angular_velocity", b) != nullptr) {
            const Vec3 wB = valueOf<Vec3>(t, "body_angular_velocity", b);
            QVERIFY(near(wB, s0.R_WB.transpose() * s0.omega_W));
            const Vec3 wB1 = valueOf<Vec3>(t, "body_angular_velocity_new", b);
            QVERIFY(near(w1, s0.R_WB * wB1 + h * s0.Iinv_W * q));
        }
        QVERIFY(near(r1.coeffs(), normalised(plus(s0.q_WB, h, rate(w1, s0.q_WB))).coeffs()));
        const Mat3 R1 = valueOf<Mat3>(t, "rotation_matrix", b);
        const Mat3 I0 = valueOf<Mat3>(t, "inertia_body", b);
        QVERIFY(near(L1, R1 * I0 * R1.transpose() * w1));
    } else if (integrator == QLatin1String("implicit-midpoint")) {
        QVERIFY(near(x1, s0.x_W + h * (s0.v_W + 0.5 * h * F / M)));
        QVERIFY(near(v1, s0.v_W + h * F / M));
        QVERIFY(near(L1, s0.L_W + h * q));
        const Vec3 LB = valueOf<Vec3>(t, "body_angular_momentum", b);
        QVERIFY(near(LB, s0.R_WB.transpose() * (s0.L_W + 0.5 * h * q)));
        const Vec3 wm = valueOf<Vec3>(t, "midpoint_angular_velocity", b);
        const Quat c = valueOf<Quat>(t, "cayley_rotation", b);
        QVERIFY(near(c.coeffs(), Quat(1.0, 0.5 * h * wm.x(), 0.5 * h * wm.y(), 0.5 * h * wm.z()).normalized().coeffs()));
        QVERIFY(near(r1.coeffs(), (s0.q_WB * c).normalized().coeffs()));
    } else {
        QFAIL("an integrator without a check here: add its formulas");
    }
}

QTEST_GUILESS_MAIN(TestDerivationIntegrators)
#include "tst_derivation_integrators.moc"
