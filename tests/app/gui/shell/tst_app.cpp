// The whole app under Xvfb, driven as a student drives it: switch lessons, Step,
// Step back, read the quantities table and the typeset derivation, watch the plots,
// drag a box, press K, and find every key in Help -> Keys.
//
// Expected numbers are hand derivations made elsewhere: Table 2.1's omega =
// (-2.4, 4.918033, -1.764706) in tst_table21.cpp, lesson 3's J = 64/27 in
// tst_collision_lessons.cpp, the plots' diagnostics against the rbw CLI.
#include "app/gui/panels/quantities/code_view.h"
#include "app/gui/panels/derivation/derivation_view.h"
#include "app/gui/panels/quantities/formula_pane.h"
#include "app/gui/shell/main_window.h"
#include "app/gui/panels/plots/body_plot_panel.h"
#include "app/gui/panels/plots/plot_panel.h"
#include "app/gui/panels/quantities/trace_model.h"
#include "app/gui/panels/view/scene_view.h"
#include "tests/test_support.h"

#include <QAbstractItemModelTester>
#include <QAction>
#include <QDeadlineTimer>
#include <QDialog>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QListWidget>
#include <QSettings>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTableWidget>
#include <QTreeView>
#include <QWebEnginePage>
#include <QtTest>


#include <mutex>

using namespace rbw;

namespace {

// Depth-first search for the row whose IdRole is `id` (optionally under a parent
// whose text is `under`, e.g. the contact group).
QModelIndex findRow(const QAbstractItemModel* model, const QString& id, const QModelIndex& parent = {})
{
    for (int r = 0; r < model->rowCount(parent); ++r) {
        const QModelIndex i = model->index(r, 0, parent);
        if (model->data(i, TraceModel::IdRole).toString() == id) return i;
        const QModelIndex found = findRow(model, id, i);
        if (found.isValid()) return found;
    }
    return {};
}

QString valueText(const QAbstractItemModel* model, const QModelIndex& row)
{
    return model->index(row.row(), TraceModel::ValueColumn, row.parent()).data().toString();
}

// Warnings printed while a lesson loads and steps: the test fails on any of ours.
// Chromium's and Mesa's own chatter goes to stderr without Qt's handler and is not
// caught here; Qt's own GL/WebEngine categories are listed as noise explicitly.
QStringList g_warnings;
std::mutex g_warningsMutex;
QtMessageHandler g_previous = nullptr;

void collectWarnings(QtMsgType type, const QMessageLogContext& context, const QString& message)
{
    if (type == QtWarningMsg || type == QtCriticalMsg) {
        const QString category = QString::fromLatin1(context.category ? context.category : "");
        const bool noise = category.startsWith("qt.webengine") || category.startsWith("js") ||
                           message.contains("XDG_RUNTIME_DIR") || message.contains("Core Profile was requested");
        if (!noise) {
            std::lock_guard<std::mutex> lock(g_warningsMutex);
            g_warnings << QStringLiteral("[%1] %2").arg(category, message);
        }
    }
    if (g_previous) g_previous(type, context, message);
}

QString pageText(DerivationView* view)
{
    QString text;
    bool done = false;
    view->page()->runJavaScript("document.body.innerText", [&](const QVariant& v) {
        text = v.toString();
        done = true;
    });
    QDeadlineTimer deadline(10000);
    while (!done && !deadline.hasExpired()) QTest::qWait(20);
    return text;   // empty if the page never answered: the caller's checks then fail
}

bool waitRendered(DerivationView* view)
{
    QSignalSpy spy(view, &DerivationView::rendered);
    return spy.wait(20000) || view->isRendered();
}

QPoint toPoint(const QPointF& p) { return QPoint(qRound(p.x()), qRound(p.y())); }

void sendMouse(QWidget* w, QEvent::Type type, const QPoint& pos, Qt::MouseButton button, Qt::MouseButtons buttons)
{
    QMouseEvent e(type, QPointF(pos), w->mapToGlobal(QPointF(pos)), button, buttons, Qt::NoModifier);
    QApplication::sendEvent(w, &e);
}

} // namespace

class TestApp : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void opensOnLesson1();
    void everyLessonLoadsAndSteps_data();
    void everyLessonLoadsAndSteps();
    void lesson1OmegaInPanelAndDerivation();
    void showCodeOfAQuantity();
    void modelIsConsistent();
    void contactsGroupedByPair();
    void valuesStayOnScreenWithLongGroupNames();
    void stepBackRestoresExactly();
    void plotsFollowTheCli();
    void dragPullsTheBox();
    void framebufferShowsTheBoxes();
    void lesson3CollisionStep();
    void kTogglesTheTorque();
    void pushKeysInLesson2();
    void keysDialogListsEveryShortcut();
    void settingsRememberLessonAndLayout();
    void parameterKeysChangeTheScene();
    void perBodyPlotsShowLesson9sIntegrators();
    void resetClearsTrace();
    void playKeepsToRealTime();
};

void TestApp::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);   // QSettings go to a test location
    QSettings().clear();
    g_previous = qInstallMessageHandler(collectWarnings);
}

void TestApp::opensOnLesson1()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("01-one-step"));
    QCOMPARE(w.currentLessonId(), QString("01-one-step"));
    QVERIFY(w.windowTitle().contains("One Euler step (Table 2.1)"));
    QCOMPARE(w.traceModel()->rowCount(), 0);   // nothing computed before the first Step
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
    g_warnings.clear();
    QVERIFY(w.openLesson(id));
    auto* step = w.findChild<QAction*>("actionStep");
    for (int k = 0; k < 5; ++k) step->trigger();
    QCOMPARE(w.world()->stepIndex(), 5L);
    QVERIFY2(w.world()->status().ok, w.world()->status().message.c_str());
    QVERIFY(w.traceModel()->rowCount() > 0);
    QVERIFY(w.derivationHtml().startsWith("<!DOCTYPE html>"));
    QCOMPARE(w.plotPanel()->sampleCount(), 6);   // t = 0 and one per step
    QCoreApplication::processEvents();
    QVERIFY2(g_warnings.isEmpty(), qPrintable(g_warnings.join('\n')));
}

void TestApp::lesson1OmegaInPanelAndDerivation()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("01-one-step"));
    w.findChild<QDockWidget*>("derivationDock")->raise();
    w.findChild<QAction*>("actionStep")->trigger();

    const QAbstractItemModel* model = w.findChild<QTreeView*>("traceView")->model();
    const QModelIndex omega = findRow(model, "angular_velocity");
    QVERIFY(omega.isValid());
    // A column, as in the derivation: one component per line.
    QCOMPARE(valueText(model, omega), QString("-2.4\n4.918033\n-1.764706"));
    QCOMPARE(model->index(omega.row(), TraceModel::SymbolColumn, omega.parent()).data().toString(), QString("ω"));
    QCOMPARE(model->index(omega.row(), TraceModel::FrameColumn, omega.parent()).data().toString(), QString("world"));
    QCOMPARE(model->index(omega.row(), TraceModel::UnitColumn, omega.parent()).data().toString(), QString("rad/s"));
    QCOMPARE(omega.parent().data().toString(), QString("box"));

    // Before and after the step (issue 10): Table 2.1 starts at rest, so v_0 = 0 and
    // v_1 = v_0 + h F/M = 2 (1, 1, 0)/2 = (1, 1, 0); r_0 = [cos 45°, 0, 0, sin 45°].
    const QModelIndex v = findRow(model, "linear_velocity");
    QCOMPARE(model->index(v.row(), TraceModel::BeforeColumn, v.parent()).data().toString(), QString("0\n0\n0"));
    QCOMPARE(valueText(model, v), QString("1\n1\n0"));
    const QModelIndex r = findRow(model, "orientation");
    QCOMPARE(model->index(r.row(), TraceModel::BeforeColumn, r.parent()).data().toString(),
             QString("w 0.7071068\nx 0\ny 0\nz 0.7071068"));
    QCOMPARE(model->headerData(TraceModel::BeforeColumn, Qt::Horizontal).toString(), QString("Before"));
    QCOMPARE(model->headerData(TraceModel::ValueColumn, Qt::Horizontal).toString(), QString("After"));
    // A force has no value before the step: it is computed in it (negative control).
    const QModelIndex f = findRow(model, "force");
    QVERIFY(model->index(f.row(), TraceModel::BeforeColumn, f.parent()).data().toString().isEmpty());
    // The formula pane typesets the selected row's formula and both values.
    const QString pane = FormulaPane::rowBodyHtml(v);
    QVERIFY2(pane.contains(QLatin1String("before: ")) && pane.contains(QLatin1String("after: ")), qPrintable(pane));
    QVERIFY(pane.contains(QLatin1String("physics/engine/integrators/explicit_euler.cpp")));
    QVERIFY(!FormulaPane::rowBodyHtml(f).contains(QLatin1String("before: ")));
    QCOMPARE(omega.parent().parent().data().toString(), QString("Integration"));

    // The typeset page: rendered by KaTeX without errors, and the omega numbers in it.
    DerivationView* page = w.derivationView();
    QVERIFY(waitRendered(page));
    QVERIFY(page->katexCount() > 10);
    QCOMPARE(page->errorCount(), 0);
    const QString text = pageText(page);
    for (const char* number : {"-2.4", "4.918033", "-1.764706"}) {
        // KaTeX typesets a minus sign as U+2212.
        const QString n = QString::fromLatin1(number);
        QVERIFY2(text.contains(n) || text.contains(QString(n).replace('-', QChar(0x2212))), number);
    }
}

void TestApp::showCodeOfAQuantity()
{
    // Lesson 1's omega row names the physics statement that computed it; Show code
    // opens that file at that line, highlighted, with the equation comment above it
    // on screen.
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("01-one-step"));
    w.findChild<QAction*>("actionStep")->trigger();
    auto* view = w.findChild<QTreeView*>("traceView");
    const QAbstractItemModel* model = view->model();
    const QModelIndex omega = findRow(model, "angular_velocity");
    QVERIFY(omega.isValid());
    view->setCurrentIndex(omega);

    // The Source column: "file.cpp:line", with the path in the tree as its tooltip.
    const QModelIndex sourceCell = model->index(omega.row(), TraceModel::SourceColumn, omega.parent());
    QCOMPARE(model->headerData(TraceModel::SourceColumn, Qt::Horizontal).toString(), QString("Source"));
    const QString source = sourceCell.data(Qt::ToolTipRole).toString();
    static const QRegularExpression located(QStringLiteral(R"(^(physics/[a-z0-9_/]+\.cpp):(\d+)$)"));
    const QRegularExpressionMatch m = located.match(source);
    QVERIFY2(m.hasMatch(), qPrintable(source));
    const QString file = m.captured(1);
    const int line = m.captured(2).toInt();
    QCOMPARE(sourceCell.data().toString(), QFileInfo(file).fileName() + ':' + QString::number(line));
    QVERIFY(omega.data(Qt::ToolTipRole).toString().contains(source));   // also on the quantity's tooltip

    // Show code is in the row's context menu and has a key.
    auto* showCode = w.findChild<QAction*>("actionShowCode");
    QVERIFY(showCode != nullptr);
    QVERIFY(view->actions().contains(showCode));
    QCOMPARE(view->contextMenuPolicy(), Qt::ActionsContextMenu);
    QVERIFY(!showCode->shortcuts().isEmpty());
    showCode->trigger();

    CodeView* code = w.codeView();
    QTRY_VERIFY(code->isVisible());
    QCOMPARE(code->file(), file);
    QCOMPARE(code->highlightedLine(), line);
    QCOMPARE(code->headerText(), source);
    // The highlighted line is the file's line, and it is code, not a blank or a comment.
    QFile onDisk(QStringLiteral(RBW_SOURCE_DIR "/") + file);
    QVERIFY(onDisk.open(QIODevice::ReadOnly | QIODevice::Text));
    const QStringList lines = QString::fromUtf8(onDisk.readAll()).split('\n');
    QVERIFY(line >= 1 && line <= lines.size());
    QCOMPARE(code->lineText(line), lines[line - 1]);
    const QString statement = code->lineText(line).trimmed();
    QVERIFY2(!statement.isEmpty() && !statement.startsWith("//"), qPrintable(statement));
    QVERIFY2(statement.contains("omega"), qPrintable(statement));   // the statement that records omega
    // On screen: the line and the context above it, where the equation comment is.
    QTRY_VERIFY(code->lineOnScreen(line));
    QCOMPARE(code->firstVisibleLine(), std::max(1, line - CodeView::kContextLines));
    bool commentAbove = false;
    for (int k = std::max(1, line - CodeView::kContextLines); k < line; ++k) {
        QVERIFY2(code->lineOnScreen(k), qPrintable(QString::number(k)));
        commentAbove = commentAbove || code->lineText(k).trimmed().startsWith("//");
    }
    QVERIFY2(commentAbove, "the equation comment above the statement is on screen");

    // Negative control: a group row has no code.
    view->setCurrentIndex(omega.parent());
    view->selectionModel()->clearSelection();
    QVERIFY(!w.showCodeOfCurrentRow());
    QCOMPARE(code->highlightedLine(), line);   // unchanged
}

void TestApp::modelIsConsistent()
{
    MainWindow w;
    QAbstractItemModelTester tester(w.traceModel(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    QVERIFY(w.openLesson("03-two-box-collision"));
    auto* step = w.findChild<QAction*>("actionStep");
    for (int i = 0; i < 30; ++i) step->trigger();
    w.findChild<QAction*>("actionStepBack")->trigger();
}

void TestApp::contactsGroupedByPair()
{
    // Lesson 6: three cubes land on a vertex (1 contact), an edge (2) and a face (4).
    // The table groups the face's 4 corners (and the edge's 2) under one node of the
    // pair, and lists the vertex's single contact on its own.
    const SceneLoadResult loaded = loadSceneFile(QStringLiteral(RBW_SOURCE_DIR "/lessons/06-box-on-plane/scene.json"));
    QVERIFY(loaded.ok());
    World world(*loaded.scene);
    StepTrace trace;
    bool fourCorners = false;
    for (int k = 0; k < 400 && !fourCorners; ++k) {
        QVERIFY(world.step(&trace).ok);
        int faceContacts = 0;
        for (const ContactHeader& c : trace.contacts) faceContacts += c.bodyA == 2 ? 1 : 0;
        fourCorners = faceContacts == 4;
    }
    QVERIFY2(fourCorners, "the face cube never had 4 contacts at once");
    TraceModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    model.setTrace(trace, *loaded.scene);
    QModelIndex collisions;
    for (int r = 0; r < model.rowCount(); ++r) {
        if (model.index(r, 0).data().toString() == QLatin1String("Collisions")) collisions = model.index(r, 0);
    }
    QVERIFY(collisions.isValid());
    QModelIndex facePair;
    for (int r = 0; r < model.rowCount(collisions); ++r) {
        if (model.index(r, 0, collisions).data().toString() == QStringLiteral("face ↔ ground · 4 contacts")) {
            facePair = model.index(r, 0, collisions);
        }
    }
    QVERIFY(facePair.isValid());
    QCOMPARE(model.rowCount(facePair), 4);
    // Each point node holds that contact's rows, the impulse among them.
    const QModelIndex point = model.index(0, 0, facePair);
    QVERIFY(point.data().toString().startsWith(QLatin1String("contact ")));
    QVERIFY(findRow(&model, QStringLiteral("impulse"), point).isValid());
}

// Lesson 11 (manifold model) names each point's group with its pair, feature and
// point ("contact 7 · stack-1 ↔ stack-2 · face-face (reference A) · point 3 of 4"),
// far wider than a quantity's name. Sized to its contents, the Quantity column pushed
// Before and After off the table at the default window size. The column is capped at
// a third of the table (the full name is the group's tooltip), so the After column
// starts on screen.
void TestApp::valuesStayOnScreenWithLongGroupNames()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("11-resting-contact"));
    auto* step = w.findChild<QAction*>("actionStep");
    for (int k = 0; k < 12; ++k) step->trigger();
    QCoreApplication::processEvents();
    auto* view = w.findChild<QTreeView*>("traceView");
    QVERIFY(view != nullptr);
    const int width = view->viewport()->width();
    // At least 40 px of the After column (its first digits) are on screen.
    const int after = view->columnViewportPosition(TraceModel::ValueColumn);
    QVERIFY2(after + 40 <= width, qPrintable(QStringLiteral("After starts at %1 of %2").arg(after).arg(width)));
    // The control: sized to its contents, the Quantity column pushes After off screen.
    const int capped = view->columnWidth(TraceModel::QuantityColumn);
    view->resizeColumnToContents(TraceModel::QuantityColumn);
    QVERIFY2(view->columnViewportPosition(TraceModel::ValueColumn) + 40 > width,
             qPrintable(QStringLiteral("natural width %1 px").arg(view->columnWidth(TraceModel::QuantityColumn))));
    view->setColumnWidth(TraceModel::QuantityColumn, capped);
    // A group's whole label is its tooltip, for where it is elided.
    const QModelIndex collisions = [&] {
        for (int r = 0; r < w.traceModel()->rowCount(); ++r) {
            const QModelIndex i = w.traceModel()->index(r, 0);
            if (i.data().toString() == QLatin1String("Collisions")) return i;
        }
        return QModelIndex();
    }();
    QVERIFY(collisions.isValid());
    QModelIndex pair;   // the first group under Collisions (a pair of bodies)
    for (int r = 0; r < w.traceModel()->rowCount(collisions) && !pair.isValid(); ++r) {
        const QModelIndex i = w.traceModel()->index(r, 0, collisions);
        if (w.traceModel()->rowCount(i) > 0) pair = i;
    }
    QVERIFY(pair.isValid());
    QVERIFY(!pair.data().toString().isEmpty());
    QCOMPARE(pair.data(Qt::ToolTipRole).toString(), pair.data().toString());
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
    const QList<QPointF> E = w.plotPanel()->points("total");
    const QList<QPointF> Trot = w.plotPanel()->points("kinetic_rotational");
    QCOMPARE(E.size(), steps + 1);
    for (int k = 0; k < steps; ++k) {
        const QJsonObject d = trace[k].toObject().value("diagnostics").toObject();
        QCOMPARE(E[k + 1].x(), trace[k].toObject().value("time").toDouble());
        QCOMPARE(E[k + 1].y(), d.value("total_energy").toDouble());
        QCOMPARE(Trot[k + 1].y(), d.value("kinetic_energy_rotational").toDouble());
    }
}

void TestApp::dragPullsTheBox()
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

void TestApp::framebufferShowsTheBoxes()
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

void TestApp::lesson3CollisionStep()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("03-two-box-collision"));
    w.findChild<QDockWidget*>("derivationDock")->raise();
    auto* step = w.findChild<QAction*>("actionStep");
    // Step until the first contact (tst_collision_lessons derives when it comes).
    int k = 0;
    while (k < 200 && (w.session()->currentTrace() == nullptr || w.session()->currentTrace()->contacts.empty())) {
        step->trigger();
        ++k;
    }
    QVERIFY(k < 200);
    const QAbstractItemModel* model = w.traceModel();
    for (const char* id : {"point", "normal", "relative_velocity", "numerator", "denominator", "impulse"}) {
        QVERIFY2(findRow(model, id).isValid(), id);
    }
    // J = 64/27 = 2.370370...
    QVERIFY2(valueText(model, findRow(model, "impulse")).startsWith("2.37037"), qPrintable(valueText(model, findRow(model, "impulse"))));
    DerivationView* page = w.derivationView();
    QVERIFY(waitRendered(page));
    QCOMPARE(page->errorCount(), 0);
    const QString text = pageText(page);
    QVERIFY2(text.contains("2.37037"), "J's value on the page");
    QVERIFY(w.derivationHtml().contains("numerator") || w.derivationHtml().contains("Numerator"));
}

void TestApp::kTogglesTheTorque()
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

void TestApp::pushKeysInLesson2()
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

void TestApp::keysDialogListsEveryShortcut()
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

void TestApp::parameterKeysChangeTheScene()
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

void TestApp::resetClearsTrace()
{
    MainWindow w;
    QVERIFY(w.openLesson("01-one-step"));
    w.findChild<QAction*>("actionStep")->trigger();
    QVERIFY(w.traceModel()->rowCount() > 0);
    QCOMPARE(w.world()->stepIndex(), 1L);
    w.findChild<QAction*>("actionReset")->trigger();
    QCOMPARE(w.world()->stepIndex(), 0L);
    QCOMPARE(w.traceModel()->rowCount(), 0);
    QCOMPARE(w.plotPanel()->sampleCount(), 1);
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

int main(int argc, char* argv[])
{
    // As in the app's main(): shared GL contexts for QtWebEngine and the 3D view.
    QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QSurfaceFormat::setDefaultFormat(SceneView::requestedFormat());
    QApplication app(argc, argv);
    QApplication::setOrganizationName("rigid-workbook-tests");
    TestApp test;
    return QTest::qExec(&test, argc, argv);
}

#include "tst_app.moc"
