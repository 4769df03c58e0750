// Fewer points for display when a run gets long. The full data stays in PlotSeries
// (and in the CSV); a chart shows at most about maxPoints points per series.
//
// Samples are grouped in buckets of `stride` consecutive samples (stride a power of
// two). A bucket is drawn as its smallest and its largest value, in time order, so
// the envelope of the curve survives: a bounce's spike is never thinned away.
// stride 1 draws every sample as it is. Only full buckets are drawn; the newest
// (stride - 1) samples at most wait for their bucket to fill.
#pragma once

#include "app/gui/panels/plots/plot_series.h"

#include <QList>
#include <QPointF>

namespace rbw {

// Points drawn for sampleCount samples at this stride: n, or 2 per full bucket.
int displayPointCount(int sampleCount, int stride);

// The smallest power-of-two stride whose display has at most maxPoints points.
int strideFor(int sampleCount, int maxPoints);

// The samples covered by the display at this stride: all, or the full buckets.
int displayedSampleCount(int sampleCount, int stride);

// Appends the display points of samples [from, to) of series q to out. from and to
// must be multiples of stride (to may be sampleCount when stride is 1).
void appendDisplayPoints(const PlotSeries& data, PlotQuantity q, int from, int to, int stride,
                         QList<QPointF>& out);

} // namespace rbw
