// The window's controls and looks under Xvfb: drag a box with the spring, the 3D
// view's framebuffer, K, the push keys, the parameter keys and Help → Keys; where
// the docks are (as the lesson texts describe them), one colour per body in the view
// and the plots, and the Accuracy panel inside its dock.
#include "app/gui/shell/main_window.h"
#include "tests/app/gui/shell/window_test_support.h"
#include "tests/test_support.h"

#include <QAction>
#include <QDockWidget>
#include <QSettings>
#include <QStandardPaths>
#include <QtTest>
#include "app/gui/panels/accuracy/accuracy_panel.h"
#include "app/gui/panels/plots/body_plot_panel.h"
#include "app/gui/panels/view/scene_end_bar.h"
#include "app/gui/panels/view/view_style.h"
#include "app/gui/style/body_colours.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QDialog>
#include <QTableWidget>

using namespace rbw;
using namespace rbw::test;

class TestWindowControls : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void dragPullsTheBox();
    void framebufferShowsTheBoxes();
    void kTogglesTheTorque();
    void pushKeysInLesson2();
    void parameterKeysChangeTheScene();
    void keysDialogListsEveryShortcut();
    void lessonTextsMatchTheWindow();
    void oneColourPerBody();
    void accuracyPanelFitsItsDock();
    void playStopsAtTheScenesEnd();
    void statusBarCountsInWords();
    void hBoxShowsAShortNumberAndEscapeDiscards();
};

void TestWindowControls::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);   // QSettings go to a test location
    QSettings().clear();
    Warnings::install();
}

void TestWindowControls::dragPullsTheBox()
{
    // Drag the box in lesson 2 (forces removed by the lesson after step 200; here we
    // start at step 0 where the Table 2.1 force acts along (1, 1, 0), so we compare
    // against a run without the drag): the drag adds momentum along the drag.
    MainWindow w;
    w.resize(1200, 800);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("02-single-body"));
    SceneView* view = w.sceneView();
    QTRY_VERIFY(view->isGlReady());

    const Vec3 x0 = w.world()->states()[0].x_W;
    const QPoint centre = toPoint(view->projectToWidget(x0));
    QVERIFY(view->rect().contains(centre));
    const QPoint target = centre + QPoint(0, -120);   // drag straight up on screen

    sendMouse(view, QEvent::MouseButtonPress, centre, Qt::LeftButton, Qt::LeftButton);
    QVERIFY2(w.session()->isGrabbing(), "a press on the box must grab it");
    sendMouse(view, QEvent::MouseMove, centre + QPoint(0, -60), Qt::NoButton, Qt::LeftButton);
    sendMouse(view, QEvent::MouseMove, target, Qt::NoButton, Qt::LeftButton);
    const auto spring = w.session()->springSegment();
    QVERIFY(spring.has_value());
    const Vec3 drag_W = spring->second - spring->first;

    auto* step = w.findChild<QAction*>("actionStep");
    for (int k = 0; k < 5; ++k) step->trigger();
    sendMouse(view, QEvent::MouseButtonRelease, target, Qt::LeftButton, Qt::NoButton);
    QVERIFY(!w.session()->isGrabbing());
    const Vec3 P_drag = w.world()->massProperties()[0].M * w.world()->states()[0].v_W;

    // Same five steps without the drag.
    w.findChild<QAction*>("actionReset")->trigger();
    for (int k = 0; k < 5; ++k) step->trigger();
    const Vec3 P_free = w.world()->massProperties()[0].M * w.world()->states()[0].v_W;
    const Vec3 dP = P_drag - P_free;
    QVERIFY2(dP.norm() > 0.0, "the drag changed nothing");
    QVERIFY2(dP.normalized().dot(drag_W.normalized()) > 0.9,
             qPrintable(QStringLiteral("dP = (%1, %2, %3) not along the drag").arg(dP.x()).arg(dP.y()).arg(dP.z())));
    // Up on the screen is up in the world for the default camera.
    QVERIFY(dP.y() > 0.0);
}

void TestWindowControls::framebufferShowsTheBoxes()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("04-many-boxes"));
    SceneView* view = w.sceneView();
    QTRY_VERIFY(view->isGlReady());
    QCOMPARE(view->format().profile(), QSurfaceFormat::CoreProfile);
    QVERIFY(view->format().version() >= qMakePair(3, 3));
    const QImage image = view->grabFramebuffer();
    QVERIFY(!image.isNull());
    // Not blank: many colours. And each body's centre shows something other than the
    // background colour in the corner pixel (the sky).
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); y += 4)
        for (int x = 0; x < image.width(); x += 4) colours.insert(image.pixel(x, y));
    QVERIFY2(colours.size() > 50, qPrintable(QString::number(colours.size())));
    const qreal dpr = image.devicePixelRatio();
    const QRgb sky = image.pixel(image.width() / 2, 2);
    int seen = 0;
    for (const BodyState& s : w.world()->states()) {
        const QPointF p = view->projectToWidget(s.x_W) * dpr;
        if (!image.rect().contains(p.toPoint())) continue;
        seen += image.pixel(p.toPoint()) != sky ? 1 : 0;
    }
    QVERIFY2(seen >= 4, qPrintable(QString::number(seen)));
}

void TestWindowControls::kTogglesTheTorque()
{
    MainWindow w;
    QVERIFY(w.openLesson("05-spinning"));
    auto* k = w.findChild<QAction*>("actionToggleTorque");
    QVERIFY(k->isEnabled());
    QCOMPARE(k->shortcut(), QKeySequence(Qt::Key_K));
    auto* step = w.findChild<QAction*>("actionStep");
    for (int i = 0; i < 100; ++i) step->trigger();
    const Vec3 omega = w.world()->states()[1].omega_W;   // (0, 0.3, 0), lesson 5's text
    QVERIFY((omega - Vec3(0, 0.3, 0)).norm() < 1e-12);
    k->trigger();
    for (int i = 0; i < 50; ++i) step->trigger();
    QCOMPARE(w.world()->states()[1].omega_W, omega);   // keeps its value
    k->trigger();
    step->trigger();
    QVERIFY(w.world()->states()[1].omega_W.y() > omega.y());

    // Elsewhere K does nothing and says so by being disabled.
    QVERIFY(w.openLesson("01-one-step"));
    QVERIFY(!k->isEnabled());
}

void TestWindowControls::pushKeysInLesson2()
{
    MainWindow w;
    QVERIFY(w.openLesson("02-single-body"));
    // +z push: 5 N for one step at h = 0.01 on M = 2: v_z = 0.025 (the Table 2.1
    // force acts in the x-y plane only, so v_z is the push's alone).
    auto* pushUp = w.findChild<QAction*>("actionPush4");
    QVERIFY(pushUp && pushUp->text().contains("+z"));
    QVERIFY(pushUp->isEnabled());
    pushUp->trigger();
    w.findChild<QAction*>("actionStep")->trigger();
    QVERIFY(std::abs(w.world()->states()[0].v_W.z() - 0.025) < 1e-15);
    QVERIFY(w.openLesson("03-two-box-collision"));
    QVERIFY(!pushUp->isEnabled());
}

void TestWindowControls::parameterKeysChangeTheScene()
{
    // h, the integrator, c and mu each have a key (Help -> Keys lists them).
    MainWindow w;
    QVERIFY(w.openLesson("07-bounce"));
    const double h = w.world()->scene().dt;
    w.findChild<QAction*>("actionHalveDt")->trigger();
    QCOMPARE(w.world()->scene().dt, h / 2);
    w.findChild<QAction*>("actionDoubleDt")->trigger();
    QCOMPARE(w.world()->scene().dt, h);
    const std::string integrator = w.world()->scene().integrator;
    w.findChild<QAction*>("actionNextIntegrator")->trigger();
    QVERIFY(w.world()->scene().integrator != integrator);
    w.findChild<QAction*>("actionPreviousIntegrator")->trigger();
    QCOMPARE(w.world()->scene().integrator, integrator);
    const double c = w.world()->scene().restitution;
    w.findChild<QAction*>("actionLessRestitution")->trigger();
    QVERIFY(std::abs(w.world()->scene().restitution - (c - 0.05)) < 1e-12);
    const double mu = w.world()->scene().friction;
    w.findChild<QAction*>("actionMoreFriction")->trigger();
    QVERIFY(std::abs(w.world()->scene().friction - (mu + 0.05)) < 1e-12);
}

void TestWindowControls::keysDialogListsEveryShortcut()
{
    MainWindow w;
    w.show();
    QVERIFY(w.openLesson("01-one-step"));
    w.findChild<QAction*>("actionKeys")->trigger();
    QDialog* dialog = nullptr;
    QTRY_VERIFY((dialog = w.findChild<QDialog*>("keysDialog")) != nullptr);
    auto* table = dialog->findChild<QTableWidget*>("keysTable");
    QStringList listed;
    for (int r = 0; r < table->rowCount(); ++r) listed << table->item(r, 1)->text();
    const QString all = listed.join('\n');
    int withKeys = 0;
    QSet<QString> seen;
    for (QAction* a : w.shortcutActions()) {
        for (const QKeySequence& k : a->shortcuts()) {
            const QString key = k.toString(QKeySequence::NativeText);
            QVERIFY2(all.contains(key), qPrintable(key));
            QVERIFY2(!seen.contains(key), qPrintable("shortcut used twice: " + key));
            seen.insert(key);
            ++withKeys;
        }
    }
    QVERIFY(withKeys >= 20);
    // Every control the issue names has a key.
    for (const char* name : {"actionStep", "actionStepBack", "actionPlay", "actionReset", "actionSlower", "actionFaster",
                             "actionGravity", "actionToggleTorque", "actionTrails", "actionFit", "actionResetView",
                             "actionHalveDt", "actionDoubleDt", "actionNextIntegrator", "actionMoreRestitution",
                             "actionLessRestitution", "actionMoreFriction", "actionLessFriction"}) {
        QVERIFY2(!w.findChild<QAction*>(name)->shortcuts().isEmpty(), name);
    }
    dialog->close();
}

// Lesson 1 speaks of the quantities table "on the right"; lesson 7 of File → Open.
void TestWindowControls::lessonTextsMatchTheWindow()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QDockWidget* traceDock = w.findChild<QDockWidget*>("traceDock");
    QVERIFY(traceDock != nullptr);
    QCOMPARE(w.dockWidgetArea(traceDock), Qt::RightDockWidgetArea);
    bool open = false;
    for (QAction* a : w.findChildren<QAction*>()) open = open || a->shortcuts().contains(QKeySequence(QKeySequence::Open));
    QVERIFY2(open, "lesson 7 speaks of File → Open (Ctrl+O), but no action of the window has that shortcut");
}

// One colour per body in the 3D view, the plots and the table, from the one function:
// lesson 4's boxes are named after colours and its text speaks of "red against
// green", so the box named red is drawn red, and its plot line is the same colour.
void TestWindowControls::oneColourPerBody()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("04-many-boxes"));
    const ViewSnapshot& snap = w.sceneView()->snapshot();
    QVERIFY(!snap.bodies.empty());
    for (int b = 0; b < int(snap.bodies.size()); ++b) {
        const ViewSnapshot::Body& body = snap.bodies[static_cast<size_t>(b)];
        const view::Rgba v = view::bodyColour(b, body.fixed, body.name);
        const QColor plot = w.bodyPlotPanel()->lineColour(b);
        // QColor keeps 16 bits per channel: equal to within 1/65535.
        const double q = 1.0 / 65535.0;
        QVERIFY2(std::abs(plot.redF() - v.r) <= q && std::abs(plot.greenF() - v.g) <= q &&
                     std::abs(plot.blueF() - v.b) <= q,
                 qPrintable(QString::fromStdString(body.name)));
        if (body.name == "red") QVERIFY(v.r > 2 * v.g && v.r > 2 * v.b);
        if (body.name == "green") QVERIFY(v.g > v.r && v.g > v.b);
        if (body.name == "blue") QVERIFY(v.b > v.r && v.b > v.g);
    }
    // Negative control: a name that is no colour keeps the palette by index.
    QVERIFY(bodyQColor(1, false, "B") == bodyQColor(1, false));
    QVERIFY(bodyQColor(0, false, "red") != bodyQColor(0, false));
}

// The Accuracy panel sat off the right edge of its dock at 1600x1000 with the cost's
// unit cut off: docked, it now stacks its settings above the chart, is no wider than
// its dock, and the cost axis' title keeps its unit.
void TestWindowControls::accuracyPanelFitsItsDock()
{
    MainWindow w;
    w.resize(1600, 1000);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("10-accuracy-lab"));
    QDockWidget* dock = w.findChild<QDockWidget*>("accuracyDock");
    QVERIFY(dock != nullptr);
    dock->show();
    dock->raise();
    QApplication::processEvents();
    QWidget* panel = w.accuracyPanel();
    QTRY_VERIFY(panel->isVisible());
    QWidget* viewport = panel->parentWidget();
    QVERIFY(viewport != nullptr);
    QTRY_VERIFY2(panel->width() <= viewport->width(),
                 qPrintable(QStringLiteral("panel %1 px in a %2 px dock").arg(panel->width()).arg(viewport->width())));
    QChart* chart = panel->findChild<QChartView*>()->chart();
    bool unit = false;
    for (QAbstractAxis* axis : chart->axes(Qt::Horizontal)) unit = unit || axis->titleText().endsWith("[ms]");
    QVERIFY(unit);
}

RBW_WINDOW_TEST_MAIN(TestWindowControls)

// Issue 20, item 7: the status bar names the integrator (not its id) and counts with
// plurals: lesson 1 after one step is "1 step taken" and "1 step back", after two
// "2 steps taken" and "2 steps back" (the history keeps every step of a small scene).
void TestWindowControls::statusBarCountsInWords()
{
    MainWindow w;
    QVERIFY(w.openLesson("01-one-step"));
    auto* status = w.findChild<QLabel*>("statusLabel");
    QVERIFY(status != nullptr);
    w.stepOnce();
    QString text = status->text();
    QVERIFY2(text.contains(" · 1 step taken · ") && text.contains(" · 1 step back"), qPrintable(text));
    QVERIFY2(text.contains(" · explicit Euler · "), qPrintable(text));
    QVERIFY2(!text.contains("explicit-euler"), qPrintable(text));
    w.stepOnce();
    text = status->text();
    QVERIFY2(text.contains(" · 2 steps taken · ") && text.contains(" · 2 steps back"), qPrintable(text));
}

void TestWindowControls::playStopsAtTheScenesEnd()
{
    // Issue 20, item 1: Play stops at the scene's `steps` (lesson 3: "steps": 3, the
    // collision and one step after it) and the end bar says so; Continue plays on.
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("03-two-box-collision"));
    const long end = w.world()->scene().steps;
    QCOMPARE(end, 3L);
    auto* bar = w.findChild<SceneEndBar*>();
    QVERIFY(bar != nullptr);
    QVERIFY(!bar->isVisible());
    QAction* play = w.findChild<QAction*>("actionPlay");
    play->trigger();
    QVERIFY(play->isChecked());
    QTRY_VERIFY_WITH_TIMEOUT(!play->isChecked(), 10000);
    QCOMPARE(w.world()->stepIndex(), end);   // exactly at the end, not one step beyond
    QVERIFY(bar->isVisible());
    QVERIFY(bar->label()->text().contains(QString::number(end)));
    // Continue: Play goes on past the end (a run started at the end does not stop there).
    bar->continueButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(w.world()->stepIndex() > end + 5, 10000);
    QVERIFY(play->isChecked());
    play->trigger();   // pause
    QVERIFY(!play->isChecked());
}

void TestWindowControls::hBoxShowsAShortNumberAndEscapeDiscards()
{
    // Issue 20, items 2 and 5: lesson 11's h = 1/60 reads "0.0166667" (6 figures, as the
    // view's overlay writes it), and that text stands for the exact 1/60: leaving the box
    // changes nothing. Typing 0.04 and pressing Escape discards it, and the keys go back
    // to the 3D view (S steps with h still 1/60).
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    w.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&w));
    QVERIFY(w.openLesson("11-resting-contact"));
    const double h = w.world()->scene().dt;
    QCOMPARE(h, 1.0 / 60.0);
    auto* dtBox = w.findChild<QComboBox*>("dtBox");
    QVERIFY(dtBox != nullptr);
    QCOMPARE(dtBox->currentText(), QString("0.0166667"));
    dtBox->setFocus(Qt::MouseFocusReason);
    QTRY_VERIFY(dtBox->hasFocus());
    dtBox->lineEdit()->selectAll();
    QTest::keyClicks(dtBox, "0.04");
    QCOMPARE(dtBox->currentText(), QString("0.04"));   // typed (control: the box takes keys)
    QTest::keyClick(dtBox, Qt::Key_Escape);
    QCOMPARE(dtBox->currentText(), QString("0.0166667"));
    QTRY_VERIFY(w.findChild<QWidget*>("sceneView")->hasFocus());
    QCOMPARE(w.world()->scene().dt, h);   // exactly 1/60, not 0.0166667 and not 0.04
    QTest::keyClick(w.findChild<QWidget*>("sceneView"), Qt::Key_S);
    QCOMPARE(w.world()->stepIndex(), 1L);
    QCOMPARE(w.world()->scene().dt, h);
    // Enter applies a typed value and also gives the keys back.
    dtBox->setFocus(Qt::MouseFocusReason);
    QTRY_VERIFY(dtBox->hasFocus());
    dtBox->lineEdit()->selectAll();
    QTest::keyClicks(dtBox, "0.01");
    QTest::keyClick(dtBox, Qt::Key_Return);
    QCOMPARE(w.world()->scene().dt, 0.01);
    QTRY_VERIFY(w.findChild<QWidget*>("sceneView")->hasFocus());
}

#include "tst_window_controls.moc"
