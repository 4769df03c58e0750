// The catalogue of plotted series: which number of Diagnostics (physics/engine/diagnostics.h)
// each series shows, its stable id (the CSV column), its short legend label and the
// chart it belongs to.
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

#include "physics/engine/diagnostics.h"

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

struct PlotSeriesInfo {
    PlotQuantity quantity;
    const char* id;         // stable, ASCII: the CSV column and the API's series id
    const char* label;      // short UTF-8 legend label, e.g. "T_trans", "|L_O|"
    const char* meaning;    // tooltip text, e.g. "rotational kinetic energy Σ ½ ω·L"
    PlotChart chart;
    bool visibleByDefault;  // totals and parts on, vector components off
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

} // namespace rbw
