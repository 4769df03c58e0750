// The axis ranges of a plot, before Qt's nice tick numbers are applied:
//   time axis   [0, 1.02 t_max]                      (a little room on the right)
//   value axis  [lo - 5% span, hi + 5% span]         span = hi - lo
//               where the padding stops at 0: data >= 0 (an energy, |P|) starts at 0
// never a zero-height range: data that is constant (span at round-off level,
// <= 1e-9 of its magnitude) is shown as v ± max(1e-9, 0.05 |v|), and no range is
// less than 2e-9 high, so round-off around 0 (1e-17) draws as a flat line at 0.
#pragma once

#include "app/gui/panels/plots/plot_series.h"

#include <QString>

namespace rbw {

inline constexpr double kValuePadFraction = 0.05;
inline constexpr double kTimeMarginFraction = 0.02;
inline constexpr double kMinHalfHeight = 1e-9;        // absolute, in the axis' unit
inline constexpr double kConstantRelativeSpan = 1e-9; // span <= this * |v|: constant

// Range of the time axis for samples up to t_max; [0, 1] when t_max <= 0.
ValueRange timeAxisRange(double tMax);

// Range of a value axis showing data between lo and hi (lo <= hi, both finite).
ValueRange valueAxisRange(double lo, double hi);

// A printf format for the tick labels of [min, max] with ticks `step` apart: fixed
// decimals for everyday magnitudes, exponent form for very large or small ones, and
// always enough digits that neighbouring ticks read differently (every plot uses it).
QString axisLabelFormat(double min, double max, double step);

} // namespace rbw
