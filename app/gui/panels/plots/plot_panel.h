// The energy and momentum plots: three Qt Charts (energy; linear momentum P;
// angular momentum about the origin L_O), one tab each, with a row of check boxes
// per chart that shows or hides its series, and export to PNG and CSV.
//
// It only shows numbers recorded by the physics: appendStep() takes a step's
// StepTrace::diagnostics (physics/engine/diagnostics.h); see plot_catalogue.h for which
// number each series is. Nothing physical is computed here.
//
// Live updates stay cheap at 60 steps/s for minutes: appendStep() only stores the
// sample; a timer (at most ~10 Hz) appends the new points to the chart series and
// rescales the axes, for the series that are drawn now (visible, current tab);
// beyond maxDisplayPoints() samples a series is drawn decimated (plot_decimation.h)
// while points() and the CSV keep every sample. Qt Charts redraws a whole line on
// every change, so the frame time grows with the points drawn: 1200 per series
// (600 min/max buckets, about one per pixel of the docked chart) keeps a frame at a
// few ms where 20 000 took 30-60 ms under Xvfb. Stroking the lines is the app's
// largest cost on the GUI thread while playing (perf, lesson 4 with 50 boxes), so
// the plots refresh at 10 Hz: the 3D view is what moves smoothly.
#pragma once

#include "app/core/session_panel.h"
#include "app/gui/panels/plots/plot_catalogue.h"
#include "app/gui/panels/plots/plot_series.h"

#include <QList>
#include <QPointF>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <array>

class QAction;
class QChart;
class QChartView;
class QCheckBox;
class QLineSeries;
class QTabWidget;
class QTimer;
class QValueAxis;

namespace rbw {

class PlotPanel : public QWidget, public SessionPanel {
    Q_OBJECT
public:
    explicit PlotPanel(QWidget* parent = nullptr);
    ~PlotPanel() override;

    // One sample per step: t (StepTrace::time, the end of the step) and the step's
    // diagnostics. A sample with a non-finite number, or a t before the last one,
    // is refused: false, nothing stored, the reason in lastError().
    bool appendStep(double t, const rbw::Diagnostics& d);
    // Keeps the first sampleCount samples (after a step back); clamped to [0, count].
    void truncate(int sampleCount);
    void clear();

    // SessionPanel (app/core/session_panel.h): sample 0 is the first state's
    // diagnostics, then one sample per recorded step; a rewind to state k keeps k + 1.
    void sceneLoaded(const World& world) override;
    void stepRecorded(const StepTrace& trace) override;
    void rewound(long stepIndex) override;

    int sampleCount() const;
    // Every sample of a series (the full data, never decimated); empty for an unknown id.
    QList<QPointF> points(const QString& seriesId) const;
    const PlotSeries& data() const { return data_; }
    QString lastError() const { return lastError_; }

    // The catalogue's ids, in CSV column order.
    static QStringList seriesIds();
    bool isSeriesVisible(const QString& id) const;   // false for an unknown id
    // Shows or hides a series (and ticks its check box); false for an unknown id.
    bool setSeriesVisible(const QString& id, bool visible);

    PlotChart currentChart() const;
    void setCurrentChart(PlotChart chart);

    // The axis ranges a chart shows now (after refreshNow() they reflect every sample).
    ValueRange xAxisRange(PlotChart chart) const;
    ValueRange yAxisRange(PlotChart chart) const;
    // How many points the chart draws for a series (fewer than sampleCount() when
    // decimated). Only the series drawn now (visible, on the current tab) are kept up
    // to date; the others catch up when they are shown.
    int displayedPointCount(const QString& id) const;
    int maxDisplayPoints() const { return maxDisplayPoints_; }
    // Whether the panel can be seen (BodyPlotPanel::setOnScreen): off screen, samples
    // are stored and the charts redrawn when it comes back.
    void setOnScreen(bool on);
    void setMaxDisplayPoints(int maxPoints);   // at least 2; default kDefaultMaxDisplayPoints
    static constexpr int kDefaultMaxDisplayPoints = 1200;

    // Applies pending samples to the charts and rescales the axes now instead of at
    // the next timer tick (tests, export).
    void refreshNow();

    // The chart of the current tab as a PNG at device pixel ratio 2 on white: the
    // image is 2 * exportLogicalSize() pixels. False with a message on failure.
    bool exportPng(const QString& path, QString* error);
    QSize exportLogicalSize() const;
    // All samples of all series (PlotSeries::csv()), written atomically.
    bool exportCsv(const QString& path, QString* error);

signals:
    void seriesVisibilityChanged(const QString& id, bool visible);

private:
    struct ChartParts {
        QChart* chart = nullptr;
        QChartView* view = nullptr;
        QValueAxis* xAxis = nullptr;
        QValueAxis* yAxis = nullptr;
        ValueRange xInput{0.0, 0.0};   // the unrounded ranges last applied
        ValueRange yInput{0.0, 0.0};
        bool hasInput = false;
    };
    struct SeriesParts {
        QLineSeries* line = nullptr;
        QCheckBox* box = nullptr;
        // What the line shows: the first shownSamples samples at shownStride;
        // shownSamples = -1 when it must be redrawn from the data.
        int shownSamples = 0;
        int shownStride = 1;
    };

    QWidget* buildChartPage(PlotChart chart);
    void scheduleRefresh();
    void updateDisplayedPoints();
    void syncSeries(SeriesParts& s, PlotQuantity q, int stride);
    void updateAxes(PlotChart chart);
    void applySeriesVisibility(PlotQuantity q, bool visible);
    void exportPngInteractive();
    void exportCsvInteractive();

    PlotSeries data_;
    QString lastError_;
    QTabWidget* tabs_ = nullptr;
    QTimer* refreshTimer_ = nullptr;
    bool onScreen_ = true;
    bool stale_ = false;   // samples arrived while off screen: redraw when shown
    QAction* exportPngAction_ = nullptr;
    QAction* exportCsvAction_ = nullptr;
    std::array<ChartParts, kPlotChartCount> charts_{};
    std::array<SeriesParts, kPlotQuantityCount> series_{};

    bool axesDirty_ = true;
    int maxDisplayPoints_ = kDefaultMaxDisplayPoints;
};

} // namespace rbw
