// The tools of issue 12 in the whole window under Xvfb, driven as a student drives
// them: the history scrubber (any recorded step exactly as `rbw run --steps N`
// prints it), the keys after editing a box in the parameter bar, "Plot over time"
// of any quantity (the series against `rbw run --trace all`) and the lesson texts'
// statements.
//
// Expected numbers come from the real rbw binary (tests/test_support.h, runRbw) and
// are compared bit for bit: both front ends run the same physics.
#include "app/core/session.h"
#include "app/gui/style/body_colours.h"
#include "app/gui/panels/accuracy/accuracy_panel.h"
#include "app/gui/shell/history_scrubber.h"
#include "app/gui/shell/main_window.h"
#include "app/gui/shell/parameter_bar.h"
#include "app/gui/panels/plots/body_plot_panel.h"
#include "app/gui/panels/plots/plot_panel.h"
#include "app/gui/panels/plots/quantity_plot_panel.h"
#include "app/gui/panels/quantities/trace_model.h"
#include "app/gui/panels/view/scene_view.h"
#include "app/gui/panels/view/view_style.h"
#include "tests/test_support.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QImage>
#include <QLineEdit>
#include <QTemporaryDir>
#include <QTreeView>
#include <QValueAxis>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSlider>
#include <QSpinBox>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QtTest>

#include <cstdio>
#include <cstdlib>

using namespace rbw;
using rbw::test::flatten;
using rbw::test::runRbw;

namespace {

// Numbers are read from rbw's text with strtod (correctly rounded), not through
// QJsonValue::toDouble, whose parser can be one ulp off: see exactJson().
QList<double> jsonNumbers(const QJsonValue& v)
{
    QList<double> out;
    if (v.isString()) {
        const QByteArray text = v.toString().toLatin1();
        out << std::strtod(text.constData(), nullptr);
    } else if (v.isDouble()) {
        out << v.toDouble();
    } else if (v.isArray()) {
        for (const QJsonValue& x : v.toArray()) out << jsonNumbers(x);
    }
    return out;
}

// rbw's JSON with every number turned into a string holding its exact text (rbw
// pretty-prints one number per line, after `"key": ` or alone in an array), so the
// comparison is bit for bit.
QJsonObject exactJson(const QByteArray& out)
{
    static const QRegularExpression number(QStringLiteral(R"(^(\s*|.*": )(-?[0-9][0-9.eE+-]*)(,?)$)"),
                                           QRegularExpression::MultilineOption);
    QString text = QString::fromUtf8(out);
    text.replace(number, QStringLiteral("\\1\"\\2\"\\3"));
    return QJsonDocument::fromJson(text.toUtf8()).object();
}

// rbw's JSON for a scene run for `steps` steps with the given --trace.
QJsonObject rbwRun(const QString& scene, long steps, const QString& trace)
{
    const rbw::test::RbwRun r = runRbw({"run", QStringLiteral(RBW_SOURCE_DIR "/lessons/") + scene, "--steps",
                                        QString::number(steps), "--trace", trace, "--format", "json"});
    if (r.exitCode != 0) qWarning("rbw failed: %s", qPrintable(r.err));
    return exactJson(r.out);
}

// Exact equality, element by element. The only two doubles == treats as equal that
// differ in their bits are +0 and -0, and rbw prints -0 as "0" (value_format.cpp), so
// that is the one difference a text comparison cannot see anyway.
bool sameNumbers(const QList<double>& a, const QList<double>& b)
{
    if (a.size() != b.size()) return false;
    for (qsizetype i = 0; i < a.size(); ++i) {
        if (!(a[i] == b[i])) return false;
    }
    return true;
}

QString hexText(const QList<double>& v)
{
    QStringList parts;
    for (double d : v) {
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%a", d);
        parts << QString::fromLatin1(buffer);
    }
    return parts.join(' ');
}

// Compares the world's state with rbw's "bodies" (bit for bit) and the current trace
// with rbw's last trace entry by entry. Empty when equal, else the first difference.
QString compareWithRbw(const World& world, const StepTrace* trace, const QJsonObject& run)
{
    const QJsonArray bodies = run.value("bodies").toArray();
    if (bodies.size() != static_cast<qsizetype>(world.states().size())) return "body count differs";
    for (int b = 0; b < bodies.size(); ++b) {
        const QJsonObject o = bodies[b].toObject();
        const BodyState& s = world.states()[b];
        const QList<QPair<QString, QList<double>>> fields = {
            {"position", rbw::test::flat(s.x_W)},          {"linear_velocity", rbw::test::flat(s.v_W)},
            {"orientation", rbw::test::flat(s.q_WB)},      {"angular_momentum", rbw::test::flat(s.L_W)},
            {"angular_velocity", rbw::test::flat(s.omega_W)}};
        for (const auto& [key, mine] : fields) {
            if (!sameNumbers(jsonNumbers(o.value(key)), mine)) {
                return QStringLiteral("body %1 %2: app %3, rbw %4")
                    .arg(b)
                    .arg(key, rbw::test::listText(mine), rbw::test::listText(jsonNumbers(o.value(key))));
            }
        }
    }
    if (!sameNumbers(jsonNumbers(run.value("time")), {world.time()})) return "time differs";
    const QJsonArray traces = run.value("trace").toArray();
    if (traces.isEmpty() || trace == nullptr) return "no trace";
    const QJsonArray quantities = traces.last().toObject().value("quantities").toArray();
    if (quantities.size() != static_cast<qsizetype>(trace->entries.size())) {
        return QStringLiteral("trace has %1 entries, rbw %2").arg(trace->entries.size()).arg(quantities.size());
    }
    for (int i = 0; i < quantities.size(); ++i) {
        const QJsonObject q = quantities[i].toObject();
        const TraceEntry& e = trace->entries[static_cast<size_t>(i)];
        if (q.value("id").toString() != QLatin1String(e.info->id) || !sameNumbers(jsonNumbers(q.value("value")), flatten(e.value))) {
            return QStringLiteral("entry %1 (%2): app %3, rbw %4 %5")
                .arg(i)
                .arg(QLatin1String(e.info->id), hexText(flatten(e.value)), q.value("id").toString(),
                     hexText(jsonNumbers(q.value("value"))));
        }
    }
    return {};
}

// The table row of quantity `id` of body `body` (depth first).
QModelIndex findRow(const TraceModel* model, const QString& id, int body, const QModelIndex& parent = {})
{
    for (int r = 0; r < model->rowCount(parent); ++r) {
        const QModelIndex i = model->index(r, 0, parent);
        const TraceEntry* e = model->entryAt(i);
        if (e != nullptr && id == QLatin1String(e->info->id) && e->body == body) return i;
        const QModelIndex found = findRow(model, id, body, i);
        if (found.isValid()) return found;
    }
    return {};
}

// (t, component c) of quantity `id` of body `bodyName` in every step of rbw's
// --trace all, bit for bit.
QList<QPointF> rbwSeries(const QJsonObject& run, const QString& id, const QString& bodyName, int component)
{
    QList<QPointF> out;
    for (const QJsonValue& step : run.value("trace").toArray()) {
        const QJsonObject o = step.toObject();
        for (const QJsonValue& q : o.value("quantities").toArray()) {
            const QJsonObject e = q.toObject();
            if (e.value("id").toString() == id && e.value("body").toString() == bodyName) {
                out.append(QPointF(jsonNumbers(o.value("time")).value(0), jsonNumbers(e.value("value")).value(component)));
            }
        }
    }
    return out;
}

} // namespace

class TestStudentTools : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void scrubToStep400OfLesson4();
    void scrubberRangeFollowsTheHistory();
    void plotOmegaYOfLesson9();
    void plotAxesAreReadable();
    void plotAContactField();
    void lesson9FlipsInThePlots_data();
    void lesson9FlipsInThePlots();
    void lessonTextsMatchTheWindow();
    void oneColourPerBody();
    void accuracyPanelFitsItsDock();
    void keysReturnToTheViewAfterEditing_data();
    void keysReturnToTheViewAfterEditing();
    void keysReturnToTheViewAfterEditingH();
};

void TestStudentTools::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
}

void TestStudentTools::scrubToStep400OfLesson4()
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

void TestStudentTools::scrubberRangeFollowsTheHistory()
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

// Plot over time of lesson 9's ω (explicit-Euler body): the y series is rbw's
// angular_velocity[1] of that body in every step of --trace all, bit for bit.
void TestStudentTools::plotOmegaYOfLesson9()
{
    MainWindow w;
    w.resize(1600, 1000);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("09-tennis-racket"));
    const long steps = 300;
    QVERIFY(w.goToStep(200));   // recorded before the plot exists: it reads the history
    QApplication::processEvents();
    const SceneDef& scene = w.world()->scene();
    const QString body0 = QString::fromStdString(scene.bodies[0].name);
    const QModelIndex row = findRow(w.traceModel(), "angular_velocity", 0);
    QVERIFY(row.isValid());
    // A group row is refused (negative control), the quantity's row plotted.
    QVERIFY(!w.plotRowOverTime(row.parent()));
    QCOMPARE(w.quantityPlotPanel()->plotCount(), 0);
    QVERIFY(w.plotRowOverTime(row));
    QCOMPARE(w.quantityPlotPanel()->plotCount(), 1);
    QuantityPlot* plot = w.quantityPlotPanel()->plot(0);
    QCOMPARE(plot->series().sampleCount(), 200);
    QVERIFY(w.goToStep(steps));   // then one sample per step
    w.quantityPlotPanel()->refreshNow();

    const QJsonObject run = rbwRun("09-tennis-racket/scene.json", steps, "all");
    const QList<QPointF> expectedY = rbwSeries(run, "angular_velocity", body0, 1);
    QCOMPARE(expectedY.size(), static_cast<qsizetype>(steps));
    QCOMPARE(plot->lineCount(), 3);
    const QList<QPointF> y = plot->linePoints(1);
    QCOMPARE(y.size(), expectedY.size());
    for (qsizetype i = 0; i < y.size(); ++i) {
        QVERIFY2(y[i].x() == expectedY[i].x() && y[i].y() == expectedY[i].y(),
                 qPrintable(QStringLiteral("sample %1: plot (%2, %3), rbw (%4, %5)")
                                .arg(i)
                                .arg(y[i].x(), 0, 'g', 17)
                                .arg(y[i].y(), 0, 'g', 17)
                                .arg(expectedY[i].x(), 0, 'g', 17)
                                .arg(expectedY[i].y(), 0, 'g', 17)));
    }
    // Negative control: the x component is another series.
    QVERIFY(plot->linePoints(0) != y);
    // The line on screen shows these points, in body 0's colour.
    QCOMPARE(plot->lineName(1), QStringLiteral("ω (%1) y").arg(body0));
    QCOMPARE(plot->colour(), bodyQColor(0, false, body0));
    QCOMPARE(w.bodyPlotPanel()->lineColour(0), plot->colour());

    // Scrubbing back drops the later samples; forward brings them back exactly.
    QVERIFY(w.goToStep(120));
    QCOMPARE(plot->series().sampleCount(), 120);
    QVERIFY(w.goToStep(steps));
    QCOMPARE(plot->linePoints(1), y);

    // Length |ω| and a phase plot ω_y against ω_z (pairs of the same step).
    plot->setShowNorm(true);
    QCOMPARE(plot->lineCount(), 1);
    const QList<QPointF> expectedZ = rbwSeries(run, "angular_velocity", body0, 2);
    plot->setShowNorm(false);
    const int zChoice = plot->xAxisBox()->findText(QStringLiteral("ω (%1) z").arg(body0));
    QVERIFY(zChoice > 0);
    plot->xAxisBox()->setCurrentIndex(zChoice);
    emit plot->xAxisBox()->activated(zChoice);
    const QList<QPointF> phase = plot->linePoints(1);
    QCOMPARE(phase.size(), expectedY.size());
    QCOMPARE(phase.first(), QPointF(expectedZ.first().y(), expectedY.first().y()));
    QCOMPARE(phase.last(), QPointF(expectedZ.last().y(), expectedY.last().y()));
    plot->xAxisBox()->setCurrentIndex(0);
    emit plot->xAxisBox()->activated(0);

    // CSV and PNG, written atomically: the CSV has every sample as rbw prints it.
    QTemporaryDir dir;
    QString error;
    QVERIFY2(plot->exportCsv(dir.filePath("omega.csv"), &error), qPrintable(error));
    QFile csv(dir.filePath("omega.csv"));
    QVERIFY(csv.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = csv.readAll().trimmed().split('\n');
    QCOMPARE(lines.size(), steps + 1);
    QVERIFY(lines[0].startsWith("step,t,"));
    const QList<QByteArray> last = lines.last().split(',');
    QCOMPARE(last.value(0).toLong(), steps - 1);
    QCOMPARE(std::strtod(last.value(3).constData(), nullptr), expectedY.last().y());
    QVERIFY2(plot->exportPng(dir.filePath("omega.png"), &error), qPrintable(error));
    QImage png(dir.filePath("omega.png"));
    QVERIFY(!png.isNull() && png.width() > 100);
    QVERIFY(!plot->exportCsv(dir.filePath("missing/omega.csv"), &error));   // negative control
    QVERIFY(!QFile::exists(dir.filePath("missing/omega.csv")));

    // Another lesson: the plots of this scene go.
    QVERIFY(w.openLesson("05-spinning"));
    QCOMPARE(w.quantityPlotPanel()->plotCount(), 0);
}

// A contact's field plotted over time: lesson 3's J has one sample, in the step of
// the collision (k = 2), and it is rbw's J = 64/27 of that step, bit for bit; the
// other steps have no contact and no sample.
void TestStudentTools::plotAContactField()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("03-two-box-collision"));
    QVERIFY(w.goToStep(3));
    QApplication::processEvents();
    const QModelIndex row = findRow(w.traceModel(), "impulse", 0);
    QVERIFY(row.isValid());
    QVERIFY(w.plotRowOverTime(row));
    QuantityPlot* plot = w.quantityPlotPanel()->plot(0);
    QVERIFY(w.goToStep(6));   // steps without the contact add nothing
    const QJsonObject run = rbwRun("03-two-box-collision/scene.json", 6, "all");
    double J = 0.0;
    double t = 0.0;
    int contacts = 0;
    for (const QJsonValue& step : run.value("trace").toArray()) {
        for (const QJsonValue& q : step.toObject().value("quantities").toArray()) {
            if (q.toObject().value("id").toString() == "impulse") {
                J = jsonNumbers(q.toObject().value("value")).value(0);
                t = jsonNumbers(step.toObject().value("time")).value(0);
                ++contacts;
            }
        }
    }
    QCOMPARE(contacts, 1);
    QCOMPARE(plot->series().sampleCount(), 1);
    QCOMPARE(plot->series().samples()[0].step, 2L);
    QCOMPARE(plot->linePoints(0), QList<QPointF>{QPointF(t, J)});
    QVERIFY(std::abs(J - 64.0 / 27.0) < 1e-12);   // lessons/03-two-box-collision/lesson.md
}

// The plots' tick labels are whole at 1600x1000 ("…" was on every y tick of the
// energy plot), also after a run has filled them.
void TestStudentTools::plotAxesAreReadable()
{
    MainWindow w;
    w.resize(1600, 1000);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("04-many-boxes"));
    QVERIFY(w.goToStep(300));
    PlotPanel* energy = w.plotPanel();
    energy->refreshNow();
    QApplication::processEvents();
    for (QValueAxis* axis : energy->findChildren<QValueAxis*>()) {
        if (!axis->isVisible()) continue;
        QVERIFY2(!axis->labelsTruncated(), qPrintable(axis->titleText()));
    }
    const QModelIndex row = findRow(w.traceModel(), "linear_velocity", 1);
    QVERIFY(row.isValid());
    QVERIFY(w.plotRowOverTime(row));
    QuantityPlot* plot = w.quantityPlotPanel()->plot(0);
    w.quantityPlotPanel()->refreshNow();
    QApplication::processEvents();
    QVERIFY(!plot->yAxis()->labelsTruncated());
    QVERIFY(!plot->xAxis()->labelsTruncated());
    QVERIFY(plot->yAxis()->tickCount() >= 2);
}

// lessons/09-tennis-racket/lesson.md, "Watch the flip in the app": Plot over time
// of a box's rotation matrix, component R 22, starts at +1 and first changes sign at
// t = 2.85 s (rk4, implicit midpoint) and 2.86 s (explicit Euler); the implicit-
// midpoint box's L_B,y starts at +5.2 and changes sign too.
void TestStudentTools::lesson9FlipsInThePlots_data()
{
    QTest::addColumn<int>("body");
    QTest::addColumn<QString>("id");
    QTest::addColumn<int>("component");
    QTest::addColumn<double>("start");
    QTest::addColumn<QString>("firstFlip");   // t of the first sample with the other sign, as the text writes it
    QTest::newRow("explicit-euler R 22") << 0 << "rotation_matrix" << 4 << 1.0 << "2.86";
    QTest::newRow("rk4 R 22") << 1 << "rotation_matrix" << 4 << 1.0 << "2.85";
    QTest::newRow("implicit-midpoint R 22") << 2 << "rotation_matrix" << 4 << 1.0 << "2.85";
    QTest::newRow("implicit-midpoint L_B y") << 2 << "body_angular_momentum" << 1 << 5.2 << "";
}

void TestStudentTools::lesson9FlipsInThePlots()
{
    QFETCH(int, body);
    QFETCH(QString, id);
    QFETCH(int, component);
    QFETCH(double, start);
    QFETCH(QString, firstFlip);
    QFile f(QStringLiteral(RBW_SOURCE_DIR "/lessons/09-tennis-racket/lesson.md"));
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(f.readAll());
    if (!firstFlip.isEmpty()) QVERIFY(text.contains(QStringLiteral("t = %1 s").arg(firstFlip)));

    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("09-tennis-racket"));
    QVERIFY(w.goToStep(320));
    QApplication::processEvents();
    const QModelIndex row = findRow(w.traceModel(), id, body);
    QVERIFY2(row.isValid(), qPrintable(id));
    QVERIFY(w.plotRowOverTime(row));
    QuantityPlot* plot = w.quantityPlotPanel()->plot(0);
    const QList<QPointF> points = plot->linePoints(component);
    QCOMPARE(points.size(), qsizetype(320));
    QVERIFY(std::abs(points.first().y() - start) < 0.01 * start);
    qsizetype flip = -1;
    for (qsizetype i = 1; i < points.size() && flip < 0; ++i) {
        if ((points[i].y() > 0) != (points[0].y() > 0)) flip = i;
    }
    QVERIFY2(flip > 0, "no flip in the first 3.2 s");
    if (!firstFlip.isEmpty()) QCOMPARE(QString::number(points[flip].x(), 'f', 2), firstFlip);
}

// Lesson 1 speaks of the quantities table "on the right"; lesson 7 of File → Open.
void TestStudentTools::lessonTextsMatchTheWindow()
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
void TestStudentTools::oneColourPerBody()
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
void TestStudentTools::accuracyPanelFitsItsDock()
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

void TestStudentTools::keysReturnToTheViewAfterEditing_data()
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

void TestStudentTools::keysReturnToTheViewAfterEditing()
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
void TestStudentTools::keysReturnToTheViewAfterEditingH()
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

int main(int argc, char* argv[])
{
    QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QSurfaceFormat::setDefaultFormat(SceneView::requestedFormat());
    QApplication app(argc, argv);
    QApplication::setOrganizationName("rigid-workbook-tests");
    TestStudentTools test;
    return QTest::qExec(&test, argc, argv);
}

#include "tst_student_tools.moc"
