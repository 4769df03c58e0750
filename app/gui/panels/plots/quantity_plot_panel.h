// "Plot over time": any quantity of the trace in a plot of its own, one tab per
// quantity (right-click a row of the quantities table). Each tab shows the
// components (x, y, z) or the length |v|, against time t or, as a phase plot,
// against one component of any plotted quantity (pairs taken at the same step), and
// exports its samples as CSV and the chart as PNG (both written with QSaveFile).
//
// The samples are QuantitySeries: read from the recorded step traces (the history
// when the plot is added, then one per recorded step), never recomputed. Each tab is
// a QuantityPlot (quantity_plot.h: one component or all, a legend that hides lines,
// a log axis, the value under the mouse); a single line is drawn in its body's colour
// (app/gui/style/body_colours.h). Drawing is throttled like the other plots (at most
// ~10 Hz).
#pragma once

#include "app/core/session_panel.h"
#include "app/gui/panels/plots/quantity_plot.h"
#include "app/gui/panels/plots/quantity_series.h"

#include <QColor>
#include <QList>
#include <QPointF>
#include <QStringList>
#include <QWidget>

#include <memory>
#include <vector>

class QLabel;
class QTabWidget;
class QTimer;

namespace rbw {

class StepHistory;

class QuantityPlotPanel : public QWidget, public SessionPanel {
    Q_OBJECT
public:
    explicit QuantityPlotPanel(QWidget* parent = nullptr);
    ~QuantityPlotPanel() override;

    // A new scene (its body names and which are fixed): plots of another scene go.
    void setScene(const QStringList& bodyNames, const QList<bool>& fixed);

    // Adds a plot of the quantity, filled from the recorded history up to its current
    // step; colour: the body's. Returns the new plot (also the current tab).
    QuantityPlot* addQuantity(const QuantityKey& key, const QString& label, const QString& unit,
                              const StepHistory& history, bool norm = false, const QString& symbol = {});

    // Follow the session: one new step; back to step k (scrub, step back); all
    // samples dropped (reset).
    void appendStep(const StepTrace& trace);
    void truncateAfter(long step);
    void clearSamples();
    void removeAll();

    // SessionPanel (app/core/session_panel.h): a scene's bodies (its plots of another
    // scene go, samples dropped), one step's trace, the steps after a rewind to state k.
    void sceneLoaded(const World& world) override;
    void stepRecorded(const StepTrace& trace) override;
    void rewound(long stepIndex) override;

    int plotCount() const;
    QuantityPlot* plot(int i) const;
    QTabWidget* tabs() const { return tabs_; }
    // Applies pending samples now (tests, export).
    void refreshNow();

signals:
    void plotAdded(int index);

private:
    void removePlot(QuantityPlot* plot);
    void updateXChoices();
    void scheduleRefresh();

    std::vector<std::unique_ptr<QuantitySeries>> series_;   // one per plot, in tab order
    QStringList bodyNames_;
    QList<bool> fixed_;
    QTabWidget* tabs_ = nullptr;
    QLabel* emptyNote_ = nullptr;
    QTimer* refresh_ = nullptr;
};

} // namespace rbw
