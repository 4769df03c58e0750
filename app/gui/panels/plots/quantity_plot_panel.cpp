#include "app/gui/panels/plots/quantity_plot_panel.h"

#include "app/core/step_history.h"
#include "app/gui/style/body_colours.h"
#include "physics/engine/world.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QLabel>
#include <QTabBar>
#include <QTabWidget>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>

namespace rbw {

namespace {

constexpr int kRefreshIntervalMs = 100;

} // namespace

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
    // One plot needs no tab (its legend names it, its bar has Close): the chart keeps
    // the row (issue 20, a chart tall enough to read at 1366x768).
    tabs_->tabBar()->setAutoHide(true);
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
                box->addItem(q.componentLabel(c), QPoint(static_cast<int>(s), c));
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

void QuantityPlotPanel::sceneLoaded(const World& world)
{
    QStringList names;
    QList<bool> fixed;
    for (const BodyDef& b : world.scene().bodies) {
        names << QString::fromStdString(b.name);
        fixed << b.fixed;
    }
    setScene(names, fixed);   // another scene's plots go
    clearSamples();
}

void QuantityPlotPanel::stepRecorded(const StepTrace& trace) { appendStep(trace); }

void QuantityPlotPanel::rewound(long stepIndex) { truncateAfter(stepIndex - 1); }   // the trace of step k leads to state k + 1

} // namespace rbw
