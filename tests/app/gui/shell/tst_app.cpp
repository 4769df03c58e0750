// The whole app under Xvfb, driven as a student drives it: open every lesson and
// step it, step back and reset, watch the plots against the rbw CLI, play at real
// time, and find the lesson and layout again after a restart. The table and the page
// are tst_quantities_table; the keys, drag and view are tst_window_controls.
//
// Expected numbers are hand derivations made elsewhere (tst_table21.cpp,
// tst_collision_lessons.cpp) or the rbw CLI's own output for the same run.
#include "app/gui/shell/main_window.h"
#include "tests/app/gui/shell/window_test_support.h"
#include "tests/test_support.h"

#include <QAction>
#include <QDockWidget>
#include <QSettings>
#include <QStandardPaths>
#include <QtTest>
#include "app/gui/panels/plots/body_plot_panel.h"
#include "app/gui/panels/plots/plot_panel.h"

#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

using namespace rbw;
using namespace rbw::test;

class TestApp : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void opensOnLesson1();
    void everyLessonLoadsAndSteps_data();
    void everyLessonLoadsAndSteps();
    void stepBackRestoresExactly();
    void resetClearsTrace();
    void plotsFollowTheCli();
    void perBodyPlotsShowLesson9sIntegrators();
    void playKeepsToRealTime();
    void settingsRememberLessonAndLayout();
};

void TestApp::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);   // QSettings go to a test location
    QSettings().clear();
    Warnings::install();
}

void TestApp::opensOnLesson1()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("01-one-step"));
    QCOMPARE(w.currentLessonId(), QString("01-one-step"));
    QVERIFY(w.windowTitle().contains("One Euler step (Table 2.1)"));
    // Before the first Step the table shows the state at t = 0 (issue 20: never blank),
    // not a step's trace.
    QVERIFY(w.traceModel()->showsStart());
    QVERIFY(w.traceModel()->rowCount() > 0);
    // The default layout fits a 1366x768 screen.
    QVERIFY(w.frameGeometry().width() <= 1366 && w.frameGeometry().height() <= 768);
}

void TestApp::everyLessonLoadsAndSteps_data()
{
    QTest::addColumn<QString>("id");
    MainWindow probe;
    for (const Lesson& l : probe.lessons()) QTest::newRow(qPrintable(l.id)) << l.id;
    QVERIFY(probe.lessons().size() >= 7);
}

void TestApp::everyLessonLoadsAndSteps()
{
    QFETCH(QString, id);
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    Warnings::clear();
    QVERIFY(w.openLesson(id));
    auto* step = w.findChild<QAction*>("actionStep");
    for (int k = 0; k < 5; ++k) step->trigger();
    QCOMPARE(w.world()->stepIndex(), 5L);
    QVERIFY2(w.world()->status().ok, w.world()->status().message.c_str());
    QVERIFY(w.traceModel()->rowCount() > 0);
    QVERIFY(w.derivationHtml().startsWith("<!DOCTYPE html>"));
    QCOMPARE(w.plotPanel()->sampleCount(), 6);   // t = 0 and one per step
    QCoreApplication::processEvents();
    QVERIFY2(Warnings::list().isEmpty(), qPrintable(Warnings::list().join('\n')));
}

void TestApp::stepBackRestoresExactly()
{
    MainWindow w;
    QVERIFY(w.openLesson("04-many-boxes"));
    auto* step = w.findChild<QAction*>("actionStep");
    for (int k = 0; k < 10; ++k) step->trigger();
    const WorldSnapshot at10 = w.world()->snapshot();
    const QString omega10 = valueText(w.traceModel(), findRow(w.traceModel(), "angular_velocity"));
    step->trigger();
    QCOMPARE(w.world()->stepIndex(), 11L);
    QCOMPARE(w.plotPanel()->sampleCount(), 12);

    w.findChild<QAction*>("actionStepBack")->trigger();
    QCOMPARE(w.world()->stepIndex(), 10L);
    QCOMPARE(w.world()->time(), at10.time);
    for (size_t b = 0; b < at10.states.size(); ++b) {
        const BodyState& s = w.world()->states()[b];
        QVERIFY(s.x_W == at10.states[b].x_W && s.v_W == at10.states[b].v_W);
        QVERIFY(s.q_WB.coeffs() == at10.states[b].q_WB.coeffs() && s.L_W == at10.states[b].L_W);
    }
    // The table shows step 10's trace again, and the plot drops the 11th sample.
    QCOMPARE(valueText(w.traceModel(), findRow(w.traceModel(), "angular_velocity")), omega10);
    QCOMPARE(w.plotPanel()->sampleCount(), 11);
}

void TestApp::resetClearsTrace()
{
    MainWindow w;
    QVERIFY(w.openLesson("01-one-step"));
    w.findChild<QAction*>("actionStep")->trigger();
    QVERIFY(w.traceModel()->rowCount() > 0);
    QVERIFY(!w.traceModel()->showsStart());   // step 0's trace
    QCOMPARE(w.world()->stepIndex(), 1L);
    w.findChild<QAction*>("actionReset")->trigger();
    QCOMPARE(w.world()->stepIndex(), 0L);
    QVERIFY(w.traceModel()->showsStart());    // the trace is gone: the state at t = 0 again
    QCOMPARE(w.plotPanel()->sampleCount(), 1);
}

void TestApp::plotsFollowTheCli()
{
    // The plots show the diagnostics the physics recorded; the CLI prints the same
    // run's per-step diagnostics. They must agree to the bit (same doubles).
    const int steps = 40;
    MainWindow w;
    QVERIFY(w.openLesson("07-bounce"));
    auto* step = w.findChild<QAction*>("actionStep");
    for (int k = 0; k < steps; ++k) step->trigger();
    QCOMPARE(w.plotPanel()->sampleCount(), steps + 1);

    const test::RbwRun run = test::runRbw({"run", QStringLiteral(RBW_SOURCE_DIR "/lessons/07-bounce/scene.json"),
                                           "--steps", QString::number(steps), "--trace", "all"});
    QCOMPARE(run.exitCode, 0);
    const QJsonArray trace = QJsonDocument::fromJson(run.out).object().value("trace").toArray();
    QCOMPARE(trace.size(), steps);
    // The series and the JSON fields by the catalogue's ids (diagnostic_catalogue.h).
    const QList<QPointF> E = w.plotPanel()->points(plotSeriesId(PlotQuantity::Total));
    const QList<QPointF> Trot = w.plotPanel()->points(plotSeriesId(PlotQuantity::KineticRotational));
    const auto field = [](const DiagnosticInfo<Diagnostics>& info) { return QString::fromLatin1(info.id.data(), qsizetype(info.id.size())); };
    QCOMPARE(E.size(), steps + 1);
    for (int k = 0; k < steps; ++k) {
        const QJsonObject d = trace[k].toObject().value("diagnostics").toObject();
        QCOMPARE(E[k + 1].x(), trace[k].toObject().value("time").toDouble());
        QCOMPARE(E[k + 1].y(), d.value(field(diag::total)).toDouble());
        QCOMPARE(Trot[k + 1].y(), d.value(field(diag::kinetic_rotational)).toDouble());
    }
}

void TestApp::perBodyPlotsShowLesson9sIntegrators()
{
    // Lesson 9: three identical boxes, one per integrator (explicit Euler, RK4,
    // implicit midpoint; see tst_tennis_racket.cpp). The per-body plot holds each
    // body's T and |L| exactly as the physics recorded them, one sample per step.
    MainWindow w;
    QVERIFY(w.openLesson("09-tennis-racket"));
    auto* step = w.findChild<QAction*>("actionStep");
    const int steps = 300;
    for (int k = 0; k < steps; ++k) step->trigger();
    BodyPlotPanel* p = w.bodyPlotPanel();
    QCOMPARE(p->sampleCount(), steps + 1);
    const Diagnostics& d = w.session()->currentTrace()->diagnostics;
    QCOMPARE(static_cast<int>(d.bodies.size()), 3);
    for (int b = 0; b < 3; ++b) {
        QCOMPARE(p->points(BodyPlotPanel::KineticEnergy, b).last().y(), d.bodies[b].kinetic);
        QCOMPARE(p->points(BodyPlotPanel::AngularMomentumNorm, b).last().y(), d.bodies[b].L_norm);
    }
    // Explicit Euler's T rises (docs/stability.md); implicit midpoint's stays put to
    // rounding. Body order as in the scene: explicit Euler first, implicit midpoint last.
    const QList<QPointF> euler = p->points(BodyPlotPanel::KineticEnergy, 0);
    const QList<QPointF> midpoint = p->points(BodyPlotPanel::KineticEnergy, 2);
    QVERIFY(euler.last().y() > euler.first().y() * (1 + 1e-6));
    QVERIFY(std::abs(midpoint.last().y() - midpoint.first().y()) <= 1e-12 * midpoint.first().y());
    w.findChild<QAction*>("actionStepBack")->trigger();
    QCOMPARE(p->sampleCount(), steps);
}

void TestApp::playKeepsToRealTime()
{
    // Play at 1x real time (PlaybackClock): lesson 5 at h = 0.01 s takes about 100 steps
    // per wall second, never more than real time allows; the table catches up on pause.
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("05-spinning"));
    QCOMPARE(w.playbackSpeed(), 1.0);
    QElapsedTimer wall;
    wall.start();
    w.findChild<QAction*>("actionPlay")->trigger();
    QTest::qWait(600);
    w.findChild<QAction*>("actionPlay")->trigger();   // pause
    const double seconds = static_cast<double>(wall.elapsed()) * 1e-3;
    const long steps = w.world()->stepIndex();
    QVERIFY2(steps > 0, "Play took no step");
    // Never ahead of real time: at most floor(t / h) steps, plus one of rounding.
    QVERIFY2(steps <= static_cast<long>(seconds / 0.01) + 1,
             qPrintable(QStringLiteral("%1 steps in %2 s").arg(steps).arg(seconds)));
    // Paused: the table shows the last step.
    QCOMPARE(w.traceModel()->trace().step, steps - 1);

    // [ down to the slowest notch: one step per frame.
    auto* slower = w.findChild<QAction*>("actionSlower");
    for (int i = 0; i < 5; ++i) slower->trigger();
    QCOMPARE(w.playbackSpeed(), 0.0);
}

void TestApp::settingsRememberLessonAndLayout()
{
    QSettings().clear();
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.openLesson("06-box-on-plane"));
        w.findChild<QDockWidget*>("plotDock")->hide();
        w.close();
    }
    QCOMPARE(QSettings().value("lesson/last").toString(), QString("06-box-on-plane"));
    MainWindow again;
    again.show();
    QVERIFY(QTest::qWaitForWindowExposed(&again));
    QVERIFY(!again.findChild<QDockWidget*>("plotDock")->isVisible());
    QSettings().clear();
}

RBW_WINDOW_TEST_MAIN(TestApp)

#include "tst_app.moc"
