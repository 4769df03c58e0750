// Play stops at the scene's `steps` (issue 20, item 1). The test plays a real Session
// with the window's play loop (a 16 ms timer, PlaybackClock, Session::advance) and the
// SceneEndBar calls the window makes (scene_end_bar.h): Play must stop exactly at
// `steps` with "End of the scene — Reset or Continue" shown, even at "as fast as
// possible", where one tick asks for far more steps than are left; Continue plays on
// past the end; Reset goes back to step 0 and hides the bar.
#include "app/core/playback_clock.h"
#include "app/core/session.h"
#include "app/gui/panels/view/scene_end_bar.h"
#include "tests/test_support.h"

#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTimer>
#include <QVBoxLayout>
#include <QtTest>

using namespace rbw;

namespace {

// The window's Play: the same calls in the same order as MainWindow's setPlaying and
// onPlayTick with the bar's hooks.
struct Player {
    Session session;
    SceneEndBar* bar = nullptr;
    QWidget window;
    QTimer timer;
    PlaybackClock clock;

    explicit Player(double speed)
    {
        auto* layout = new QVBoxLayout(&window);
        bar = new SceneEndBar(&session);
        layout->addWidget(bar);
        clock.setSpeed(speed);
        timer.setInterval(PlaybackClock::kTickIntervalMs);
        QObject::connect(&timer, &QTimer::timeout, &timer, [this] { tick(); });
        QObject::connect(bar, &SceneEndBar::endReached, &timer, [this] { timer.stop(); });
        QObject::connect(bar, &SceneEndBar::continueRequested, &timer, [this] { play(); });
        QObject::connect(bar, &SceneEndBar::resetRequested, &timer, [this] {
            timer.stop();
            session.reset();
        });
    }
    void play()
    {
        bar->playStarted();
        clock.start();
        timer.start();
    }
    void tick()
    {
        const double h = session.world()->scene().dt;
        const int due = bar->stepsAllowed(clock.stepsDue(h));
        if (due > 0) clock.stepsTaken(due, session.advance(due, clock.budgetMs()), h);
        bar->checkEnd();
    }
};

} // namespace

class TestSceneEndBar : public QObject {
    Q_OBJECT
private slots:
    void playStopsAtTheScenesSteps_data();
    void playStopsAtTheScenesSteps();
    void stepIsNotLimited();
};

void TestSceneEndBar::playStopsAtTheScenesSteps_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<long>("steps");    // the scene file's "steps"
    QTest::addColumn<double>("speed");  // PlaybackClock: -1 as fast as possible, 0 one step a tick
    QTest::newRow("lesson 1, one step") << "01-one-step/scene.json" << 1L << 1.0;
    QTest::newRow("lesson 3, 3 steps, one a tick") << "03-two-box-collision/scene.json" << 3L << 0.0;
    QTest::newRow("lesson 6, 60 steps, as fast as possible") << "06-box-on-plane/scene.json" << 60L << -1.0;
    QTest::newRow("lesson 2, 1000 steps, as fast as possible") << "02-single-body/scene.json" << 1000L << -1.0;
}

void TestSceneEndBar::playStopsAtTheScenesSteps()
{
    QFETCH(QString, scene);
    QFETCH(long, steps);
    QFETCH(double, speed);
    Player p(speed);
    p.session.load(test::lessonScene(scene));
    p.window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&p.window));
    QCOMPARE(p.bar->endStep(), steps);
    QVERIFY(!p.bar->isVisible());

    QSignalSpy ends(p.bar, &SceneEndBar::endReached);
    p.play();
    QVERIFY(p.bar->stopsAtEnd());
    QTRY_VERIFY_WITH_TIMEOUT(!p.timer.isActive(), 20000);
    QCOMPARE(p.session.world()->stepIndex(), steps);   // exactly there, not a step past
    QCOMPARE(ends.count(), 1);
    QVERIFY(p.bar->isVisible());
    QVERIFY2(p.bar->label()->text().startsWith(QStringLiteral("End of the scene")), qPrintable(p.bar->label()->text()));
    QVERIFY(p.bar->label()->text().contains(QStringLiteral("Reset or Continue")));

    // Continue plays on past the end and does not stop there again.
    QTest::mouseClick(p.bar->continueButton(), Qt::LeftButton);
    QVERIFY(!p.bar->isVisible());
    QVERIFY(p.timer.isActive());
    QVERIFY(!p.bar->stopsAtEnd());
    QTRY_VERIFY_WITH_TIMEOUT(p.session.world()->stepIndex() >= steps + 2, 20000);
    p.timer.stop();
    QCOMPARE(ends.count(), 1);

    // Reset: step 0, the bar gone; Play stops at the end again.
    p.bar->show();
    QTest::mouseClick(p.bar->resetButton(), Qt::LeftButton);
    QCOMPARE(p.session.world()->stepIndex(), 0L);
    QVERIFY(!p.bar->isVisible());
    p.play();
    QTRY_VERIFY_WITH_TIMEOUT(!p.timer.isActive(), 20000);
    QCOMPARE(p.session.world()->stepIndex(), steps);
    QCOMPARE(ends.count(), 2);
}

void TestSceneEndBar::stepIsNotLimited()
{
    // Step and Step back are the student's own: the bar never stops them, and stepping
    // back before the end takes the note away.
    Player p(1.0);
    p.session.load(test::lessonScene("01-one-step/scene.json"));
    p.window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&p.window));
    for (int k = 0; k < 3; ++k) QVERIFY(p.session.step());
    QCOMPARE(p.session.world()->stepIndex(), 3L);
    // Play from past the end (as after Continue): it goes on.
    p.play();
    QVERIFY(!p.bar->stopsAtEnd());
    QCOMPARE(p.bar->stepsAllowed(7), 7);
    QTRY_VERIFY_WITH_TIMEOUT(p.session.world()->stepIndex() >= 5, 20000);
    p.timer.stop();
    QVERIFY(!p.bar->isVisible());
    // Negative control: a run started before the end is capped at the steps left.
    p.session.reset();
    p.bar->playStarted();
    p.timer.stop();
    QCOMPARE(p.bar->stepsAllowed(7), 1);
    QVERIFY(p.bar->checkEnd() == false);
    p.session.step();
    QVERIFY(p.bar->checkEnd());
    QVERIFY(p.bar->isVisible());
    QVERIFY(p.session.stepBack());
    QVERIFY(!p.bar->isVisible());
}

QTEST_MAIN(TestSceneEndBar)
#include "tst_scene_end_bar.moc"
