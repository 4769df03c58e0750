// The axis ranges of a plot, before Qt's nice tick numbers are applied:
//   time axis   [0, 1.02 t_max]                      (a little room on the right)
//   value axis  [lo - 5% span, hi + 5% span]         span = hi - lo
//               where the padding stops at 0: data >= 0 (an energy, |P|) starts at 0
// never a zero-height range: data that is constant (span at round-off level,
// <= 1e-9 of its magnitude) is shown as v ± 0.05 |v|, and data that is 0 up to
// round-off (every |value| <= 1e-9: a momentum of 0, 1e-17) as a flat line at 0 on
// [-1, 1] (a "±1e-09" axis read as if the round-off were the quantity).
// The ticks then go at multiples of 1, 2 or 5 times a power of ten (niceTicks), the
// axis ends on a tick: never "1.6, 3.2".
#pragma once

#include "app/gui/panels/plots/plot_series.h"

#include <QString>

namespace rbw {

inline constexpr double kValuePadFraction = 0.05;
inline constexpr double kTimeMarginFraction = 0.02;
inline constexpr double kZeroMagnitude = 1e-9;        // |data| <= this everywhere: 0 up to round-off
inline constexpr double kZeroHalfHeight = 1.0;        // the axis of such data: [-1, 1]
inline constexpr double kConstantRelativeSpan = 1e-9; // span <= this * |v|: constant

// Range of the time axis for samples up to t_max; [0, 1] when t_max <= 0.
ValueRange timeAxisRange(double tMax);

// Range of a value axis showing data between lo and hi (lo <= hi, both finite).
ValueRange valueAxisRange(double lo, double hi);

// The ticks of an axis: every tick at a multiple of step, step = {1, 2, 5} x 10^k,
// the smallest such step whose ticks from min (<= wanted.min) to max (>= wanted.max)
// number at most maxTicks (at least 2).
struct NiceTicks {
    double min = 0.0;
    double max = 1.0;
    double step = 1.0;
    int count = 2;
};
NiceTicks niceTicks(ValueRange wanted, int maxTicks);

// A printf format for the tick labels of [min, max] with ticks `step` apart: fixed
// decimals for everyday magnitudes, exponent form for very large or small ones, and
// always enough digits that neighbouring ticks read differently (every plot uses it).
QString axisLabelFormat(double min, double max, double step);

} // namespace rbw
