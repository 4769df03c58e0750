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
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QTemporaryDir>

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
    void afterABlowUp();
    void aStepNoLongerKeptIsSaid();
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


// Lesson 1 with a force of 1e153 N at the centre in every step (x0 = 0, so the point
// (0, 0, 0) is the centre: no torque) and the energy-jump check off: v grows by
// h F / M = 1e153 m/s a step and the kinetic energy M v²/2 = v² overflows once
// v > 1.34e154, in step 13 (v_14 = 1.4e154); steps 0..12 are kept. After the blow-up
// the world is at step 14 (its numbers are not results) and the history ends at 13:
// the scrubber said "step 14 of 13" (issue 20, item 7).
void TestHistoryScrubber::afterABlowUp()
{
    QTemporaryDir dir;
    QFile lesson(QStringLiteral(RBW_SOURCE_DIR "/lessons/01-one-step/scene.json"));
    QVERIFY(lesson.open(QIODevice::ReadOnly));
    QJsonObject scene = QJsonDocument::fromJson(lesson.readAll()).object();
    scene.insert("forces", QJsonArray{QJsonObject{{"body", "box"},
                                                  {"point", QJsonArray{0, 0, 0}},
                                                  {"force", QJsonArray{1e153, 0, 0}},
                                                  {"from_step", 0},
                                                  {"to_step", 100}}});
    scene.insert("energy_jump", QJsonObject{{"factor", 0}});
    QFile out(dir.filePath("blows.json"));
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(QJsonDocument(scene).toJson());
    out.close();

    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openSceneFile(out.fileName()));
    HistoryScrubber* scrubber = w.historyScrubber();
    for (int i = 0; i < 40 && w.world()->status().ok; ++i) {
        w.stepOnce();
        // negative control: until the blow-up the label is the world's step
        if (w.world()->status().ok) QCOMPARE(scrubber->label()->text(), QStringLiteral("after step k = %1 · %2 of %2 steps").arg(w.world()->stepIndex() - 1).arg(w.world()->stepIndex()));
    }
    QVERIFY(!w.world()->status().ok);
    const long kept = w.session()->history().lastStep();
    QCOMPARE(kept, 13L);
    QCOMPARE(w.world()->stepIndex(), kept + 1);
    QCOMPARE(scrubber->label()->text(), QStringLiteral("after step k = 12 · 13 of 13 steps · the next step blew up"));
    QCOMPARE(scrubber->slider()->value(), 13);
    QCOMPARE(scrubber->stepBox()->value(), 13);
    // Go to a kept step: the state there, and the run may go on from it.
    scrubber->stepBox()->setValue(5);
    QTest::mouseClick(scrubber->goButton(), Qt::LeftButton);
    QCOMPARE(w.world()->stepIndex(), 5L);
    QVERIFY(w.world()->status().ok);
    QCOMPARE(scrubber->label()->text(), QStringLiteral("after step k = 4 · 5 of 13 steps"));
}

// Lesson 1 (one box) keeps the last 1000 steps: after 1100, steps 0..99 are gone.
// "Go to step 3" says so beside the slider, and the world stays where it is.
void TestHistoryScrubber::aStepNoLongerKeptIsSaid()
{
    MainWindow w;
    w.resize(1366, 768);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("01-one-step"));
    QCOMPARE(w.session()->advance(1100, 1e9), 1100);
    HistoryScrubber* scrubber = w.historyScrubber();
    QCOMPARE(w.session()->history().firstStep(), 100L);
    QCOMPARE(scrubber->label()->text(), QStringLiteral("after step k = 1099 · 1100 of 1100 steps (from n = 100)"));
    QVERIFY(!scrubber->note()->isVisible());
    scrubber->stepBox()->setValue(3);
    QTest::mouseClick(scrubber->goButton(), Qt::LeftButton);
    QCOMPARE(w.world()->stepIndex(), 1100L);
    QVERIFY(scrubber->note()->isVisible());
    QCOMPARE(scrubber->note()->text(), QStringLiteral("n = 3 is no longer kept: the history keeps the last 1000 steps (from n = 100)"));
    QVERIFY(scrubber->note()->width() >= scrubber->note()->fontMetrics().horizontalAdvance("n = 3 is no longer kept") ||
            scrubber->note()->height() > scrubber->note()->fontMetrics().height());   // on screen, not squeezed away
    // A kept step goes, and the note goes with the new request.
    scrubber->stepBox()->setValue(500);
    QTest::mouseClick(scrubber->goButton(), Qt::LeftButton);
    QCOMPARE(w.world()->stepIndex(), 500L);
    QVERIFY(!scrubber->note()->isVisible());
}

RBW_WINDOW_TEST_MAIN(TestHistoryScrubber)

#include "tst_history_scrubber.moc"
