// The derivation builder and its template language, without a display: lesson 1's
// page against the hand calculation of Table 2.1 (docs/references.md §1), lesson 3's
// impulse against lessons/03-two-box-collision/lesson.md, the "not computed" note,
// template syntax errors, the fallback, every lesson's template over its steps, and
// the standalone-HTML export.
#include "app/derivation/derivation_builder.h"
#include "app/derivation/derivation_page.h"
#include "app/derivation/derivation_template.h"
#include "app/derivation/standalone_html.h"
#include "app/derivation/trace_lookup.h"
#include "physics/engine/integrator_registry.h"
#include "tests/app/derivation/derivation_test_support.h"

#include <QDir>
#include <QTemporaryDir>
#include <QtTest>

using namespace rbw;
using namespace rbw::test;

class TestDerivationBuilder : public QObject {
    Q_OBJECT
private slots:
    void lesson1IsAStandardsModeDocument();
    void lesson1RowsInOrder();
    void lesson1Rows_data();
    void lesson1Rows();
    void lesson3Impulse();
    void missingEntryShowsNote();
    void bodySelectors();
    void valueBeforeContactFollowsTheContacts();
    void syntaxErrors_data();
    void syntaxErrors();
    void validTemplateHasNoErrors();
    void fallbackShowsEveryEntry();
    void focusBodyWritesOneBody_data();
    void focusBodyWritesOneBody();
    void lessonTemplatesCoverTheirSteps_data();
    void lessonTemplatesCoverTheirSteps();
    void standaloneHtmlEmbedsFonts();
    void exponentsAsPowersOfTen_data();
    void exponentsAsPowersOfTen();
    void tracedIntegratorIsTheOneThatRan_data();
    void tracedIntegratorIsTheOneThatRan();
    void switchingAfterAStepKeepsItsIntegrator();

private:
    DerivationDocument lesson1() const
    {
        const SceneDef scene = lessonScene(QStringLiteral("01-one-step"));
        return buildLessonDerivation(traceOfStep(scene, 0), scene, lessonDir(QStringLiteral("01-one-step")));
    }
};

void TestDerivationBuilder::lesson1IsAStandardsModeDocument()
{
    const DerivationDocument doc = lesson1();
    // KaTeX refuses quirks mode silently: the doctype must come first.
    QVERIFY(doc.html.startsWith(QLatin1String("<!DOCTYPE html>")));
    QVERIFY2(doc.errors.isEmpty(), qPrintable(doc.errors.join('\n')));
    QVERIFY2(doc.notes.isEmpty(), qPrintable(doc.notes.join('\n')));
    QVERIFY(!doc.fallback);
    QVERIFY(doc.html.contains(QLatin1String("katex.min.js")));
}

void TestDerivationBuilder::lesson1RowsInOrder()
{
    // The order of the worked solution: F, q, L, I0, R, I^-1, omega, then v_p.
    const QStringList math = mathOf(lesson1().html);
    const QStringList starts = {QStringLiteral("\\mathbf{F} &"), QStringLiteral("\\mathbf{q} &"),
                                QStringLiteral("\\mathbf{L} &"), QStringLiteral("I_0 &"),
                                QStringLiteral("R &"), QStringLiteral("I^{-1} &"),
                                QStringLiteral("\\boldsymbol{\\omega} &"), QStringLiteral("\\mathbf{v}_p &")};
    int previous = -1;
    for (const QString& s : starts) {
        const int at = rowIndex(math, s);
        QVERIFY2(at >= 0, qPrintable(QStringLiteral("no row for ") + s));
        QVERIFY2(at > previous, qPrintable(QStringLiteral("row out of order: ") + s));
        previous = at;
    }
}

void TestDerivationBuilder::lesson1Rows_data()
{
    QTest::addColumn<QString>("start");      // the row's formula
    QTest::addColumn<QStringList>("parts");  // written out in the row, in this order

    // Table 2.1: box size (1, 0.6, 0.5), M = 2, turned 90 deg about z; f = (1, 1, 0)
    // at p = (0.3, 0.5, 0.25); x = 0; h = 2.
    // F = f = (1, 1, 0).
    QTest::newRow("F") << QStringLiteral("\\mathbf{F} &") << QStringList{vec("1", "1", "0"), vec("1", "1", "0")};
    // q = x_0 x f_0 with x_0 = p - x = (0.3, 0.5, 0.25):
    // (0.5*0 - 0.25*1, 0.25*1 - 0.3*0, 0.3*1 - 0.5*1) = (-0.25, 0.25, -0.2).
    QTest::newRow("q") << QStringLiteral("\\mathbf{q} &")
                       << QStringList{vec("0.3", "0.5", "0.25") + QStringLiteral(" \\times ") + vec("1", "1", "0"),
                                      vec("-0.25", "0.25", "-0.2")};
    // L = 0 + h q = 2 (-0.25, 0.25, -0.2) = (-0.5, 0.5, -0.4).
    QTest::newRow("L") << QStringLiteral("\\mathbf{L} &")
                       << QStringList{QStringLiteral("2\\,") + vec("-0.25", "0.25", "-0.2"), vec("-0.5", "0.5", "-0.4")};
    // I0 = 2/12 diag(0.36 + 0.25, 1 + 0.25, 1 + 0.36) = diag(0.1016667, 0.2083333, 0.2266667).
    QTest::newRow("I0") << QStringLiteral("I_0 &")
                        << QStringList{QStringLiteral("0.6^2 + 0.5^2"),
                                       mat({"0.1016667 & 0 & 0", "0 & 0.2083333 & 0", "0 & 0 & 0.2266667"})};
    // R = Rz(90) = [[0, -1, 0], [1, 0, 0], [0, 0, 1]] (cos 90 = 6e-17 is chopped).
    QTest::newRow("R") << QStringLiteral("R &")
                       << QStringList{mat({"0 & -1 & 0", "1 & 0 & 0", "0 & 0 & 1"})};
    // I^-1 = R I0^-1 R^T: I0^-1 = diag(1/0.1016667, 1/0.2083333, 1/0.2266667)
    // = diag(9.836066, 4.8, 4.411765); the turn swaps x and y: diag(4.8, 9.836066, 4.411765).
    QTest::newRow("Iinv") << QStringLiteral("I^{-1} &")
                          << QStringList{mat({"0 & -1 & 0", "1 & 0 & 0", "0 & 0 & 1"}) + QStringLiteral("\\,") +
                                             mat({"9.836066 & 0 & 0", "0 & 4.8 & 0", "0 & 0 & 4.411765"}) +
                                             QStringLiteral("\\,") + mat({"0 & 1 & 0", "-1 & 0 & 0", "0 & 0 & 1"}),
                                         mat({"4.8 & 0 & 0", "0 & 9.836066 & 0", "0 & 0 & 4.411765"})};
    // omega = I^-1 L = (4.8 (-0.5), 9.836066 (0.5), 4.411765 (-0.4)) = (-2.4, 4.918033, -1.764706).
    QTest::newRow("omega") << QStringLiteral("\\boldsymbol{\\omega} &")
                           << QStringList{mat({"4.8 & 0 & 0", "0 & 9.836066 & 0", "0 & 0 & 4.411765"}) +
                                              QStringLiteral("\\,") + vec("-0.5", "0.5", "-0.4"),
                                          vec("-2.4", "4.918033", "-1.764706")};
    // v_p = v + omega x (p - x) for p = (-0.3, -0.5, -0.25):
    // omega x p = (4.918033(-0.25) - (-1.764706)(-0.5), -1.764706(-0.3) - (-2.4)(-0.25), -2.4(-0.5) - 4.918033(-0.3))
    //           = (-2.111861, -0.070588, 2.675410); + v = (1, 1, 0) -> (-1.111861, 0.929412, 2.67541),
    // shown with 7 significant digits: 0.9294118 (= 1 - 1.2/17).
    QTest::newRow("v_p") << QStringLiteral("\\mathbf{v}_p &")
                         << QStringList{vec("1", "1", "0") + QStringLiteral(" + ") + vec("-2.4", "4.918033", "-1.764706"),
                                        vec("-0.3", "-0.5", "-0.25"), vec("-1.111861", "0.9294118", "2.67541")};
}

void TestDerivationBuilder::lesson1Rows()
{
    QFETCH(QString, start);
    QFETCH(QStringList, parts);
    const QStringList math = mathOf(lesson1().html);
    const int at = rowIndex(math, start);
    QVERIFY2(at >= 0, qPrintable(QStringLiteral("no row for ") + start));
    const QString& row = math[at];
    int from = 0;
    for (const QString& part : parts) {
        const int found = row.indexOf(part, from);
        QVERIFY2(found >= 0, qPrintable(QStringLiteral("missing or out of order:\n  %1\nin\n  %2").arg(part, row)));
        from = found + 1;
    }
}

void TestDerivationBuilder::lesson3Impulse()
{
    // lessons/03-two-box-collision/lesson.md: in step k = 2 B's corner is 0.01 into A's
    // face. numerator -(1 + 1)(-2) = 4; 1/M_A = 0.5, 1/M_B = 1; [.]_A = 3/4 |x_a x n|^2
    // = 3/4 0.25 = 0.1875; [.]_B = 0 (x_b parallel to n); denominator 27/16 = 1.6875;
    // J = 4 / 1.6875 = 64/27 = 2.370370...
    const SceneDef scene = lessonScene(QStringLiteral("03-two-box-collision"));
    const DerivationDocument doc =
        buildLessonDerivation(traceOfStep(scene, 2), scene, lessonDir(QStringLiteral("03-two-box-collision")));
    QVERIFY2(doc.errors.isEmpty(), qPrintable(doc.errors.join('\n')));
    QVERIFY2(doc.notes.isEmpty(), qPrintable(doc.notes.join('\n')));
    const QStringList math = mathOf(doc.html);
    const int numerator = rowIndex(math, QStringLiteral("-(1+c)"));
    QVERIFY(numerator >= 0);
    // The shown result is coloured: \textcolor{...}{<value>\ <unit>}.
    const QString result = QStringLiteral("\\textcolor{#0b4f8a}{");
    QVERIFY2(math[numerator].contains(QLatin1String("-(1 + 1) \\cdot (-2)")) &&
                 math[numerator].contains(result + QLatin1String("4\\ ")),
             qPrintable(math[numerator]));
    const int denominator = rowIndex(math, QStringLiteral("k_n"));
    QVERIFY(denominator >= 0);
    QVERIFY2(math[denominator].contains(QLatin1String("0.5 + 1 + 0.1875 + 0")), qPrintable(math[denominator]));
    QVERIFY2(math[denominator].contains(result + QLatin1String("1.6875\\ ")), qPrintable(math[denominator]));
    const int j = rowIndex(math, QStringLiteral("J &"));
    QVERIFY(j >= 0);
    QVERIFY2(math[j].contains(QLatin1String("\\frac{ 4 }{ 1.6875 }")), qPrintable(math[j]));
    QVERIFY2(math[j].contains(result + QLatin1String("2.37037\\ ")), qPrintable(math[j]));
    // Negative control: the step before has no contact, so no J at all.
    const DerivationDocument before =
        buildLessonDerivation(traceOfStep(scene, 1), scene, lessonDir(QStringLiteral("03-two-box-collision")));
    QCOMPARE(rowIndex(mathOf(before.html), QStringLiteral("J &")), -1);
    QVERIFY(!before.html.contains(QLatin1String("2.37037")));
}

void TestDerivationBuilder::missingEntryShowsNote()
{
    const QString tmpl = QStringLiteral("= J && {{impulse}}\n");
    // Lesson 1 has no collision stage: no J in its trace, so a note and no number.
    const SceneDef one = lessonScene(QStringLiteral("01-one-step"));
    const DerivationDocument doc = buildDerivation(traceOfStep(one, 0), one, tmpl, QStringLiteral("t.md"));
    QVERIFY(doc.errors.isEmpty());
    QCOMPARE(doc.notes, QStringList{QStringLiteral("t.md:1: {{impulse}}: not computed in this step")});
    const QStringList math = mathOf(doc.html);
    const int row = rowIndex(math, QStringLiteral("J &"));
    QVERIFY(row >= 0);
    QVERIFY(math[row].contains(QLatin1String("not computed in this step")));
    // Negative control: in lesson 3's collision step the same placeholder is J = 64/27.
    const SceneDef three = lessonScene(QStringLiteral("03-two-box-collision"));
    const DerivationDocument hit = buildDerivation(traceOfStep(three, 2), three, tmpl, QStringLiteral("t.md"));
    QVERIFY(hit.notes.isEmpty());
    QVERIFY(hit.html.contains(QLatin1String("2.37037")));
    QVERIFY(!hit.html.contains(QLatin1String("not computed")));
}

void TestDerivationBuilder::bodySelectors()
{
    // Lesson 3, step 0: two bodies, both with a linear_velocity, so the bare id is
    // ambiguous; @A / @B pick one. No force acts: v stays (1,0,0) and (-1,0,0).
    const SceneDef scene = lessonScene(QStringLiteral("03-two-box-collision"));
    const StepTrace t = traceOfStep(scene, 0);
    const DerivationDocument bare = buildDerivation(t, scene, QStringLiteral("= v && {{linear_velocity}}\n"),
                                                    QStringLiteral("t.md"));
    QCOMPARE(bare.notes.size(), 1);
    QVERIFY(bare.notes.first().contains(QLatin1String("ambiguous")));
    const DerivationDocument named = buildDerivation(
        t, scene, QStringLiteral("= v_A && {{linear_velocity@A}}\n= v_B && {{linear_velocity@B}}\n"), QStringLiteral("t.md"));
    QVERIFY2(named.notes.isEmpty(), qPrintable(named.notes.join('\n')));
    const QStringList math = mathOf(named.html);
    QCOMPARE(math.size(), 2);
    QVERIFY(math.value(0).contains(vec("1", "0", "0")));
    QVERIFY(math.value(1).contains(vec("-1", "0", "0")));
}

void TestDerivationBuilder::valueBeforeContactFollowsTheContacts()
{
    // Lesson 6: the "face" cube lands flat, so one step has four corner contacts on it,
    // resolved in turn. {{pre:...}} must give the velocity each contact started from:
    // the integrated one for the first, the previous contact's result for the others.
    const SceneDef scene = lessonScene(QStringLiteral("06-box-on-plane"));
    const int face = scene.bodyIndex("face");
    World w(scene);
    StepTrace t;
    std::vector<int> mine;
    for (int k = 0; k < 60 && mine.size() < 4; ++k) {
        QVERIFY(w.step(&t).ok);
        mine.clear();
        for (int c = 0; c < int(t.contacts.size()); ++c) {
            if (t.contacts[c].bodyA == face && !t.contacts[c].separating) mine.push_back(c);
        }
    }
    QCOMPARE(int(mine.size()), 4);
    const Vec3 integrated = std::get<Vec3>(t.find("linear_velocity", face)->value);
    Vec3 expected = integrated;
    for (const int c : mine) {
        const TraceEntry* pre = valueBeforeContact(t, "linear_velocity", face, c);
        QVERIFY(pre != nullptr);
        QCOMPARE(std::get<Vec3>(pre->value), expected);
        // v_A(p) = v_A + omega_A x x_a with the values this contact started from.
        const Vec3 omega = std::get<Vec3>(valueBeforeContact(t, "angular_velocity", face, c)->value);
        const Vec3 x_a = std::get<Vec3>(t.find("x_a", face, c)->value);
        const Vec3 vA = std::get<Vec3>(t.find("velocity_a", face, c)->value);
        QVERIFY(((expected + omega.cross(x_a)) - vA).norm() <= 1e-12 * (1.0 + vA.norm()));
        expected = std::get<Vec3>(t.find("linear_velocity_a", face, c)->value);
    }
    // Negative control: the last contact did not start from the integrated velocity.
    QVERIFY(std::get<Vec3>(valueBeforeContact(t, "linear_velocity", face, mine.back())->value) != integrated);
}

void TestDerivationBuilder::syntaxErrors_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("message");
    QTest::addColumn<bool>("parseError");   // false: found while filling in (the page is still built)

    QTest::newRow("unclosed block") << QStringLiteral("# T\n@foreach body\n= x && {{position}}\n")
                                    << QStringLiteral("t.md:2: this block is never closed: add @end") << true;
    QTest::newRow("stray @end") << QStringLiteral("text\n\n@end\n")
                                << QStringLiteral("t.md:3: @end without an opening @foreach, @body or @if") << true;
    QTest::newRow("misspelt id") << QStringLiteral("# T\n= x && {{angular_velocty}}\n")
                                 << QStringLiteral("t.md:2: unknown quantity 'angular_velocty'") << true;
    QTest::newRow("unknown directive") << QStringLiteral("@for body\n")
                                       << QStringLiteral("t.md:1: unknown directive '@for'") << true;
    QTest::newRow("open placeholder") << QStringLiteral("a\nb {{torque\n")
                                      << QStringLiteral("t.md:2: '{{' without a closing '}}'") << true;
    QTest::newRow("four cells") << QStringLiteral("= a && b && c && d\n")
                                << QStringLiteral("t.md:1: a row has at most 3 cells") << true;
    QTest::newRow("unknown loop") << QStringLiteral("@foreach wheel\n@end\n")
                                  << QStringLiteral("t.md:1: @foreach needs body, force") << true;
    QTest::newRow("unbalanced $") << QStringLiteral("x $a\n") << QStringLiteral("t.md:1: unbalanced $") << true;
    QTest::newRow("open section") << QStringLiteral("= q && {{#force}}{{lever_arm}}\n")
                                  << QStringLiteral("t.md:1: {{#force}} is not closed on this line") << true;
    QTest::newRow("unknown body") << QStringLiteral("@body wheel\n= x && {{position}}\n@end\n")
                                  << QStringLiteral("t.md:1: no body named 'wheel' in this scene") << false;
}

void TestDerivationBuilder::syntaxErrors()
{
    QFETCH(QString, text);
    QFETCH(QString, message);
    QFETCH(bool, parseError);
    const SceneDef scene = lessonScene(QStringLiteral("01-one-step"));
    const DerivationDocument doc = buildDerivation(traceOfStep(scene, 0), scene, text, QStringLiteral("t.md"));
    const QString all = doc.errors.join('\n');
    QVERIFY2(all.contains(message), qPrintable(QStringLiteral("expected \"%1\" in:\n%2").arg(message, all)));
    // The page shows the message (HTML-escaped) in its error box.
    QVERIFY(doc.html.contains(QLatin1String("class=\"template-error\"")));
    QVERIFY(doc.html.contains(message.toHtmlEscaped()));
    // A template that cannot be read falls back to every traced quantity.
    QCOMPARE(doc.fallback, parseError);
    QVERIFY(doc.html.startsWith(QLatin1String("<!DOCTYPE html>")));
}

void TestDerivationBuilder::validTemplateHasNoErrors()
{
    // Negative control for syntaxErrors: the same constructs, written correctly.
    const QString text = QStringLiteral(
        "# T\n@foreach body\n## {{body}}\n@foreach force\n= x && {{lever_arm}}\n@end\n"
        "= q && {{#force}}{{lever_arm}} \\times {{applied_force}}{{/force}} && {{torque}}\n"
        "@body box\n= x && {{position}}\n@end\n@end\nSome $x = {{position@box}}$ text.\n");
    const TemplateParseResult parsed = parseDerivationTemplate(text, QStringLiteral("t.md"));
    QVERIFY2(parsed.ok(), qPrintable(parsed.errors.join('\n')));
    const SceneDef scene = lessonScene(QStringLiteral("01-one-step"));
    const DerivationDocument doc = buildDerivation(traceOfStep(scene, 0), scene, text, QStringLiteral("t.md"));
    QVERIFY(doc.errors.isEmpty());
    QVERIFY2(doc.notes.isEmpty(), qPrintable(doc.notes.join('\n')));
    QVERIFY(!doc.html.contains(QLatin1String("class=\"template-error\"")));
}

void TestDerivationBuilder::fallbackShowsEveryEntry()
{
    // A lesson folder without derivation.md gets the generic page: one row per traced
    // quantity, grouped by stage in pipeline order.
    QTemporaryDir empty;
    QVERIFY(empty.isValid());
    const SceneDef scene = lessonScene(QStringLiteral("01-one-step"));
    const StepTrace t = traceOfStep(scene, 0);
    const DerivationDocument doc = buildLessonDerivation(t, scene, empty.path());
    QVERIFY(doc.fallback);
    QVERIFY(doc.errors.isEmpty());
    QVERIFY(doc.html.startsWith(QLatin1String("<!DOCTYPE html>")));
    int rows = 0;
    for (const QString& m : mathOf(doc.html)) rows += m.startsWith(QLatin1String("\\begin{aligned}")) ? 1 : 0;
    QCOMPARE(rows, int(t.entries.size()));
    const int forces = doc.html.indexOf(QLatin1String("<h2>Forces</h2>"));
    const int integration = doc.html.indexOf(QLatin1String("<h2>Integration</h2>"));
    const int probes = doc.html.indexOf(QLatin1String("<h2>Probes</h2>"));
    QVERIFY(forces >= 0 && forces < integration && integration < probes);
    QVERIFY(doc.html.contains(vec("-2.4", "4.918033", "-1.764706")));
}

void TestDerivationBuilder::focusBodyWritesOneBody_data()
{
    QTest::addColumn<bool>("withTemplate");
    QTest::newRow("lesson 4's template") << true;
    QTest::newRow("fallback") << false;
}

void TestDerivationBuilder::focusBodyWritesOneBody()
{
    // Lesson 4's fifty boxes: with options.focusBody the page writes out that box
    // alone, under a note at the top that names it; without, every box.
    QFETCH(bool, withTemplate);
    QTemporaryDir empty;
    const QString dir = withTemplate ? lessonDir(QStringLiteral("04-many-boxes")) : empty.path();
    const SceneLoadResult loaded = loadSceneFile(lessonDir(QStringLiteral("04-many-boxes")) + "/fifty-boxes.json");
    QVERIFY(loaded.ok());
    const SceneDef& scene = *loaded.scene;
    QCOMPARE(int(scene.bodies.size()), 50);
    const StepTrace t = traceOfStep(scene, 0);
    const QString b08 = QString::fromStdString(scene.bodies[7].name);
    const QString b09 = QString::fromStdString(scene.bodies[8].name);
    // The fallback names a body's group by its name alone; the template by "Motion of".
    auto mentions = [&](const QString& html, const QString& name) {
        return html.contains(QStringLiteral(">Motion of %1<").arg(name)) || html.contains(QStringLiteral(">%1<").arg(name));
    };

    DerivationOptions options;
    options.focusBody = 7;
    const DerivationDocument focused = buildLessonDerivation(t, scene, dir, options);
    QCOMPARE(focused.fallback, !withTemplate);
    QVERIFY2(focused.errors.isEmpty(), qPrintable(focused.errors.join('\n')));
    const QString note = QStringLiteral("<main class=\"derivation\">\n<p class=\"focus-note\"");
    QVERIFY2(focused.html.contains(note), "the note comes first on the page");
    QVERIFY(focused.html.contains(QStringLiteral("This scene has 50 bodies: the page writes out <b>%1</b>").arg(b08)));
    QVERIFY(mentions(focused.html, b08));
    QVERIFY(!mentions(focused.html, b09));

    // Negative control: the same step without a focus writes out box 9, and no note.
    const DerivationDocument all = buildLessonDerivation(t, scene, dir);
    QVERIFY(!all.html.contains(QLatin1String("focus-note")));
    QVERIFY(mentions(all.html, b08));
    QVERIFY(mentions(all.html, b09));
}

void TestDerivationBuilder::lessonTemplatesCoverTheirSteps_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::addColumn<int>("steps");
    // Enough steps to reach the lesson's first contacts (04: the first box lands near
    // step 70; 06: t = 0.2 to 0.35; 07: the particle lands near step 150).
    QTest::newRow("01") << QStringLiteral("01-one-step") << 1;
    QTest::newRow("02") << QStringLiteral("02-single-body") << 210;
    QTest::newRow("03") << QStringLiteral("03-two-box-collision") << 3;
    QTest::newRow("04") << QStringLiteral("04-many-boxes") << 400;
    QTest::newRow("05") << QStringLiteral("05-spinning") << 20;
    QTest::newRow("06") << QStringLiteral("06-box-on-plane") << 60;
    QTest::newRow("07") << QStringLiteral("07-bounce") << 600;
    QTest::newRow("08") << QStringLiteral("08-conventions") << 1000;
    QTest::newRow("09") << QStringLiteral("09-tennis-racket") << 2000;
    // 11: the box lands near step 25 and rests on four manifold points by step 60.
    QTest::newRow("11") << QStringLiteral("11-resting-contact") << 60;
}

void TestDerivationBuilder::lessonTemplatesCoverTheirSteps()
{
    // Every placeholder of a lesson's template finds its number in every step of the
    // lesson (no "not computed" note where the template expects a value), and no page
    // shows NaN.
    QFETCH(QString, lesson);
    QFETCH(int, steps);
    // Every row names a lesson with a template (lesson 10, the accuracy lab, has none
    // and no row): a lost template fails here rather than skipping silently.
    QVERIFY2(QFileInfo::exists(lessonDir(lesson) + QStringLiteral("/derivation.md")), qPrintable(lesson));
    const SceneDef scene = lessonScene(lesson);
    World w(scene);
    StepTrace t;
    int contacts = 0;
    for (int k = 0; k < steps; ++k) {
        QVERIFY(w.step(&t).ok);
        contacts += int(t.contacts.size());
        const DerivationDocument doc = buildLessonDerivation(t, scene, lessonDir(lesson));
        QVERIFY2(doc.errors.isEmpty(), qPrintable(doc.errors.join('\n')));
        QVERIFY2(doc.notes.isEmpty(), qPrintable(QStringLiteral("step %1:\n").arg(k) + doc.notes.join('\n')));
        QVERIFY(!doc.fallback);
        QVERIFY(!doc.html.contains(QLatin1String("nan"), Qt::CaseInsensitive));
    }
    if (lesson.startsWith(QLatin1String("03")) || lesson.startsWith(QLatin1String("04")) ||
        lesson.startsWith(QLatin1String("06")) || lesson.startsWith(QLatin1String("07"))) {
        QVERIFY2(contacts > 0, "the steps must include contacts, or the contact part is untested");
    }
}

void TestDerivationBuilder::standaloneHtmlEmbedsFonts()
{
    QString error;
    const QString css = inlinedKatexCss(QStringLiteral("/usr/share/javascript/katex"), &error);
    QVERIFY2(!css.isEmpty(), qPrintable(error));
    // katex.min.css 0.16 declares 20 @font-face rules, each now one woff2 data: URL.
    QCOMPARE(css.count(QLatin1String("@font-face")), 20);
    QCOMPARE(css.count(QLatin1String("url(data:font/woff2;base64,")), 20);
    QVERIFY(!css.contains(QLatin1String("url(fonts/")));

    const QString html = standaloneDerivationHtml(
        QStringLiteral("<main><span class=\"katex\">x</span></main><script>alert(1)</script>"), QStringLiteral("T"),
        QStringLiteral("/usr/share/javascript/katex"), &error);
    QVERIFY(html.startsWith(QLatin1String("<!DOCTYPE html>")));
    QVERIFY(html.contains(QLatin1String("<span class=\"katex\">x</span>")));
    QVERIFY(!html.contains(QLatin1String("<script")));

    // Negative control: no KaTeX folder, a clear error and no page.
    QString missingError;
    QVERIFY(standaloneDerivationHtml(QStringLiteral("<p>x</p>"), QStringLiteral("T"), QStringLiteral("/nonexistent"),
                                     &missingError)
                .isEmpty());
    QVERIFY(missingError.contains(QLatin1String("/nonexistent/katex.min.css")));
}

// Tiny and huge numbers as powers of ten, never "2.86e − 17" (issue 20); letters and
// commands that contain an e are left alone (the negative controls).
void TestDerivationBuilder::exponentsAsPowersOfTen_data()
{
    QTest::addColumn<QString>("latex");
    QTest::addColumn<QString>("expected");
    QTest::newRow("tiny") << "v = 2.86e-17" << "v = 2.86 \\cdot 10^{-17}";
    QTest::newRow("negative, padded") << "(-3.2e-08, 1)" << "(-3.2 \\cdot 10^{-8}, 1)";
    QTest::newRow("huge") << "1e+21" << "1 \\cdot 10^{21}";
    QTest::newRow("plain numbers stay") << "0.000123 + 42" << "0.000123 + 42";
    QTest::newRow("command") << "\\mathbf{e}_1 \\sec 2" << "\\mathbf{e}_1 \\sec 2";
    QTest::newRow("word") << "\\text{step 2e}" << "\\text{step 2e}";
}

void TestDerivationBuilder::exponentsAsPowersOfTen()
{
    QFETCH(QString, latex);
    QFETCH(QString, expected);
    QCOMPARE(texExponents(latex), expected);
    QVERIFY(inlineMathHtml(latex).contains(htmlEscape(expected)));
}

void TestDerivationBuilder::tracedIntegratorIsTheOneThatRan_data()
{
    QTest::addColumn<QString>("integrator");
    for (const IntegratorInfo& info : integratorCatalogue()) QTest::newRow(info.name) << QString::fromLatin1(info.name);
}

// Lesson 2's box stepped with each registered integrator: the trace names it.
void TestDerivationBuilder::tracedIntegratorIsTheOneThatRan()
{
    QFETCH(QString, integrator);
    SceneDef scene = lessonScene(QStringLiteral("02-single-body"));
    scene.integrator = integrator.toStdString();
    const QString traced = tracedIntegrator(traceOfStep(scene, 1), 0);
    // rotation-matrix-orthonormalised runs rotation_matrix.cpp's code: the trace tells
    // the family only (the expander then keeps the scene's name).
    if (integrator == QLatin1String("rotation-matrix-orthonormalised")) {
        QVERIFY2(integrator.startsWith(traced) && !traced.isEmpty(), qPrintable(traced));
    } else {
        QCOMPARE(traced, integrator);
    }
    QCOMPARE(tracedIntegrator(StepTrace{}, 0), QString());   // nothing traced: nothing known
}

// Lesson 1's step taken with explicit Euler, then the integrator switched to RK4 (the
// scene the window now holds): the page still writes the Euler step (issue 20).
void TestDerivationBuilder::switchingAfterAStepKeepsItsIntegrator()
{
    const SceneDef euler = lessonScene(QStringLiteral("01-one-step"));
    const StepTrace trace = traceOfStep(euler, 0);
    SceneDef switched = euler;
    switched.integrator = "rk4";
    const QString dir = lessonDir(QStringLiteral("01-one-step"));
    const DerivationDocument doc = buildLessonDerivation(trace, switched, dir);
    QVERIFY2(doc.errors.isEmpty(), qPrintable(doc.errors.join('\n')));
    QVERIFY(doc.html.contains(QLatin1String("explicit Euler")));
    QVERIFY(!doc.html.contains(QLatin1String("Runge")));
    // Negative control: an RK4 step is written as RK4.
    const StepTrace rk4 = traceOfStep(switched, 0);
    QVERIFY(buildLessonDerivation(rk4, switched, dir).html.contains(QLatin1String("Runge")));
}

QTEST_GUILESS_MAIN(TestDerivationBuilder)
#include "tst_derivation_builder.moc"
