// The derivation view under Xvfb: KaTeX renders lesson 1's page completely and in
// standards mode, a broken formula is counted as an error (the negative control),
// lesson 3's collision step shows J's terms, and the HTML and PDF exports work.
// Set RBW_SCREENSHOT_DIR to keep screenshots (deriv_lesson01.png, deriv_lesson03.png,
// deriv_lesson03_impulse.png), the exported page and the PDF (deriv_export.html, deriv.pdf).
#include "app/derivation/derivation_builder.h"
#include "app/gui/panels/derivation/derivation_view.h"
#include "tests/app/derivation/derivation_test_support.h"

#include <QApplication>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QWebEnginePage>
#include <QtTest>

using namespace rbw;
using namespace rbw::test;

namespace {

// Runs a script in the page and waits for its result.
QVariant evaluate(DerivationView& view, const QString& script)
{
    QVariant result;
    bool done = false;
    view.page()->runJavaScript(script, [&](const QVariant& v) {
        result = v;
        done = true;
    });
    if (!QTest::qWaitFor([&] { return done; }, 10000)) qWarning("script timed out: %s", qPrintable(script));
    return result;
}

// The text KaTeX drew (its HTML output, not the MathML copy of the source).
QString renderedText(DerivationView& view)
{
    return evaluate(view, QStringLiteral("Array.from(document.querySelectorAll('.katex-html'))"
                                         ".map(function (e) { return e.textContent; }).join(' ')"))
        .toString();
}

void saveScreenshot(DerivationView& view, const QString& name)
{
    const QString dir = qEnvironmentVariable("RBW_SCREENSHOT_DIR");
    if (!dir.isEmpty()) QVERIFY(view.grab().save(dir + QLatin1Char('/') + name));
}

} // namespace

class TestDerivationView : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void lesson1Renders();
    void brokenFormulaIsCounted();
    void lesson3CollisionStep();
    void exportHtml();
    void exportPdf();
    void noBrowserMenu();

private:
    // Shows a page and waits for rendered(); returns its arguments.
    QList<QVariant> show(const QString& html);
    DerivationView* view_ = nullptr;
};

void TestDerivationView::init()
{
    view_ = new DerivationView;
    view_->resize(500, 900);   // the width of the app's dock
    view_->show();
    QVERIFY(QTest::qWaitForWindowExposed(view_));
}

void TestDerivationView::cleanup()
{
    delete view_;
    view_ = nullptr;
}

QList<QVariant> TestDerivationView::show(const QString& html)
{
    QSignalSpy spy(view_, &DerivationView::rendered);
    view_->showStep(html);
    if (!spy.wait(30000)) return {};
    return spy.takeFirst();
}

void TestDerivationView::lesson1Renders()
{
    const SceneDef scene = lessonScene(QStringLiteral("01-one-step"));
    const DerivationDocument doc =
        buildLessonDerivation(traceOfStep(scene, 0), scene, lessonDir(QStringLiteral("01-one-step")));
    const QList<QVariant> args = show(doc.html);
    QCOMPARE(args.size(), 2);
    const int katex = args[0].toInt();
    const int errors = args[1].toInt();
    // Every .tex element became one .katex: the rows and the inline math of the page.
    const int texElements = evaluate(*view_, QStringLiteral("document.querySelectorAll('.tex').length")).toInt();
    QVERIFY2(katex >= 20, qPrintable(QString::number(katex)));
    QCOMPARE(katex, texElements);
    QCOMPARE(errors, 0);
    QCOMPARE(evaluate(*view_, QStringLiteral("document.compatMode")).toString(), QStringLiteral("CSS1Compat"));
    // omega = (-2.4, 4.918033, -1.764706) as KaTeX drew it (its minus is U+2212).
    const QString text = renderedText(*view_);
    for (const QString& number : {QStringLiteral("\u22122.4"), QStringLiteral("4.918033"), QStringLiteral("\u22121.764706")}) {
        QVERIFY2(text.contains(number), qPrintable(number));
    }
    // A normal row fits the 500 px dock: the page itself does not scroll sideways.
    QVERIFY(evaluate(*view_, QStringLiteral("document.documentElement.scrollWidth <= document.documentElement.clientWidth"))
                .toBool());
    saveScreenshot(*view_, QStringLiteral("deriv_lesson01.png"));
}

void TestDerivationView::brokenFormulaIsCounted()
{
    // Negative control for errorCount == 0 above: KaTeX cannot parse \frac{1}{.
    const QString html = derivationPage(rowHtml(QStringLiteral("x = \\frac{1}{")) + rowHtml(QStringLiteral("y = 2")),
                                        QStringLiteral("broken"));
    const QList<QVariant> args = show(html);
    QCOMPARE(args.size(), 2);
    QVERIFY(args[1].toInt() >= 1);
    QCOMPARE(args[0].toInt(), 1);   // the good formula still renders
}

void TestDerivationView::lesson3CollisionStep()
{
    // J = 4 / (0.5 + 1 + 0.1875 + 0) = 64/27 (lessons/03-two-box-collision/lesson.md).
    const SceneDef scene = lessonScene(QStringLiteral("03-two-box-collision"));
    const DerivationDocument doc =
        buildLessonDerivation(traceOfStep(scene, 2), scene, lessonDir(QStringLiteral("03-two-box-collision")));
    const QList<QVariant> args = show(doc.html);
    QCOMPARE(args.size(), 2);
    QCOMPARE(args[1].toInt(), 0);
    const QString text = renderedText(*view_);
    for (const QString& part : {QStringLiteral("0.5+1+0.1875+0"), QStringLiteral("1.6875"), QStringLiteral("2.37037")}) {
        QString squeezed = text;
        squeezed.remove(QChar(0x200b)).remove(QLatin1Char(' '));
        QVERIFY2(squeezed.contains(part), qPrintable(part));
    }
    saveScreenshot(*view_, QStringLiteral("deriv_lesson03.png"));
    // The impulse itself, scrolled to the top of the view.
    QVERIFY(evaluate(*view_, QStringLiteral("(function () { var h = Array.from(document.querySelectorAll('h3'))"
                                            ".find(function (e) { return e.textContent.indexOf('The impulse J') >= 0; });"
                                            " if (!h) return false; h.scrollIntoView(); return true; })()"))
                .toBool());
    QTest::qWait(300);
    saveScreenshot(*view_, QStringLiteral("deriv_lesson03_impulse.png"));
}

void TestDerivationView::exportHtml()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("step.html"));
    QString error;
    // Nothing rendered yet: a clear refusal.
    QVERIFY(!view_->exportHtml(path, &error));
    QVERIFY(error.contains(QLatin1String("not rendered")));

    const SceneDef scene = lessonScene(QStringLiteral("01-one-step"));
    const QList<QVariant> args = show(
        buildLessonDerivation(traceOfStep(scene, 0), scene, lessonDir(QStringLiteral("01-one-step"))).html);
    QCOMPARE(args.size(), 2);
    QVERIFY2(view_->exportHtml(path, &error), qPrintable(error));
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QString html = QString::fromUtf8(f.readAll());
    QVERIFY(html.startsWith(QLatin1String("<!DOCTYPE html>")));
    QVERIFY(!html.contains(QLatin1String("<script"), Qt::CaseInsensitive));
    QVERIFY(html.contains(QLatin1String("class=\"katex-html\"")));
    QVERIFY(html.contains(QLatin1String("url(data:font/woff2;base64,")));
    QVERIFY(!html.contains(QLatin1String("file:///")));
    const QString keep = qEnvironmentVariable("RBW_SCREENSHOT_DIR");
    if (!keep.isEmpty()) QFile::copy(path, keep + QStringLiteral("/deriv_export.html"));
}

void TestDerivationView::exportPdf()
{
    const SceneDef scene = lessonScene(QStringLiteral("01-one-step"));
    QCOMPARE(show(buildLessonDerivation(traceOfStep(scene, 0), scene, lessonDir(QStringLiteral("01-one-step"))).html).size(),
             2);
    QTemporaryDir dir;
    const QString keep = qEnvironmentVariable("RBW_SCREENSHOT_DIR");
    const QString path = keep.isEmpty() ? dir.filePath(QStringLiteral("step.pdf")) : keep + QStringLiteral("/deriv.pdf");
    QFile::remove(path);
    QSignalSpy spy(view_, &DerivationView::pdfExported);
    view_->exportPdf(path);
    QVERIFY(spy.wait(30000));
    QCOMPARE(spy.first().at(0).toString(), path);
    QVERIFY(spy.first().at(1).toBool());
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QVERIFY(f.size() > 1000);
    QCOMPARE(f.read(5), QByteArray("%PDF-"));
}

// The right-click menu is Copy and Select all, never the browser's Back, Forward or
// Reload (Back showed an earlier step's page, issue 20).
void TestDerivationView::noBrowserMenu()
{
    DerivationView view;
    QCOMPARE(view.contextMenuPolicy(), Qt::ActionsContextMenu);
    const QList<QAction*> actions = view.actions();
    QCOMPARE(actions.size(), 2);
    QVERIFY(actions.contains(view.pageAction(QWebEnginePage::Copy)));
    QVERIFY(actions.contains(view.pageAction(QWebEnginePage::SelectAll)));
    for (const QWebEnginePage::WebAction a : {QWebEnginePage::Back, QWebEnginePage::Forward, QWebEnginePage::Reload}) {
        QVERIFY(!actions.contains(view.pageAction(a)));
    }
}

int main(int argc, char** argv)
{
    // QtWebEngine shares OpenGL contexts with the widgets: set before the application.
    QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QApplication app(argc, argv);
    TestDerivationView test;
    return QTest::qExec(&test, argc, argv);
}

#include "tst_derivation_view.moc"
