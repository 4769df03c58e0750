// The number grid that exercise values are drawn from (docs/exercises.md): a rule's
// values are lo + k step, k = 0, 1, ..., rounded to the step's decimals, and k is drawn
// from std::mt19937_64 by a mapping written here, not by a standard distribution (whose
// results differ between standard libraries), so a seed gives the same numbers on
// every machine.
#pragma once

#include <cstdint>
#include <random>

namespace rbw {

// An integer uniform in [0, n], from the engine's raw 64-bit outputs by rejection
// (portable: the same numbers with every standard library).
std::uint64_t uniformIndex(std::mt19937_64& engine, std::uint64_t n);

// Decimals of a rounding step (0.5 -> 1, 0.25 -> 2, 2 -> 0), at most 6; -1 if the step
// has more, or is below 10^-6 (5e-324 is not a step of 0 decimals).
int decimalsOf(double step);

// lo + k step, rounded to `decimals`: the double nearest to that decimal.
double gridValue(double lo, std::uint64_t k, double step, int decimals);

// The largest k with lo + k step <= hi (the grid has gridCount + 1 values); the
// largest uint64 when k does not fit (a huge range for its step).
std::uint64_t gridCount(double lo, double hi, double step);

} // namespace rbw
