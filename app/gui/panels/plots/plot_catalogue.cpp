#include "app/gui/panels/plots/plot_catalogue.h"

namespace rbw {

namespace {

using Q = PlotQuantity;
using C = PlotChart;

const std::array<PlotSeriesInfo, kPlotQuantityCount> kSeries{{
    {Q::KineticTranslational, "kinetic_translational", "T_trans", "translational kinetic energy Σ ½ M |v|²", C::Energy, true},
    {Q::KineticRotational, "kinetic_rotational", "T_rot", "rotational kinetic energy Σ ½ ω·L", C::Energy, true},
    {Q::Potential, "potential", "V", "potential energy Σ −M g·x (0 at the origin)", C::Energy, true},
    {Q::Total, "total", "E", "total energy E = T_trans + T_rot + V", C::Energy, true},
    {Q::P_x, "P_x", "P_x", "x component of the total linear momentum P = Σ M v (world)", C::LinearMomentum, false},
    {Q::P_y, "P_y", "P_y", "y component of the total linear momentum P = Σ M v (world)", C::LinearMomentum, false},
    {Q::P_z, "P_z", "P_z", "z component of the total linear momentum P = Σ M v (world)", C::LinearMomentum, false},
    {Q::P_norm, "P_norm", "|P|", "length of the total linear momentum P = Σ M v", C::LinearMomentum, true},
    {Q::L_O_x, "L_O_x", "L_O,x", "x component of the angular momentum about the origin L_O = Σ (x × M v + L) (world)", C::AngularMomentum, false},
    {Q::L_O_y, "L_O_y", "L_O,y", "y component of the angular momentum about the origin L_O = Σ (x × M v + L) (world)", C::AngularMomentum, false},
    {Q::L_O_z, "L_O_z", "L_O,z", "z component of the angular momentum about the origin L_O = Σ (x × M v + L) (world)", C::AngularMomentum, false},
    {Q::L_O_norm, "L_O_norm", "|L_O|", "length of the angular momentum about the world origin L_O = Σ (x × M v + L)", C::AngularMomentum, true},
}};

const std::array<PlotChartInfo, kPlotChartCount> kCharts{{
    {C::Energy, "Energy", "E [J]"},
    {C::LinearMomentum, "Momentum P", "P [kg·m/s]"},
    {C::AngularMomentum, "Ang. momentum L_O", "L_O [kg·m²/s]"},
}};

} // namespace

const std::array<PlotSeriesInfo, kPlotQuantityCount>& plotSeriesCatalogue() { return kSeries; }

const PlotSeriesInfo& plotSeriesInfo(PlotQuantity q) { return kSeries[static_cast<std::size_t>(plotIndex(q))]; }

const PlotChartInfo& plotChartInfo(PlotChart c) { return kCharts[static_cast<std::size_t>(plotIndex(c))]; }

const PlotSeriesInfo* findPlotSeries(QStringView id)
{
    for (const PlotSeriesInfo& s : kSeries) {
        if (id == QLatin1String(s.id)) return &s;
    }
    return nullptr;
}

double plotValue(PlotQuantity q, const Diagnostics& d)
{
    switch (q) {
    case Q::KineticTranslational: return d.kineticTranslational;
    case Q::KineticRotational: return d.kineticRotational;
    case Q::Potential: return d.potential;
    case Q::Total: return d.total;
    case Q::P_x: return d.P_W.x();
    case Q::P_y: return d.P_W.y();
    case Q::P_z: return d.P_W.z();
    // |P| = sqrt(P . P): the length of the recorded vector, for display only.
    case Q::P_norm: return d.P_W.norm();
    case Q::L_O_x: return d.L_O_W.x();
    case Q::L_O_y: return d.L_O_W.y();
    case Q::L_O_z: return d.L_O_W.z();
    // |L_O| = sqrt(L_O . L_O): the length of the recorded vector, for display only.
    case Q::L_O_norm: return d.L_O_W.norm();
    }
    return 0.0;
}

} // namespace rbw
