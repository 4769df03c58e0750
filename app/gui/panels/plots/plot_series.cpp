#include "app/gui/panels/plots/plot_series.h"

#include "app/output/atomic_file.h"

#include <QLocale>

#include <algorithm>
#include <cmath>

namespace rbw {

namespace {

// Shortest text that reads back as the same double (as CsvWriter does). Qt writes
// -0 as "0"; "-0" keeps the sign, so every bit reads back.
QByteArray exact(double x)
{
    if (x == 0.0 && std::signbit(x)) return QByteArrayLiteral("-0");
    return QByteArray::number(x, 'g', QLocale::FloatingPointShortest);
}

} // namespace

bool PlotSeries::append(double t, const Diagnostics& d, QString* error)
{
    auto fail = [error](const QString& message) {
        if (error != nullptr) *error = message;
        return false;
    };
    if (!std::isfinite(t)) {
        return fail(QStringLiteral("plot sample refused: the time t is not finite"));
    }
    if (!t_.empty() && t < t_.back()) {
        return fail(QStringLiteral("plot sample refused: t = %1 s is before the last sample's t = %2 s "
                                   "(clear or truncate the plot first)")
                        .arg(t, 0, 'g', 17)
                        .arg(t_.back(), 0, 'g', 17));
    }
    std::array<double, kPlotQuantityCount> row{};
    for (const PlotSeriesInfo& s : plotSeriesCatalogue()) {
        const double v = plotValue(s.quantity, d);
        if (!std::isfinite(v)) {
            return fail(QStringLiteral("plot sample refused: %1 at t = %2 s is not finite")
                            .arg(s.label)
                            .arg(t, 0, 'g', 17));
        }
        row[static_cast<std::size_t>(plotIndex(s.quantity))] = v;
    }

    const bool first = t_.empty();
    t_.push_back(t);
    for (std::size_t k = 0; k < row.size(); ++k) {
        values_[k].push_back(row[k]);
        ValueRange& r = ranges_[k];
        r.min = first ? row[k] : std::min(r.min, row[k]);
        r.max = first ? row[k] : std::max(r.max, row[k]);
    }
    return true;
}

void PlotSeries::truncate(int count)
{
    const std::size_t keep = static_cast<std::size_t>(std::clamp(count, 0, sampleCount()));
    if (keep == t_.size()) return;
    t_.resize(keep);
    for (std::vector<double>& v : values_) v.resize(keep);
    recomputeRanges();
}

void PlotSeries::clear()
{
    truncate(0);
}

void PlotSeries::recomputeRanges()
{
    for (std::size_t k = 0; k < values_.size(); ++k) {
        if (values_[k].empty()) {
            ranges_[k] = ValueRange{};
            continue;
        }
        const auto [lo, hi] = std::minmax_element(values_[k].begin(), values_[k].end());
        ranges_[k] = ValueRange{*lo, *hi};
    }
}

QList<QPointF> PlotSeries::points(PlotQuantity q) const
{
    const std::vector<double>& v = values_[static_cast<std::size_t>(plotIndex(q))];
    QList<QPointF> out;
    out.reserve(static_cast<qsizetype>(t_.size()));
    for (std::size_t i = 0; i < t_.size(); ++i) out.append(QPointF(t_[i], v[i]));
    return out;
}

std::optional<ValueRange> PlotSeries::valueRange(PlotQuantity q) const
{
    if (t_.empty()) return std::nullopt;
    return ranges_[static_cast<std::size_t>(plotIndex(q))];
}

QByteArray PlotSeries::csv() const
{
    QByteArray out;
    out.reserve(static_cast<qsizetype>((t_.size() + 1) * 13 * 20));
    out += "t";
    for (const PlotSeriesInfo& s : plotSeriesCatalogue()) {
        out += ',';
        out += s.id.toLatin1();
    }
    out += '\n';
    for (std::size_t i = 0; i < t_.size(); ++i) {
        out += exact(t_[i]);
        for (const std::vector<double>& v : values_) {
            out += ',';
            out += exact(v[i]);
        }
        out += '\n';
    }
    return out;
}

bool PlotSeries::writeCsv(const QString& path, QString* error) const
{
    return writeFileAtomically(path, csv(), error);   // complete or not at all
}

} // namespace rbw
