// "Plot over time": any quantity of the trace in a plot of its own, one tab per
// quantity (right-click a row of the quantities table). Each tab shows the
// components (x, y, z) or the length |v|, against time t or, as a phase plot,
// against one component of any plotted quantity (pairs taken at the same step), and
// exports its samples as CSV and the chart as PNG (both written with QSaveFile).
//
// The samples are QuantitySeries: read from the recorded step traces (the history
// when the plot is added, then one per recorded step), never recomputed. The lines
// of a body's quantity are drawn in that body's colour (app/gui/style/body_colours.h),
// the components told apart by their dash pattern (x solid, y dashed, z dotted).
// Drawing is throttled like the other plots (at most ~10 Hz).
#pragma once

#include "app/gui/panels/plots/quantity_series.h"

#include <QColor>
#include <QList>
#include <QPointF>
#include <QStringList>
#include <QWidget>

#include <memory>
#include <vector>

class QChart;
class QChartView;
class QCheckBox;
class QComboBox;
class QLabel;
class QLineSeries;
class QTabWidget;
class QTimer;
class QValueAxis;

namespace rbw {

class StepHistory;

class QuantityPlot : public QWidget {
    Q_OBJECT
public:
    QuantityPlot(const QuantitySeries* series, QColor colour, QWidget* parent = nullptr);

    const QuantitySeries& series() const { return *series_; }
    // Components or |v|.
    void setShowNorm(bool norm);
    bool showsNorm() const { return showNorm_; }
    // x axis: time (xSeries nullptr) or component xComponent (-1: |v|) of xSeries.
    void setXAxis(const QuantitySeries* xSeries, int xComponent);
    const QuantitySeries* xSeries() const { return xSeries_; }
    int xComponent() const { return xComponent_; }

    // The points a line shows (all samples, never thinned): line i is component i,
    // or the norm when showsNorm().
    int lineCount() const;
    QList<QPointF> linePoints(int line) const;
    QString lineName(int line) const;
    QString yAxisTitle() const;
    QString xAxisTitle() const;
    QColor colour() const { return colour_; }

    // Redraws from the series now (the panel's timer calls it).
    void refresh();

    // The chart as a PNG at device pixel ratio 2 on white; the samples as CSV (each
    // component and, for a vector, its length; a phase plot adds the x column).
    bool exportPng(const QString& path, QString* error);
    bool exportCsv(const QString& path, QString* error) const;
    QByteArray csv() const;

    QComboBox* modeBox() const { return modeBox_; }
    QComboBox* xAxisBox() const { return xBox_; }
    QValueAxis* xAxis() const { return xAxis_; }
    QValueAxis* yAxis() const { return yAxis_; }

signals:
    void closeRequested();
    // The x-axis box was changed by the student: the panel resolves the choice.
    void xAxisChoiceChanged(int choice);

private:
    void exportPngInteractive();
    void exportCsvInteractive();

    const QuantitySeries* series_;
    const QuantitySeries* xSeries_ = nullptr;
    int xComponent_ = 0;
    bool showNorm_ = false;
    QColor colour_;
    QChart* chart_ = nullptr;
    QChartView* view_ = nullptr;
    QValueAxis* xAxis_ = nullptr;
    QValueAxis* yAxis_ = nullptr;
    std::vector<QLineSeries*> lines_;
    QComboBox* modeBox_ = nullptr;
    QComboBox* xBox_ = nullptr;
    QLabel* note_ = nullptr;

    friend class QuantityPlotPanel;
};

class QuantityPlotPanel : public QWidget {
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
