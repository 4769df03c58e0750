// Numbers on every derivation line (issue 20, item 7): an equation row of a lesson's
// derivation writes out the numbers its formula uses, not only the symbols. Checked on
// every lesson scene (the lesson's scene.json and its variants, as written) at every
// 10th of its first 400 steps, at the first contact and five steps after it (warm
// start), with the page built as the app builds it (focus on one body in many-body
// scenes).
//
// What "shows its numbers" means for a row (unnumbered() below):
// - a row without "=" (or "\leftarrow") in its formula is a definition or a value
//   (d (overlap) = 0.01) and needs nothing more;
// - a two-cell row (formula = value) whose formula's right-hand side is a computation
//   (an operator: + - × · a fraction, an inverse, a norm, max/min, a sum, a bracket)
//   skips the numbers of that computation: it needs a substituted cell;
// - a substituted cell must hold at least one number and no symbol of a quantity: what
//   is left after the numbers (a pmatrix, a quaternion tuple, 2.86 \cdot 10^{-17}) and
//   the typesetting commands are taken out must contain no letter. A function applied
//   to numbers (I^{-1}(...), ‖·‖) counts as a symbol: its value is a traced number too,
//   except in the row that defines that value (R = R(r), I^{-1}_2 = I^{-1}(r_2),
//   r = r(R), det R = det(...)), and
//   norm bars around numbers are an operation, not a symbol;
// - a placeholder whose number is not in the trace (a red "not computed" note) fails
//   its line too.
//
// Run with RBW_AUDIT=1 to print, per lesson scene, every template line that fails (the
// audit issue 20's numbers were fixed against: 79 template lines, counted per lesson
// scene, failed before, 0 after).
#include "app/core/focus_filter.h"
#include "app/derivation/derivation_builder.h"
#include "tests/app/derivation/derivation_test_support.h"
#include "physics/engine/integrator_registry.h"

#include <QDir>
#include <QRegularExpression>
#include <QtTest>

#include <map>

using namespace rbw;
using namespace rbw::test;

namespace {

QString withoutText(QString s)
{
    static const QRegularExpression text(QStringLiteral(R"(\\(?:text|mathrm|operatorname)\{[^{}]*\})"));
    return s.remove(text);
}

// The right-hand side of a formula: after its first "=" or "\leftarrow"; empty if it has none.
QString rightHandSide(const QString& formula)
{
    const QString f = withoutText(formula);
    static const QRegularExpression eq(QStringLiteral(R"(=|\\leftarrow)"));
    const QRegularExpressionMatch m = eq.match(f);
    return m.hasMatch() ? f.mid(m.capturedEnd()) : QString();
}

bool isComputation(const QString& rhs)
{
    static const QRegularExpression op(QStringLiteral(
        R"([-+(]|\\times|\\cdot|\\frac|\\tfrac|\^\{-1\}|\\lVert|\\max|\\min|\\sum|\\big|\\Big|\[)"));
    return op.match(rhs).hasMatch();
}

// A substituted cell with the numbers and the typesetting taken out: what is left is a
// symbol (or nothing).
QString symbolsLeft(QString s)
{
    static const QRegularExpression matrices(QStringLiteral(R"(\\begin\{pmatrix\}.*?\\end\{pmatrix\})"));
    static const QRegularExpression number(QStringLiteral(R"(-?\d+(?:\.\d+)?(?:e[-+]?\d+|\s*\\cdot\s*10\^\{-?\d+\})?)"));
    static const QRegularExpression commands(QStringLiteral(
        R"(\\(?:times|cdot|tfrac|dfrac|frac|min|max|big[lr]?|Big[lr]?|bigg|left|right|mathbf\{0\}|mathsf\{T\}|quad|qquad|sqrt|ldots|cdots|infty)(?![A-Za-z]))"));
    static const QRegularExpression spacing(QStringLiteral(R"(\\[,;:! ]|\\\\)"));
    s = withoutText(s);
    // ||.|| standing for a number is a symbol; norm bars around numbers are not
    if (s.contains(QLatin1String("\\lVert\\cdot\\rVert"))) return QStringLiteral("\\lVert\\cdot\\rVert");
    static const QRegularExpression bars(QStringLiteral(R"((?:\\[Bb]ig)?\\[lr]Vert)"));
    s.remove(bars);
    s.remove(matrices);
    s.remove(commands);
    s.remove(spacing);
    s.remove(number);
    static const QRegularExpression letters(QStringLiteral(R"(\\?[A-Za-z]+)"));
    QStringList left;
    QRegularExpressionMatchIterator it = letters.globalMatch(s);
    while (it.hasNext()) left << it.next().captured(0);
    return left.join(QLatin1Char(' '));
}

bool hasNumber(const QString& s)
{
    static const QRegularExpression digit(QStringLiteral(R"(\d)"));
    return digit.match(withoutText(s)).hasMatch();
}

} // namespace

// Why a row does not show its numbers; empty when it does (or needs none).
QString unnumbered(const DerivationRow& row)
{
    const QString rhs = rightHandSide(row.formula);
    // A row that defines a function's value by its argument (R = R(r), I^-1_2 = I^-1(r))
    // writes the function's own name before the argument's numbers: that name is the
    // row's result, not a number left out.
    QString substituted = row.substituted;
    for (const QString& head : {QStringLiteral("R"), QStringLiteral("I^{-1}"), QStringLiteral("r"), QStringLiteral("\\det")}) {
        const QString f = withoutText(row.formula);
        const bool definesIt = f.startsWith(head + QStringLiteral(" ")) || f.startsWith(head + QStringLiteral("_")) ||
                               f.startsWith(head + QStringLiteral("\\"));
        for (const QString& open : {QStringLiteral("\\big("), QStringLiteral("\\Big("), QStringLiteral(" \\begin{pmatrix}")}) {
            if (definesIt && substituted.startsWith(head + open)) substituted = substituted.mid(head.size());
        }
    }
    if (rhs.isEmpty() && row.substituted.isEmpty()) return QString();   // a definition or a value
    if (row.substituted.isEmpty()) {
        if (!isComputation(rhs)) return QString();   // symbol = symbol's value
        if (!hasNumber(row.result)) return QStringLiteral("no number at all");
        return QStringLiteral("the computation is shown without its numbers");
    }
    if (!hasNumber(substituted) && !hasNumber(row.result)) return QStringLiteral("no number at all");
    const QString left = symbolsLeft(substituted);
    if (!left.isEmpty()) return QStringLiteral("symbols without numbers: ") + left;
    return QString();
}

namespace {

// The steps to look at: every 10th of the first 400 (resting, sliding, asleep), the
// first contact and five steps later (warm start).
std::vector<StepTrace> tracesToCheck(const SceneDef& scene)
{
    std::vector<StepTrace> out;
    World w(scene);
    int contactAt = -1;
    for (int k = 0; k < 400; ++k) {
        StepTrace t;
        if (!w.step(&t).ok) break;
        const bool first = contactAt < 0 && !t.contacts.empty();
        if (first) contactAt = k;
        if (k % 10 == 0 || first || (contactAt >= 0 && k == contactAt + 5)) out.push_back(std::move(t));
    }
    return out;
}

} // namespace

class TestDerivationNumbers : public QObject {
    Q_OBJECT
private slots:
    void checkSeesRowsWithoutNumbers();
    void checkSeesATemplateLineWithoutNumbers();
    void everyLineHasNumbers_data();
    void everyLineHasNumbers();
};

void TestDerivationNumbers::checkSeesRowsWithoutNumbers()
{
    // Negative control: rows known to skip numbers are reported ...
    const std::vector<DerivationRow> bad = {
        {QStringLiteral("synthetic:1"), QStringLiteral("m_n = \\big(\\tfrac{1}{M_A} + \\tfrac{1}{M_B}\\big)^{-1}"), QString(),
         QStringLiteral("0.5\\ \\mathrm{kg}")},
        {QStringLiteral("synthetic:2"), QStringLiteral("r_{n+1} = \\frac{r_n + h k}{\\lVert\\cdot\\rVert}"),
         QStringLiteral("\\frac{(1,\\ 0,\\ 0,\\ 0) + 0.5}{\\lVert\\cdot\\rVert}"), QStringLiteral("(1,\\ 0,\\ 0,\\ 0)")},
        {QStringLiteral("synthetic:3"), QStringLiteral("\\boldsymbol{\\omega}_2 = I^{-1}(r)\\,\\mathbf{L}"),
         QStringLiteral("I^{-1}\\Big((1,\\ 0,\\ 0,\\ 0)\\Big)\\,\\begin{pmatrix} 1 \\\\ 0 \\\\ 0 \\end{pmatrix}"),
         QStringLiteral("\\begin{pmatrix} 1 \\\\ 0 \\\\ 0 \\end{pmatrix}")},
        {QStringLiteral("synthetic:4"), QStringLiteral("\\mathbf{v}_p = \\mathbf{v} + \\boldsymbol{\\omega}\\times\\mathbf{r}"),
         QStringLiteral("\\mathbf{v} + \\boldsymbol{\\omega}\\times\\mathbf{r}"), QStringLiteral("\\mathbf{v}_p")},
    };
    for (const DerivationRow& r : bad) QVERIFY2(!unnumbered(r).isEmpty(), qPrintable(r.where));
    // ... and rows that write out their numbers, or need none, are not.
    const std::vector<DerivationRow> good = {
        {QStringLiteral("synthetic:5"), QStringLiteral("d\\ \\text{(overlap)}"), QString(), QStringLiteral("0.01")},
        {QStringLiteral("synthetic:6"), QStringLiteral("\\mathbf{k}_{L,1} = \\mathbf{q}"), QString(),
         QStringLiteral("\\begin{pmatrix} 0 \\\\ 0 \\\\ 1 \\end{pmatrix}")},
        {QStringLiteral("synthetic:7"), QStringLiteral("\\mathbf{x} \\leftarrow \\mathbf{x} + h\\,\\mathbf{v}"),
         QStringLiteral("\\begin{pmatrix} 1 \\\\ 0 \\\\ 0 \\end{pmatrix} + 0.5 \\cdot \\mathbf{0} + 2.86 \\cdot 10^{-17}"),
         QStringLiteral("\\begin{pmatrix} 1 \\\\ 0 \\\\ 0 \\end{pmatrix}")},
        {QStringLiteral("synthetic:8"), QStringLiteral("r_{n+1} = \\frac{r_n + h k}{\\lVert\\cdot\\rVert}"),
         QStringLiteral("\\frac{(1,\\ 0,\\ 0,\\ 0)}{1.0002}"), QStringLiteral("(1,\\ 0,\\ 0,\\ 0)")},
        // a function's own value row: its name, then the numbers of its argument
        {QStringLiteral("synthetic:9"), QStringLiteral("R = R(r)"), QStringLiteral("R\\big((1,\\ 0,\\ 0,\\ 0)\\big)"),
         QStringLiteral("\\begin{pmatrix} 1 & 0 & 0 \\\\ 0 & 1 & 0 \\\\ 0 & 0 & 1 \\end{pmatrix}")},
        {QStringLiteral("synthetic:10"), QStringLiteral("I^{-1}_{2} = I^{-1}\\big(r_n + \\tfrac{h}{2}\\,k_{r,1}\\big)"),
         QStringLiteral("I^{-1}\\Big((1,\\ 0,\\ 0,\\ 0) + \\tfrac{ 0.01 }{2}\\,(0,\\ 0,\\ 1,\\ 0)\\Big)"),
         QStringLiteral("\\begin{pmatrix} 1 & 0 & 0 \\\\ 0 & 1 & 0 \\\\ 0 & 0 & 1 \\end{pmatrix}")},
    };
    for (const DerivationRow& r : good) QVERIFY2(unnumbered(r).isEmpty(), qPrintable(r.where + ": " + unnumbered(r)));
}

void TestDerivationNumbers::checkSeesATemplateLineWithoutNumbers()
{
    // Negative control through the whole page: a synthetic template, filled from lesson
    // 1's first step like a lesson's, with two lines that skip numbers (omega = I^-1 L
    // with no substitution; the norm left as a symbol) and one that writes them out.
    const QString templateText = QStringLiteral(
        "# synthetic\n"
        "@foreach body\n"
        "= {{formula:angular_velocity}} && {{angular_velocity}}\n"
        "= {{formula:orientation}} && \\frac{ {{start:orientation}} }{\\lVert\\cdot\\rVert} && {{orientation}}\n"
        "= {{formula:angular_velocity}} && {{inverse_inertia_world}}\\,{{angular_momentum}} && {{angular_velocity}}\n"
        "@end\n");
    const SceneDef scene = lessonScene(QStringLiteral("01-one-step"));
    const DerivationDocument doc =
        buildDerivation(traceOfStep(scene, 0), scene, templateText, QStringLiteral("synthetic.md"));
    QVERIFY2(doc.errors.isEmpty() && doc.notes.isEmpty(), qPrintable((doc.errors + doc.notes).join('\n')));
    QCOMPARE(int(doc.rows.size()), 3);
    QVERIFY2(!unnumbered(doc.rows[0]).isEmpty(), qPrintable(doc.rows[0].formula));
    QVERIFY2(unnumbered(doc.rows[1]).contains(QLatin1String("lVert")), qPrintable(doc.rows[1].substituted));
    QVERIFY2(unnumbered(doc.rows[2]).isEmpty(), qPrintable(unnumbered(doc.rows[2]) + ": " + doc.rows[2].substituted));
}

void TestDerivationNumbers::everyLineHasNumbers_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::addColumn<QString>("integrator");   // empty: as written
    for (const QString& lesson : lessonScenesWithTemplates()) QTest::newRow(qPrintable(lesson)) << lesson << QString();
    // A student may switch the integrator: every integrator's section, on a lesson with
    // a force and a probe (1), a free spinning body (9) and contacts (3).
    for (const char* lesson : {"01-one-step/scene.json", "03-two-box-collision/scene.json", "09-tennis-racket/scene.json"}) {
        for (const IntegratorInfo& info : integratorCatalogue()) {
            QTest::addRow("%s with %s", lesson, info.name) << QString::fromLatin1(lesson) << QString::fromLatin1(info.name);
        }
    }
}

void TestDerivationNumbers::everyLineHasNumbers()
{
    QFETCH(QString, lesson);
    QFETCH(QString, integrator);
    const SceneLoadResult loaded = loadSceneFile(QStringLiteral(RBW_SOURCE_DIR "/lessons/") + lesson);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errors.join('\n')));
    SceneDef scene = *loaded.scene;
    if (!integrator.isEmpty()) {
        scene.integrator = integrator.toStdString();
        for (BodyDef& b : scene.bodies) b.integrator.clear();
    }
    DerivationOptions options;
    options.focusBody = derivationFocusBody(scene, -1);
    std::map<QString, QString> failures;   // template line "file:line" -> its first failure
    int rows = 0;
    for (const StepTrace& trace : tracesToCheck(scene)) {
        const DerivationDocument doc = buildLessonDerivation(trace, scene, lessonDir(lesson.section('/', 0, 0)), options);
        QVERIFY2(doc.errors.isEmpty(), qPrintable(doc.errors.join('\n')));
        // Every number a row names is in the trace (a branch of the template that asks
        // for a value this step did not compute would show a red note instead).
        for (const QString& note : doc.notes) {
            const QString where = note.section(QStringLiteral(": "), 0, 0);
            if (!failures.count(where)) failures[where] = QStringLiteral("step %1: ").arg(trace.step) + note;
        }
        for (const DerivationRow& row : doc.rows) {
            ++rows;
            const QString why = unnumbered(row);
            if (!why.isEmpty() && !failures.count(row.where)) {
                failures[row.where] = row.where + QStringLiteral(": ") + why + QStringLiteral("\n      ") + row.formula +
                                      QStringLiteral("\n      ") + row.substituted;
            }
        }
    }
    QVERIFY(rows > 0);
    if (qEnvironmentVariableIsSet("RBW_AUDIT")) {
        qInfo().noquote() << "AUDIT" << lesson << failures.size() << "template lines without numbers";
        for (const auto& f : failures) qInfo().noquote() << "  " << f.second;
    }
    QStringList list;
    for (const auto& f : failures) list << f.second;
    QVERIFY2(failures.empty(), qPrintable(QStringLiteral("%1 lines without numbers:\n").arg(failures.size()) + list.join('\n')));
}

QTEST_GUILESS_MAIN(TestDerivationNumbers)
#include "tst_derivation_numbers.moc"
