#include "app/gui/panels/accuracy/study_front.h"

#include <algorithm>
#include <limits>

namespace rbw {

int StudyFront::pointCount() const
{
    int n = 0;
    for (const IntegratorCurve& c : curves) n += int(c.points.size());
    return n;
}

std::optional<double> errorOf(const lab::StudyRow& row, ErrorMetric metric)
{
    switch (metric) {
    case ErrorMetric::Orientation: return row.orientationError;
    case ErrorMetric::Omega: return row.omegaError;
    case ErrorMetric::Position: return row.positionError;
    }
    return std::nullopt;
}

StudyFront buildFront(const lab::StudyResult& result, ErrorMetric metric)
{
    StudyFront front;
    front.minCost = front.minError = std::numeric_limits<double>::infinity();
    front.maxCost = front.maxError = 0.0;
    QList<FrontPoint> all;
    for (const lab::StudyRow& row : result.rows) {
        const QString name = QString::fromStdString(row.integrator);
        if (front.curves.isEmpty() || front.curves.back().integrator != name) {
            front.curves.append(IntegratorCurve{name, {}});
        }
        const std::optional<double> error = errorOf(row, metric);
        const std::optional<double> cost_ns = row.totalNs();
        if (row.status != lab::RunStatus::Ok || !error || !cost_ns) {
            ++front.blownUp;
            continue;
        }
        if (*error <= 0.0) {
            ++front.zeroErrors;
            continue;
        }
        // cost = ns per step x N, in ms
        const FrontPoint p{*cost_ns * 1e-6, *error, row.dt, name};
        front.curves.back().points.append(p);
        all.append(p);
        front.minCost = std::min(front.minCost, p.cost_ms);
        front.maxCost = std::max(front.maxCost, p.cost_ms);
        front.minError = std::min(front.minError, p.error);
        front.maxError = std::max(front.maxError, p.error);
    }
    // Pareto front: cheapest first, keep a point if it is more accurate than every
    // cheaper one.
    std::sort(all.begin(), all.end(), [](const FrontPoint& a, const FrontPoint& b) {
        return a.cost_ms < b.cost_ms || (a.cost_ms == b.cost_ms && a.error < b.error);
    });
    double best = std::numeric_limits<double>::infinity();
    for (const FrontPoint& p : all) {
        if (p.error < best) {
            front.pareto.append(p);
            best = p.error;
        }
    }
    return front;
}

QString metricTitle(ErrorMetric metric)
{
    switch (metric) {
    case ErrorMetric::Orientation: return QStringLiteral("orientation error at T [rad]");
    case ErrorMetric::Omega: return QStringLiteral("ω error at T [rad/s]");
    case ErrorMetric::Position: return QStringLiteral("position error at T [m]");
    }
    return {};
}

QString costTitle()
{
    return QStringLiteral("cost to reach T = ns per step × steps, trace off [ms]");
}

} // namespace rbw
