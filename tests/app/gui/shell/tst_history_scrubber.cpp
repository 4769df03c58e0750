// The history scrubber in the whole window under Xvfb (issue 12): any recorded step
// exactly as `rbw run --steps N` prints it, bit for bit; the slider's range follows
// the history; and the keys step and play again after a box of the parameter bar or
// the scrubber was edited.
#include "app/gui/shell/main_window.h"
#include "tests/app/gui/shell/window_test_support.h"
#include "tests/test_support.h"

#include <QAction>
#include <QDockWidget>
#include <QSettings>
#include <QStandardPaths>
#include <QtTest>
#include "app/core/session.h"
#include "app/gui/shell/history_scrubber.h"
#include "app/gui/shell/parameter_bar.h"
#include "tests/app/gui/shell/rbw_compare.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>

using namespace rbw;
using namespace rbw::test;

class TestHistoryScrubber : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void scrubToStep400OfLesson4();
    void stepBackThenStepInLesson11();
    void scrubberRangeFollowsTheHistory();
    void keysReturnToTheViewAfterEditing_data();
    void keysReturnToTheViewAfterEditing();
    void keysReturnToTheViewAfterEditingH();
};

void TestHistoryScrubber::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);   // QSettings go to a test location
    QSettings().clear();
    Warnings::install();
}

void TestHistoryScrubber::scrubToStep400OfLesson4()
{
    MainWindow w;
    w.resize(1600, 1000);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("04-many-boxes"));
    HistoryScrubber* scrubber = w.historyScrubber();
    QVERIFY(scrubber != nullptr);

    // "Go to step 600": beyond the recording, so the app steps on to it.
    scrubber->stepBox()->setValue(600);
    QTest::mouseClick(scrubber->goButton(), Qt::LeftButton);
    QCOMPARE(w.world()->stepIndex(), 600L);
    QCOMPARE(scrubber->slider()->maximum(), 600);

    // Drag the slider back to 400: the state and trace there are rbw's after 400 steps.
    scrubber->slider()->setValue(400);
    QCOMPARE(w.world()->stepIndex(), 400L);
    const QJsonObject at400 = rbwRun("04-many-boxes/scene.json", 400, "last");
    QVERIFY(!at400.isEmpty());
    QString diff = compareWithRbw(*w.world(), w.session()->currentTrace(), at400);
    QVERIFY2(diff.isEmpty(), qPrintable(diff));
    // Negative control: step 401's trace is not step 400's.
    const QJsonObject at401 = rbwRun("04-many-boxes/scene.json", 401, "last");
    QVERIFY(!compareWithRbw(*w.world(), w.session()->currentTrace(), at401).isEmpty());

    // The later history is still there: forward to 600 and back to 400 again.
    QCOMPARE(scrubber->slider()->maximum(), 600);
    scrubber->slider()->setValue(600);
    QCOMPARE(w.world()->stepIndex(), 600L);
    scrubber->slider()->setValue(400);
    diff = compareWithRbw(*w.world(), w.session()->currentTrace(), at400);
    QVERIFY2(diff.isEmpty(), qPrintable(diff));

    // Escape in the step box drops what was typed and gives the keys back to the view.
    QApplication::setActiveWindow(&w);
    scrubber->stepBox()->setFocus();
    QTRY_VERIFY(scrubber->stepBox()->hasFocus());
    QTest::keyClicks(scrubber->stepBox(), "12");
    QTest::keyClick(scrubber->stepBox(), Qt::Key_Escape);
    QTRY_VERIFY(w.sceneView()->hasFocus());
    QCOMPARE(w.world()->stepIndex(), 400L);
    QCOMPARE(scrubber->stepBox()->value(), 400);

    // Stepping on from 400 discards 401..600 (editor undo) and computes step 400 anew,
    // which is rbw's step 401.
    w.stepOnce();
    QCOMPARE(w.world()->stepIndex(), 401L);
    QCOMPARE(scrubber->slider()->maximum(), 401);
    diff = compareWithRbw(*w.world(), w.session()->currentTrace(), at401);
    QVERIFY2(diff.isEmpty(), qPrintable(diff));
}

// Issue 19: Step back then Step in a manifold scene shows the same numbers as the
// first time. Lesson 11's box lands and rests on four contact points whose
// warm-start impulses carry over from step to step; the snapshot holds them, so
// step 31 recomputed after Step back is bit for bit rbw's step 31 (before the
// snapshot held the cache, body 0's v differed in the fourth digit).
void TestHistoryScrubber::stepBackThenStepInLesson11()
{
    MainWindow w;
    w.resize(1600, 1000);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("11-resting-contact"));
    for (int k = 0; k < 31; ++k) w.stepOnce();
    QCOMPARE(w.world()->stepIndex(), 31L);
    const QJsonObject at31 = rbwRun("11-resting-contact/scene.json", 31, "last");
    QVERIFY(!at31.isEmpty());
    QString diff = compareWithRbw(*w.world(), w.session()->currentTrace(), at31);
    QVERIFY2(diff.isEmpty(), qPrintable(diff));
    // The box is in contact by then: the step's contacts carry warm-start impulses.
    QVERIFY(w.world()->contactState().cache.bytes() > 0);

    for (int back = 0; back < 3; ++back) w.stepBack();
    QCOMPARE(w.world()->stepIndex(), 28L);
    // Step again: the recorded 29..31 are discarded and recomputed from the snapshot.
    for (int k = 0; k < 3; ++k) w.stepOnce();
    QCOMPARE(w.world()->stepIndex(), 31L);
    diff = compareWithRbw(*w.world(), w.session()->currentTrace(), at31);
    QVERIFY2(diff.isEmpty(), qPrintable(diff));
    // Negative control: step 30's numbers are not step 31's.
    const QJsonObject at30 = rbwRun("11-resting-contact/scene.json", 30, "last");
    QVERIFY(!compareWithRbw(*w.world(), w.session()->currentTrace(), at30).isEmpty());
}

void TestHistoryScrubber::scrubberRangeFollowsTheHistory()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("05-spinning"));
    QSlider* slider = w.historyScrubber()->slider();
    QCOMPARE(slider->minimum(), 0);
    QCOMPARE(slider->maximum(), 0);
    for (int k = 0; k < 5; ++k) w.stepOnce();
    QCOMPARE(slider->maximum(), 5);
    QCOMPARE(slider->value(), 5);
    w.stepBack();
    QCOMPARE(slider->value(), 4);
    QCOMPARE(slider->maximum(), 5);   // step 5 is still recorded
    w.resetLesson();
    QCOMPARE(slider->maximum(), 0);
}

void TestHistoryScrubber::keysReturnToTheViewAfterEditing_data()
{
    QTest::addColumn<QString>("box");
    QTest::addColumn<int>("key");
    QTest::addColumn<double>("expected");   // the box's value afterwards
    // Lesson 3 starts with c = 1 and μ = 0 (scene.json).
    QTest::newRow("c, Enter applies") << "restitutionBox" << int(Qt::Key_Return) << 0.5;
    QTest::newRow("c, Escape discards") << "restitutionBox" << int(Qt::Key_Escape) << 1.0;
    QTest::newRow("mu, Enter applies") << "frictionBox" << int(Qt::Key_Enter) << 0.5;
    QTest::newRow("mu, Escape discards") << "frictionBox" << int(Qt::Key_Escape) << 0.0;
}

void TestHistoryScrubber::keysReturnToTheViewAfterEditing()
{
    QFETCH(QString, box);
    QFETCH(int, key);
    QFETCH(double, expected);
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QApplication::setActiveWindow(&w);
    QVERIFY(w.openLesson("03-two-box-collision"));
    auto* spin = w.parameterBar()->findChild<QDoubleSpinBox*>(box);
    QVERIFY(spin != nullptr);
    spin->setFocus();
    QTRY_VERIFY(spin->hasFocus());
    spin->selectAll();
    QTest::keyClicks(spin, "0.5");
    // Negative control: while the box has the focus, S is typed into it, no step.
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_S);
    QCOMPARE(w.world()->stepIndex(), 0L);
    QTest::keyClick(QApplication::focusWidget(), Qt::Key(key));
    QTRY_VERIFY(w.sceneView()->hasFocus());
    QCOMPARE(spin->value(), expected);
    const SceneDef& scene = w.world()->scene();
    QCOMPARE(box == "restitutionBox" ? scene.restitution : scene.friction, expected);
    // The keys step, play and step back again.
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_S);
    QCOMPARE(w.world()->stepIndex(), 1L);
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Right);
    QCOMPARE(w.world()->stepIndex(), 2L);
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Left);
    QCOMPARE(w.world()->stepIndex(), 1L);
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Space);
    QTRY_VERIFY(w.world()->stepIndex() > 1L);
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Space);   // pause
}

// The same for h, an editable list: Enter applies the typed h, Escape drops it.
void TestHistoryScrubber::keysReturnToTheViewAfterEditingH()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QApplication::setActiveWindow(&w);
    QVERIFY(w.openLesson("05-spinning"));
    auto* box = w.parameterBar()->findChild<QComboBox*>("dtBox");
    QVERIFY(box != nullptr && box->lineEdit() != nullptr);
    const double h0 = w.world()->scene().dt;
    box->lineEdit()->setFocus();
    QTRY_VERIFY(box->lineEdit()->hasFocus());
    box->lineEdit()->selectAll();
    QTest::keyClicks(box->lineEdit(), "0.02");
    QTest::keyClick(box->lineEdit(), Qt::Key_Escape);
    QTRY_VERIFY(w.sceneView()->hasFocus());
    QCOMPARE(w.world()->scene().dt, h0);
    QCOMPARE(box->currentText(), QString::number(h0, 'g', 10));
    box->lineEdit()->setFocus();
    QTRY_VERIFY(box->lineEdit()->hasFocus());
    box->lineEdit()->selectAll();
    QTest::keyClicks(box->lineEdit(), "0.02");
    QTest::keyClick(box->lineEdit(), Qt::Key_Return);
    QTRY_VERIFY(w.sceneView()->hasFocus());
    QCOMPARE(w.world()->scene().dt, 0.02);
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_S);
    QCOMPARE(w.world()->stepIndex(), 1L);
}

RBW_WINDOW_TEST_MAIN(TestHistoryScrubber)

#include "tst_history_scrubber.moc"
