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
    ValueRange r{lo, hi};
    if (hi - lo <= kConstantRelativeSpan * magnitude) {
        // Constant (up to round-off): v ± max(1e-9, 0.05 |v|).
        const double centre = 0.5 * (lo + hi);
        const double half = std::max(kMinHalfHeight, kValuePadFraction * magnitude);
        return ValueRange{centre - half, centre + half};
    }
    // Varying: 5 % of the span beyond each end, but the padding does not cross 0:
    // data that never goes below 0 (energies, lengths) gets an axis from 0.
    const double pad = kValuePadFraction * (hi - lo);
    r.min = (lo >= 0.0) ? std::max(0.0, lo - pad) : lo - pad;
    r.max = (hi <= 0.0) ? std::min(0.0, hi + pad) : hi + pad;
    // Never less than 2e-9 high: round-off around 0 draws as a flat line.
    if (r.max - r.min < 2.0 * kMinHalfHeight) {
        const double centre = 0.5 * (r.min + r.max);
        r = ValueRange{centre - kMinHalfHeight, centre + kMinHalfHeight};
    }
    return r;
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
