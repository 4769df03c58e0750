#include "app/gui/panels/plots/quantity_plot_panel.h"

#include "app/output/atomic_file.h"
#include "app/core/step_history.h"
#include "app/gui/style/body_colours.h"
#include "app/gui/panels/plots/axis_fit.h"
#include "app/gui/panels/plots/export_dialog.h"
#include "app/gui/panels/plots/plot_axis_range.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QCoreApplication>
#include <QGraphicsLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLegend>
#include <QLineSeries>
#include <QPainter>
#include <QTabWidget>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <optional>

namespace rbw {

namespace {

constexpr int kRefreshIntervalMs = 100;
constexpr int kAxisTickCount = 5;

const Qt::PenStyle kComponentStyles[] = {Qt::SolidLine, Qt::DashLine, Qt::DotLine, Qt::DashDotLine};

// Applies a wanted range to an axis with nice numbers and labels that fit.
void applyRange(QValueAxis* axis, const ValueRange& wanted, const QRectF& area)
{
    const bool vertical = axis->orientation() == Qt::Vertical;
    axis->setTickCount(
        fittingTickCount(vertical ? area.height() : area.width(), axis->labelsFont(), kAxisTickCount, vertical));
    axis->setRange(wanted.min, wanted.max);
    axis->applyNiceNumbers();
    const double step = (axis->max() - axis->min()) / std::max(1, axis->tickCount() - 1);
    axis->setLabelFormat(axisLabelFormat(axis->min(), axis->max(), step));
}

} // namespace

// --- QuantityPlot ---

QuantityPlot::QuantityPlot(const QuantitySeries* series, QColor colour, QWidget* parent)
    : QWidget(parent)
    , series_(series)
    , colour_(colour)
{
    QFont smallFont = font();
    smallFont.setPointSizeF(std::max(7.0, smallFont.pointSizeF() - 1.0));

    chart_ = new QChart();
    chart_->setAnimationOptions(QChart::NoAnimation);
    chart_->setBackgroundRoundness(0);
    chart_->setMargins(QMargins(2, 2, 8, 2));
    chart_->legend()->setAlignment(Qt::AlignRight);
    chart_->legend()->setFont(smallFont);
    // The legend draws each line with its pen: the components differ by dash pattern.
    chart_->legend()->setMarkerShape(QLegend::MarkerShapeFromSeries);
    xAxis_ = new QValueAxis(chart_);
    yAxis_ = new QValueAxis(chart_);
    for (QValueAxis* axis : {xAxis_, yAxis_}) {
        axis->setLabelsFont(smallFont);
        axis->setTitleFont(smallFont);
        axis->setTickCount(kAxisTickCount);
        keepLabelsWhole(axis);
    }
    chart_->addAxis(xAxis_, Qt::AlignBottom);
    connect(chart_, &QChart::plotAreaChanged, this, [this](const QRectF& area) {
        if (fittingTickCount(area.height(), yAxis_->labelsFont(), kAxisTickCount, true) != yAxis_->tickCount()) {
            QTimer::singleShot(0, this, &QuantityPlot::refresh);
        }
    });
    chart_->addAxis(yAxis_, Qt::AlignLeft);
    view_ = new QChartView(chart_, this);
    view_->setRenderHint(QPainter::Antialiasing);
    view_->setMinimumSize(160, 100);

    modeBox_ = new QComboBox;
    modeBox_->setObjectName("plotModeBox");
    modeBox_->addItems({tr("components"), tr("length |v|")});
    modeBox_->setToolTip(tr("Each component, or the Euclidean length of the vector"));
    connect(modeBox_, &QComboBox::activated, this, [this](int i) { setShowNorm(i == 1); });
    xBox_ = new QComboBox;
    xBox_->setObjectName("plotXAxisBox");
    xBox_->setToolTip(tr("Against time, or against a component of a plotted quantity (a phase plot)"));
    connect(xBox_, &QComboBox::activated, this, &QuantityPlot::xAxisChoiceChanged);
    note_ = new QLabel;
    note_->setObjectName("plotNote");

    auto* exportButton = new QToolButton;
    exportButton->setText(tr("Export"));
    exportButton->setPopupMode(QToolButton::InstantPopup);
    auto* png = new QAction(tr("Export PNG…"), this);
    auto* csvAction = new QAction(tr("Export CSV…"), this);
    connect(png, &QAction::triggered, this, &QuantityPlot::exportPngInteractive);
    connect(csvAction, &QAction::triggered, this, &QuantityPlot::exportCsvInteractive);
    exportButton->addAction(png);
    exportButton->addAction(csvAction);
    view_->addAction(png);
    view_->addAction(csvAction);
    view_->setContextMenuPolicy(Qt::ActionsContextMenu);
    auto* close = new QToolButton;
    close->setText(tr("Close"));
    close->setToolTip(tr("Remove this plot"));
    connect(close, &QToolButton::clicked, this, &QuantityPlot::closeRequested);

    auto* bar = new QHBoxLayout;
    bar->setContentsMargins(4, 2, 4, 0);
    bar->addWidget(new QLabel(tr("Show")));
    bar->addWidget(modeBox_);
    bar->addWidget(new QLabel(tr("against")));
    bar->addWidget(xBox_, 1);
    bar->addWidget(note_);
    bar->addStretch(0);
    bar->addWidget(exportButton);
    bar->addWidget(close);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addLayout(bar);
    layout->addWidget(view_, 1);
    refresh();
}

void QuantityPlot::setShowNorm(bool norm)
{
    showNorm_ = norm && series_->componentCount() != 1;
    modeBox_->setCurrentIndex(showNorm_ ? 1 : 0);
    refresh();
}

void QuantityPlot::setXAxis(const QuantitySeries* xSeries, int xComponent)
{
    xSeries_ = xSeries;
    xComponent_ = xComponent;
    refresh();
}

int QuantityPlot::lineCount() const
{
    if (showNorm_) return 1;
    return std::max(1, series_->componentCount());
}

QList<QPointF> QuantityPlot::linePoints(int line) const
{
    const int component = showNorm_ ? -1 : line;
    if (xSeries_ == nullptr) return series_->points(component);
    // Phase plot: (x of step k, y of step k) for the steps both series have.
    QList<QPointF> out;
    for (const QuantitySeries::Sample& s : series_->samples()) {
        const QuantitySeries::Sample* x = xSeries_->sampleAt(s.step);
        if (x == nullptr) continue;
        const double xv = xComponent_ < 0 ? normOf(x->values)
                                          : (xComponent_ < static_cast<int>(x->values.size())
                                                 ? x->values[static_cast<std::size_t>(xComponent_)]
                                                 : std::nan(""));
        const double yv = component < 0 ? normOf(s.values)
                                        : (component < static_cast<int>(s.values.size())
                                               ? s.values[static_cast<std::size_t>(component)]
                                               : std::nan(""));
        if (std::isfinite(xv) && std::isfinite(yv)) out.append(QPointF(xv, yv));
    }
    return out;
}

QString QuantityPlot::lineName(int line) const
{
    const QString& label = series_->label();
    if (showNorm_) return QStringLiteral("|%1|").arg(label);
    const QStringList names = series_->componentNames();
    if (line < 0 || line >= names.size() || names[line].isEmpty()) return label;
    return QStringLiteral("%1 %2").arg(label, names[line]);
}

QString QuantityPlot::yAxisTitle() const
{
    const QString unit = series_->unit().isEmpty() ? QString() : QStringLiteral(" [%1]").arg(series_->unit());
    // The symbol only: the legend and the tab name the body (a long title is elided).
    return (showNorm_ ? QStringLiteral("|%1|").arg(series_->symbol()) : series_->symbol()) + unit;
}

QString QuantityPlot::xAxisTitle() const
{
    if (xSeries_ == nullptr) return QStringLiteral("t [s]");
    const QStringList names = xSeries_->componentNames();
    QString name = xComponent_ < 0 ? QStringLiteral("|%1|").arg(xSeries_->symbol())
                                   : (xComponent_ < names.size() && !names[xComponent_].isEmpty()
                                          ? QStringLiteral("%1 %2").arg(xSeries_->symbol(), names[xComponent_])
                                          : xSeries_->symbol());
    if (!xSeries_->unit().isEmpty()) name += QStringLiteral(" [%1]").arg(xSeries_->unit());
    return name;
}

void QuantityPlot::refresh()
{
    const int wanted = lineCount();
    while (static_cast<int>(lines_.size()) < wanted) {
        auto* line = new QLineSeries(chart_);
        chart_->addSeries(line);
        line->attachAxis(xAxis_);
        line->attachAxis(yAxis_);
        lines_.push_back(line);
    }
    while (static_cast<int>(lines_.size()) > wanted) {
        chart_->removeSeries(lines_.back());
        delete lines_.back();
        lines_.pop_back();
    }
    std::optional<ValueRange> xr;
    std::optional<ValueRange> yr;
    auto grow = [](std::optional<ValueRange>& r, double v) {
        if (!r) r = ValueRange{v, v};
        r->min = std::min(r->min, v);
        r->max = std::max(r->max, v);
    };
    for (int i = 0; i < wanted; ++i) {
        const QList<QPointF> points = linePoints(i);
        for (const QPointF& p : points) {
            grow(xr, p.x());
            grow(yr, p.y());
        }
        QLineSeries* line = lines_[static_cast<std::size_t>(i)];
        line->setName(lineName(i));
        QPen pen(colour_);
        pen.setWidthF(showNorm_ ? 2.4 : 1.8);
        pen.setStyle(kComponentStyles[static_cast<std::size_t>(i) % std::size(kComponentStyles)]);
        line->setPen(pen);
        // Sparse series (a contact seen in a few steps, a phase plot) show their points.
        line->setPointsVisible(points.size() < 30 || (series_->sampleCount() > 0 && points.size() < 2));
        line->replace(points);
    }
    xAxis_->setTitleText(xAxisTitle());
    yAxis_->setTitleText(yAxisTitle());
    const QRectF area = chart_->plotArea();
    if (xSeries_ == nullptr) {
        applyRange(xAxis_, timeAxisRange(xr ? xr->max : 0.0), area);
    } else {
        applyRange(xAxis_, xr ? valueAxisRange(xr->min, xr->max) : ValueRange{0.0, 1.0}, area);
    }
    applyRange(yAxis_, yr ? valueAxisRange(yr->min, yr->max) : ValueRange{0.0, 1.0}, area);
    modeBox_->setEnabled(series_->componentCount() != 1);
    note_->setText(tr("%n step(s)", "", series_->sampleCount()));
}

QByteArray QuantityPlot::csv() const
{
    if (xSeries_ == nullptr) return series_->csv(true);
    // A phase plot: the x column, then y's columns, for the steps both have.
    QByteArray out = "step,t," + xAxisTitle().toUtf8().replace(',', ';');
    for (int i = 0; i < lineCount(); ++i) out += ',' + lineName(i).toUtf8().replace(',', ';');
    out += '\n';
    for (const QuantitySeries::Sample& s : series_->samples()) {
        const QuantitySeries::Sample* x = xSeries_->sampleAt(s.step);
        if (x == nullptr) continue;
        const double xv = xComponent_ < 0 ? normOf(x->values) : x->values.at(static_cast<std::size_t>(xComponent_));
        out += QByteArray::number(static_cast<qlonglong>(s.step)) + ',' + csvNumber(s.t) + ',' + csvNumber(xv);
        if (showNorm_) {
            out += ',' + csvNumber(normOf(s.values));
        } else {
            for (double v : s.values) out += ',' + csvNumber(v);
        }
        out += '\n';
    }
    return out;
}

bool QuantityPlot::exportCsv(const QString& path, QString* error) const
{
    return writeFileAtomically(path, csv(), error);
}

bool QuantityPlot::exportPng(const QString& path, QString* error)
{
    refresh();
    return writeChartPng(chart_, view_->isVisible(), path, error);
}

void QuantityPlot::exportPngInteractive()
{
    exportPlotInteractively(this, PlotExportFormat::Png, QStringLiteral("quantity.png"),
                            [this](const QString& path, QString* error) { return exportPng(path, error); });
}

void QuantityPlot::exportCsvInteractive()
{
    exportPlotInteractively(this, PlotExportFormat::Csv, QStringLiteral("quantity.csv"),
                            [this](const QString& path, QString* error) { return exportCsv(path, error); });
}

// --- QuantityPlotPanel ---

QuantityPlotPanel::QuantityPlotPanel(QWidget* parent)
    : QWidget(parent)
{
    refresh_ = new QTimer(this);
    refresh_->setSingleShot(true);
    refresh_->setInterval(kRefreshIntervalMs);
    connect(refresh_, &QTimer::timeout, this, &QuantityPlotPanel::refreshNow);
    tabs_ = new QTabWidget(this);
    tabs_->setObjectName("quantityPlotTabs");
    tabs_->setDocumentMode(true);
    tabs_->setTabsClosable(true);
    connect(tabs_, &QTabWidget::tabCloseRequested, this,
            [this](int i) { removePlot(qobject_cast<QuantityPlot*>(tabs_->widget(i))); });
    connect(tabs_, &QTabWidget::currentChanged, this, [this](int) { refreshNow(); });
    emptyNote_ = new QLabel(tr("Right-click a row of the quantities table (or a contact's row) and choose "
                               "<b>Plot over time</b> to plot any number of the trace here."));
    emptyNote_->setWordWrap(true);
    emptyNote_->setAlignment(Qt::AlignCenter);
    emptyNote_->setMargin(12);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(emptyNote_);
    layout->addWidget(tabs_, 1);
    tabs_->hide();
}

QuantityPlotPanel::~QuantityPlotPanel()
{
    // The plots point into series_: delete them first.
    while (tabs_->count() > 0) delete tabs_->widget(0);
}

void QuantityPlotPanel::setScene(const QStringList& bodyNames, const QList<bool>& fixed)
{
    if (bodyNames != bodyNames_) removeAll();
    bodyNames_ = bodyNames;
    fixed_ = fixed;
}

QuantityPlot* QuantityPlotPanel::addQuantity(const QuantityKey& key, const QString& label, const QString& unit,
                                             const StepHistory& history, bool norm, const QString& symbol)
{
    auto series = std::make_unique<QuantitySeries>(key, label, unit, symbol);
    series->fillFromHistory(history);
    const bool fixed = key.body >= 0 && key.body < fixed_.size() && fixed_[key.body];
    auto* plot = new QuantityPlot(series.get(), bodyQColor(key.body, fixed, bodyNames_.value(key.body)));
    plot->setObjectName(QStringLiteral("quantityPlot%1").arg(series_.size()));
    series_.push_back(std::move(series));
    connect(plot, &QuantityPlot::closeRequested, this, [this, plot] { removePlot(plot); });
    connect(plot, &QuantityPlot::xAxisChoiceChanged, this, [this, plot](int choice) {
        const QVariant data = plot->xAxisBox()->itemData(choice);
        if (!data.isValid()) {
            plot->setXAxis(nullptr, 0);
            return;
        }
        const QPoint which = data.toPoint();   // (series index, component)
        plot->setXAxis(series_.at(static_cast<std::size_t>(which.x())).get(), which.y());
    });
    const int index = tabs_->addTab(plot, label);
    tabs_->setTabToolTip(index, label);
    emptyNote_->hide();
    tabs_->show();
    updateXChoices();
    plot->setShowNorm(norm);
    tabs_->setCurrentIndex(index);
    emit plotAdded(index);
    return plot;
}

void QuantityPlotPanel::removePlot(QuantityPlot* plot)
{
    if (plot == nullptr) return;
    const int index = tabs_->indexOf(plot);
    if (index < 0) return;
    const QuantitySeries* gone = &plot->series();
    tabs_->removeTab(index);
    delete plot;
    for (int i = 0; i < tabs_->count(); ++i) {
        auto* p = qobject_cast<QuantityPlot*>(tabs_->widget(i));
        if (p != nullptr && p->xSeries() == gone) p->setXAxis(nullptr, 0);
    }
    series_.erase(std::remove_if(series_.begin(), series_.end(),
                                 [gone](const std::unique_ptr<QuantitySeries>& s) { return s.get() == gone; }),
                  series_.end());
    updateXChoices();
    if (tabs_->count() == 0) {
        tabs_->hide();
        emptyNote_->show();
    }
}

void QuantityPlotPanel::removeAll()
{
    while (tabs_->count() > 0) removePlot(qobject_cast<QuantityPlot*>(tabs_->widget(0)));
    series_.clear();
}

void QuantityPlotPanel::updateXChoices()
{
    for (int i = 0; i < tabs_->count(); ++i) {
        auto* plot = qobject_cast<QuantityPlot*>(tabs_->widget(i));
        if (plot == nullptr) continue;
        QComboBox* box = plot->xAxisBox();
        const QSignalBlocker block(box);
        box->clear();
        box->addItem(tr("time t"));
        for (std::size_t s = 0; s < series_.size(); ++s) {
            const QuantitySeries& q = *series_[s];
            const QStringList names = q.componentNames();
            for (int c = 0; c < names.size(); ++c) {
                box->addItem(names[c].isEmpty() ? q.label() : QStringLiteral("%1 %2").arg(q.label(), names[c]),
                             QPoint(static_cast<int>(s), c));
                if (plot->xSeries() == &q && plot->xComponent() == c) box->setCurrentIndex(box->count() - 1);
            }
            if (q.componentCount() > 1) {
                box->addItem(QStringLiteral("|%1|").arg(q.label()), QPoint(static_cast<int>(s), -1));
                if (plot->xSeries() == &q && plot->xComponent() == -1) box->setCurrentIndex(box->count() - 1);
            }
        }
    }
}

void QuantityPlotPanel::appendStep(const StepTrace& trace)
{
    bool any = false;
    for (const std::unique_ptr<QuantitySeries>& s : series_) {
        const bool hadComponents = s->componentCount() > 0;
        if (s->append(trace)) {
            any = true;
            if (!hadComponents) updateXChoices();
        }
    }
    if (any) scheduleRefresh();
}

void QuantityPlotPanel::truncateAfter(long step)
{
    for (const std::unique_ptr<QuantitySeries>& s : series_) s->truncateAfter(step);
    scheduleRefresh();
}

void QuantityPlotPanel::clearSamples()
{
    for (const std::unique_ptr<QuantitySeries>& s : series_) s->clear();
    scheduleRefresh();
}

int QuantityPlotPanel::plotCount() const { return tabs_->count(); }

QuantityPlot* QuantityPlotPanel::plot(int i) const { return qobject_cast<QuantityPlot*>(tabs_->widget(i)); }

void QuantityPlotPanel::scheduleRefresh()
{
    if (!refresh_->isActive()) refresh_->start();
}

void QuantityPlotPanel::refreshNow()
{
    refresh_->stop();
    // Only the plot on screen is redrawn; the others catch up when their tab is shown.
    if (auto* p = qobject_cast<QuantityPlot*>(tabs_->currentWidget())) p->refresh();
}

} // namespace rbw
