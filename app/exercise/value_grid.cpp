#include "app/exercise/value_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rbw {

std::uint64_t uniformIndex(std::mt19937_64& engine, std::uint64_t n)
{
    if (n == std::numeric_limits<std::uint64_t>::max()) return engine();
    const std::uint64_t range = n + 1;
    // 2^64 mod range: the first `threshold` raw values are rejected, so the rest are a
    // whole number of copies of [0, range) and x % range is exactly uniform.
    const std::uint64_t threshold = (0 - range) % range;
    for (;;) {
        const std::uint64_t x = engine();
        if (x >= threshold) return x % range;
    }
}

int decimalsOf(double step)
{
    for (int d = 0; d <= 6; ++d) {
        const double scaled = step * std::pow(10.0, d);
        // A whole number of units of 10^-d, and at least one (else the grid's step
        // would round to 0 units and every value be lo).
        if (std::round(scaled) >= 1.0 && std::abs(scaled - std::round(scaled)) <= 1e-9 * std::max(1.0, scaled)) return d;
    }
    return -1;
}

// An integer divided by a power of ten, which IEEE division rounds correctly, so the
// double is the nearest one to the decimal and JSON writes it as the short decimal
// ("0.3", never "0.30000000000000004").
double gridValue(double lo, std::uint64_t k, double step, int decimals)
{
    const double scale = std::pow(10.0, decimals);
    const double units = std::round(lo * scale) + static_cast<double>(k) * std::round(step * scale);
    return units / scale;
}

std::uint64_t gridCount(double lo, double hi, double step)
{
    const double count = std::floor((hi - lo) / step + 1e-9);
    // 2^64: a double at or above it (or NaN) would make the cast undefined.
    if (!(count < 18446744073709551616.0)) return std::numeric_limits<std::uint64_t>::max();
    return static_cast<std::uint64_t>(count);
}

} // namespace rbw
