// One plot of "Plot over time": a traced quantity against time t or, as a phase
// plot, against one component of another plotted quantity (pairs of the same step).
//
// What a student needs to read it (issue 20):
// - Show: all components, the length |v|, or one component alone (R₂₂, ω_y), named
//   after the quantity catalogue's symbol (QuantitySeries::componentSymbol);
// - one colour per line (a single line keeps the body's colour), and a legend whose
//   entries hide and show their line when clicked (the axes then fit the lines shown);
// - a log y axis: a sample <= 0 has no place on it, so it is left out and the note
//   beside the box says how many; with no positive sample the log axis is refused
//   (the plot stays linear and says why);
// - the value under the mouse (the nearest sample of a shown line) in the readout;
// - ticks at 1, 2 or 5 times a power of ten (plot_axis_range.h), labels never elided;
// - a title in the exported PNG (the quantity and body).
//
// The samples are QuantitySeries: read from the recorded step traces, never
// recomputed; the only arithmetic is |v| when asked for.
#pragma once

#include "app/gui/panels/plots/quantity_series.h"

#include <QColor>
#include <QList>
#include <QPointF>
#include <QString>
#include <QWidget>

#include <vector>

class QChart;
class QChartView;
class QCheckBox;
class QComboBox;
class QLabel;
class QLineSeries;
class QLogValueAxis;
class QValueAxis;

namespace rbw {

// The height a docked plot's chart is given when it is added (at 1366x768 too).
inline constexpr int kReadableChartHeight = 300;

class QuantityPlot : public QWidget {
    Q_OBJECT
public:
    // shownComponent(): every component, the length, or component c >= 0.
    static constexpr int kAllComponents = -2;
    static constexpr int kLength = -1;

    QuantityPlot(const QuantitySeries* series, QColor colour, QWidget* parent = nullptr);

    const QuantitySeries& series() const { return *series_; }
    // Components or |v|.
    void setShowNorm(bool norm);
    bool showsNorm() const { return shown_ == kLength; }
    // kAllComponents, kLength or one component (0-based: R₂₂ of a matrix is 4).
    void setShownComponent(int shown);
    int shownComponent() const { return shown_; }
    // x axis: time (xSeries nullptr) or component xComponent (-1: |v|) of xSeries.
    void setXAxis(const QuantitySeries* xSeries, int xComponent);
    const QuantitySeries* xSeries() const { return xSeries_; }
    int xComponent() const { return xComponent_; }

    // The points a line shows (all samples, never thinned, also those the log axis
    // leaves out): line i is component i, the one component shown, or the norm.
    int lineCount() const;
    QList<QPointF> linePoints(int line) const;
    QString lineName(int line) const;
    QColor lineColour(int line) const;
    QLineSeries* chartLine(int line) const;   // the chart's series of line i
    QString yAxisTitle() const;
    QString xAxisTitle() const;
    QString title() const;   // the exported PNG's title
    QColor colour() const { return colour_; }   // the body's

    // What a click on a line's legend entry does.
    bool isLineVisible(int line) const;
    void setLineVisible(int line, bool visible);

    // Log y axis; false (and linear) when no sample of a shown line is positive.
    bool setLogScale(bool on);
    bool logScale() const { return log_; }
    // Samples of the shown lines the log axis leaves out (<= 0).
    int samplesLeftOut() const { return leftOut_; }

    // The nearest sample of a shown line to a point of the chart view's viewport,
    // as the readout shows it ("R₂₂ (racket) = 0.998 at t = 1.5 s"); empty outside
    // the plot area or with nothing drawn. Also sets the readout label.
    QString readoutAt(const QPoint& viewportPos);

    // Redraws from the series now (the panel's timer calls it).
    void refresh();

    // The chart as a PNG at device pixel ratio 2 on white, titled; the samples as CSV
    // (each component and, for a vector, its length; a phase plot adds the x column).
    bool exportPng(const QString& path, QString* error);
    bool exportCsv(const QString& path, QString* error) const;
    QByteArray csv() const;

    QComboBox* modeBox() const { return modeBox_; }
    QComboBox* xAxisBox() const { return xBox_; }
    QCheckBox* logBox() const { return logBox_; }
    QLabel* readout() const { return readout_; }
    QLabel* note() const { return note_; }
    QChart* chart() const { return chart_; }
    QChartView* chartView() const { return view_; }
    QValueAxis* xAxis() const { return xAxis_; }
    QValueAxis* yAxis() const { return yAxis_; }
    QLogValueAxis* yLogAxis() const { return yLog_; }

signals:
    void closeRequested();
    // The x-axis box was changed by the student: the panel resolves the choice.
    void xAxisChoiceChanged(int choice);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void rebuildModeBox();
    void placeReadout();
    void applyLineVisibility(int line);
    void exportPngInteractive();
    void exportCsvInteractive();

    const QuantitySeries* series_;
    const QuantitySeries* xSeries_ = nullptr;
    int xComponent_ = 0;
    int shown_ = kAllComponents;
    int modeBoxComponents_ = -1;   // the component count the mode box was built for
    bool log_ = false;
    int leftOut_ = 0;
    std::vector<bool> hidden_;     // per line, by a legend click
    QColor colour_;
    QChart* chart_ = nullptr;
    QChartView* view_ = nullptr;
    QValueAxis* xAxis_ = nullptr;
    QValueAxis* yAxis_ = nullptr;
    QLogValueAxis* yLog_ = nullptr;
    std::vector<QLineSeries*> lines_;
    QComboBox* modeBox_ = nullptr;
    QComboBox* xBox_ = nullptr;
    QCheckBox* logBox_ = nullptr;
    QLabel* note_ = nullptr;
    QLabel* readout_ = nullptr;
};

} // namespace rbw
