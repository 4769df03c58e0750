// Value axes whose tick labels are always whole: Qt Charts elides a label to "…"
// when the axis is too short for its ticks (the docked energy plot at 1600x1000 had
// "…" on every y tick, and so had its PNG). So labels are never truncated, and a
// value axis gets only as many ticks as its length holds with a label height of
// room between them (at least 2, at most `wanted`).
//
// applyNiceRange() puts an axis on nice ticks (plot_axis_range.h: multiples of 1, 2
// or 5 x 10^k, the axis ending on a tick), as many as its length holds.
#pragma once

#include "app/gui/panels/plots/plot_axis_range.h"

#include <QFontMetrics>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace rbw {

// Ticks for an axis `pixels` long whose labels are set in `font` (vertical axis:
// one label height plus the same again between labels).
inline int fittingTickCount(double pixels, const QFont& font, int wanted, bool vertical)
{
    const QFontMetrics fm(font);
    const double perLabel = vertical ? 2.0 * fm.height() : fm.horizontalAdvance(QStringLiteral("0.000000")) * 1.3;
    if (!(pixels > 0.0) || !(perLabel > 0.0)) return wanted;
    const int fits = static_cast<int>(std::floor(pixels / perLabel)) + 1;
    return std::clamp(fits, 2, std::max(2, wanted));
}

inline void keepLabelsWhole(QValueAxis* axis)
{
    axis->setTruncateLabels(false);
}

// The axis shows `wanted` on nice ticks; pixels: the axis' length on screen.
inline void applyNiceRange(QValueAxis* axis, const ValueRange& wanted, double pixels, int maxTicks)
{
    const bool vertical = axis->orientation() == Qt::Vertical;
    const NiceTicks ticks = niceTicks(wanted, fittingTickCount(pixels, axis->labelsFont(), maxTicks, vertical));
    axis->setRange(ticks.min, ticks.max);
    axis->setTickCount(ticks.count);
    axis->setLabelFormat(axisLabelFormat(ticks.min, ticks.max, ticks.step));
}

} // namespace rbw
