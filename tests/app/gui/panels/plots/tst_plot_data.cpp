// The plots' data layer, without a window: the catalogue reads the right numbers,
// the sample store refuses bad samples and truncates exactly, the CSV reads back
// bit for bit, the axis ranges follow their rule (plot_axis_range.h) and the
// decimation keeps the envelope of a curve.
#include "app/gui/panels/plots/plot_axis_range.h"
#include "app/gui/panels/plots/plot_catalogue.h"
#include "app/gui/panels/plots/plot_decimation.h"
#include "app/gui/panels/plots/plot_series.h"
#include "app/gui/panels/plots/quantity_series.h"
#include "physics/engine/quantities.h"
#include "tests/test_support.h"

#include <QSet>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <limits>

using rbw::Diagnostics;
using rbw::PlotQuantity;
using rbw::PlotSeries;
using rbw::ValueRange;
using rbw::Vec3;

Q_DECLARE_METATYPE(rbw::PlotQuantity)

namespace {

// A diagnostics record with every field distinct, so a mixed-up field shows.
Diagnostics sample(double s)
{
    Diagnostics d;
    d.kineticTranslational = 1.0 * s;
    d.kineticRotational = 2.0 * s;
    d.kinetic = 3.0 * s;
    d.potential = -4.0 * s;
    d.total = -1.0 * s;
    d.P_W = Vec3(5.0 * s, 6.0 * s, 7.0 * s);
    d.L_O_W = Vec3(8.0 * s, 9.0 * s, 10.0 * s);
    return d;
}

// A diagnostics catalogue row's id, as the plots' CSV spells it.
QByteArray idOf(const rbw::DiagnosticInfo<Diagnostics>& d)
{
    return QByteArray(d.id.data(), static_cast<qsizetype>(d.id.size()));
}

} // namespace

class TestPlotData : public QObject {
    Q_OBJECT
private slots:
    void catalogueIdsAreUniqueAndFound();
    void seriesTextsComeFromTheDiagnosticsCatalogue_data();
    void seriesTextsComeFromTheDiagnosticsCatalogue();
    void valuesAreTheRecordedNumbers();
    void refusesBadSamples_data();
    void refusesBadSamples();
    void truncateKeepsTheFirstSamples();
    void csvRoundTripsEveryBit();
    void csvToUnwritablePathFails();
    void valueAxisRange_data();
    void valueAxisRange();
    void timeAxisRange();
    void niceTicks_data();
    void niceTicks();
    void componentNamesFollowTheCatalogue();
    void strideKeepsWithinBudget_data();
    void strideKeepsWithinBudget();
    void decimationKeepsTheEnvelope();
    void quantitySeriesReadsTheTrace_data();
    void quantitySeriesReadsTheTrace();
    void quantitySeriesSkipsNonFinite();
};

void TestPlotData::catalogueIdsAreUniqueAndFound()
{
    QSet<QString> ids;
    for (const rbw::PlotSeriesInfo& s : rbw::plotSeriesCatalogue()) {
        ids.insert(s.id);
        QCOMPARE(rbw::findPlotSeries(s.id), &s);
        QCOMPARE(&rbw::plotSeriesInfo(s.quantity), &s);
    }
    QCOMPARE(ids.size(), rbw::kPlotQuantityCount);
    // Negative control: an id that is not in the catalogue is not found.
    QVERIFY(rbw::findPlotSeries(u"kinetic") == nullptr);
}

void TestPlotData::seriesTextsComeFromTheDiagnosticsCatalogue_data()
{
    namespace diag = rbw::diag;
    QTest::addColumn<PlotQuantity>("quantity");
    QTest::addColumn<QByteArray>("id");
    QTest::addColumn<QString>("label");
    // A scalar keeps its row's id and symbol; a vector's part appends _x or _norm to the
    // id and shows P_x / |P| (a comma where the symbol already has a subscript: L_O,x).
    QTest::newRow("T_trans") << PlotQuantity::KineticTranslational << idOf(diag::kinetic_translational)
                             << QStringLiteral("T_trans");
    QTest::newRow("V") << PlotQuantity::Potential << idOf(diag::potential) << QStringLiteral("V");
    QTest::newRow("E") << PlotQuantity::Total << idOf(diag::total) << QStringLiteral("E");
    QTest::newRow("P_x") << PlotQuantity::P_x << idOf(diag::linear_momentum) + "_x" << QStringLiteral("P_x");
    QTest::newRow("|P|") << PlotQuantity::P_norm << idOf(diag::linear_momentum) + "_norm" << QStringLiteral("|P|");
    QTest::newRow("L_O,z") << PlotQuantity::L_O_z << idOf(diag::angular_momentum_origin) + "_z"
                           << QStringLiteral("L_O,z");
    QTest::newRow("|L_O|") << PlotQuantity::L_O_norm << idOf(diag::angular_momentum_origin) + "_norm"
                           << QStringLiteral("|L_O|");
}

void TestPlotData::seriesTextsComeFromTheDiagnosticsCatalogue()
{
    QFETCH(PlotQuantity, quantity);
    QFETCH(QByteArray, id);
    QFETCH(QString, label);
    const rbw::PlotSeriesInfo& s = rbw::plotSeriesInfo(quantity);
    QCOMPARE(s.id.toLatin1(), id);
    QCOMPARE(rbw::plotSeriesId(quantity), s.id);
    QCOMPARE(s.label, label);
    // The tooltip is the row's meaning (for a part, with what part it is in front).
    const QString meaning = QString::fromUtf8(s.diagnostic->meaning.data(), static_cast<qsizetype>(s.diagnostic->meaning.size()));
    QVERIFY2(s.meaning.endsWith(meaning), qPrintable(s.meaning));
    // A value is read from a scalar row, a part from a vector row, never the other way.
    QCOMPARE(s.part == rbw::PlotPart::Value, s.diagnostic->scalar != nullptr);
}

void TestPlotData::valuesAreTheRecordedNumbers()
{
    Diagnostics d;
    d.kineticTranslational = 1.25;
    d.kineticRotational = 0.5;
    d.potential = -3.0;
    d.total = -1.25;
    d.P_W = Vec3(3.0, 4.0, 0.0);    // |P| = 5 (3-4-5 triangle)
    d.L_O_W = Vec3(2.0, -3.0, 6.0); // |L_O| = sqrt(4 + 9 + 36) = 7
    QCOMPARE(rbw::plotValue(PlotQuantity::KineticTranslational, d), 1.25);
    QCOMPARE(rbw::plotValue(PlotQuantity::KineticRotational, d), 0.5);
    QCOMPARE(rbw::plotValue(PlotQuantity::Potential, d), -3.0);
    QCOMPARE(rbw::plotValue(PlotQuantity::Total, d), -1.25);
    QCOMPARE(rbw::plotValue(PlotQuantity::P_x, d), 3.0);
    QCOMPARE(rbw::plotValue(PlotQuantity::P_y, d), 4.0);
    QCOMPARE(rbw::plotValue(PlotQuantity::P_z, d), 0.0);
    QCOMPARE(rbw::plotValue(PlotQuantity::P_norm, d), 5.0);
    QCOMPARE(rbw::plotValue(PlotQuantity::L_O_x, d), 2.0);
    QCOMPARE(rbw::plotValue(PlotQuantity::L_O_y, d), -3.0);
    QCOMPARE(rbw::plotValue(PlotQuantity::L_O_z, d), 6.0);
    QCOMPARE(rbw::plotValue(PlotQuantity::L_O_norm, d), 7.0);
}

void TestPlotData::refusesBadSamples_data()
{
    QTest::addColumn<double>("t");
    QTest::addColumn<double>("total");
    QTest::addColumn<bool>("accepted");
    QTest::addColumn<QString>("reason");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    // The store already holds one sample at t = 1.
    QTest::newRow("good (control)") << 1.5 << 2.0 << true << QString();
    QTest::newRow("same t is allowed") << 1.0 << 2.0 << true << QString();
    QTest::newRow("NaN energy") << 1.5 << nan << false << QStringLiteral("not finite");
    QTest::newRow("infinite energy") << 1.5 << inf << false << QStringLiteral("not finite");
    QTest::newRow("NaN time") << nan << 2.0 << false << QStringLiteral("not finite");
    QTest::newRow("time going back") << 0.5 << 2.0 << false << QStringLiteral("before the last");
}

void TestPlotData::refusesBadSamples()
{
    QFETCH(double, t);
    QFETCH(double, total);
    QFETCH(bool, accepted);
    QFETCH(QString, reason);
    PlotSeries data;
    QVERIFY(data.append(1.0, sample(1.0)));
    Diagnostics d = sample(2.0);
    d.total = total;
    QString error;
    QCOMPARE(data.append(t, d, &error), accepted);
    QCOMPARE(data.sampleCount(), accepted ? 2 : 1);
    if (!accepted) {
        QVERIFY2(error.contains(reason), qPrintable(error));
        // Nothing of the refused sample was stored, in any series.
        for (const rbw::PlotSeriesInfo& s : rbw::plotSeriesCatalogue()) QCOMPARE(data.points(s.quantity).size(), 1);
    }
}

void TestPlotData::truncateKeepsTheFirstSamples()
{
    PlotSeries data;
    // T_trans = k for k = 1..10 at t = 0.1 k.
    for (int k = 1; k <= 10; ++k) QVERIFY(data.append(0.1 * k, sample(k)));
    QCOMPARE(data.valueRange(PlotQuantity::KineticTranslational)->max, 10.0);
    data.truncate(3);
    QCOMPARE(data.sampleCount(), 3);
    const QList<QPointF> pts = data.points(PlotQuantity::KineticTranslational);
    QCOMPARE(pts.size(), 3);
    for (int i = 0; i < 3; ++i) QCOMPARE(pts[i], QPointF(0.1 * (i + 1), i + 1.0));
    // The range shrinks with the data: T_trans in [1, 3], V = -4 k in [-12, -4].
    QCOMPARE(data.valueRange(PlotQuantity::KineticTranslational)->min, 1.0);
    QCOMPARE(data.valueRange(PlotQuantity::KineticTranslational)->max, 3.0);
    QCOMPARE(data.valueRange(PlotQuantity::Potential)->min, -12.0);
    QCOMPARE(data.valueRange(PlotQuantity::Potential)->max, -4.0);
    QCOMPARE(data.lastTime(), 0.1 * 3);
    // Out-of-range counts are clamped; clear() empties.
    data.truncate(99);
    QCOMPARE(data.sampleCount(), 3);
    data.truncate(-1);
    QCOMPARE(data.sampleCount(), 0);
    QVERIFY(!data.valueRange(PlotQuantity::Total).has_value());
    QVERIFY(data.append(0.0, sample(1.0)));
    data.clear();
    QCOMPARE(data.sampleCount(), 0);
}

void TestPlotData::csvRoundTripsEveryBit()
{
    // Doubles whose shortest text is long, tiny, huge or denormal (not so huge that
    // |L_O|^2 overflows: such a sample is refused, see refusesBadSamples).
    const QList<double> scales{0.1 + 0.2, 1.0 / 3.0, 4.800000000000001, 1e-300, 2.2250738585072014e-308,
                               1.2345678901234567e150, -0.0, 123456789.125};
    PlotSeries data;
    double t = 0.0;
    for (double s : scales) {
        t += 0.1;
        QVERIFY(data.append(t, sample(s)));
    }
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("plots.csv"));
    QString error;
    QVERIFY2(data.writeCsv(path, &error), qPrintable(error));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = file.readAll().split('\n');
    // Header, one row per sample, and the empty piece after the final newline.
    QCOMPARE(lines.size(), scales.size() + 2);
    // The header: t, the world's energies by their catalogue ids, then the two vectors'
    // components and lengths (id + _x, _y, _z, _norm, as the CLI's CSV names a vector's parts).
    QByteArray header = "t," + idOf(rbw::diag::kinetic_translational) + ',' + idOf(rbw::diag::kinetic_rotational) + ','
                        + idOf(rbw::diag::potential) + ',' + idOf(rbw::diag::total);
    for (const rbw::DiagnosticInfo<Diagnostics>* v : {&rbw::diag::linear_momentum, &rbw::diag::angular_momentum_origin}) {
        for (const char* part : {"_x", "_y", "_z", "_norm"}) header += ',' + idOf(*v) + part;
    }
    QCOMPARE(lines[0], header);
    QVERIFY(lines.last().isEmpty());
    for (int i = 0; i < scales.size(); ++i) {
        const QList<QByteArray> cells = lines[i + 1].split(',');
        QCOMPARE(cells.size(), 1 + rbw::kPlotQuantityCount);
        bool ok = false;
        QCOMPARE(cells[0].toDouble(&ok), data.time(i));
        QVERIFY(ok);
        for (const rbw::PlotSeriesInfo& s : rbw::plotSeriesCatalogue()) {
            const double read = cells[1 + rbw::plotIndex(s.quantity)].toDouble(&ok);
            QVERIFY(ok);
            const double stored = data.value(s.quantity, i);
            // Bit for bit (memcmp also tells -0 from +0, which == does not).
            QVERIFY2(std::memcmp(&read, &stored, sizeof(double)) == 0,
                     qPrintable(QStringLiteral("%1 row %2: %3 vs %4")
                                    .arg(s.id)
                                    .arg(i)
                                    .arg(read, 0, 'g', 17)
                                    .arg(stored, 0, 'g', 17)));
        }
    }
    // Negative control: 6 significant digits would not round-trip 1/3.
    const double third = 1.0 / 3.0;
    QVERIFY(QByteArray::number(third, 'g', 6).toDouble() != third);
}

void TestPlotData::csvToUnwritablePathFails()
{
    PlotSeries data;
    QVERIFY(data.append(0.0, sample(1.0)));
    QString error;
    QVERIFY(!data.writeCsv(QStringLiteral("/nonexistent-dir/plots.csv"), &error));
    QVERIFY2(error.contains(QStringLiteral("/nonexistent-dir/plots.csv")), qPrintable(error));
}

void TestPlotData::valueAxisRange_data()
{
    QTest::addColumn<double>("lo");
    QTest::addColumn<double>("hi");
    QTest::addColumn<double>("expectedMin");
    QTest::addColumn<double>("expectedMax");
    // Varying: pad 5 % of the span on each side. [10, 20]: span 10, pad 0.5.
    QTest::newRow("positive 10..20") << 10.0 << 20.0 << 9.5 << 20.5;
    // The padding stops at 0: [0, 10] -> [0, 10.5]; [-10, 0] -> [-10.5, 0];
    // [0.2, 10.2]: pad 0.5 would cross 0 -> [0, 10.7].
    QTest::newRow("ramp 0..10") << 0.0 << 10.0 << 0.0 << 10.5;
    QTest::newRow("ramp -10..0") << -10.0 << 0.0 << -10.5 << 0.0;
    QTest::newRow("near 0 from above") << 0.2 << 10.2 << 0.0 << 10.7;
    // Crossing 0: padded on both sides. [-2, 2]: pad 0.2.
    QTest::newRow("crossing 0") << -2.0 << 2.0 << -2.2 << 2.2;
    // [-50, -20]: span 30, pad 1.5.
    QTest::newRow("negative -50..-20") << -50.0 << -20.0 << -51.5 << -18.5;
    // [1, 1.001]: span 1e-3 is far above round-off (1e-9 * 1.001): pad 5e-5.
    QTest::newRow("small but real change") << 1.0 << 1.001 << 1.0 - 5e-5 << 1.001 + 5e-5;
    // Constant: v ± 0.05 |v|. 3 -> ±0.15; -200 -> ±10.
    QTest::newRow("constant 3") << 3.0 << 3.0 << 2.85 << 3.15;
    QTest::newRow("constant -200") << -200.0 << -200.0 << -210.0 << -190.0;
    // 0 (a momentum of 0, the empty per-body plot before the first step) is a flat
    // line at 0 on [-1, 1], not an axis of "±1e-09" (issue 20).
    QTest::newRow("constant 0") << 0.0 << 0.0 << -1.0 << 1.0;
    // Round-off (lesson 3's kinetic energy 1.5 -> 1.4999999999999996) counts as
    // constant: centre 1.4999999999999998, ±0.075.
    QTest::newRow("round-off around 1.5") << 1.4999999999999996 << 1.5 << 1.4999999999999998 - 0.075
                                          << 1.4999999999999998 + 0.075;
    // Round-off around 0 (every |value| <= 1e-9) is 0: the same [-1, 1].
    QTest::newRow("round-off around 0") << 0.0 << 1e-17 << -1.0 << 1.0;
    // Just above the round-off bound it is data: [0, 2e-9] padded 1e-10 above.
    QTest::newRow("tiny but real") << 0.0 << 2e-9 << 0.0 << 2.1e-9;
}

void TestPlotData::valueAxisRange()
{
    QFETCH(double, lo);
    QFETCH(double, hi);
    QFETCH(double, expectedMin);
    QFETCH(double, expectedMax);
    const ValueRange r = rbw::valueAxisRange(lo, hi);
    const double tol = 1e-12 * std::max(1.0, std::abs(expectedMax));
    RBW_COMPARE_NEAR(r.min, expectedMin, tol);
    RBW_COMPARE_NEAR(r.max, expectedMax, tol);
    QVERIFY(r.max - r.min > 0.0);
    QVERIFY(r.min <= lo && r.max >= hi);
}

// Ticks at multiples of 1, 2 or 5 x 10^k, the axis ending on ticks, at most
// maxTicks: the smallest such step that fits (worked by hand in each row).
void TestPlotData::niceTicks_data()
{
    QTest::addColumn<double>("lo");
    QTest::addColumn<double>("hi");
    QTest::addColumn<int>("maxTicks");
    QTest::addColumn<double>("min");
    QTest::addColumn<double>("max");
    QTest::addColumn<double>("step");
    QTest::addColumn<int>("count");
    // [0, 6.4], 5 ticks: step 1 needs 0..7 (8 ticks), step 2 needs 0..8 (5): 0, 2, 4, 6, 8
    // (Qt's applyNiceNumbers gave 0, 1.6, 3.2, 4.8, 6.4 here).
    QTest::newRow("0..6.4") << 0.0 << 6.4 << 5 << 0.0 << 8.0 << 2.0 << 5;
    // [0, 2.04] (t up to 2 s plus 2 %), 6 ticks: 0.2 needs 12, 0.5 needs 0..2.5 (6).
    QTest::newRow("time to 2 s") << 0.0 << 2.04 << 6 << 0.0 << 2.5 << 0.5 << 6;
    // [-1, 1] (a quantity at 0), 5 ticks: 0.2 needs 11, 0.5 needs 5.
    QTest::newRow("zero line") << -1.0 << 1.0 << 5 << -1.0 << 1.0 << 0.5 << 5;
    // [0.95, 1.05] (constant 1), 5 ticks: 0.01 needs 11, 0.02 needs 0.94..1.06 (7),
    // 0.05 needs 0.95..1.05 (3; 0.95 / 0.05 = 18.999999999999996 is tick 19).
    QTest::newRow("constant 1") << 0.95 << 1.05 << 5 << 0.95 << 1.05 << 0.05 << 3;
    // [-0.315, 0.315] (lesson 9's R entries), 6 ticks: 0.1 needs -0.4..0.4 (9), 0.2 needs
    // -0.4..0.4 (5).
    QTest::newRow("crossing 0") << -0.315 << 0.315 << 6 << -0.4 << 0.4 << 0.2 << 5;
}

void TestPlotData::niceTicks()
{
    QFETCH(double, lo);
    QFETCH(double, hi);
    QFETCH(int, maxTicks);
    QFETCH(double, min);
    QFETCH(double, max);
    QFETCH(double, step);
    QFETCH(int, count);
    const rbw::NiceTicks t = rbw::niceTicks(ValueRange{lo, hi}, maxTicks);
    RBW_COMPARE_NEAR(t.min, min, 1e-12);
    RBW_COMPARE_NEAR(t.max, max, 1e-12);
    RBW_COMPARE_NEAR(t.step, step, 1e-12);
    QCOMPARE(t.count, count);
    // The invariants every row must meet: the data inside (to the 1e-9 of a step that
    // counts as on a tick), ticks that fit, 1-2-5 steps.
    QVERIFY(t.min <= lo + 1e-9 * t.step && t.max >= hi - 1e-9 * t.step);
    QVERIFY(t.count <= maxTicks);
    RBW_COMPARE_NEAR(t.min + (t.count - 1) * t.step, t.max, 1e-12);
    const double mantissa = t.step / std::pow(10.0, std::floor(std::log10(t.step) + 1e-12));
    QVERIFY2(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 || std::abs(mantissa - 5) < 1e-9,
             qPrintable(QString::number(t.step)));
}

// The names students read in the legend: the catalogue's symbol with the
// component, R₂₂ for a matrix entry, ω_y for a vector's.
void TestPlotData::componentNamesFollowTheCatalogue()
{
    rbw::QuantitySeries r(rbw::QuantityKey{"rotation_matrix", 0, -1}, QStringLiteral("R (racket)"), QString(), "R");
    rbw::QuantitySeries w(rbw::QuantityKey{"angular_velocity", 0, -1}, QStringLiteral("ω (racket)"), "rad/s",
                          QStringLiteral("ω"));
    rbw::StepTrace t;
    t.step = 0;
    t.time = 0.01;
    rbw::Mat3 R;
    R << 1, 2, 3, 4, 5, 6, 7, 8, 9;
    t.add(rbw::q::rotation_matrix, 0, R, -1);
    t.add(rbw::q::angular_velocity, 0, Vec3(1, 2, 3), -1);
    QVERIFY(r.append(t));
    QVERIFY(w.append(t));
    QCOMPARE(r.componentSymbol(4), QStringLiteral("R₂₂"));
    QCOMPARE(r.componentLabel(4), QStringLiteral("R₂₂ (racket)"));
    QCOMPARE(r.samples()[0].values[4], 5.0);   // row 2, column 2, as R(1, 1) in Eigen's 0-based terms
    QCOMPARE(r.componentSymbol(5), QStringLiteral("R₂₃"));
    QCOMPARE(w.componentLabel(1), QStringLiteral("ω_y (racket)"));
    QCOMPARE(w.componentSymbol(-1), QStringLiteral("ω"));   // no component: the symbol
}

void TestPlotData::timeAxisRange()
{
    // [0, 1.02 t_max]: t_max = 2 -> 2.04.
    QCOMPARE(rbw::timeAxisRange(2.0).min, 0.0);
    RBW_COMPARE_NEAR(rbw::timeAxisRange(2.0).max, 2.04, 1e-15);
    // Nothing yet: [0, 1].
    QCOMPARE(rbw::timeAxisRange(0.0).max, 1.0);
}

void TestPlotData::strideKeepsWithinBudget_data()
{
    QTest::addColumn<int>("samples");
    QTest::addColumn<int>("maxPoints");
    QTest::addColumn<int>("stride");
    QTest::addColumn<int>("points");
    // Up to the budget every sample is drawn.
    QTest::newRow("at budget") << 20000 << 20000 << 1 << 20000;
    // One over: stride 2 gives 2 points per bucket of 2, 20000 points.
    QTest::newRow("one over") << 20001 << 20000 << 2 << 20000;
    // 36000 samples (10 min at 60 steps/s): stride 2 -> 36000 > 20000; stride 4 -> 18000.
    QTest::newRow("ten minutes") << 36000 << 20000 << 4 << 18000;
}

void TestPlotData::strideKeepsWithinBudget()
{
    QFETCH(int, samples);
    QFETCH(int, maxPoints);
    QFETCH(int, stride);
    QFETCH(int, points);
    QCOMPARE(rbw::strideFor(samples, maxPoints), stride);
    QCOMPARE(rbw::displayPointCount(samples, stride), points);
}

void TestPlotData::decimationKeepsTheEnvelope()
{
    // 5000 samples of a slow wave with one spike (a bounce) at sample 2345 and one
    // dip at 4001, drawn at stride 8.
    PlotSeries data;
    for (int i = 0; i < 5000; ++i) {
        double v = std::sin(0.01 * i);
        if (i == 2345) v = 50.0;
        if (i == 4001) v = -50.0;
        Diagnostics d;
        d.kineticTranslational = v;
        QVERIFY(data.append(0.005 * i, d));
    }
    const int stride = 8;
    QList<QPointF> shown;
    rbw::appendDisplayPoints(data, PlotQuantity::KineticTranslational, 0, rbw::displayedSampleCount(5000, stride),
                             stride, shown);
    QCOMPARE(shown.size(), rbw::displayPointCount(5000, stride));   // 2 * 625
    double maxShown = -1e300;
    double minShown = 1e300;
    for (int i = 0; i < shown.size(); ++i) {
        maxShown = std::max(maxShown, shown[i].y());
        minShown = std::min(minShown, shown[i].y());
        if (i > 0) QVERIFY(shown[i].x() > shown[i - 1].x());   // in time order
    }
    QCOMPARE(maxShown, 50.0);
    QCOMPARE(minShown, -50.0);
    // Every point drawn is a recorded sample: t = 0.005 i and its value.
    for (const QPointF& p : shown) {
        const int i = static_cast<int>(std::lround(p.x() / 0.005));
        QCOMPARE(p.x(), data.time(i));
        QCOMPARE(p.y(), data.value(PlotQuantity::KineticTranslational, i));
    }
    // Negative control: plain thinning (every 8th sample) loses the spike.
    double maxThinned = -1e300;
    for (int i = 0; i < 5000; i += stride) maxThinned = std::max(maxThinned, data.value(PlotQuantity::KineticTranslational, i));
    QVERIFY(maxThinned < 50.0);
}

// Plot over time's data: the entry of (id, body, index) in each step's trace, as
// recorded; steps without it (a contact that is not there) have no sample; CSV
// numbers read back bit for bit.
void TestPlotData::quantitySeriesReadsTheTrace_data()
{
    QTest::addColumn<int>("body");
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("expectedSamples");
    QTest::newRow("omega of body 0 (every step)") << 0 << -1 << 5;
    QTest::newRow("contact 1 of body 0 (steps 1 and 3)") << 0 << 1 << 2;
    QTest::newRow("body 1: not in the trace") << 1 << -1 << 0;
}

void TestPlotData::quantitySeriesReadsTheTrace()
{
    QFETCH(int, body);
    QFETCH(int, index);
    QFETCH(int, expectedSamples);
    const QString id = index < 0 ? QStringLiteral("angular_velocity") : QStringLiteral("normal");
    rbw::QuantitySeries series(rbw::QuantityKey{id, body, index}, "q", "u");
    for (int k = 0; k < 5; ++k) {
        rbw::StepTrace t;
        t.step = k;
        t.time = 0.1 * (k + 1);
        t.add(rbw::q::angular_velocity, 0, rbw::Vec3(k, 1.0 / 3.0, -k), -1);
        if (k % 2 == 1) t.add(rbw::q::contact_normal, 0, rbw::Vec3(0, 1, 0.1 * k), 1);
        t.add(rbw::q::contact_normal, 0, rbw::Vec3(0, 1, 0), 0);   // another contact: not ours
        series.append(t);
    }
    QCOMPARE(series.sampleCount(), expectedSamples);
    if (expectedSamples == 0) return;
    QCOMPARE(series.componentCount(), 3);
    if (index < 0) {
        QCOMPARE(series.points(1).last(), QPointF(0.5, 1.0 / 3.0));   // exactly the recorded double
        QCOMPARE(series.points(-1).first().y(), std::sqrt(0.0 + 1.0 / 9.0 + 0.0));
    } else {
        QCOMPARE(series.samples()[0].step, 1L);
        QCOMPARE(series.samples()[1].step, 3L);
        QVERIFY(series.sampleAt(2) == nullptr);
    }
    // Back to step 2: only steps k <= 2 stay.
    rbw::QuantitySeries copy = series;
    copy.truncateAfter(2);
    for (const auto& sample : copy.samples()) QVERIFY(sample.step <= 2);
    // CSV: the numbers read back bit for bit.
    const QList<QByteArray> lines = series.csv(true).trimmed().split('\n');
    QCOMPARE(lines.size(), expectedSamples + 1);
    const QList<QByteArray> last = lines.last().split(',');
    QCOMPARE(last.size(), 2 + 3 + 1);
    QCOMPARE(last[3].toDouble(), series.samples().back().values[1]);
}

void TestPlotData::quantitySeriesSkipsNonFinite()
{
    rbw::QuantitySeries series(rbw::QuantityKey{"angular_velocity", 0, -1}, "ω", "rad/s");
    rbw::StepTrace t;
    t.step = 0;
    t.time = 0.01;
    t.add(rbw::q::angular_velocity, 0, rbw::Vec3(std::numeric_limits<double>::quiet_NaN(), 0, 0), -1);
    QVERIFY(!series.append(t));   // never drawn
    QCOMPARE(series.sampleCount(), 0);
    t.entries.clear();
    t.add(rbw::q::angular_velocity, 0, rbw::Vec3(1, 2, 3), -1);
    QVERIFY(series.append(t));
    QVERIFY(!series.append(t));   // the same step twice: refused
    QCOMPARE(series.sampleCount(), 1);
}

QTEST_GUILESS_MAIN(TestPlotData)
#include "tst_plot_data.moc"
