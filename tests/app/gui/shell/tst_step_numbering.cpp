// One step numbering on every screen (issue 20 item 7; docs/user-guide.md, "Step
// numbers"; app/core/step_numbering.h): steps are numbered k = 0, 1, 2, ...; step k
// takes the state at t_k to t_{k+1}; after n steps the time is t_n and the screen
// shows the last step taken, step k = n - 1. Lesson 3 after its 3 steps: the 3D view's
// top line, the history slider, the status bar, the derivation's heading, Check my
// numbers and the quantities table's columns all name step k = 2, from t₂ to t₃;
// after Step back, all name k = 1 (negative control: nothing still says k = 2).
#include "app/gui/shell/history_scrubber.h"
#include "app/gui/shell/main_window.h"
#include "tests/app/gui/shell/window_test_support.h"

#include <QDockWidget>
#include <QLabel>
#include <QSettings>
#include <QSlider>
#include <QSpinBox>
#include <QStandardPaths>
#include <QtTest>

using namespace rbw;
using namespace rbw::test;

class TestStepNumbering : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }
    void everyScreenNamesTheSameStep_data();
    void everyScreenNamesTheSameStep();
};

void TestStepNumbering::everyScreenNamesTheSameStep_data()
{
    QTest::addColumn<int>("taken");   // n: steps taken (lesson 3 has "steps": 3)
    QTest::addColumn<int>("back");    // then Step back this often
    QTest::newRow("3 steps: step k = 2, t2 to t3") << 3 << 0;
    QTest::newRow("3 steps, 1 back: step k = 1, t1 to t2") << 3 << 1;
}

void TestStepNumbering::everyScreenNamesTheSameStep()
{
    QFETCH(int, taken);
    QFETCH(int, back);
    MainWindow w;
    w.resize(1600, 1000);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("03-two-box-collision"));
    for (int i = 0; i < taken; ++i) w.stepOnce();
    for (int i = 0; i < back; ++i) w.stepBack();
    const int n = taken - back;   // the state shown is t_n, after step k = n - 1
    const int k = n - 1;
    QCOMPARE(w.world()->stepIndex(), long(n));
    auto t = [](int i) { return QStringLiteral("t") + QChar(0x2080 + i); };   // t₂ (i < 10)
    const QString stepK = QStringLiteral("step k = %1").arg(k);
    const QString wrongK = QStringLiteral("step k = %1").arg(n);   // the count read as a step number
    w.findChild<QDockWidget*>("checkDock")->raise();
    QApplication::processEvents();

    // The 3D view's top line: the step just taken and the time it led to.
    const QString overlay = w.sceneView()->infoText();
    QVERIFY2(overlay.startsWith(QStringLiteral("after %1 · %2 = ").arg(stepK, t(n))), qPrintable(overlay));
    // The slider (its positions are states, n) and the Go to box.
    HistoryScrubber* scrubber = w.historyScrubber();
    QCOMPARE(scrubber->label()->text(), QStringLiteral("after %1 · %2 of %3 steps").arg(stepK).arg(n).arg(taken));
    QCOMPARE(scrubber->slider()->value(), n);
    QCOMPARE(scrubber->stepBox()->value(), n);
    // The status bar: n steps taken, at t_n.
    const QString status = w.findChild<QLabel*>("statusLabel")->text();
    QVERIFY2(status.contains(QStringLiteral(" · %1 steps taken · %2 = ").arg(n).arg(t(n))), qPrintable(status));
    // Check my numbers' header.
    const QString check = w.findChild<QLabel*>("checkHeader")->text();
    QVERIFY2(check.contains(QStringLiteral("%1 (%2 → %3)").arg(stepK, t(k), t(n))), qPrintable(check));
    // The quantities table's columns: the step's two times.
    QCOMPARE(w.traceModel()->headerData(TraceModel::BeforeColumn, Qt::Horizontal).toString(),
             QStringLiteral("Before, %1").arg(t(k)));
    QCOMPARE(w.traceModel()->headerData(TraceModel::ValueColumn, Qt::Horizontal).toString(),
             QStringLiteral("After, %1").arg(t(n)));
    // The derivation's heading.
    w.findChild<QDockWidget*>("derivationDock")->raise();
    w.refreshDerivation();
    QVERIFY(waitRendered(w.derivationView()));
    QString page;
    QTRY_VERIFY_WITH_TIMEOUT((page = pageText(w.derivationView())).contains(QStringLiteral("%1, from %2 = ").arg(stepK, t(k))), 10000);
    QVERIFY2(page.contains(QStringLiteral(" to %1 = ").arg(t(n))), qPrintable(page.left(400)));
    // Negative control: no screen reads the count n as the step's number.
    for (const QString& text : {overlay, scrubber->label()->text(), status, check, page}) {
        QVERIFY2(!text.contains(wrongK), qPrintable(text.left(300)));
    }
}

RBW_WINDOW_TEST_MAIN(TestStepNumbering)

#include "tst_step_numbering.moc"
