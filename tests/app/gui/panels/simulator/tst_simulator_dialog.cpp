// Tools → Compare with my simulator (app/gui/panels/simulator/, issue 23): the dialog
// runs the shipped reference simulator (examples/simulator/, target
// rbw_reference_simulator) with one --mistake switched on and must show, on screen,
// what the real rbw binary says about the same program (rbw diagnose --format json,
// an independent front end over the same code): the verdict, the mistake's id with
// its equation from the checker's catalogue, and the first divergence (probe, step,
// body, quantity, expected, given), highlighted in the probe's step table and
// selected by the answer slider. Negative control: the program without a mistake
// matches and nothing is highlighted in any probe. Bad programs show rbw diagnose's
// own message in the dialog. Cancel stops a hanging program: no child is left.
#include "app/gui/panels/simulator/simulator_dialog.h"
#include "app/gui/panels/simulator/simulator_result_view.h"
#include "app/gui/shell/main_window.h"
#include "physics/workbook/checker/mistakes.h"
#include "tests/app/gui/shell/window_test_support.h"
#include "tests/test_support.h"

#include <QAction>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

using namespace rbw;

namespace {

const QString kReference = QStringLiteral(RBW_REFERENCE_SIMULATOR_PATH);
constexpr int kRunMs = 120000;

// The numbers as the dialog writes them: "(a, b, c)", 9 significant digits.
QString numbers(const QJsonArray& a)
{
    QStringList parts;
    for (const QJsonValue& v : a) parts << QString::number(v.toDouble(), 'g', 9);
    return '(' + parts.join(", ") + ')';
}

bool runAndWait(SimulatorDialog& dialog)
{
    QSignalSpy done(&dialog, &SimulatorDialog::checkFinished);
    if (!dialog.run()) return false;
    return done.wait(kRunMs) && !dialog.isRunning();
}

// Rows of the step table drawn with the divergence background.
QList<int> highlightedRows(const QTableWidget* steps)
{
    QList<int> rows;
    for (int r = 0; r < steps->rowCount(); ++r) {
        if (steps->item(r, 5)->background().style() != Qt::NoBrush) rows << r;
    }
    return rows;
}

bool running(qint64 pid)
{
    QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!stat.open(QIODevice::ReadOnly)) return false;
    const QByteArray text = stat.readAll();
    const qsizetype close = text.lastIndexOf(')');
    return close >= 0 && close + 2 < text.size() && text[close + 2] != 'Z';
}

} // namespace

class TestSimulatorDialog : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void mistakeOnScreen_data();
    void mistakeOnScreen();
    void matchesHasNoDivergence();
    void badProgramShowsTheCliMessage_data();
    void badProgramShowsTheCliMessage();
    void cancelStopsTheProgram();
    void toolsMenuOpensTheDialog();
    void lessonsPointAtIt();
};

void TestSimulatorDialog::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QVERIFY2(QFile::exists(kReference), qPrintable(kReference));
}

void TestSimulatorDialog::mistakeOnScreen_data()
{
    QTest::addColumn<QString>("options");   // the reference simulator's
    QTest::addColumn<QString>("group");     // --probes
    QTest::addColumn<QString>("id");        // the mistake the verdict must name
    QTest::newRow("transposed-inertia") << "--mistake transposed-inertia" << "motion" << "transposed-inertia";
    QTest::newRow("lever-arm-from-origin") << "--mistake lever-arm-from-origin" << "motion" << "lever-arm-from-origin";
    QTest::newRow("impulse-linear-only, c = 0.35")
        << "--restitution 0.35 --mistake impulse-linear-only" << "collision" << "impulse-linear-only";
}

void TestSimulatorDialog::mistakeOnScreen()
{
    QFETCH(QString, options);
    QFETCH(QString, group);
    QFETCH(QString, id);
    const QString command = kReference + " " + options;
    const rbw::test::RbwRun cli =
        rbw::test::runRbw({"diagnose", "--simulator", command, "--probes", group, "--format", "json"});
    QCOMPARE(cli.exitCode, 1);
    const QJsonObject doc = QJsonDocument::fromJson(cli.out).object();
    QCOMPARE(doc.value("verdict").toString(), QStringLiteral("explained"));
    QCOMPARE(doc.value("mistakes").toArray(), QJsonArray{id});

    SimulatorDialog dialog;
    dialog.show();
    dialog.setCommand(command);
    dialog.setProbeGroup(probes::probeGroupNamed(group.toStdString()));
    QVERIFY(runAndWait(dialog));
    SimulatorResultView* view = dialog.resultView();
    QVERIFY2(view->errorText().isEmpty(), qPrintable(view->errorText()));

    // the verdict and the mistake with its equation, on screen
    const auto* verdict = dialog.findChild<QLabel*>("verdictLabel");
    QVERIFY(verdict->isVisible());
    QVERIFY2(verdict->text().startsWith("Verdict: explained — "), qPrintable(verdict->text()));
    const QString details = view->detailsText();
    const MistakeInfo* info = findMistake(id.toStdString());
    QVERIFY(info != nullptr);
    QVERIFY2(details.contains(id) && details.contains(QString::fromLatin1(info->equation)), qPrintable(details));
    QVERIFY2(details.contains(QString::fromLatin1(info->explanation)), qPrintable(details));
    if (group == "collision") {
        // c is fitted to the answers: the same number as rbw's
        const QJsonObject fit = doc.value("restitution").toArray().first().toObject();
        QVERIFY2(details.contains("c = " + QString::number(fit.value("c").toDouble(), 'g', 6)), qPrintable(details));
    }

    // the first divergence in words, as rbw names it
    const QJsonObject f = doc.value("first_divergence").toObject();
    const int probe = f.value("probe").toInt() - 1;
    // rbw's "step" is the steps taken before the answer, n; the dialog words the state as
    // every screen of the app does (app/core/step_numbering.h): after step k = n - 1
    const int n = f.value("step").toInt();
    const QString state = n > 0 ? QStringLiteral("after step k = %1").arg(n - 1) : QStringLiteral("before step k = 0");
    const QString words = QStringLiteral("probe %1 (%2), %3, body %4, %5: expected %6, yours %7")
                              .arg(probe + 1)
                              .arg(f.value("probe_name").toString())
                              .arg(state)
                              .arg(f.value("body").toInt())
                              .arg(SimulatorResultView::quantityWords(f.value("quantity").toString().toStdString()),
                                   numbers(f.value("expected").toArray()), numbers(f.value("given").toArray()));
    QVERIFY2(details.contains("First divergence from the right algorithm: " + words), qPrintable(details));
    // never the old count of steps taken as a step number ("step 1" for the state after step k = 0)
    QVERIFY2(!details.contains(QStringLiteral("), step %1,").arg(n)), qPrintable(details));

    // the probe of the divergence is selected, its step table highlights one row, the
    // one the slider selected, with rbw's expected and given side by side
    QCOMPARE(view->selectedProbe(), probe);
    QVERIFY(dialog.findChild<QLabel*>("probeDivergenceLabel")->text().contains(words));
    const auto* steps = dialog.findChild<QTableWidget*>("stepsTable");
    const QList<int> rows = highlightedRows(steps);
    QCOMPARE(rows.size(), 1);
    QCOMPARE(steps->currentRow(), rows.first());
    QCOMPARE(steps->horizontalHeaderItem(1)->text(), QStringLiteral("State"));
    QCOMPARE(steps->item(rows.first(), 1)->text(), state);
    QCOMPARE(steps->item(rows.first(), 2)->text(), QString::number(f.value("body").toInt()));
    QCOMPARE(steps->item(rows.first(), 4)->text(), numbers(f.value("expected").toArray()));
    QCOMPARE(steps->item(rows.first(), 5)->text(), numbers(f.value("given").toArray()));
    auto* slider = dialog.findChild<QSlider*>("stepSlider");
    QCOMPARE(steps->item(rows.first(), 0)->text(), QString::number(slider->value()));
    const QString sliderText = dialog.findChild<QLabel*>("stepSliderLabel")->text();
    QVERIFY2(sliderText == QStringLiteral("answer %1 · %2 · body %3").arg(slider->value()).arg(state).arg(f.value("body").toInt()),
             qPrintable(sliderText));

    // the slider moves the selection; "Go to the first divergence" comes back
    slider->setValue(0);
    QCOMPARE(steps->item(steps->currentRow(), 0)->text(), QStringLiteral("0"));
    QTest::mouseClick(dialog.findChild<QPushButton*>("divergenceButton"), Qt::LeftButton);
    QCOMPARE(steps->currentRow(), rows.first());

    // every probe's verdict as rbw's
    const auto* table = dialog.findChild<QTableWidget*>("probesTable");
    const QJsonArray probesJson = doc.value("probes").toArray();
    QCOMPARE(table->rowCount(), probesJson.size());
    for (int p = 0; p < table->rowCount(); ++p) {
        QCOMPARE(table->item(p, 1)->text(),
                 probesJson[p].toObject().value("matches").toBool() ? QStringLiteral("matches") : QStringLiteral("differs"));
    }
}

// Negative control: the right simulator matches, every probe, nothing highlighted.
void TestSimulatorDialog::matchesHasNoDivergence()
{
    SimulatorDialog dialog;
    dialog.show();
    dialog.setCommand(kReference);
    QVERIFY(runAndWait(dialog));
    SimulatorResultView* view = dialog.resultView();
    QVERIFY2(view->verdictText().startsWith("Verdict: matches — "), qPrintable(view->verdictText()));
    QVERIFY(!view->detailsText().contains("First divergence"));
    QVERIFY(view->detailsText().contains("No divergence"));
    QVERIFY(view->detailsText().contains("public tests"));   // all probes: the template's tests ran too
    const auto* table = dialog.findChild<QTableWidget*>("probesTable");
    const auto* steps = dialog.findChild<QTableWidget*>("stepsTable");
    QVERIFY(table->rowCount() > 0);
    for (int p = 0; p < table->rowCount(); ++p) {
        view->selectProbe(p);
        QCOMPARE(table->item(p, 1)->text(), QStringLiteral("matches"));
        QVERIFY(steps->rowCount() > 0);
        QVERIFY(highlightedRows(steps).isEmpty());
        QVERIFY(!dialog.findChild<QPushButton*>("divergenceButton")->isEnabled());
    }
}

void TestSimulatorDialog::badProgramShowsTheCliMessage_data()
{
    QTest::addColumn<QString>("command");
    QTest::newRow("not found") << "/nonexistent/rbw-simulator";
    QTest::newRow("nan") << kReference + " --fail nan";
    QTest::newRow("exits") << kReference + " --fail exit";
    QTest::newRow("garbage") << kReference + " --fail garbage";
    QTest::newRow("empty") << "   ";
}

// The dialog shows the sentence rbw diagnose prints on standard error (after its
// "rbw: diagnose: " prefix), and no verdict.
void TestSimulatorDialog::badProgramShowsTheCliMessage()
{
    QFETCH(QString, command);
    const rbw::test::RbwRun cli = rbw::test::runRbw({"diagnose", "--simulator", command, "--probes", "motion"});
    QCOMPARE(cli.exitCode, 2);
    const QString prefix = QStringLiteral("rbw: diagnose: ");
    const QString firstLine = cli.err.section('\n', 0, 0);
    QVERIFY2(firstLine.startsWith(prefix), qPrintable(cli.err));
    const QString message = firstLine.mid(prefix.size());
    QVERIFY(!message.isEmpty());

    SimulatorDialog dialog;
    dialog.show();
    dialog.setCommand(command);
    dialog.setProbeGroup(probes::ProbeGroup::Motion);
    QVERIFY(runAndWait(dialog));
    const auto* error = dialog.findChild<QLabel*>("errorLabel");
    QVERIFY(error->isVisible());
    QVERIFY2(error->text().startsWith(message), qPrintable(error->text() + "\n---\n" + message));
    QVERIFY(!dialog.findChild<QLabel*>("verdictLabel")->isVisible());
    QCOMPARE(dialog.findChild<QTableWidget*>("probesTable")->rowCount(), 0);
}

// A program that hangs after its first step: Cancel ends the run at once, long before
// the timeout, and the program (which wrote its pid) is gone.
void TestSimulatorDialog::cancelStopsTheProgram()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString pidFile = dir.filePath("pid");
    const QString script = dir.filePath("hang.sh");
    QFile f(script);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(QStringLiteral("#!/bin/sh\necho $$ > '%1'\nexec '%2' --fail hang\n").arg(pidFile, kReference).toUtf8());
    f.close();
    QVERIFY(f.setPermissions(QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner));

    SimulatorDialog dialog;
    dialog.show();
    dialog.setCommand(script);
    dialog.setTimeoutSeconds(60);
    QSignalSpy done(&dialog, &SimulatorDialog::checkFinished);
    QVERIFY(dialog.run());
    QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(pidFile) && QFile(pidFile).size() > 0, 20000);
    QFile pf(pidFile);
    QVERIFY(pf.open(QIODevice::ReadOnly));
    const qint64 pid = pf.readAll().trimmed().toLongLong();
    QVERIFY(pid > 0);
    QTest::qWait(200);   // it answers nothing now: the run waits
    QVERIFY(dialog.isRunning());
    QVERIFY(running(pid));
    QElapsedTimer clock;
    clock.start();
    QTest::mouseClick(dialog.findChild<QPushButton*>("cancelButton"), Qt::LeftButton);
    QVERIFY(done.wait(10000));
    QVERIFY2(clock.elapsed() < 5000, qPrintable(QString::number(clock.elapsed())));   // not the 60 s timeout
    QVERIFY(dialog.outcome().run.cancelled);
    QVERIFY2(dialog.resultView()->errorText().startsWith("cancelled at probe 1"),
             qPrintable(dialog.resultView()->errorText()));
    QTRY_VERIFY_WITH_TIMEOUT(!running(pid), 5000);
    QVERIFY(dialog.findChild<QPushButton*>("runButton")->isEnabled());
}

// The shell adds Tools → Compare with my simulator…, which opens the one dialog.
void TestSimulatorDialog::toolsMenuOpensTheDialog()
{
    MainWindow w;
    w.show();
    QMenu* tools = nullptr;
    for (QAction* a : w.menuBar()->actions()) {
        if (a->text() == QStringLiteral("&Tools")) tools = a->menu();
    }
    QVERIFY(tools != nullptr);
    QAction* compare = w.findChild<QAction*>("actionCompareSimulator");
    QVERIFY(compare != nullptr && tools->actions().contains(compare));
    QVERIFY(w.findChild<SimulatorDialog*>() == nullptr);
    compare->trigger();
    auto* dialog = w.findChild<SimulatorDialog*>();
    QVERIFY(dialog != nullptr);
    QTRY_VERIFY(dialog->isVisible());
    dialog->close();
    compare->trigger();
    QCOMPARE(w.findChildren<SimulatorDialog*>().size(), 1);
}

// Lessons 1 and 8 send the student to the menu item by the words the menu shows.
void TestSimulatorDialog::lessonsPointAtIt()
{
    MainWindow w;
    QString menuPath;
    for (QAction* a : w.menuBar()->actions()) {
        if (a->menu() != nullptr && a->menu()->actions().contains(w.findChild<QAction*>("actionCompareSimulator"))) {
            menuPath = a->text().remove('&') + " → " +
                       w.findChild<QAction*>("actionCompareSimulator")->text().remove('&').remove("…");
        }
    }
    QCOMPARE(menuPath, QStringLiteral("Tools → Compare with my simulator"));
    for (const char* lesson : {"01-one-step", "08-conventions"}) {
        QFile f(QStringLiteral(RBW_SOURCE_DIR "/lessons/%1/lesson.md").arg(QLatin1String(lesson)));
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY2(QString::fromUtf8(f.readAll()).contains("**" + menuPath + "**"), lesson);
    }
}

RBW_WINDOW_TEST_MAIN(TestSimulatorDialog)

#include "tst_simulator_dialog.moc"
