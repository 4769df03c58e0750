#include "app/gui/panels/plots/plot_catalogue.h"

namespace rbw {

namespace {

using Q = PlotQuantity;
using C = PlotChart;
using P = PlotPart;

QString latin1(std::string_view s) { return QString::fromLatin1(s.data(), static_cast<qsizetype>(s.size())); }
QString utf8(std::string_view s) { return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())); }

// One series: the catalogue row, the part and the chart; the texts follow from them.
PlotSeriesInfo series(Q q, const DiagnosticInfo<Diagnostics>& d, P part, C chart, bool visible)
{
    PlotSeriesInfo s{q, &d, part, chart, visible, latin1(d.id), utf8(d.symbol), utf8(d.meaning)};
    const auto component = [&](const char* axis) {
        s.id += QStringLiteral("_%1").arg(QLatin1String(axis));
        // "P_x", but "L_O,x" where the symbol already has a subscript.
        s.label += (s.label.contains(QLatin1Char('_')) ? QStringLiteral(",%1") : QStringLiteral("_%1")).arg(QLatin1String(axis));
        s.meaning = QStringLiteral("%1 component of the %2").arg(QLatin1String(axis), s.meaning);
    };
    switch (part) {
    case P::Value: break;
    case P::X: component("x"); break;
    case P::Y: component("y"); break;
    case P::Z: component("z"); break;
    case P::Norm:
        s.id += QLatin1String("_norm");
        s.label = QStringLiteral("|%1|").arg(s.label);
        s.meaning = QStringLiteral("length of the %1").arg(s.meaning);
        break;
    }
    return s;
}

const std::array<PlotSeriesInfo, kPlotQuantityCount>& seriesTable()
{
    static const std::array<PlotSeriesInfo, kPlotQuantityCount> kSeries{{
        series(Q::KineticTranslational, diag::kinetic_translational, P::Value, C::Energy, true),
        series(Q::KineticRotational, diag::kinetic_rotational, P::Value, C::Energy, true),
        series(Q::Potential, diag::potential, P::Value, C::Energy, true),
        series(Q::Total, diag::total, P::Value, C::Energy, true),
        series(Q::P_x, diag::linear_momentum, P::X, C::LinearMomentum, false),
        series(Q::P_y, diag::linear_momentum, P::Y, C::LinearMomentum, false),
        series(Q::P_z, diag::linear_momentum, P::Z, C::LinearMomentum, false),
        series(Q::P_norm, diag::linear_momentum, P::Norm, C::LinearMomentum, true),
        series(Q::L_O_x, diag::angular_momentum_origin, P::X, C::AngularMomentum, false),
        series(Q::L_O_y, diag::angular_momentum_origin, P::Y, C::AngularMomentum, false),
        series(Q::L_O_z, diag::angular_momentum_origin, P::Z, C::AngularMomentum, false),
        series(Q::L_O_norm, diag::angular_momentum_origin, P::Norm, C::AngularMomentum, true),
    }};
    return kSeries;
}

const std::array<PlotChartInfo, kPlotChartCount> kCharts{{
    {C::Energy, "Energy", "E [J]"},
    {C::LinearMomentum, "Momentum P", "P [kg·m/s]"},
    {C::AngularMomentum, "Ang. momentum L_O", "L_O [kg·m²/s]"},
}};

} // namespace

const std::array<PlotSeriesInfo, kPlotQuantityCount>& plotSeriesCatalogue() { return seriesTable(); }

const PlotSeriesInfo& plotSeriesInfo(PlotQuantity q) { return seriesTable()[static_cast<std::size_t>(plotIndex(q))]; }

const PlotChartInfo& plotChartInfo(PlotChart c) { return kCharts[static_cast<std::size_t>(plotIndex(c))]; }

const PlotSeriesInfo* findPlotSeries(QStringView id)
{
    for (const PlotSeriesInfo& s : seriesTable()) {
        if (id == s.id) return &s;
    }
    return nullptr;
}

double plotValue(PlotQuantity q, const Diagnostics& d)
{
    const PlotSeriesInfo& s = plotSeriesInfo(q);
    if (s.part == PlotPart::Value) return d.*(s.diagnostic->scalar);
    const Vec3& v = d.*(s.diagnostic->vector);
    switch (s.part) {
    case PlotPart::Value: break;
    case PlotPart::X: return v.x();
    case PlotPart::Y: return v.y();
    case PlotPart::Z: return v.z();
    // |P| = sqrt(P . P), |L_O| likewise: the length of the recorded vector, for display only.
    case PlotPart::Norm: return v.norm();
    }
    return 0.0;
}

} // namespace rbw
