#include "app/gui/panels/plots/quantity_plot.h"

#include "app/gui/panels/plots/axis_fit.h"
#include "app/gui/panels/plots/export_dialog.h"
#include "app/gui/panels/plots/plot_axis_range.h"
#include "app/output/atomic_file.h"

#include <QAction>
#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QMouseEvent>
#include <QPainter>
#include <QTimer>
#include <QToolButton>
#include <QToolTip>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <optional>

namespace rbw {

namespace {

constexpr int kAxisTickCount = 6;
// The nearest sample counts as under the mouse within this many pixels.
constexpr double kReadoutReachPx = 40.0;

// One colour per line when there are several (Tableau 10: told apart on screen and
// on paper); a single line keeps the body's colour.
const QColor kLineColours[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xff, 0x7f, 0x0e), QColor(0x2c, 0xa0, 0x2c),
                               QColor(0xd6, 0x27, 0x28), QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
                               QColor(0xe3, 0x77, 0xc2), QColor(0x7f, 0x7f, 0x7f), QColor(0xbc, 0xbd, 0x22),
                               QColor(0x17, 0xbe, 0xcf)};

QString number(double v) { return QString::number(v, 'g', 6).replace('-', QChar(0x2212)); }

} // namespace

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
    chart_->legend()->setToolTip(tr("Click an entry to hide or show its line"));
    xAxis_ = new QValueAxis(chart_);
    yAxis_ = new QValueAxis(chart_);
    for (QValueAxis* axis : {xAxis_, yAxis_}) {
        axis->setLabelsFont(smallFont);
        axis->setTitleFont(smallFont);
        keepLabelsWhole(axis);
    }
    yLog_ = new QLogValueAxis(chart_);
    yLog_->setBase(10.0);
    yLog_->setLabelFormat(QStringLiteral("%g"));
    yLog_->setMinorTickCount(8);
    yLog_->setLabelsFont(smallFont);
    yLog_->setTitleFont(smallFont);
    yLog_->setTruncateLabels(false);
    chart_->addAxis(xAxis_, Qt::AlignBottom);
    chart_->addAxis(yAxis_, Qt::AlignLeft);
    chart_->addAxis(yLog_, Qt::AlignLeft);
    yLog_->setVisible(false);
    connect(chart_, &QChart::plotAreaChanged, this, [this](const QRectF& area) {
        if (!log_ && fittingTickCount(area.height(), yAxis_->labelsFont(), kAxisTickCount, true) != yAxis_->tickCount()) {
            QTimer::singleShot(0, this, &QuantityPlot::refresh);
        }
    });
    view_ = new QChartView(chart_, this);
    view_->setRenderHint(QPainter::Antialiasing);
    view_->setMinimumSize(160, 160);
    view_->viewport()->setMouseTracking(true);
    view_->viewport()->installEventFilter(this);

    modeBox_ = new QComboBox;
    modeBox_->setObjectName("plotModeBox");
    modeBox_->setToolTip(tr("Every component, the Euclidean length of the vector, or one component alone"));
    connect(modeBox_, &QComboBox::activated, this,
            [this](int i) { setShownComponent(modeBox_->itemData(i).toInt()); });
    xBox_ = new QComboBox;
    xBox_->setObjectName("plotXAxisBox");
    xBox_->setToolTip(tr("Against time, or against a component of a plotted quantity (a phase plot)"));
    connect(xBox_, &QComboBox::activated, this, &QuantityPlot::xAxisChoiceChanged);
    logBox_ = new QCheckBox(tr("log y"));
    logBox_->setObjectName("plotLogBox");
    logBox_->setToolTip(tr("A logarithmic y axis (for values spanning decades, such as an energy going to "
                           "0). Values of 0 or below cannot be drawn on it and are left out."));
    connect(logBox_, &QCheckBox::toggled, this, [this](bool on) { setLogScale(on); });
    note_ = new QLabel;
    note_->setObjectName("plotNote");
    // The value under the mouse, over the chart's top left corner (no row of its own:
    // the chart keeps the height).
    readout_ = new QLabel(view_);
    readout_->setObjectName("plotReadout");
    readout_->setAttribute(Qt::WA_TransparentForMouseEvents);
    readout_->setStyleSheet(QStringLiteral("QLabel { background: rgba(255, 255, 255, 220); color: black; "
                                           "border: 1px solid #bbb; padding: 1px 4px; }"));
    readout_->hide();

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
    bar->addWidget(logBox_);
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

void QuantityPlot::rebuildModeBox()
{
    const int count = series_->componentCount();
    if (count == modeBoxComponents_) return;
    modeBoxComponents_ = count;
    const QSignalBlocker block(modeBox_);
    modeBox_->clear();
    if (count <= 1) {
        modeBox_->addItem(series_->symbol(), kAllComponents);
    } else {
        modeBox_->addItem(tr("all components"), kAllComponents);
        modeBox_->addItem(tr("length |%1|").arg(series_->symbol()), kLength);
        for (int c = 0; c < count; ++c) modeBox_->addItem(series_->componentSymbol(c), c);
    }
    modeBox_->setEnabled(count > 1);
    const int at = modeBox_->findData(shown_);
    modeBox_->setCurrentIndex(std::max(0, at));
}

void QuantityPlot::setShowNorm(bool norm) { setShownComponent(norm ? kLength : kAllComponents); }

void QuantityPlot::setShownComponent(int shown)
{
    const int count = series_->componentCount();
    // A scalar has only itself; a component beyond the value's is refused.
    if (count == 1 || shown < kAllComponents || (count > 0 && shown >= count)) shown = kAllComponents;
    if (shown != shown_) hidden_.clear();   // other lines: all shown again
    shown_ = shown;
    modeBoxComponents_ = -1;
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
    if (shown_ != kAllComponents) return 1;
    return std::max(1, series_->componentCount());
}

QList<QPointF> QuantityPlot::linePoints(int line) const
{
    const int component = shown_ == kAllComponents ? line : shown_;
    if (xSeries_ == nullptr) return series_->points(component);
    // Phase plot: (x of step k, y of step k) for the steps both series have.
    QList<QPointF> out;
    auto pick = [](const std::vector<double>& values, int c) {
        if (c < 0) return normOf(values);
        return c < static_cast<int>(values.size()) ? values[static_cast<std::size_t>(c)] : std::nan("");
    };
    for (const QuantitySeries::Sample& s : series_->samples()) {
        const QuantitySeries::Sample* x = xSeries_->sampleAt(s.step);
        if (x == nullptr) continue;
        const double xv = pick(x->values, xComponent_);
        const double yv = pick(s.values, component);
        if (std::isfinite(xv) && std::isfinite(yv)) out.append(QPointF(xv, yv));
    }
    return out;
}

QString QuantityPlot::lineName(int line) const
{
    if (shown_ == kLength) return QStringLiteral("|%1|").arg(series_->label());
    return series_->componentLabel(shown_ == kAllComponents ? line : shown_);
}

QColor QuantityPlot::lineColour(int line) const
{
    if (lineCount() == 1) return colour_;
    return kLineColours[static_cast<std::size_t>(line) % std::size(kLineColours)];
}

QLineSeries* QuantityPlot::chartLine(int line) const
{
    return line >= 0 && line < static_cast<int>(lines_.size()) ? lines_[static_cast<std::size_t>(line)] : nullptr;
}

QString QuantityPlot::yAxisTitle() const
{
    const QString unit = series_->unit().isEmpty() ? QString() : QStringLiteral(" [%1]").arg(series_->unit());
    // The symbol only: the legend and the tab name the body (a long title is elided).
    QString name = series_->symbol();
    if (shown_ == kLength) name = QStringLiteral("|%1|").arg(name);
    if (shown_ >= 0) name = series_->componentSymbol(shown_);
    return name + unit;
}

QString QuantityPlot::xAxisTitle() const
{
    if (xSeries_ == nullptr) return QStringLiteral("t [s]");
    QString name = xComponent_ < 0 ? QStringLiteral("|%1|").arg(xSeries_->symbol()) : xSeries_->componentSymbol(xComponent_);
    if (!xSeries_->unit().isEmpty()) name += QStringLiteral(" [%1]").arg(xSeries_->unit());
    return name;
}

QString QuantityPlot::title() const
{
    QString what = shown_ == kLength ? QStringLiteral("|%1|").arg(series_->label())
                                     : (shown_ >= 0 ? series_->componentLabel(shown_) : series_->label());
    if (!series_->unit().isEmpty()) what += QStringLiteral(" [%1]").arg(series_->unit());
    return xSeries_ == nullptr ? tr("%1 over time").arg(what) : tr("%1 against %2").arg(what, xAxisTitle());
}

bool QuantityPlot::isLineVisible(int line) const
{
    return line >= 0 && line < lineCount()
           && !(line < static_cast<int>(hidden_.size()) && hidden_[static_cast<std::size_t>(line)]);
}

void QuantityPlot::setLineVisible(int line, bool visible)
{
    if (line < 0 || line >= lineCount()) return;
    if (static_cast<int>(hidden_.size()) <= line) hidden_.resize(static_cast<std::size_t>(line) + 1, false);
    hidden_[static_cast<std::size_t>(line)] = !visible;
    refresh();   // the axes fit the lines shown
}

void QuantityPlot::applyLineVisibility(int line)
{
    QLineSeries* series = chartLine(line);
    if (series == nullptr) return;
    const bool visible = isLineVisible(line);
    series->setVisible(visible);
    // The entry stays in the legend, greyed, so a click brings the line back.
    for (QLegendMarker* marker : chart_->legend()->markers(series)) {
        marker->setVisible(true);
        QColor text = palette().color(QPalette::WindowText);
        QColor swatch = lineColour(line);
        if (!visible) {
            text.setAlphaF(0.35);
            swatch.setAlphaF(0.25);
        }
        marker->setLabelBrush(text);
        marker->setBrush(swatch);
        QPen pen = marker->pen();
        pen.setColor(swatch);
        marker->setPen(pen);
    }
}

bool QuantityPlot::setLogScale(bool on)
{
    bool positive = false;
    if (on) {
        for (int i = 0; i < lineCount() && !positive; ++i) {
            if (!isLineVisible(i)) continue;
            for (const QPointF& p : linePoints(i)) {
                if (p.y() > 0.0) {
                    positive = true;
                    break;
                }
            }
        }
    }
    log_ = on && positive;
    {
        const QSignalBlocker block(logBox_);
        logBox_->setChecked(log_);
    }
    for (QLineSeries* line : lines_) {
        line->detachAxis(log_ ? static_cast<QAbstractAxis*>(yAxis_) : yLog_);
        line->attachAxis(log_ ? static_cast<QAbstractAxis*>(yLog_) : yAxis_);
    }
    yAxis_->setVisible(!log_);
    yLog_->setVisible(log_);
    refresh();
    if (on && !log_) {
        note_->setText(tr("log y: no value above 0 to draw"));
        note_->setToolTip(tr("A logarithmic axis shows only values above 0; every value of this plot is 0 or below."));
    }
    return log_ == on;
}

void QuantityPlot::refresh()
{
    const int wanted = lineCount();
    while (static_cast<int>(lines_.size()) < wanted) {
        auto* line = new QLineSeries(chart_);
        chart_->addSeries(line);
        line->attachAxis(xAxis_);
        line->attachAxis(log_ ? static_cast<QAbstractAxis*>(yLog_) : yAxis_);
        const int index = static_cast<int>(lines_.size());
        for (QLegendMarker* marker : chart_->legend()->markers(line)) {
            connect(marker, &QLegendMarker::clicked, this, [this, index] { setLineVisible(index, !isLineVisible(index)); });
        }
        lines_.push_back(line);
    }
    while (static_cast<int>(lines_.size()) > wanted) {
        chart_->removeSeries(lines_.back());
        delete lines_.back();
        lines_.pop_back();
    }
    rebuildModeBox();
    std::optional<ValueRange> xr;
    std::optional<ValueRange> yr;
    auto grow = [](std::optional<ValueRange>& r, double v) {
        if (!r) r = ValueRange{v, v};
        r->min = std::min(r->min, v);
        r->max = std::max(r->max, v);
    };
    leftOut_ = 0;
    for (int i = 0; i < wanted; ++i) {
        QList<QPointF> points = linePoints(i);
        if (log_) {
            // A log axis has no place for 0 or below: those samples are left out (and counted).
            const qsizetype before = points.size();
            points.removeIf([](const QPointF& p) { return !(p.y() > 0.0); });
            if (isLineVisible(i)) leftOut_ += static_cast<int>(before - points.size());
        }
        if (isLineVisible(i)) {
            for (const QPointF& p : points) {
                grow(xr, p.x());
                grow(yr, p.y());
            }
        }
        QLineSeries* line = lines_[static_cast<std::size_t>(i)];
        line->setName(lineName(i));
        QPen pen(lineColour(i));
        pen.setWidthF(wanted == 1 ? 2.2 : 1.6);
        line->setPen(pen);
        line->setColor(lineColour(i));
        // Sparse series (a contact seen in a few steps, a phase plot) show their points.
        line->setPointsVisible(points.size() < 30);
        line->replace(points);
        applyLineVisibility(i);
    }
    chart_->legend()->setVisible(true);
    xAxis_->setTitleText(xAxisTitle());
    yAxis_->setTitleText(yAxisTitle());
    yLog_->setTitleText(yAxisTitle());
    const QRectF area = chart_->plotArea();
    if (xSeries_ == nullptr) {
        applyNiceRange(xAxis_, timeAxisRange(xr ? xr->max : 0.0), area.width(), kAxisTickCount);
    } else {
        applyNiceRange(xAxis_, xr ? valueAxisRange(xr->min, xr->max) : ValueRange{0.0, 1.0}, area.width(),
                       kAxisTickCount);
    }
    if (log_) {
        // Whole decades around the positive samples: 10^floor(lg min) .. 10^ceil(lg max).
        const double lo = yr ? std::pow(10.0, std::floor(std::log10(yr->min))) : 0.1;
        double hi = yr ? std::pow(10.0, std::ceil(std::log10(yr->max))) : 10.0;
        if (!(hi > lo)) hi = lo * 10.0;
        yLog_->setRange(lo, hi);
    } else {
        applyNiceRange(yAxis_, yr ? valueAxisRange(yr->min, yr->max) : ValueRange{0.0, 1.0}, area.height(),
                       kAxisTickCount);
    }
    const int n = series_->sampleCount();
    QString note = n == 1 ? tr("1 step") : tr("%1 steps").arg(n);
    if (log_ && leftOut_ > 0) {
        note += leftOut_ == 1 ? tr("; 1 value ≤ 0 not on the log axis")
                              : tr("; %1 values ≤ 0 not on the log axis").arg(leftOut_);
    }
    note_->setText(note);
    note_->setToolTip(QString());
}

QString QuantityPlot::readoutAt(const QPoint& viewportPos)
{
    const QPointF chartPos = chart_->mapFromScene(view_->mapToScene(viewportPos));
    QString text;
    if (chart_->plotArea().contains(chartPos)) {
        double best = kReadoutReachPx;
        for (int i = 0; i < lineCount(); ++i) {
            QLineSeries* line = chartLine(i);
            if (line == nullptr || !isLineVisible(i) || line->count() == 0) continue;
            const QList<QPointF> points = line->points();
            auto consider = [&](qsizetype k) {
                if (k < 0 || k >= points.size()) return;
                const QPointF at = chart_->mapToPosition(points[k], line);
                const double d = std::hypot(at.x() - chartPos.x(), at.y() - chartPos.y());
                if (d >= best) return;
                best = d;
                const QString unit = series_->unit().isEmpty() ? QString() : QStringLiteral(" ") + series_->unit();
                const QString x = xSeries_ == nullptr ? QStringLiteral("t = %1 s").arg(number(points[k].x()))
                                                      : QStringLiteral("%1 = %2").arg(xAxisTitle(), number(points[k].x()));
                text = QStringLiteral("%1 = %2%3 at %4").arg(lineName(i), number(points[k].y()), unit, x);
            };
            if (xSeries_ == nullptr) {
                // Time runs forward: the samples either side of the mouse's t.
                const double t = chart_->mapToValue(chartPos, line).x();
                const auto it = std::lower_bound(points.begin(), points.end(), t,
                                                 [](const QPointF& p, double v) { return p.x() < v; });
                const qsizetype k = it - points.begin();
                consider(k - 1);
                consider(k);
            } else {
                for (qsizetype k = 0; k < points.size(); ++k) consider(k);
            }
        }
    }
    readout_->setText(text);
    placeReadout();
    return text;
}

void QuantityPlot::placeReadout()
{
    if (readout_->text().isEmpty()) {
        readout_->hide();
        return;
    }
    readout_->adjustSize();
    const QPoint corner = view_->mapFromScene(chart_->mapToScene(chart_->plotArea().topLeft()));
    readout_->move(corner + QPoint(4, 4));
    readout_->show();
    readout_->raise();
}

bool QuantityPlot::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == view_->viewport()) {
        if (event->type() == QEvent::MouseMove) {
            const auto* move = static_cast<QMouseEvent*>(event);
            const QString text = readoutAt(move->position().toPoint());
            if (text.isEmpty()) {
                QToolTip::hideText();
            } else {
                QToolTip::showText(move->globalPosition().toPoint(), text, view_);
            }
        } else if (event->type() == QEvent::Leave) {
            readout_->clear();
            placeReadout();
        }
    }
    return QWidget::eventFilter(watched, event);
}

QByteArray QuantityPlot::csv() const
{
    if (xSeries_ == nullptr) return series_->csv(true);
    // A phase plot: the x column, then y's columns, for the steps both have.
    QByteArray out = "step,t," + xAxisTitle().toUtf8().replace(',', ';');
    const bool norm = shown_ == kLength;
    if (norm) {
        out += ',' + lineName(0).toUtf8().replace(',', ';');
    } else {
        for (int c = 0; c < std::max(1, series_->componentCount()); ++c) {
            out += ',' + series_->componentLabel(c).toUtf8().replace(',', ';');
        }
    }
    out += '\n';
    for (const QuantitySeries::Sample& s : series_->samples()) {
        const QuantitySeries::Sample* x = xSeries_->sampleAt(s.step);
        if (x == nullptr) continue;
        const double xv = xComponent_ < 0 ? normOf(x->values) : x->values.at(static_cast<std::size_t>(xComponent_));
        out += QByteArray::number(static_cast<qlonglong>(s.step)) + ',' + csvNumber(s.t) + ',' + csvNumber(xv);
        if (norm) {
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
    return writeChartPng(chart_, view_->isVisible(), path, error, title());
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

} // namespace rbw
