// The points of the accuracy plot, from a study's rows (physics/workbook/lab/study.h): for
// each integrator, (cost, error) at each h, and the Pareto front over all of them.
// Data only (Qt Core); AccuracyPanel draws it.
//
//   cost  = ns per step x N: the wall time to reach T with the trace off  [ms]
//   error = the chosen error at T (orientation angle, |d omega| or |dx|)
// Log-log axes cannot show an error of exactly 0 (a body at rest has e_x = 0) or a
// run with no numbers (blown up): those are counted, not drawn.
#pragma once

#include "physics/workbook/lab/study.h"

#include <QList>
#include <QString>

namespace rbw {

enum class ErrorMetric { Orientation, Omega, Position };

struct FrontPoint {
    double cost_ms = 0.0;
    double error = 0.0;
    double dt = 0.0;
    QString integrator;
};

struct IntegratorCurve {
    QString integrator;
    QList<FrontPoint> points;   // in the study's dt order
};

struct StudyFront {
    QList<IntegratorCurve> curves;   // one per integrator, in the study's order
    // The points no other point beats in both cost and error, cheapest first.
    QList<FrontPoint> pareto;
    int zeroErrors = 0;   // rows with error exactly 0 (not drawn on a log axis)
    int blownUp = 0;      // rows without numbers
    // Bounds of the drawn points (valid when pointCount() > 0).
    double minCost = 0.0, maxCost = 0.0, minError = 0.0, maxError = 0.0;
    int pointCount() const;
};

// The error of a row for the metric; empty when the row has none.
std::optional<double> errorOf(const lab::StudyRow& row, ErrorMetric metric);

StudyFront buildFront(const lab::StudyResult& result, ErrorMetric metric);

// Axis titles: "orientation error at T [rad]" (the angle of q_exact^-1 q), ...
QString metricTitle(ErrorMetric metric);
QString costTitle();

} // namespace rbw
