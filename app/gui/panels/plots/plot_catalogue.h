// The catalogue of plotted series: which row of the diagnostics catalogue
// (physics/engine/diagnostic_catalogue.h) each series shows, which part of it (the
// value, a world-frame component or a vector's length) and the chart it belongs to.
// The id, legend label and tooltip are made from that row, so no id is spelled here:
// a scalar keeps the catalogue's id ("total_energy"), a vector's part appends "_x",
// "_y", "_z" or "_norm" ("linear_momentum_norm"), as the CLI's CSV does for vectors.
//
// Glossary (all sums over the bodies that are not fixed, after a step, world frame)
//   T_trans = sum 1/2 M |v|^2          Diagnostics::kineticTranslational   [J]
//   T_rot   = sum 1/2 omega . L        Diagnostics::kineticRotational      [J]
//   V       = sum -M g . x             Diagnostics::potential              [J]
//   E       = T_trans + T_rot + V      Diagnostics::total                  [J]
//   P       = sum M v                  Diagnostics::P_W                    [kg m/s]
//   L_O     = sum (x x M v + L)        Diagnostics::L_O_W, about the origin [kg m^2/s]
// The plots compute nothing physical: a series is one recorded number, or the
// Euclidean length |P| or |L_O| of a recorded vector (for display only).
#pragma once

#include "physics/engine/diagnostic_catalogue.h"

#include <QString>
#include <QStringView>

#include <array>

namespace rbw {

// One chart per unit: energy [J], linear momentum [kg m/s], angular momentum [kg m^2/s].
enum class PlotChart { Energy, LinearMomentum, AngularMomentum };
inline constexpr int kPlotChartCount = 3;

// Every plotted series, in CSV column order.
enum class PlotQuantity {
    KineticTranslational,
    KineticRotational,
    Potential,
    Total,
    P_x,
    P_y,
    P_z,
    P_norm,
    L_O_x,
    L_O_y,
    L_O_z,
    L_O_norm,
};
inline constexpr int kPlotQuantityCount = 12;

// Which part of a diagnostic a series shows: a scalar's value, one world-frame
// component of a vector, or the vector's Euclidean length (for display only).
enum class PlotPart { Value, X, Y, Z, Norm };

struct PlotSeriesInfo {
    PlotQuantity quantity;
    const DiagnosticInfo<Diagnostics>* diagnostic;   // the catalogue row it shows
    PlotPart part;
    PlotChart chart;
    bool visibleByDefault;  // totals and parts on, vector components off
    QString id;             // stable, ASCII: the CSV column and the API's series id
    QString label;          // short legend label, e.g. "T_trans", "L_O,x", "|L_O|"
    QString meaning;        // tooltip text, e.g. "rotational kinetic energy Σ ½ ω·L"
};

struct PlotChartInfo {
    PlotChart chart;
    const char* tabTitle;   // "Energy"
    const char* axisTitle;  // y axis: quantity and unit, "E [J]"
};

const std::array<PlotSeriesInfo, kPlotQuantityCount>& plotSeriesCatalogue();
const PlotSeriesInfo& plotSeriesInfo(PlotQuantity q);
const PlotChartInfo& plotChartInfo(PlotChart c);

// The series with this id, or nullptr when there is none.
const PlotSeriesInfo* findPlotSeries(QStringView id);

// The recorded number a series shows for one step's diagnostics.
double plotValue(PlotQuantity q, const Diagnostics& d);

inline int plotIndex(PlotQuantity q) { return static_cast<int>(q); }
inline int plotIndex(PlotChart c) { return static_cast<int>(c); }

// The id of a series (plotSeriesInfo(q).id).
inline const QString& plotSeriesId(PlotQuantity q) { return plotSeriesInfo(q).id; }

} // namespace rbw
