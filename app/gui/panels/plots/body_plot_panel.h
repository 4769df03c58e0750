// Per-body plots: each body's kinetic energy T and the length of its angular
// momentum |L| about its own centre of mass, one line per body. This is where
// side-by-side lessons show their difference: in lesson 9 three identical boxes,
// one per integrator, so explicit Euler's rising T sits beside RK4's and implicit
// midpoint's flat lines.
//
// The numbers are StepTrace::diagnostics.bodies (physics/engine/diagnostics.h), recorded by
// the physics after each step; nothing is computed here. Drawing is throttled like
// PlotPanel's (10 Hz, at most kMaxDrawn points per line, every sample kept, and only
// while the panel is visible).
#pragma once

#include "app/core/session_panel.h"
#include "physics/engine/diagnostics.h"

#include <QColor>
#include <QList>
#include <QPointF>
#include <QStringList>
#include <QWidget>

#include <array>
#include <vector>

class QChart;
class QChartView;
class QLineSeries;
class QTabWidget;
class QTimer;
class QValueAxis;

namespace rbw {

class BodyPlotPanel : public QWidget, public SessionPanel {
    Q_OBJECT
public:
    enum Quantity { KineticEnergy, AngularMomentumNorm, QuantityCount };
    static constexpr int kMaxDrawn = 1200;

    explicit BodyPlotPanel(QWidget* parent = nullptr);

    // A new scene: one line per body, named, in the body's colour (body_colours.h;
    // grey for a fixed body); drops every sample.
    void setBodies(const QStringList& names, const QList<bool>& fixed = {});
    // The colour of body b's line.
    QColor lineColour(int body) const;
    // One sample per step; false (nothing stored) if the sample does not have one
    // entry per body or holds a non-finite number.
    bool appendStep(double t, const Diagnostics& d);
    // Keeps the first sampleCount samples (after a step back).
    void truncate(int sampleCount);
    int sampleCount() const { return static_cast<int>(t_.size()); }
    // Every sample of one body's line (never thinned).
    QList<QPointF> points(Quantity q, int body) const;
    // Renders the current tab's chart at twice its size on white.
    bool exportPng(const QString& path, QString* error);
    void refreshNow();
    // Whether the panel can be seen: false while its dock is a tab behind another
    // (QDockWidget::visibilityChanged; the widget itself stays "visible" there). Off
    // screen, samples are stored and the lines redrawn when it comes back.
    void setOnScreen(bool on);

    // SessionPanel (app/core/session_panel.h): a scene's bodies and its first sample,
    // one sample per step, the samples after a rewind dropped.
    void sceneLoaded(const World& world) override;
    void stepRecorded(const StepTrace& trace) override;
    void rewound(long stepIndex) override;

private:
    struct Chart {
        QChart* chart = nullptr;
        QChartView* view = nullptr;
        QValueAxis* x = nullptr;
        QValueAxis* y = nullptr;
        std::vector<QLineSeries*> lines;
    };
    void rebuildLines();
    void scheduleRefresh();

    QStringList names_;
    QList<bool> fixed_;
    std::vector<double> t_;
    std::array<std::vector<std::vector<double>>, QuantityCount> values_;   // [q][body][sample]
    std::array<Chart, QuantityCount> charts_;
    QTabWidget* tabs_ = nullptr;
    QTimer* refresh_ = nullptr;
    // Samples arrived while the panel was off screen: the lines are redrawn when it is
    // shown. QLineSeries::replace() lays out and strokes the path even for a chart
    // nobody sees: 50 lines at 10 Hz in lesson 4's fifty boxes.
    bool onScreen_ = true;
    bool stale_ = false;
};

} // namespace rbw
