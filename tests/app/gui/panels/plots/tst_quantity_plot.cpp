// One plot of "Plot over time" under Xvfb, what a student reads off it (issue 20):
// one component alone, one colour per line, legend entries that hide and show their
// line, a log axis that is honest about values <= 0, the value under the mouse,
// 1-2-5 ticks, no "±1e-09" on an empty plot, a title in the exported PNG.
//
// The series is made by hand so every number is known: step k (k = 0..19) ends at
// t = 0.1 (k + 1) and has ω = (k, 10 - k, 0.25 k) rad/s, a kinetic energy
// T = 2^-k J, or a T that is 0 from step 10 on (a box that came to rest).
#include "app/gui/panels/plots/export_dialog.h"
#include "app/gui/panels/plots/quantity_plot.h"
#include "physics/engine/quantities.h"
#include "tests/test_support.h"

#include <QCheckBox>
#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QImage>
#include <QLabel>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QSet>
#include <QTemporaryDir>
#include <QValueAxis>
#include <QtTest>

#include <cmath>
#include <functional>

using rbw::QuantityPlot;
using rbw::QuantitySeries;

namespace {

constexpr int kSteps = 20;

QuantitySeries omegaSeries()
{
    QuantitySeries s(rbw::QuantityKey{"angular_velocity", 0, -1}, QStringLiteral("ω (box)"), "rad/s",
                     QStringLiteral("ω"));
    for (int k = 0; k < kSteps; ++k) {
        rbw::StepTrace t;
        t.step = k;
        t.time = 0.1 * (k + 1);
        t.add(rbw::q::angular_velocity, 0, rbw::Vec3(k, 10 - k, 0.25 * k), -1);
        s.append(t);
    }
    return s;
}

QuantitySeries energySeries(const std::function<double(int)>& T)
{
    QuantitySeries s(rbw::QuantityKey{"kinetic_energy_after", -1, -1}, QStringLiteral("T⁺"), "J",
                     QStringLiteral("T⁺"));
    for (int k = 0; k < kSteps; ++k) {
        rbw::StepTrace t;
        t.step = k;
        t.time = 0.1 * (k + 1);
        t.add(rbw::q::kinetic_energy_after, -1, T(k), -1);
        s.append(t);
    }
    return s;
}

void show(QuantityPlot& plot)
{
    plot.resize(900, 420);
    plot.show();
    QVERIFY(QTest::qWaitForWindowExposed(&plot));
    QApplication::processEvents();
    plot.refresh();
    QApplication::processEvents();
}

// Dark pixels (text, not the light grid) in the band of rows [top, bottom) of the
// middle half of the image.
int darkPixels(const QImage& image, int top, int bottom)
{
    int n = 0;
    for (int y = std::max(0, top); y < std::min(bottom, image.height()); ++y) {
        for (int x = image.width() / 4; x < 3 * image.width() / 4; ++x) {
            if (qGray(image.pixel(x, y)) < 100) ++n;
        }
    }
    return n;
}

bool isOneTwoFive(double step)
{
    const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-12));
    return std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 || std::abs(mantissa - 5) < 1e-9;
}

} // namespace

class TestQuantityPlot : public QObject {
    Q_OBJECT
private slots:
    void oneComponentAlone();
    void oneColourPerLine();
    void legendClickHidesAndShows();
    void logScale_data();
    void logScale();
    void readoutUnderTheMouse();
    void ticksAndTheEmptyPlot();
    void pngHasTheTitle();
};

// "Show" offers each component by the catalogue's symbol; ω_y alone is one line,
// the recorded ω_y = 10 - k of every step, in the body's colour.
void TestQuantityPlot::oneComponentAlone()
{
    const QuantitySeries s = omegaSeries();
    QuantityPlot plot(&s, Qt::darkGreen);
    show(plot);
    const int item = plot.modeBox()->findText(QStringLiteral("ω_y"));
    QVERIFY(item >= 0);
    plot.modeBox()->setCurrentIndex(item);
    emit plot.modeBox()->activated(item);
    QCOMPARE(plot.shownComponent(), 1);
    QCOMPARE(plot.lineCount(), 1);
    QCOMPARE(plot.chart()->series().size(), qsizetype(1));
    const QList<QPointF> points = plot.chartLine(0)->points();
    QCOMPARE(points.size(), qsizetype(kSteps));
    for (int k = 0; k < kSteps; ++k) QCOMPARE(points[k], QPointF(0.1 * (k + 1), 10.0 - k));
    QCOMPARE(plot.lineName(0), QStringLiteral("ω_y (box)"));
    QCOMPARE(plot.chartLine(0)->pen().color(), QColor(Qt::darkGreen));
    QCOMPARE(plot.yAxis()->titleText(), QStringLiteral("ω_y [rad/s]"));
    // Back to all: three lines again (negative control for the count).
    plot.setShownComponent(QuantityPlot::kAllComponents);
    QCOMPARE(plot.chart()->series().size(), qsizetype(3));
}

void TestQuantityPlot::oneColourPerLine()
{
    const QuantitySeries s = omegaSeries();
    QuantityPlot plot(&s, Qt::darkGreen);
    show(plot);
    QCOMPARE(plot.lineCount(), 3);
    QSet<QRgb> colours;
    for (int i = 0; i < 3; ++i) colours.insert(plot.chartLine(i)->pen().color().rgb());
    QCOMPARE(colours.size(), qsizetype(3));
    // The legend names each line after its component.
    QCOMPARE(plot.chartLine(2)->name(), QStringLiteral("ω_z (box)"));
}

// A click on ω_y's legend entry hides its line (the entry stays, greyed, to click
// again) and the y axis fits the lines still shown: ω_x = k and ω_z = k/4 reach 19,
// ω_y = 10 - k reaches down to -9, so without ω_y the axis starts at 0.
void TestQuantityPlot::legendClickHidesAndShows()
{
    const QuantitySeries s = omegaSeries();
    QuantityPlot plot(&s, Qt::darkGreen);
    show(plot);
    QVERIFY(plot.yAxis()->min() < -8.9);
    const QList<QLegendMarker*> markers = plot.chart()->legend()->markers(plot.chartLine(1));
    QCOMPARE(markers.size(), qsizetype(1));
    emit markers.first()->clicked();
    QVERIFY(!plot.chartLine(1)->isVisible());
    QVERIFY(!plot.isLineVisible(1));
    QVERIFY(plot.chartLine(0)->isVisible() && plot.chartLine(2)->isVisible());
    QVERIFY(markers.first()->isVisible());
    QCOMPARE(plot.yAxis()->min(), 0.0);
    emit markers.first()->clicked();
    QVERIFY(plot.chartLine(1)->isVisible());
    QVERIFY(plot.yAxis()->min() < -8.9);
}

// The log axis: T = 2^-k is drawn whole; a T that is 0 from step 10 keeps its 10
// positive samples and says that 10 are left out; a T that is never above 0 is
// refused (the plot stays linear and says why).
void TestQuantityPlot::logScale_data()
{
    QTest::addColumn<int>("kind");      // 0: 2^-k, 1: 0 from step 10, 2: always 0
    QTest::addColumn<bool>("accepted");
    QTest::addColumn<int>("drawn");
    QTest::addColumn<int>("leftOut");
    QTest::newRow("2^-k, all positive") << 0 << true << kSteps << 0;
    QTest::newRow("at rest from step 10") << 1 << true << 10 << 10;
    QTest::newRow("always 0: refused") << 2 << false << kSteps << 0;
}

void TestQuantityPlot::logScale()
{
    QFETCH(int, kind);
    QFETCH(bool, accepted);
    QFETCH(int, drawn);
    QFETCH(int, leftOut);
    const QuantitySeries s = energySeries([kind](int k) {
        if (kind == 2) return 0.0;
        if (kind == 1 && k >= 10) return 0.0;
        return std::ldexp(1.0, -k);
    });
    QuantityPlot plot(&s, Qt::darkGreen);
    show(plot);
    QCOMPARE(plot.setLogScale(true), accepted);
    QCOMPARE(plot.logScale(), accepted);
    QCOMPARE(plot.logBox()->isChecked(), accepted);
    QCOMPARE(plot.yLogAxis()->isVisible(), accepted);
    QCOMPARE(plot.yAxis()->isVisible(), !accepted);
    QCOMPARE(plot.chartLine(0)->points().size(), qsizetype(drawn));
    QCOMPARE(plot.samplesLeftOut(), leftOut);
    if (accepted) {
        // Whole decades around the samples drawn: 2^-19 = 1.9e-6 -> 1e-6; 1 -> 1.
        const double smallest = std::ldexp(1.0, -(drawn - 1));
        QCOMPARE(plot.yLogAxis()->min(), std::pow(10.0, std::floor(std::log10(smallest))));
        QCOMPARE(plot.yLogAxis()->max(), 1.0);
        QCOMPARE(plot.note()->text().contains(QStringLiteral("not on the log axis")), leftOut > 0);
        // The linear axis again: every sample back.
        QVERIFY(plot.setLogScale(false));
        QCOMPARE(plot.chartLine(0)->points().size(), qsizetype(kSteps));
    } else {
        QVERIFY2(plot.note()->text().contains(QStringLiteral("no value above 0")), qPrintable(plot.note()->text()));
    }
}

// The mouse over ω_y's sample of step 4 (t = 0.5 s, ω_y = 6) reads it out; outside
// the plot area there is nothing to read.
void TestQuantityPlot::readoutUnderTheMouse()
{
    const QuantitySeries s = omegaSeries();
    QuantityPlot plot(&s, Qt::darkGreen);
    show(plot);
    QChart* chart = plot.chart();
    const QPointF at = chart->mapToPosition(QPointF(0.5, 6.0), plot.chartLine(1));
    const QPoint onViewport = plot.chartView()->mapFromScene(chart->mapToScene(at));
    QTest::mouseMove(plot.chartView()->viewport(), onViewport);
    QApplication::processEvents();
    const QString expected = QStringLiteral("ω_y (box) = 6 rad/s at t = 0.5 s");
    QCOMPARE(plot.readout()->text(), expected);
    QCOMPARE(plot.readoutAt(onViewport), expected);
    QCOMPARE(plot.readoutAt(QPoint(1, 1)), QString());   // the corner: outside the plot area
    // A hidden line is not read out (another line's sample or nothing is, then).
    plot.setLineVisible(1, false);
    QVERIFY(!plot.readoutAt(onViewport).startsWith(QStringLiteral("ω_y")));
}

// Ticks 1-2-5 apart on both axes after data; an empty plot reads [0, 1] (not ±1e-09).
void TestQuantityPlot::ticksAndTheEmptyPlot()
{
    const QuantitySeries s = omegaSeries();
    QuantityPlot plot(&s, Qt::darkGreen);
    show(plot);
    for (QValueAxis* axis : {plot.xAxis(), plot.yAxis()}) {
        const double step = (axis->max() - axis->min()) / (axis->tickCount() - 1);
        QVERIFY2(isOneTwoFive(step), qPrintable(QString::number(step)));
        QVERIFY(!axis->labelsTruncated());
    }
    const QuantitySeries empty(rbw::QuantityKey{"angular_velocity", 0, -1}, QStringLiteral("ω (box)"), "rad/s",
                               QStringLiteral("ω"));
    QuantityPlot none(&empty, Qt::darkGreen);
    show(none);
    QCOMPARE(none.yAxis()->min(), 0.0);
    QCOMPARE(none.yAxis()->max(), 1.0);
    QVERIFY(!none.yAxis()->labelFormat().contains('e'));
}

// The exported PNG carries the plot's title above the chart: dark text pixels in
// the band of the title's height at the top, where the same chart written without a
// title has none (negative control).
void TestQuantityPlot::pngHasTheTitle()
{
    const QuantitySeries s = omegaSeries();
    QuantityPlot plot(&s, Qt::darkGreen);
    show(plot);
    plot.setShownComponent(1);
    QCOMPARE(plot.title(), QStringLiteral("ω_y (box) [rad/s] over time"));
    QTemporaryDir dir;
    QString error;
    QVERIFY2(plot.exportPng(dir.filePath("titled.png"), &error), qPrintable(error));
    QVERIFY2(rbw::writeChartPng(plot.chart(), true, dir.filePath("plain.png"), &error), qPrintable(error));
    const QImage titled(dir.filePath("titled.png"));
    const QImage plain(dir.filePath("plain.png"));
    QVERIFY(!titled.isNull() && !plain.isNull());
    QCOMPARE(titled.size(), plain.size());
    QFont bold = plot.chart()->titleFont();
    bold.setBold(true);
    const int band = 2 * (QFontMetrics(bold).height() + 8);   // device pixel ratio 2
    const int text = darkPixels(titled, 0, band);
    QVERIFY2(text > 30, qPrintable(QString::number(text)));
    QCOMPARE(darkPixels(plain, 0, band), 0);
    QVERIFY(plot.chart()->title().isEmpty());   // the screen keeps no title
}

QTEST_MAIN(TestQuantityPlot)
#include "tst_quantity_plot.moc"
