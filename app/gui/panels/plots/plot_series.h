// The plotted samples: for every series of the catalogue (plot_catalogue.h) one
// value per recorded step, all sharing the step's time t. It holds the full data;
// the panel may show fewer points (plot_decimation.h), the CSV always has them all.
//
// No widgets here: the class can be filled, truncated and exported without a window.
#pragma once

#include "app/gui/panels/plots/plot_catalogue.h"

#include <QList>
#include <QPointF>
#include <QString>

#include <array>
#include <optional>
#include <vector>

namespace rbw {

struct ValueRange {
    double min = 0.0;
    double max = 0.0;
};

class PlotSeries {
public:
    // Appends one sample to every series: t and each series' value read from d.
    // Refuses (returns false, stores nothing, says why in *error) a sample with a
    // non-finite t or value, or with t before the last sample's t (call clear() or
    // truncate() first when the run goes back).
    bool append(double t, const Diagnostics& d, QString* error = nullptr);

    // Keeps the first `count` samples (a step back); count is clamped to [0, size].
    void truncate(int count);
    void clear();

    int sampleCount() const { return static_cast<int>(t_.size()); }
    double time(int i) const { return t_[static_cast<std::size_t>(i)]; }
    double value(PlotQuantity q, int i) const
    {
        return values_[static_cast<std::size_t>(plotIndex(q))][static_cast<std::size_t>(i)];
    }
    // The time of the last sample, 0 when empty.
    double lastTime() const { return t_.empty() ? 0.0 : t_.back(); }

    // Every sample of a series as (t, value).
    QList<QPointF> points(PlotQuantity q) const;

    // Smallest and largest value of a series over all samples; empty when there are none.
    std::optional<ValueRange> valueRange(PlotQuantity q) const;

    // The CSV text: a header "t,kinetic_energy_translational,...,angular_momentum_origin_norm"
    // (the catalogue's ids), then one row per sample. Numbers are the shortest text that reads back as
    // the same double, as in the CLI's CSV (app/output/csv_output.cpp).
    QByteArray csv() const;
    // Writes csv() to path atomically (app/output/atomic_file.h). False with a message on failure.
    bool writeCsv(const QString& path, QString* error) const;

private:
    void recomputeRanges();

    std::vector<double> t_;
    std::array<std::vector<double>, kPlotQuantityCount> values_;
    std::array<ValueRange, kPlotQuantityCount> ranges_{};   // valid when t_ is not empty
};

} // namespace rbw
