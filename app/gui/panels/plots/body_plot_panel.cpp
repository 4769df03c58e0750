#include "app/gui/panels/plots/body_plot_panel.h"

#include "app/gui/style/body_colours.h"
#include "app/gui/panels/plots/axis_fit.h"

#include "app/gui/panels/plots/plot_axis_range.h"
#include "app/output/atomic_file.h"
#include "physics/engine/world.h"

#include <QChart>
#include <QChartView>
#include <QCoreApplication>
#include <QImage>
#include <QLineSeries>
#include <QPainter>
#include <QBuffer>
#include <QTabWidget>
#include <QTimer>
#include <QValueAxis>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rbw {

namespace {

const char* const kTitles[] = {"T per body", "|L| per body"};
const char* const kAxisTitles[] = {"T [J]", "|L| [kg·m²/s]"};

double valueOf(BodyPlotPanel::Quantity q, const BodyDiagnostics& b)
{
    return q == BodyPlotPanel::KineticEnergy ? b.kinetic : b.L_norm;
}

} // namespace

BodyPlotPanel::BodyPlotPanel(QWidget* parent) : QWidget(parent)
{
    tabs_ = new QTabWidget(this);
    tabs_->setDocumentMode(true);
    for (int q = 0; q < QuantityCount; ++q) {
        Chart& c = charts_[q];
        c.chart = new QChart();
        c.chart->setAnimationOptions(QChart::NoAnimation);
        c.chart->setBackgroundRoundness(0);
        c.chart->setMargins(QMargins(2, 2, 6, 2));
        c.chart->legend()->setAlignment(Qt::AlignRight);
        c.x = new QValueAxis(c.chart);
        c.x->setTitleText("t [s]");
        c.y = new QValueAxis(c.chart);
        c.y->setTitleText(QString::fromUtf8(kAxisTitles[q]));
        keepLabelsWhole(c.x);
        keepLabelsWhole(c.y);
        c.chart->addAxis(c.x, Qt::AlignBottom);
        c.chart->addAxis(c.y, Qt::AlignLeft);
        connect(c.chart, &QChart::plotAreaChanged, this, &BodyPlotPanel::scheduleRefresh);
        c.view = new QChartView(c.chart);
        c.view->setRenderHint(QPainter::Antialiasing);
        tabs_->addTab(c.view, QString::fromUtf8(kTitles[q]));
    }
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(tabs_);
    refresh_ = new QTimer(this);
    refresh_->setSingleShot(true);
    refresh_->setInterval(100);   // 10 Hz, as PlotPanel
    connect(refresh_, &QTimer::timeout, this, &BodyPlotPanel::refreshNow);
    connect(tabs_, &QTabWidget::currentChanged, this, &BodyPlotPanel::scheduleRefresh);
}

void BodyPlotPanel::setBodies(const QStringList& names, const QList<bool>& fixed)
{
    names_ = names;
    fixed_ = fixed;
    t_.clear();
    for (auto& perBody : values_) perBody.assign(names.size(), {});
    rebuildLines();
}

void BodyPlotPanel::rebuildLines()
{
    for (int q = 0; q < QuantityCount; ++q) {
        Chart& c = charts_[q];
        c.chart->removeAllSeries();
        c.lines.clear();
        for (int b = 0; b < names_.size(); ++b) {
            auto* line = new QLineSeries();
            line->setName(names_[b]);
            QPen pen(lineColour(b));
            pen.setWidthF(1.8);
            line->setPen(pen);
            c.chart->addSeries(line);
            line->attachAxis(c.x);
            line->attachAxis(c.y);
            c.lines.push_back(line);
        }
    }
    refreshNow();
}

QColor BodyPlotPanel::lineColour(int body) const
{
    return bodyQColor(body, body >= 0 && body < fixed_.size() && fixed_[body], names_.value(body));
}

bool BodyPlotPanel::appendStep(double t, const Diagnostics& d)
{
    if (static_cast<int>(d.bodies.size()) != names_.size() || !std::isfinite(t)) return false;
    for (const BodyDiagnostics& b : d.bodies) {
        if (!std::isfinite(b.kinetic) || !std::isfinite(b.L_norm)) return false;
    }
    t_.push_back(t);
    for (int q = 0; q < QuantityCount; ++q) {
        for (size_t b = 0; b < d.bodies.size(); ++b) {
            values_[q][b].push_back(valueOf(static_cast<Quantity>(q), d.bodies[b]));
        }
    }
    scheduleRefresh();
    return true;
}

void BodyPlotPanel::truncate(int sampleCount)
{
    const size_t n = static_cast<size_t>(std::clamp(sampleCount, 0, this->sampleCount()));
    t_.resize(n);
    for (auto& perBody : values_) {
        for (auto& v : perBody) v.resize(n);
    }
    scheduleRefresh();
}

QList<QPointF> BodyPlotPanel::points(Quantity q, int body) const
{
    QList<QPointF> out;
    if (body < 0 || body >= names_.size()) return out;
    for (size_t i = 0; i < t_.size(); ++i) out.append(QPointF(t_[i], values_[q][body][i]));
    return out;
}

void BodyPlotPanel::scheduleRefresh()
{
    if (!onScreen_) {
        stale_ = true;
        return;
    }
    if (!refresh_->isActive()) refresh_->start();
}

void BodyPlotPanel::setOnScreen(bool on)
{
    onScreen_ = on;
    if (on && stale_) refreshNow();
}

void BodyPlotPanel::refreshNow()
{
    refresh_->stop();
    stale_ = false;
    const int q = tabs_->currentIndex();
    if (q < 0 || q >= QuantityCount) return;
    Chart& c = charts_[q];
    const int n = sampleCount();
    const int stride = std::max(1, (n + kMaxDrawn - 1) / kMaxDrawn);
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (size_t b = 0; b < c.lines.size(); ++b) {
        QList<QPointF> shown;
        shown.reserve(n / stride + 2);
        for (int i = 0; i < n; i += stride) shown.append(QPointF(t_[i], values_[q][b][i]));
        if (n > 0 && (n - 1) % stride != 0) shown.append(QPointF(t_[n - 1], values_[q][b][n - 1]));
        for (double v : values_[q][b]) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        c.lines[b]->replace(shown);
    }
    const ValueRange xr = timeAxisRange(n > 0 ? t_.back() : 1.0);
    const QRectF area = c.chart->plotArea();
    applyNiceRange(c.x, xr, area.width(), 5);
    // No sample yet (before the first step): [0, 1], not a range around nothing.
    const ValueRange yr = n > 0 ? valueAxisRange(lo, hi) : ValueRange{0.0, 1.0};
    applyNiceRange(c.y, yr, area.height(), 5);
}

bool BodyPlotPanel::exportPng(const QString& path, QString* error)
{
    refreshNow();
    const int q = tabs_->currentIndex();
    QChartView* view = charts_[q].view;
    QChart* chart = charts_[q].chart;
    const QSize size = view->size().expandedTo(QSize(480, 320));
    QImage image(size * 2, QImage::Format_ARGB32);
    image.setDevicePixelRatio(2.0);
    image.fill(Qt::white);
    // A title in the image only, so the PNG says what it shows.
    const QFont screenFont = chart->titleFont();
    QFont bold = screenFont;
    bold.setBold(true);
    chart->setTitleFont(bold);
    chart->setTitle(QStringLiteral("%1: %2").arg(QString::fromUtf8(kTitles[q]), QString::fromUtf8(kAxisTitles[q])));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    QPainter painter(&image);
    view->render(&painter, QRectF(QPointF(0, 0), QSizeF(size)));
    painter.end();
    chart->setTitle(QString());
    chart->setTitleFont(screenFont);
    // The PNG appears complete or not at all (app/output/atomic_file.h).
    QByteArray png;
    QBuffer buffer(&png);
    if (!buffer.open(QIODevice::WriteOnly) || !image.save(&buffer, "PNG")) {
        if (error != nullptr) *error = tr("%1: cannot write: the PNG could not be encoded").arg(path);
        return false;
    }
    return writeFileAtomically(path, png, error);
}

void BodyPlotPanel::sceneLoaded(const World& world)
{
    QStringList names;
    QList<bool> fixed;
    for (const BodyDef& b : world.scene().bodies) {
        names << QString::fromStdString(b.name);
        fixed << b.fixed;
    }
    setBodies(names, fixed);
    appendStep(world.time(), world.diagnostics());   // sample 0: t = 0, computed by the physics
}

void BodyPlotPanel::stepRecorded(const StepTrace& trace) { appendStep(trace.time, trace.diagnostics); }

void BodyPlotPanel::rewound(long stepIndex) { truncate(static_cast<int>(stepIndex) + 1); }   // sample 0 is t = 0

} // namespace rbw
