// The pacing of Play without a window: how many steps a tick of the play timer takes
// at each speed, what is left owed to real time, what happens when the session
// cannot keep up, and when the panels are due. Every expectation is worked out by
// hand in the row: debt += s Δt (Δt capped at 100 ms), steps = floor(debt / h), then
// debt -= taken h, and debt = min(debt, h) when fewer steps were taken than asked.
#include "app/core/playback_clock.h"
#include "tests/test_support.h"

#include <QtTest>

#include <limits>

using namespace rbw;

class TestPlaybackClock : public QObject {
    Q_OBJECT
private slots:
    void oneTick_data();
    void oneTick();
    void ticksInARow_data();
    void ticksInARow();
    void newSpeedDropsTheDebt();
    void startDropsTheDebt();
    void panelsDue_data();
    void panelsDue();
    void derivationOnlyWhenPaused();
    void measuredTickUsesTheWallClock();
};

void TestPlaybackClock::oneTick_data()
{
    QTest::addColumn<double>("speed");
    QTest::addColumn<double>("h");
    QTest::addColumn<double>("wallMs");
    QTest::addColumn<int>("expectedDue");
    QTest::addColumn<double>("debtBefore");   // after the tick's wall time is added
    QTest::addColumn<int>("taken");           // what the session managed in the budget
    QTest::addColumn<double>("debtAfter");

    const int all = std::numeric_limits<int>::max();
    // 1x: 16 ms owe 0.016 s = 1.6 steps of 0.01 -> 1 step, 0.006 s left.
    QTest::newRow("1x, h 0.01, 16 ms") << 1.0 << 0.01 << 16.0 << 1 << 0.016 << 1 << 0.006;
    // 1x: 5 ms owe 0.005 s, half a step: none this tick, the debt stays.
    QTest::newRow("1x, h 0.01, 5 ms: none yet") << 1.0 << 0.01 << 5.0 << 0 << 0.005 << 0 << 0.005;
    // 2x: 0.032 s = 3.2 steps -> 3, 0.002 s left.
    QTest::newRow("2x, h 0.01, 16 ms") << 2.0 << 0.01 << 16.0 << 3 << 0.032 << 3 << 0.002;
    // 1/4x: 18 ms owe 0.0045 s = 4.5 steps of 0.001 -> 4, 0.0005 s left.
    QTest::newRow("1/4x, h 0.001, 18 ms") << 0.25 << 0.001 << 18.0 << 4 << 0.0045 << 4 << 0.0005;
    // A 500 ms stall counts as 100 ms: 0.1 s = 3.33 steps of 0.03 -> 3, 0.01 s left.
    QTest::newRow("stall capped at 100 ms") << 1.0 << 0.03 << 500.0 << 3 << 0.1 << 3 << 0.01;
    // 10x: 0.17 s = 56.7 steps of 0.003 -> 56; the session manages 20 in the budget:
    // 0.17 - 0.06 = 0.11 s would be left, dropped to one step, 0.003 s.
    QTest::newRow("10x cannot keep up: backlog dropped") << 10.0 << 0.003 << 17.0 << 56 << 0.17 << 20 << 0.003;
    // A blow-up takes none of 4 owed steps (0.045 s): at most one step (0.01 s) stays owed.
    QTest::newRow("no step taken") << 1.0 << 0.01 << 45.0 << 4 << 0.045 << 0 << 0.01;
    // One step per frame whatever the wall time; no debt is kept.
    QTest::newRow("1 step/frame") << PlaybackClock::kOneStepPerTick << 0.01 << 250.0 << 1 << 0.0 << 1 << 0.0;
    // As fast as possible: the budget, not the clock, ends the batch.
    QTest::newRow("as fast as possible") << PlaybackClock::kAsFastAsPossible << 0.01 << 16.0 << all << 0.0 << 1200
                                         << 0.0;
}

void TestPlaybackClock::oneTick()
{
    QFETCH(double, speed);
    QFETCH(double, h);
    QFETCH(double, wallMs);
    QFETCH(int, expectedDue);
    QFETCH(double, debtBefore);
    QFETCH(int, taken);
    QFETCH(double, debtAfter);

    PlaybackClock clock;
    clock.setSpeed(speed);
    clock.start();
    QCOMPARE(clock.debt(), 0.0);
    const int due = clock.stepsDue(wallMs, h);
    QCOMPARE(due, expectedDue);
    RBW_COMPARE_NEAR_STRICT(clock.debt(), debtBefore, 1e-15);
    clock.stepsTaken(due, taken, h);
    RBW_COMPARE_NEAR_STRICT(clock.debt(), debtAfter, 1e-15);
    QCOMPARE(clock.budgetMs(), 12.0);
}

void TestPlaybackClock::ticksInARow_data()
{
    QTest::addColumn<double>("speed");
    QTest::addColumn<double>("h");
    QTest::addColumn<QList<int>>("steps");   // per 16 ms tick, every step taken

    // 1x, h = 0.01: debt 0.016 -> 1 (0.006), 0.022 -> 2 (0.002), 0.018 -> 1 (0.008),
    // 0.024 -> 2 (0.004): 6 steps, 0.06 s simulated in 64 ms.
    QTest::newRow("1x") << 1.0 << 0.01 << QList<int>{1, 2, 1, 2};
    // 1/2x: 0.008 -> 0, 0.016 -> 1 (0.006), 0.014 -> 1 (0.004), 0.012 -> 1 (0.002).
    QTest::newRow("1/2x") << 0.5 << 0.01 << QList<int>{0, 1, 1, 1};
    // 3x, h = 0.02: 0.048 -> 2 (0.008), 0.056 -> 2 (0.016), 0.064 -> 3 (0.004),
    // 0.052 -> 2 (0.012).
    QTest::newRow("3x, h 0.02") << 3.0 << 0.02 << QList<int>{2, 2, 3, 2};
}

void TestPlaybackClock::ticksInARow()
{
    QFETCH(double, speed);
    QFETCH(double, h);
    QFETCH(QList<int>, steps);

    PlaybackClock clock;
    clock.setSpeed(speed);
    clock.start();
    QList<int> got;
    for (int k = 0; k < steps.size(); ++k) {
        const int due = clock.stepsDue(16.0, h);
        clock.stepsTaken(due, due, h);
        got << due;
    }
    QCOMPARE(got, steps);
}

void TestPlaybackClock::newSpeedDropsTheDebt()
{
    PlaybackClock clock;
    QCOMPARE(clock.speed(), 1.0);   // the parameter bar's default, 1x real time
    clock.start();
    QCOMPARE(clock.stepsDue(5.0, 0.01), 0);
    QVERIFY(clock.debt() > 0.0);
    clock.setSpeed(2.0);
    QCOMPARE(clock.speed(), 2.0);
    QCOMPARE(clock.debt(), 0.0);
}

void TestPlaybackClock::startDropsTheDebt()
{
    PlaybackClock clock;
    clock.setSpeed(1.0);
    clock.start();
    QCOMPARE(clock.stepsDue(9.0, 0.01), 0);   // 0.009 s owed
    clock.start();                            // pause, play again
    QCOMPARE(clock.debt(), 0.0);
    QCOMPARE(clock.stepsDue(9.0, 0.01), 0);   // not 0.018 -> 1
}

void TestPlaybackClock::panelsDue_data()
{
    QTest::addColumn<bool>("playing");
    QTest::addColumn<qint64>("msSinceRefresh");
    QTest::addColumn<bool>("due");

    QTest::newRow("paused: at once") << false << qint64(0) << true;
    QTest::newRow("playing, 16 ms") << true << qint64(16) << false;
    QTest::newRow("playing, 249 ms") << true << qint64(249) << false;
    QTest::newRow("playing, 250 ms: 4 Hz") << true << qint64(250) << true;
    QTest::newRow("playing, 1 s") << true << qint64(1000) << true;
}

void TestPlaybackClock::panelsDue()
{
    QFETCH(bool, playing);
    QFETCH(qint64, msSinceRefresh);
    QFETCH(bool, due);
    QCOMPARE(PlaybackClock::panelsDue(playing, msSinceRefresh), due);
}

void TestPlaybackClock::derivationOnlyWhenPaused()
{
    QVERIFY(PlaybackClock::derivationDue(false));
    QVERIFY(!PlaybackClock::derivationDue(true));
}

void TestPlaybackClock::measuredTickUsesTheWallClock()
{
    // The measured overload feeds the wall time since the last tick into the same
    // rule: at 1x and h = 1 s, 30 ms of waiting owe no step yet, but some debt.
    PlaybackClock clock;
    clock.start();
    QTest::qSleep(30);
    QCOMPARE(clock.stepsDue(1.0), 0);
    QVERIFY(clock.debt() >= 0.025 && clock.debt() <= 0.1);   // capped at 100 ms
    // Panels: just refreshed -> not due while playing, due while paused.
    clock.panelsRefreshed();
    QVERIFY(!clock.panelsDue(true));
    QVERIFY(clock.panelsDue(false));
}

QTEST_GUILESS_MAIN(TestPlaybackClock)
#include "tst_playback_clock.moc"
