#include "app/gui/panels/plots/plot_panel.h"

#include "app/gui/panels/plots/axis_fit.h"
#include "app/gui/panels/plots/export_dialog.h"
#include "app/gui/panels/plots/plot_axis_range.h"
#include "app/gui/panels/plots/plot_decimation.h"
#include "physics/engine/world.h"

#include <QAction>
#include <QChart>
#include <QChartView>
#include <QCoreApplication>
#include <QGraphicsLayout>
#include <QCheckBox>
#include <QHBoxLayout>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QMenu>
#include <QPainter>
#include <QPixmap>
#include <QTabWidget>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace rbw {

namespace {

// At most ~10 repaints per second, however fast the steps come.
constexpr int kRefreshIntervalMs = 100;
constexpr int kAxisTickCount = 5;

// Colours: energy parts in distinct hues, components x, y, z in the usual red,
// green, blue of the axes, and every total or length in black.
QColor seriesColour(PlotQuantity q)
{
    switch (q) {
    case PlotQuantity::KineticTranslational: return QColor(0x1f, 0x77, 0xb4);
    case PlotQuantity::KineticRotational: return QColor(0xff, 0x7f, 0x0e);
    case PlotQuantity::Potential: return QColor(0x2c, 0xa0, 0x2c);
    case PlotQuantity::P_x:
    case PlotQuantity::L_O_x: return QColor(0xd6, 0x27, 0x28);
    case PlotQuantity::P_y:
    case PlotQuantity::L_O_y: return QColor(0x2c, 0xa0, 0x2c);
    case PlotQuantity::P_z:
    case PlotQuantity::L_O_z: return QColor(0x1f, 0x77, 0xb4);
    case PlotQuantity::Total:
    case PlotQuantity::P_norm:
    case PlotQuantity::L_O_norm: return QColor(Qt::black);
    }
    return QColor(Qt::gray);
}

QIcon swatch(const QColor& colour)
{
    QPixmap pixmap(12, 12);
    pixmap.fill(colour);
    return QIcon(pixmap);
}

} // namespace

PlotPanel::PlotPanel(QWidget* parent)
    : QWidget(parent)
{
    // The throttle first: building the pages already schedules a refresh.
    refreshTimer_ = new QTimer(this);
    refreshTimer_->setSingleShot(true);
    refreshTimer_->setInterval(kRefreshIntervalMs);
    connect(refreshTimer_, &QTimer::timeout, this, &PlotPanel::refreshNow);

    tabs_ = new QTabWidget(this);
    tabs_->setDocumentMode(true);
    for (int c = 0; c < kPlotChartCount; ++c) {
        const PlotChart chart = static_cast<PlotChart>(c);
        tabs_->addTab(buildChartPage(chart), QString::fromUtf8(plotChartInfo(chart).tabTitle));
    }

    exportPngAction_ = new QAction(tr("Export PNG…"), this);
    exportPngAction_->setToolTip(tr("Save the chart of this tab as a PNG image"));
    exportCsvAction_ = new QAction(tr("Export CSV…"), this);
    exportCsvAction_->setToolTip(tr("Save every sample of every series as CSV"));
    connect(exportPngAction_, &QAction::triggered, this, &PlotPanel::exportPngInteractive);
    connect(exportCsvAction_, &QAction::triggered, this, &PlotPanel::exportCsvInteractive);

    auto* exportButton = new QToolButton(tabs_);
    exportButton->setText(tr("Export"));
    exportButton->setPopupMode(QToolButton::InstantPopup);
    exportButton->setAutoRaise(true);
    auto* exportMenu = new QMenu(exportButton);
    exportMenu->addAction(exportPngAction_);
    exportMenu->addAction(exportCsvAction_);
    exportButton->setMenu(exportMenu);
    tabs_->setCornerWidget(exportButton, Qt::TopRightCorner);
    connect(tabs_, &QTabWidget::currentChanged, this, [this](int) { refreshNow(); });

    for (const ChartParts& parts : charts_) {
        parts.view->addAction(exportPngAction_);
        parts.view->addAction(exportCsvAction_);
        parts.view->setContextMenuPolicy(Qt::ActionsContextMenu);
    }

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(tabs_);

    refreshNow();
}

PlotPanel::~PlotPanel() = default;

QWidget* PlotPanel::buildChartPage(PlotChart which)
{
    ChartParts& parts = charts_[static_cast<std::size_t>(plotIndex(which))];

    QFont smallFont = font();
    smallFont.setPointSizeF(std::max(7.0, smallFont.pointSizeF() - 1.0));

    parts.chart = new QChart();
    parts.chart->setAnimationOptions(QChart::NoAnimation);
    parts.chart->setBackgroundRoundness(0);
    parts.chart->setMargins(QMargins(2, 2, 6, 2));
    // On the right: the dock is wider than it is tall.
    parts.chart->legend()->setAlignment(Qt::AlignRight);
    parts.chart->legend()->setFont(smallFont);

    parts.xAxis = new QValueAxis(parts.chart);
    parts.xAxis->setTitleText(QStringLiteral("t [s]"));
    parts.yAxis = new QValueAxis(parts.chart);
    parts.yAxis->setTitleText(QString::fromUtf8(plotChartInfo(which).axisTitle));
    for (QValueAxis* axis : {parts.xAxis, parts.yAxis}) {
        axis->setLabelsFont(smallFont);
        axis->setTitleFont(smallFont);
        axis->setTickCount(kAxisTickCount);
        keepLabelsWhole(axis);
    }
    parts.chart->addAxis(parts.xAxis, Qt::AlignBottom);
    // A resized dock changes how many y ticks fit: re-fit the axes.
    connect(parts.chart, &QChart::plotAreaChanged, this, [this, which](const QRectF& area) {
        ChartParts& p = charts_[static_cast<std::size_t>(plotIndex(which))];
        if (fittingTickCount(area.height(), p.yAxis->labelsFont(), kAxisTickCount, true) != p.yAxis->tickCount()) {
            p.hasInput = false;
            axesDirty_ = true;
            scheduleRefresh();
        }
    });
    parts.chart->addAxis(parts.yAxis, Qt::AlignLeft);

    auto* page = new QWidget(tabs_);
    auto* boxes = new QHBoxLayout();
    boxes->setContentsMargins(4, 2, 4, 0);
    boxes->setSpacing(8);

    for (const PlotSeriesInfo& info : plotSeriesCatalogue()) {
        if (info.chart != which) continue;
        SeriesParts& s = series_[static_cast<std::size_t>(plotIndex(info.quantity))];
        const QString label = info.label;
        const QColor colour = seriesColour(info.quantity);

        s.line = new QLineSeries(parts.chart);
        s.line->setName(label);
        QPen pen(colour);
        pen.setWidthF(info.quantity == PlotQuantity::Total || info.quantity == PlotQuantity::P_norm
                              || info.quantity == PlotQuantity::L_O_norm
                          ? 2.5
                          : 1.8);
        s.line->setPen(pen);
        parts.chart->addSeries(s.line);
        s.line->attachAxis(parts.xAxis);
        s.line->attachAxis(parts.yAxis);

        s.box = new QCheckBox(label, page);
        s.box->setIcon(swatch(colour));
        s.box->setToolTip(info.meaning);
        s.box->setChecked(info.visibleByDefault);
        const PlotQuantity q = info.quantity;
        connect(s.box, &QCheckBox::toggled, this, [this, q](bool on) { applySeriesVisibility(q, on); });
        boxes->addWidget(s.box);
        applySeriesVisibility(q, info.visibleByDefault);
    }
    boxes->addStretch(1);

    parts.view = new QChartView(parts.chart, page);
    parts.view->setRenderHint(QPainter::Antialiasing);
    parts.view->setMinimumSize(200, 120);

    auto* layout = new QVBoxLayout(page);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addLayout(boxes);
    layout->addWidget(parts.view, 1);
    return page;
}

bool PlotPanel::appendStep(double t, const Diagnostics& d)
{
    QString error;
    if (!data_.append(t, d, &error)) {
        lastError_ = error;
        return false;
    }
    axesDirty_ = true;
    scheduleRefresh();
    return true;
}

void PlotPanel::truncate(int sampleCount)
{
    const int keep = std::clamp(sampleCount, 0, data_.sampleCount());
    if (keep == data_.sampleCount()) return;
    data_.truncate(keep);
    for (SeriesParts& s : series_) {
        if (s.shownStride == 1 && keep <= s.shownSamples) {
            // Drop the later points from the line itself: no redraw from the data.
            s.line->removePoints(keep, s.shownSamples - keep);
            s.shownSamples = keep;
        } else if (s.shownSamples > 0) {
            s.shownSamples = -1;   // a bucket was cut: redraw
        }
    }
    // After a step back the axes fit the remaining data again (no hysteresis).
    for (ChartParts& parts : charts_) parts.hasInput = false;
    axesDirty_ = true;
    scheduleRefresh();
}

void PlotPanel::clear()
{
    data_.clear();
    for (SeriesParts& s : series_) {
        s.line->clear();
        s.shownSamples = 0;
        s.shownStride = 1;
    }
    for (ChartParts& parts : charts_) parts.hasInput = false;
    axesDirty_ = true;
    scheduleRefresh();
}

int PlotPanel::sampleCount() const
{
    return data_.sampleCount();
}

QList<QPointF> PlotPanel::points(const QString& seriesId) const
{
    const PlotSeriesInfo* info = findPlotSeries(seriesId);
    if (info == nullptr) return {};
    return data_.points(info->quantity);
}

QStringList PlotPanel::seriesIds()
{
    QStringList ids;
    for (const PlotSeriesInfo& s : plotSeriesCatalogue()) ids << s.id;
    return ids;
}

bool PlotPanel::isSeriesVisible(const QString& id) const
{
    const PlotSeriesInfo* info = findPlotSeries(id);
    if (info == nullptr) return false;
    return series_[static_cast<std::size_t>(plotIndex(info->quantity))].line->isVisible();
}

bool PlotPanel::setSeriesVisible(const QString& id, bool visible)
{
    const PlotSeriesInfo* info = findPlotSeries(id);
    if (info == nullptr) {
        lastError_ = QStringLiteral("unknown plot series \"%1\"").arg(id);
        return false;
    }
    // The check box's toggled signal applies it (and nothing happens if it is unchanged).
    series_[static_cast<std::size_t>(plotIndex(info->quantity))].box->setChecked(visible);
    return true;
}

void PlotPanel::applySeriesVisibility(PlotQuantity q, bool visible)
{
    SeriesParts& s = series_[static_cast<std::size_t>(plotIndex(q))];
    const ChartParts& parts = charts_[static_cast<std::size_t>(plotIndex(plotSeriesInfo(q).chart))];
    // Bring the line up to date before it shows (it is not updated while hidden).
    if (visible) syncSeries(s, q, strideFor(data_.sampleCount(), maxDisplayPoints_));
    s.line->setVisible(visible);
    // A hidden series leaves the legend too.
    for (QLegendMarker* marker : parts.chart->legend()->markers(s.line)) marker->setVisible(visible);
    axesDirty_ = true;
    scheduleRefresh();
    emit seriesVisibilityChanged(plotSeriesId(q), visible);
}

PlotChart PlotPanel::currentChart() const
{
    return static_cast<PlotChart>(std::max(0, tabs_->currentIndex()));
}

void PlotPanel::setCurrentChart(PlotChart chart)
{
    tabs_->setCurrentIndex(plotIndex(chart));
}

ValueRange PlotPanel::xAxisRange(PlotChart chart) const
{
    const ChartParts& parts = charts_[static_cast<std::size_t>(plotIndex(chart))];
    return ValueRange{parts.xAxis->min(), parts.xAxis->max()};
}

ValueRange PlotPanel::yAxisRange(PlotChart chart) const
{
    const ChartParts& parts = charts_[static_cast<std::size_t>(plotIndex(chart))];
    return ValueRange{parts.yAxis->min(), parts.yAxis->max()};
}

int PlotPanel::displayedPointCount(const QString& id) const
{
    const PlotSeriesInfo* info = findPlotSeries(id);
    if (info == nullptr) return 0;
    return static_cast<int>(series_[static_cast<std::size_t>(plotIndex(info->quantity))].line->count());
}

void PlotPanel::setMaxDisplayPoints(int maxPoints)
{
    maxDisplayPoints_ = std::max(2, maxPoints);
    for (SeriesParts& s : series_) s.shownSamples = -1;
    scheduleRefresh();
}

void PlotPanel::scheduleRefresh()
{
    // Off screen (a closed dock, or a tab behind another: setOnScreen): redrawn when
    // it comes back, since QLineSeries::replace() lays out and strokes the path even
    // for a chart nobody sees.
    if (!onScreen_) {
        stale_ = true;
        return;
    }
    if (!refreshTimer_->isActive()) refreshTimer_->start();
}

void PlotPanel::setOnScreen(bool on)
{
    onScreen_ = on;
    if (on && stale_) refreshNow();
}

void PlotPanel::refreshNow()
{
    refreshTimer_->stop();
    stale_ = false;
    updateDisplayedPoints();
    if (axesDirty_) {
        for (int c = 0; c < kPlotChartCount; ++c) updateAxes(static_cast<PlotChart>(c));
        axesDirty_ = false;
    }
}

void PlotPanel::updateDisplayedPoints()
{
    const int stride = strideFor(data_.sampleCount(), maxDisplayPoints_);
    const PlotChart current = currentChart();
    for (const PlotSeriesInfo& info : plotSeriesCatalogue()) {
        SeriesParts& s = series_[static_cast<std::size_t>(plotIndex(info.quantity))];
        // Only what is drawn now; a hidden series or another tab catches up when shown.
        if (info.chart != current || !s.line->isVisible()) continue;
        syncSeries(s, info.quantity, stride);
    }
}

void PlotPanel::syncSeries(SeriesParts& s, PlotQuantity q, int stride)
{
    const int shown = displayedSampleCount(data_.sampleCount(), stride);
    if (s.shownSamples < 0 || stride != s.shownStride || shown < s.shownSamples) {
        // New stride, or a step back cut into a bucket: redraw from the data.
        QList<QPointF> pts;
        pts.reserve(displayPointCount(data_.sampleCount(), stride));
        appendDisplayPoints(data_, q, 0, shown, stride, pts);
        s.line->replace(pts);
    } else if (shown > s.shownSamples) {
        // The new samples after the ones shown, in one replace(): Qt 6.4's
        // QXYSeries::append(QList) appends point by point, and each point lays out and
        // strokes the whole line again (a quarter of the GUI thread in lesson 4).
        QList<QPointF> pts = s.line->points();
        appendDisplayPoints(data_, q, s.shownSamples, shown, stride, pts);
        s.line->replace(pts);
    }
    s.shownSamples = shown;
    s.shownStride = stride;
}

void PlotPanel::updateAxes(PlotChart chart)
{
    ChartParts& parts = charts_[static_cast<std::size_t>(plotIndex(chart))];

    // The wanted ranges: all samples in time, the visible series' values.
    const ValueRange xWanted = timeAxisRange(data_.lastTime());
    bool any = false;
    ValueRange data{0.0, 0.0};
    for (const PlotSeriesInfo& info : plotSeriesCatalogue()) {
        if (info.chart != chart) continue;
        if (!series_[static_cast<std::size_t>(plotIndex(info.quantity))].line->isVisible()) continue;
        const std::optional<ValueRange> r = data_.valueRange(info.quantity);
        if (!r) continue;
        data.min = any ? std::min(data.min, r->min) : r->min;
        data.max = any ? std::max(data.max, r->max) : r->max;
        any = true;
    }
    const ValueRange yWanted = any ? valueAxisRange(data.min, data.max) : ValueRange{0.0, 1.0};

    // Keep the current (nice) range while it still holds the wanted one and the
    // wanted one has not shrunk to less than half of what the axis was made for;
    // otherwise re-fit. This spares a relayout on most refreshes.
    const QRectF area = parts.chart->plotArea();
    auto apply = [&area](QValueAxis* axis, ValueRange& input, const ValueRange& wanted, bool force) {
        const bool inside = wanted.min >= axis->min() && wanted.max <= axis->max();
        const bool shrunk = (wanted.max - wanted.min) < 0.5 * (input.max - input.min);
        if (!force && inside && !shrunk) return;
        input = wanted;
        const bool vertical = axis->orientation() == Qt::Vertical;
        applyNiceRange(axis, wanted, vertical ? area.height() : area.width(), kAxisTickCount);
    };
    apply(parts.xAxis, parts.xInput, xWanted, !parts.hasInput);
    apply(parts.yAxis, parts.yInput, yWanted, !parts.hasInput);
    parts.hasInput = true;
}

QSize PlotPanel::exportLogicalSize() const
{
    const ChartParts& parts = charts_[static_cast<std::size_t>(plotIndex(currentChart()))];
    return parts.chart->size().toSize();
}

bool PlotPanel::exportPng(const QString& path, QString* error)
{
    refreshNow();
    ChartParts& parts = charts_[static_cast<std::size_t>(plotIndex(currentChart()))];
    const PlotChartInfo& info = plotChartInfo(currentChart());
    return writeChartPng(parts.chart, parts.view->isVisible(), path, error,
                         QStringLiteral("%1: %2").arg(tr(info.tabTitle), QString::fromUtf8(info.axisTitle)));
}

bool PlotPanel::exportCsv(const QString& path, QString* error)
{
    return data_.writeCsv(path, error);
}

void PlotPanel::exportPngInteractive()
{
    exportPlotInteractively(this, PlotExportFormat::Png, QStringLiteral("plot.png"),
                            [this](const QString& path, QString* error) { return exportPng(path, error); });
}

void PlotPanel::exportCsvInteractive()
{
    exportPlotInteractively(this, PlotExportFormat::Csv, QStringLiteral("plot.csv"),
                            [this](const QString& path, QString* error) { return exportCsv(path, error); });
}

void PlotPanel::sceneLoaded(const World& world)
{
    clear();
    appendStep(world.time(), world.diagnostics());   // sample 0: t = 0, computed by the physics
}

void PlotPanel::stepRecorded(const StepTrace& trace) { appendStep(trace.time, trace.diagnostics); }

void PlotPanel::rewound(long stepIndex) { truncate(static_cast<int>(stepIndex) + 1); }   // sample 0 is t = 0

} // namespace rbw
