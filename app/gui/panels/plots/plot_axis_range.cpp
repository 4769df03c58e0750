#include "app/gui/panels/plots/plot_axis_range.h"

#include <algorithm>
#include <cmath>

namespace rbw {

ValueRange timeAxisRange(double tMax)
{
    if (!(tMax > 0.0)) return ValueRange{0.0, 1.0};
    // x from 0 to t_max plus 2 % so the newest point is not on the frame.
    return ValueRange{0.0, tMax * (1.0 + kTimeMarginFraction)};
}

ValueRange valueAxisRange(double lo, double hi)
{
    const double magnitude = std::max(std::abs(lo), std::abs(hi));
    // 0 up to round-off: a flat line at 0 on [-1, 1].
    if (magnitude <= kZeroMagnitude) return ValueRange{-kZeroHalfHeight, kZeroHalfHeight};
    ValueRange r{lo, hi};
    if (hi - lo <= kConstantRelativeSpan * magnitude) {
        // Constant (up to round-off): v ± 0.05 |v|.
        const double centre = 0.5 * (lo + hi);
        const double half = kValuePadFraction * magnitude;
        return ValueRange{centre - half, centre + half};
    }
    // Varying: 5 % of the span beyond each end, but the padding does not cross 0:
    // data that never goes below 0 (energies, lengths) gets an axis from 0.
    const double pad = kValuePadFraction * (hi - lo);
    r.min = (lo >= 0.0) ? std::max(0.0, lo - pad) : lo - pad;
    r.max = (hi <= 0.0) ? std::min(0.0, hi + pad) : hi + pad;
    return r;
}

NiceTicks niceTicks(ValueRange wanted, int maxTicks)
{
    maxTicks = std::max(2, maxTicks);
    double lo = wanted.min;
    double hi = wanted.max;
    if (!std::isfinite(lo) || !std::isfinite(hi)) return NiceTicks{};
    if (hi < lo) std::swap(lo, hi);
    if (!(hi > lo)) {
        const double half = lo == 0.0 ? 1.0 : 0.05 * std::abs(lo);
        lo -= half;
        hi += half;
    }
    const double raw = (hi - lo) / (maxTicks - 1);
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    // A tick that lies within 1e-9 of a step from the data end counts as on it
    // (0.3 / 0.1 = 2.9999999999999996 is tick 3).
    constexpr double kSnap = 1e-9;
    for (double scale : {0.1, 1.0, 10.0, 100.0}) {
        for (double mantissa : {1.0, 2.0, 5.0}) {
            const double step = mantissa * decade * scale;
            const double first = std::floor(lo / step + kSnap);
            const double last = std::ceil(hi / step - kSnap);
            const int count = static_cast<int>(std::llround(last - first)) + 1;
            if (count <= maxTicks) return NiceTicks{first * step, last * step, step, std::max(2, count)};
        }
    }
    return NiceTicks{lo, hi, hi - lo, 2};
}

QString axisLabelFormat(double min, double max, double step)
{
    const double magnitude = std::max(std::abs(min), std::abs(max));
    if (!(step > 0.0) || !(magnitude > 0.0)) return QStringLiteral("%.1f");
    if (magnitude >= 1e5 || magnitude < 1e-3) {
        const int digits = std::clamp(static_cast<int>(std::ceil(std::log10(magnitude / step))), 1, 12);
        return QStringLiteral("%.%1e").arg(digits);
    }
    const int decimals = std::clamp(static_cast<int>(-std::floor(std::log10(step) + 1e-9)), 0, 12);
    return QStringLiteral("%.%1f").arg(decimals);
}

} // namespace rbw
