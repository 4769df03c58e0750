#include "app/gui/panels/plots/plot_decimation.h"

#include <algorithm>

namespace rbw {

int displayPointCount(int sampleCount, int stride)
{
    return stride <= 1 ? sampleCount : 2 * (sampleCount / stride);
}

int strideFor(int sampleCount, int maxPoints)
{
    int stride = 1;
    while (displayPointCount(sampleCount, stride) > std::max(maxPoints, 2)) stride *= 2;
    return stride;
}

int displayedSampleCount(int sampleCount, int stride)
{
    return stride <= 1 ? sampleCount : (sampleCount / stride) * stride;
}

void appendDisplayPoints(const PlotSeries& data, PlotQuantity q, int from, int to, int stride,
                         QList<QPointF>& out)
{
    if (stride <= 1) {
        for (int i = from; i < to; ++i) out.append(QPointF(data.time(i), data.value(q, i)));
        return;
    }
    for (int b = from; b + stride <= to; b += stride) {
        // The bucket's smallest and largest value, drawn in the order they occur.
        int iMin = b;
        int iMax = b;
        for (int i = b + 1; i < b + stride; ++i) {
            if (data.value(q, i) < data.value(q, iMin)) iMin = i;
            if (data.value(q, i) > data.value(q, iMax)) iMax = i;
        }
        const int first = std::min(iMin, iMax);
        const int second = std::max(iMin, iMax) == first ? b + stride - 1 : std::max(iMin, iMax);
        out.append(QPointF(data.time(first), data.value(q, first)));
        out.append(QPointF(data.time(second), data.value(q, second)));
    }
}

} // namespace rbw
