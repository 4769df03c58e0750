// Log axes over whole decades, for the error-against-cost plots of the Accuracy tab.
#pragma once

#include <QLogValueAxis>

#include <cmath>

namespace rbw {

// The axis from the decade at or below lo to the decade at or above hi (lo, hi > 0).
inline void setDecades(QLogValueAxis* axis, double lo, double hi)
{
    const double a = std::pow(10.0, std::floor(std::log10(lo)));
    double b = std::pow(10.0, std::ceil(std::log10(hi)));
    if (b <= a) b = a * 10.0;
    axis->setRange(a, b);
    axis->setMinorTickCount(0);
}

} // namespace rbw
