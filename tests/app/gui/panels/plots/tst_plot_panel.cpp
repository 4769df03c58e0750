// The plot panel under Xvfb. It is fed what the app feeds it, each step's
// StepTrace::diagnostics from a World running a lesson, and must then show exactly
// the numbers the rbw command line prints for the same run: one point per step,
// every series equal to the CLI's per-step "diagnostics" (docs/cli.md). Also: step
// back (truncate), the axis ranges, the visibility check boxes, decimation, and the
// PNG and CSV exports.
#include "app/scene/scene_loader.h"
#include "app/gui/panels/plots/plot_panel.h"
#include "physics/engine/world.h"
#include "tests/test_support.h"

#include <QCheckBox>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <limits>

using rbw::Diagnostics;
using rbw::PlotChart;
using rbw::PlotPanel;
using rbw::plotSeriesId;
using Q = rbw::PlotQuantity;
using rbw::ValueRange;

namespace {

QString lessonScene(const QString& id)
{
    return QStringLiteral(RBW_SOURCE_DIR "/lessons/%1/scene.json").arg(id);
}

// Steps a lesson's world `steps` times with a trace and appends each step's
// diagnostics to the panel. Fails the test (returns false) on any refusal.
bool feedLesson(PlotPanel& panel, const QString& id, int steps, QString* why)
{
    const rbw::SceneLoadResult loaded = rbw::loadSceneFile(lessonScene(id));
    if (!loaded.ok()) {
        *why = loaded.errors.join('\n');
        return false;
    }
    rbw::World world(*loaded.scene);
    rbw::StepTrace trace;
    for (int k = 0; k < steps; ++k) {
        const rbw::StepStatus status = world.step(&trace);
        if (!status.ok) {
            *why = QString::fromStdString(status.message);
            return false;
        }
        if (!panel.appendStep(trace.time, trace.diagnostics)) {
            *why = panel.lastError();
            return false;
        }
        if (panel.sampleCount() != k + 1) {
            *why = QStringLiteral("after step %1 the panel has %2 samples").arg(k).arg(panel.sampleCount());
            return false;
        }
    }
    return true;
}

// The CLI's diagnostics of one step, in the catalogue's order (plot_catalogue.h),
// split in the numbers the plot must show unchanged and the two vector lengths.
struct CliRow {
    double t = 0.0;
    QList<double> recorded;   // T_trans, T_rot, V, E, P_x, P_y, P_z, L_O,x, L_O,y, L_O,z
    QList<double> lengths;    // |P|, |L_O| = sqrt(x^2 + y^2 + z^2) of the CLI's vectors
};

CliRow cliRow(const QJsonObject& step)
{
    const QJsonObject d = step.value("diagnostics").toObject();
    // The JSON's fields are named by the diagnostics catalogue, as the CSV's columns.
    const auto field = [&d](const rbw::DiagnosticInfo<Diagnostics>& info) {
        return d.value(QLatin1String(info.id.data(), static_cast<qsizetype>(info.id.size())));
    };
    const QJsonArray P = field(rbw::diag::linear_momentum).toArray();
    const QJsonArray L = field(rbw::diag::angular_momentum_origin).toArray();
    auto length = [](const QJsonArray& v) {
        return std::sqrt(v[0].toDouble() * v[0].toDouble() + v[1].toDouble() * v[1].toDouble()
                         + v[2].toDouble() * v[2].toDouble());
    };
    CliRow row;
    row.t = step.value("time").toDouble();
    row.recorded = {field(rbw::diag::kinetic_translational).toDouble(), field(rbw::diag::kinetic_rotational).toDouble(),
                    field(rbw::diag::potential).toDouble(), field(rbw::diag::total).toDouble(), P[0].toDouble(), P[1].toDouble(), P[2].toDouble(),
                    L[0].toDouble(), L[1].toDouble(), L[2].toDouble()};
    row.lengths = {length(P), length(L)};
    return row;
}

// The plotted numbers of sample k, in the same order as CliRow.
struct PlotRow {
    double t = 0.0;
    QList<double> recorded;
    QList<double> lengths;
};

PlotRow plotRow(const QHash<QString, QList<QPointF>>& series, int k)
{
    PlotRow row;
    row.t = series.value(plotSeriesId(Q::Total))[k].x();
    for (Q q : {Q::KineticTranslational, Q::KineticRotational, Q::Potential, Q::Total, Q::P_x, Q::P_y, Q::P_z,
                Q::L_O_x, Q::L_O_y, Q::L_O_z}) {
        row.recorded << series.value(plotSeriesId(q))[k].y();
    }
    row.lengths << series.value(plotSeriesId(Q::P_norm))[k].y() << series.value(plotSeriesId(Q::L_O_norm))[k].y();
    return row;
}

// Empty when the plot shows the CLI's numbers: time and recorded values exactly
// (both are the same doubles: JSON prints the shortest round-trip form), the two
// lengths to 1e-12 relative (the CLI does not print them; the test's sqrt may sum
// in another order than Eigen's norm).
QString compareRow(const PlotRow& plot, const CliRow& cli)
{
    if (!(plot.t == cli.t)) {
        return QStringLiteral("t %1 vs CLI %2").arg(plot.t, 0, 'g', 17).arg(cli.t, 0, 'g', 17);
    }
    const QString recorded = rbw::test::mismatch(plot.recorded, cli.recorded, 0.0);
    if (!recorded.isEmpty()) return QStringLiteral("recorded values: ") + recorded;
    for (int i = 0; i < plot.lengths.size(); ++i) {
        const QString len = rbw::test::mismatch({plot.lengths[i]}, {cli.lengths[i]}, 1e-12);
        if (!len.isEmpty()) return QStringLiteral("length %1: ").arg(i) + len;
    }
    return {};
}

QHash<QString, QList<QPointF>> allSeries(const PlotPanel& panel)
{
    QHash<QString, QList<QPointF>> out;
    for (const QString& id : PlotPanel::seriesIds()) out.insert(id, panel.points(id));
    return out;
}

Diagnostics energyOnly(double tTrans, double tRot, double v, double e)
{
    Diagnostics d;
    d.kineticTranslational = tTrans;
    d.kineticRotational = tRot;
    d.potential = v;
    d.total = e;
    return d;
}

// Share of pixels not (near) white, and of pixels near a colour.
double nonWhiteShare(const QImage& image)
{
    qint64 count = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (c.red() < 240 || c.green() < 240 || c.blue() < 240) ++count;
        }
    }
    return double(count) / (double(image.width()) * image.height());
}

qint64 pixelsNear(const QImage& image, const QColor& colour)
{
    qint64 count = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (std::abs(c.red() - colour.red()) + std::abs(c.green() - colour.green())
                    + std::abs(c.blue() - colour.blue()) < 30) {
                ++count;
            }
        }
    }
    return count;
}

} // namespace

class TestPlotPanel : public QObject {
    Q_OBJECT
private slots:
    void defaultsAndUnknownIds();
    void matchesCliDiagnostics_data();
    void matchesCliDiagnostics();
    void comparisonDetectsASmallChange();
    void refusesNonFiniteSample();
    void truncateDropsLaterPoints();
    void axisRangeCoversVisibleData_data();
    void axisRangeCoversVisibleData();
    void hidingASeriesRescales();
    void checkBoxesToggleSeries();
    void liveUpdatesArriveByTimer();
    void decimatesForDisplayOnly();
    void csvExportRoundTrips();
    void exportsToBadPathFail();
    void pngExportIsDrawn();
    void snapshots_data();
    void snapshots();
};

void TestPlotPanel::defaultsAndUnknownIds()
{
    PlotPanel panel;
    // Totals and energy parts on, vector components off.
    for (Q q : {Q::KineticTranslational, Q::KineticRotational, Q::Potential, Q::Total, Q::P_norm, Q::L_O_norm})
        QVERIFY2(panel.isSeriesVisible(plotSeriesId(q)), qPrintable(plotSeriesId(q)));
    for (Q q : {Q::P_x, Q::P_y, Q::P_z, Q::L_O_x, Q::L_O_y, Q::L_O_z})
        QVERIFY2(!panel.isSeriesVisible(plotSeriesId(q)), qPrintable(plotSeriesId(q)));
    QCOMPARE(PlotPanel::seriesIds().size(), rbw::kPlotQuantityCount);
    QVERIFY(!panel.setSeriesVisible(QStringLiteral("omega"), true));
    QVERIFY(panel.lastError().contains(QStringLiteral("omega")));
    QVERIFY(panel.points(QStringLiteral("omega")).isEmpty());
    QCOMPARE(panel.sampleCount(), 0);
}

void TestPlotPanel::matchesCliDiagnostics_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::addColumn<int>("steps");
    QTest::newRow("01-one-step") << QStringLiteral("01-one-step") << 1;
    QTest::newRow("03-two-box-collision") << QStringLiteral("03-two-box-collision") << 5;
    QTest::newRow("04-many-boxes") << QStringLiteral("04-many-boxes") << 300;
    QTest::newRow("07-bounce") << QStringLiteral("07-bounce") << 400;
}

void TestPlotPanel::matchesCliDiagnostics()
{
    QFETCH(QString, lesson);
    QFETCH(int, steps);
    PlotPanel panel;
    QString why;
    QVERIFY2(feedLesson(panel, lesson, steps, &why), qPrintable(why));
    QCOMPARE(panel.sampleCount(), steps);
    const QHash<QString, QList<QPointF>> series = allSeries(panel);
    for (auto it = series.begin(); it != series.end(); ++it) QCOMPARE(it.value().size(), steps);

    const rbw::test::RbwRun run = rbw::test::runRbw(
        {"run", lessonScene(lesson), "--steps", QString::number(steps), "--trace", "all"});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(run.out, &parseError);
    QVERIFY2(parseError.error == QJsonParseError::NoError, qPrintable(parseError.errorString()));
    const QJsonArray trace = doc.object().value("trace").toArray();
    QCOMPARE(trace.size(), steps);
    for (int k = 0; k < steps; ++k) {
        const QJsonObject step = trace[k].toObject();
        QCOMPARE(step.value("step").toInt(), k);
        const QString diff = compareRow(plotRow(series, k), cliRow(step));
        QVERIFY2(diff.isEmpty(), qPrintable(QStringLiteral("step %1: %2").arg(k).arg(diff)));
    }
}

void TestPlotPanel::comparisonDetectsASmallChange()
{
    // Negative control for compareRow: lesson 7's step 99 as the CLI prints it,
    // with one number changed by 1e-6 relative, must be reported; unchanged it passes.
    PlotPanel panel;
    QString why;
    QVERIFY2(feedLesson(panel, QStringLiteral("07-bounce"), 100, &why), qPrintable(why));
    const rbw::test::RbwRun run =
        rbw::test::runRbw({"run", lessonScene(QStringLiteral("07-bounce")), "--steps", "100", "--trace", "last"});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    const QJsonObject step = QJsonDocument::fromJson(run.out).object().value("trace").toArray()[0].toObject();
    const PlotRow plotted = plotRow(allSeries(panel), 99);
    const CliRow cli = cliRow(step);
    QVERIFY2(compareRow(plotted, cli).isEmpty(), qPrintable(compareRow(plotted, cli)));
    for (int i = 0; i < cli.recorded.size(); ++i) {
        if (cli.recorded[i] == 0.0) continue;
        CliRow changed = cli;
        changed.recorded[i] *= 1.0 + 1e-6;
        QVERIFY2(!compareRow(plotted, changed).isEmpty(), qPrintable(QStringLiteral("entry %1").arg(i)));
    }
    for (int i = 0; i < cli.lengths.size(); ++i) {
        CliRow changed = cli;
        changed.lengths[i] *= 1.0 + 1e-6;
        QVERIFY(!compareRow(plotted, changed).isEmpty());
    }
    CliRow shifted = cli;
    shifted.t += 1e-9;
    QVERIFY(!compareRow(plotted, shifted).isEmpty());
}

void TestPlotPanel::refusesNonFiniteSample()
{
    PlotPanel panel;
    QVERIFY(panel.appendStep(0.01, energyOnly(1, 2, 3, 6)));
    Diagnostics bad = energyOnly(1, 2, 3, 6);
    bad.L_O_W.y() = std::numeric_limits<double>::quiet_NaN();
    QVERIFY(!panel.appendStep(0.02, bad));
    QVERIFY2(panel.lastError().contains(QStringLiteral("not finite")), qPrintable(panel.lastError()));
    QCOMPARE(panel.sampleCount(), 1);
    panel.refreshNow();
    // The axes never saw the NaN.
    QVERIFY(std::isfinite(panel.yAxisRange(PlotChart::AngularMomentum).min));
    QVERIFY(std::isfinite(panel.yAxisRange(PlotChart::AngularMomentum).max));
}

void TestPlotPanel::truncateDropsLaterPoints()
{
    // Run lesson 7 for 200 steps, keeping the world's snapshot after 150 steps.
    const rbw::SceneLoadResult loaded = rbw::loadSceneFile(lessonScene(QStringLiteral("07-bounce")));
    QVERIFY(loaded.ok());
    rbw::World world(*loaded.scene);
    rbw::StepTrace trace;
    PlotPanel panel;
    rbw::WorldSnapshot at150;
    for (int k = 0; k < 200; ++k) {
        if (k == 150) at150 = world.snapshot();
        QVERIFY(world.step(&trace).ok);
        QVERIFY(panel.appendStep(trace.time, trace.diagnostics));
    }
    panel.refreshNow();
    const QHash<QString, QList<QPointF>> before = allSeries(panel);
    // The energy tab is current: its four lines are drawn with every sample.
    QStringList energy;
    for (Q q : {Q::KineticTranslational, Q::KineticRotational, Q::Potential, Q::Total}) energy << plotSeriesId(q);
    for (const QString& id : energy) QCOMPARE(panel.displayedPointCount(id), 200);

    // Step back to 150 steps: exactly the later 50 points go, the first 150 stay.
    panel.truncate(150);
    QCOMPARE(panel.sampleCount(), 150);
    for (const QString& id : PlotPanel::seriesIds()) {
        QCOMPARE(panel.points(id), before.value(id).mid(0, 150));
    }
    panel.refreshNow();
    for (const QString& id : energy) QCOMPARE(panel.displayedPointCount(id), 150);
    // A line that was not drawn catches up when it is shown: P_x on its tab.
    QVERIFY(panel.setSeriesVisible(plotSeriesId(Q::P_x), true));
    panel.setCurrentChart(PlotChart::LinearMomentum);
    QCOMPARE(panel.displayedPointCount(plotSeriesId(Q::P_x)), 150);
    QCOMPARE(panel.displayedPointCount(plotSeriesId(Q::P_norm)), 150);
    panel.setCurrentChart(PlotChart::Energy);
    // The time axis follows: t_max = 150 h now.
    QVERIFY(panel.xAxisRange(PlotChart::Energy).max < before.value(plotSeriesId(Q::Total))[199].x());

    // Running on from the snapshot gives the same 50 points again (the physics is
    // deterministic), so the panel ends where it was.
    world.restore(at150);
    for (int k = 150; k < 200; ++k) {
        QVERIFY(world.step(&trace).ok);
        QVERIFY(panel.appendStep(trace.time, trace.diagnostics));
    }
    for (const QString& id : PlotPanel::seriesIds()) QCOMPARE(panel.points(id), before.value(id));

    // Clamping: more than there is changes nothing; below zero empties.
    panel.truncate(1000);
    QCOMPARE(panel.sampleCount(), 200);
    panel.truncate(-5);
    QCOMPARE(panel.sampleCount(), 0);
    panel.refreshNow();
    for (const QString& id : energy) QCOMPARE(panel.displayedPointCount(id), 0);
}

void TestPlotPanel::axisRangeCoversVisibleData_data()
{
    QTest::addColumn<QString>("visibleId");   // the only visible series of its chart
    QTest::addColumn<QList<double>>("values");
    QTest::addColumn<bool>("constant");
    QTest::newRow("ramp") << plotSeriesId(Q::KineticTranslational) << QList<double>{0, 2.5, 5, 7.5, 10} << false;
    QTest::newRow("negative potential") << plotSeriesId(Q::Potential) << QList<double>{-50, -35, -20} << false;
    QTest::newRow("constant total") << plotSeriesId(Q::Total) << QList<double>{3, 3, 3} << true;
    QTest::newRow("constant zero") << plotSeriesId(Q::KineticRotational) << QList<double>{0, 0} << true;
    QTest::newRow("large values") << plotSeriesId(Q::Total) << QList<double>{2.0e6, 2.5e6, 2.1e6} << false;
    QTest::newRow("tiny values") << plotSeriesId(Q::KineticTranslational) << QList<double>{1e-6, 3e-6} << false;
    QTest::newRow("P_x oscillating") << plotSeriesId(Q::P_x) << QList<double>{-2, 1.5, -0.5, 2} << false;
    QTest::newRow("L_O_z constant") << plotSeriesId(Q::L_O_z) << QList<double>{-7, -7, -7} << true;
}

void TestPlotPanel::axisRangeCoversVisibleData()
{
    QFETCH(QString, visibleId);
    QFETCH(QList<double>, values);
    QFETCH(bool, constant);
    PlotPanel panel;
    const rbw::PlotSeriesInfo* info = rbw::findPlotSeries(visibleId);
    QVERIFY(info != nullptr);
    // Only the row's series is visible in its chart.
    for (const rbw::PlotSeriesInfo& s : rbw::plotSeriesCatalogue()) {
        if (s.chart == info->chart) QVERIFY(panel.setSeriesVisible(s.id, s.quantity == info->quantity));
    }
    // Samples at t = 0.5, 1.0, ...; every series gets the row's value (the others are hidden).
    for (int i = 0; i < values.size(); ++i) {
        const double v = values[i];
        Diagnostics d = energyOnly(v, v, v, v);
        d.P_W = rbw::Vec3(v, v, v);
        d.L_O_W = rbw::Vec3(v, v, v);
        QVERIFY(panel.appendStep(0.5 * (i + 1), d));
    }
    panel.refreshNow();
    const double lo = *std::min_element(values.begin(), values.end());
    const double hi = *std::max_element(values.begin(), values.end());
    // What must be covered (plot_axis_range.h): 5 % beyond the data, v ± 0.05|v|, or [-1, 1] for 0.
    const bool zero = std::max(std::abs(lo), std::abs(hi)) <= 1e-9;
    const double pad = zero ? 1.0 : (constant ? 0.05 * std::abs(lo) : 0.05 * (hi - lo));
    // (The padding stops at 0 for data that does not cross it.)
    const double needMin = (!constant && lo >= 0.0) ? std::max(0.0, lo - pad) : lo - pad;
    const double needMax = (!constant && hi <= 0.0) ? std::min(0.0, hi + pad) : hi + pad;
    const ValueRange y = panel.yAxisRange(info->chart);
    const double slack = 1e-12 * std::max(1.0, std::abs(needMax) + std::abs(needMin));
    QVERIFY2(y.min <= needMin + slack && y.max >= needMax - slack,
             qPrintable(QStringLiteral("axis [%1, %2] misses [%3, %4]").arg(y.min).arg(y.max).arg(needMin).arg(needMax)));
    // ... and not much more: nice numbers widen by at most a few ticks.
    QVERIFY2(y.max - y.min <= 3.0 * (needMax - needMin),
             qPrintable(QStringLiteral("axis [%1, %2] too wide for [%3, %4]").arg(y.min).arg(y.max).arg(needMin).arg(needMax)));
    // Time: from 0 to past the last sample.
    const ValueRange x = panel.xAxisRange(info->chart);
    QCOMPARE(x.min, 0.0);
    QVERIFY(x.max >= 0.5 * values.size());
    QVERIFY(x.max <= 3.0 * 0.5 * values.size());
}

void TestPlotPanel::hidingASeriesRescales()
{
    // E = 1000 far above T_trans in [0, 1]: with E shown the axis reaches 1000;
    // hidden, the axis fits [0, 1] (T_rot = V = 0 stay visible).
    PlotPanel panel;
    for (int i = 0; i <= 10; ++i) QVERIFY(panel.appendStep(0.1 * i, energyOnly(0.1 * i, 0, 0, 1000)));
    panel.refreshNow();
    QVERIFY(panel.yAxisRange(PlotChart::Energy).max >= 1000.0);
    QVERIFY(panel.setSeriesVisible(plotSeriesId(Q::Total), false));
    QVERIFY(!panel.isSeriesVisible(plotSeriesId(Q::Total)));
    panel.refreshNow();
    const ValueRange y = panel.yAxisRange(PlotChart::Energy);
    QVERIFY2(y.max >= 1.05 && y.max <= 3.0, qPrintable(QString::number(y.max)));
    QVERIFY(y.min <= 0.0 && y.min >= -1.0);
}

void TestPlotPanel::checkBoxesToggleSeries()
{
    PlotPanel panel;
    QCheckBox* px = nullptr;
    for (QCheckBox* box : panel.findChildren<QCheckBox*>()) {
        if (box->text() == rbw::plotSeriesInfo(Q::P_x).label) px = box;
    }
    QVERIFY(px != nullptr);
    QVERIFY(!px->isChecked());
    QSignalSpy spy(&panel, &PlotPanel::seriesVisibilityChanged);
    px->setChecked(true);
    QVERIFY(panel.isSeriesVisible(plotSeriesId(Q::P_x)));
    QCOMPARE(spy.count(), 1);
    QCOMPARE(spy[0][0].toString(), plotSeriesId(Q::P_x));
    // The API ticks the box too.
    QVERIFY(panel.setSeriesVisible(plotSeriesId(Q::P_x), false));
    QVERIFY(!px->isChecked());
}

void TestPlotPanel::liveUpdatesArriveByTimer()
{
    // Without refreshNow(): the throttle timer brings the points to the chart.
    PlotPanel panel;
    for (int i = 1; i <= 30; ++i) QVERIFY(panel.appendStep(0.01 * i, energyOnly(i, 0, 0, i)));
    QTRY_COMPARE(panel.displayedPointCount(plotSeriesId(Q::Total)), 30);
    QTRY_VERIFY(panel.yAxisRange(PlotChart::Energy).max >= 30.0);
}

void TestPlotPanel::decimatesForDisplayOnly()
{
    PlotPanel panel;
    panel.setMaxDisplayPoints(1000);
    // 5000 samples, one spike of T_trans = 50 at sample 3333.
    for (int i = 0; i < 5000; ++i) {
        const double v = i == 3333 ? 50.0 : std::sin(0.003 * i);
        QVERIFY(panel.appendStep(0.005 * i, energyOnly(v, 0, 0, 0)));
        if (i % 97 == 0) panel.refreshNow();   // appended in many refreshes, as when playing
    }
    panel.refreshNow();
    const int shown = panel.displayedPointCount(plotSeriesId(Q::KineticTranslational));
    QVERIFY2(shown <= 1000 && shown >= 500, qPrintable(QString::number(shown)));
    QCOMPARE(panel.points(plotSeriesId(Q::KineticTranslational)).size(), 5000);
    // The spike is inside the axis range (the data's envelope, not the thinned one).
    QVERIFY(panel.yAxisRange(PlotChart::Energy).max >= 50.0);
    // Back under the budget after a step back: every sample drawn again.
    panel.truncate(800);
    panel.refreshNow();
    QCOMPARE(panel.displayedPointCount(plotSeriesId(Q::KineticTranslational)), 800);
}

void TestPlotPanel::csvExportRoundTrips()
{
    PlotPanel panel;
    QString why;
    QVERIFY2(feedLesson(panel, QStringLiteral("04-many-boxes"), 200, &why), qPrintable(why));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("plot.csv"));
    QString error;
    QVERIFY2(panel.exportCsv(path, &error), qPrintable(error));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QList<QByteArray> lines = file.readAll().split('\n');
    QVERIFY(lines.last().isEmpty());
    lines.removeLast();
    QCOMPARE(lines.size(), 1 + 200);
    const QList<QByteArray> header = lines[0].split(',');
    QCOMPARE(header.size(), 1 + rbw::kPlotQuantityCount);
    QCOMPARE(header[0], QByteArray("t"));
    const QHash<QString, QList<QPointF>> series = allSeries(panel);
    int mismatches = 0;
    for (int row = 0; row < 200; ++row) {
        const QList<QByteArray> cells = lines[row + 1].split(',');
        QCOMPARE(cells.size(), header.size());
        for (int c = 1; c < header.size(); ++c) {
            const QPointF p = series.value(QString::fromLatin1(header[c]))[row];
            if (cells[0].toDouble() != p.x() || cells[c].toDouble() != p.y()) ++mismatches;
        }
    }
    QCOMPARE(mismatches, 0);
}

void TestPlotPanel::exportsToBadPathFail()
{
    PlotPanel panel;
    panel.resize(450, 300);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QVERIFY(panel.appendStep(0.1, energyOnly(1, 1, 1, 3)));
    QString error;
    QVERIFY(!panel.exportPng(QStringLiteral("/nonexistent-dir/plot.png"), &error));
    QVERIFY2(error.contains(QStringLiteral("/nonexistent-dir/plot.png")), qPrintable(error));
    error.clear();
    QVERIFY(!panel.exportCsv(QStringLiteral("/nonexistent-dir/plot.csv"), &error));
    QVERIFY2(error.contains(QStringLiteral("/nonexistent-dir/plot.csv")), qPrintable(error));
}

void TestPlotPanel::pngExportIsDrawn()
{
    PlotPanel panel;
    panel.resize(600, 400);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QString why;
    QVERIFY2(feedLesson(panel, QStringLiteral("07-bounce"), 300, &why), qPrintable(why));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("plot.png"));
    QString error;
    QVERIFY2(panel.exportPng(path, &error), qPrintable(error));
    const QImage image(path);
    QVERIFY(!image.isNull());
    const QSize logical = panel.exportLogicalSize();
    QVERIFY(logical.width() > 300 && logical.height() > 200);
    QCOMPARE(image.size(), logical * 2);
    // Drawn, not blank: axes, labels and curves cover a few % of the white image,
    // and the T_trans blue and the E black lines are there.
    QVERIFY2(nonWhiteShare(image) > 0.02, qPrintable(QString::number(nonWhiteShare(image))));
    QVERIFY(pixelsNear(image, QColor(0x1f, 0x77, 0xb4)) > 200);
    QVERIFY(pixelsNear(image, QColor(Qt::black)) > 200);
    // Negative control: the same checks refuse a blank white image.
    QImage blank(image.size(), QImage::Format_ARGB32);
    blank.fill(Qt::white);
    QVERIFY(nonWhiteShare(blank) <= 0.02);
    QCOMPARE(pixelsNear(blank, QColor(0x1f, 0x77, 0xb4)), 0);
}

void TestPlotPanel::snapshots_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::addColumn<int>("steps");
    QTest::newRow("04-many-boxes") << QStringLiteral("04-many-boxes") << 300;
    QTest::newRow("07-bounce") << QStringLiteral("07-bounce") << 600;
}

void TestPlotPanel::snapshots()
{
    // For looking at: with RBW_PLOTS_SNAPSHOT_DIR set, each chart of each lesson is
    // saved there as plots_<lesson>_<chart>.png at the size of a dock (450 x 300).
    const QString outDir = qEnvironmentVariable("RBW_PLOTS_SNAPSHOT_DIR");
    if (outDir.isEmpty()) QSKIP("RBW_PLOTS_SNAPSHOT_DIR not set");
    QFETCH(QString, lesson);
    QFETCH(int, steps);
    PlotPanel panel;
    panel.resize(450, 300);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QString why;
    QVERIFY2(feedLesson(panel, lesson, steps, &why), qPrintable(why));
    const char* names[] = {"energy", "P", "L_O"};
    for (int c = 0; c < rbw::kPlotChartCount; ++c) {
        panel.setCurrentChart(static_cast<PlotChart>(c));
        QTest::qWait(50);
        QString error;
        const QString path = QDir(outDir).filePath(QStringLiteral("plots_%1_%2.png").arg(lesson, names[c]));
        QVERIFY2(panel.exportPng(path, &error), qPrintable(error));
    }
    // The components too, and the whole panel at dock size on the energy tab.
    for (Q q : {Q::P_x, Q::P_y, Q::P_z, Q::L_O_x, Q::L_O_y, Q::L_O_z}) QVERIFY(panel.setSeriesVisible(plotSeriesId(q), true));
    for (int c = 1; c < rbw::kPlotChartCount; ++c) {
        panel.setCurrentChart(static_cast<PlotChart>(c));
        QTest::qWait(50);
        QString error;
        const QString path =
            QDir(outDir).filePath(QStringLiteral("plots_%1_%2_components.png").arg(lesson, names[c]));
        QVERIFY2(panel.exportPng(path, &error), qPrintable(error));
    }
    panel.setCurrentChart(PlotChart::Energy);
    QTest::qWait(50);
    const QString grab = QDir(outDir).filePath(QStringLiteral("plots_%1_panel.png").arg(lesson));
    QVERIFY(panel.grab().save(grab));
}

QTEST_MAIN(TestPlotPanel)
#include "tst_plot_panel.moc"
