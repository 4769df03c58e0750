// RefreshScheduler (issue 18): the shell tells every SessionPanel of a scene, a step and
// a rewind in a loop, and each marked panel catches up only when its pace is due. The
// pace table, from PlaybackClock's rules (app/core/playback_clock.h):
//   AsItGoes   never (the plots draw in stepRecorded)
//   PanelRate  when the clock says the panels are due (always when paused, 4 Hz playing)
//   WhenPaused only when not playing (Check my numbers, the derivation)
// A panel that nothing marked is never refreshed (the negative control of each row).
#include "app/gui/shell/refresh_scheduler.h"
#include "physics/engine/trace.h"

#include <QtTest>

using namespace rbw;

namespace {

struct CountingPanel : SessionPanel {
    explicit CountingPanel(RefreshPace pace) : pace_(pace) {}
    void sceneLoaded(const World&) override { ++loaded; }
    void stepRecorded(const StepTrace&) override { ++steps; }
    void rewound(long k) override { lastRewind = k; }
    RefreshPace refreshPace() const override { return pace_; }
    void refresh() override { ++refreshed; }

    RefreshPace pace_;
    int loaded = 0;
    int steps = 0;
    long lastRewind = -1;
    int refreshed = 0;
};

} // namespace

class TestRefreshScheduler : public QObject {
    Q_OBJECT
private slots:
    void paceDecidesRefresh_data();
    void paceDecidesRefresh();
    void everyPanelToldInTurn();
    void refreshIfDirty();
};

void TestRefreshScheduler::paceDecidesRefresh_data()
{
    QTest::addColumn<int>("pace");
    QTest::addColumn<bool>("playing");
    QTest::addColumn<bool>("panelsDue");
    QTest::addColumn<bool>("expected");
    using P = SessionPanel::RefreshPace;
    QTest::newRow("as it goes, paused") << int(P::AsItGoes) << false << true << false;
    QTest::newRow("as it goes, playing, due") << int(P::AsItGoes) << true << true << false;
    QTest::newRow("panel rate, paused") << int(P::PanelRate) << false << true << true;
    QTest::newRow("panel rate, playing, due") << int(P::PanelRate) << true << true << true;
    QTest::newRow("panel rate, playing, not due") << int(P::PanelRate) << true << false << false;
    QTest::newRow("when paused, paused") << int(P::WhenPaused) << false << true << true;
    QTest::newRow("when paused, playing, due") << int(P::WhenPaused) << true << true << false;
}

void TestRefreshScheduler::paceDecidesRefresh()
{
    QFETCH(int, pace);
    QFETCH(bool, playing);
    QFETCH(bool, panelsDue);
    QFETCH(bool, expected);
    CountingPanel panel(static_cast<SessionPanel::RefreshPace>(pace));
    RefreshScheduler scheduler;
    scheduler.add(&panel);
    // Negative control: nothing marked it, so nothing is refreshed, whatever the pace.
    scheduler.refreshDue(playing, panelsDue);
    QCOMPARE(panel.refreshed, 0);
    scheduler.stepRecorded(StepTrace{});   // marks every panel
    QVERIFY(scheduler.isDirty(&panel));
    scheduler.refreshDue(playing, panelsDue);
    QCOMPARE(panel.refreshed, expected ? 1 : 0);
    QCOMPARE(scheduler.isDirty(&panel), !expected);
    // Refreshed once per change: asking again without a new step does nothing more.
    scheduler.refreshDue(playing, panelsDue);
    QCOMPARE(panel.refreshed, expected ? 1 : 0);
}

void TestRefreshScheduler::everyPanelToldInTurn()
{
    CountingPanel table(SessionPanel::RefreshPace::PanelRate);
    CountingPanel check(SessionPanel::RefreshPace::WhenPaused);
    CountingPanel plot(SessionPanel::RefreshPace::AsItGoes);
    RefreshScheduler scheduler;
    for (SessionPanel* p : {static_cast<SessionPanel*>(&table), static_cast<SessionPanel*>(&check),
                            static_cast<SessionPanel*>(&plot)})
        scheduler.add(p);
    scheduler.stepRecorded(StepTrace{});
    scheduler.stepRecorded(StepTrace{});
    scheduler.rewound(1);
    for (const CountingPanel* p : {&table, &check, &plot}) {
        QCOMPARE(p->steps, 2);
        QCOMPARE(p->lastRewind, 1L);
    }
    // Playing, panels due: the table catches up, the paused-only one waits (still marked).
    scheduler.refreshDue(true, true);
    QCOMPARE(table.refreshed, 1);
    QCOMPARE(check.refreshed, 0);
    QVERIFY(scheduler.isDirty(&check));
    scheduler.refreshDue(false, true);   // paused
    QCOMPARE(check.refreshed, 1);
    QCOMPARE(table.refreshed, 1);        // it had caught up already
    QCOMPARE(plot.refreshed, 0);
}

void TestRefreshScheduler::refreshIfDirty()
{
    CountingPanel derivation(SessionPanel::RefreshPace::WhenPaused);
    CountingPanel other(SessionPanel::RefreshPace::WhenPaused);
    RefreshScheduler scheduler;
    scheduler.add(&derivation);
    scheduler.add(&other);
    scheduler.refreshIfDirty(&derivation);   // nothing marked: no refresh
    QCOMPARE(derivation.refreshed, 0);
    scheduler.mark(&derivation);             // only this one (a grab changed its body)
    QVERIFY(!scheduler.isDirty(&other));
    scheduler.refreshIfDirty(&derivation);   // its dock comes into view, while playing
    QCOMPARE(derivation.refreshed, 1);
    QCOMPARE(other.refreshed, 0);
    scheduler.refreshNow(&other);            // asked for by name (a test, Export)
    QCOMPARE(other.refreshed, 1);
}

QTEST_GUILESS_MAIN(TestRefreshScheduler)
#include "tst_refresh_scheduler.moc"
