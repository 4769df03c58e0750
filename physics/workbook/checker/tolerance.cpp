#include "physics/workbook/checker/tolerance.h"

#include <algorithm>
#include <cmath>

namespace rbw::checking {

Vec3 vecOf(const Values& v) { return Vec3(v[0], v[1], v[2]); }

Mat3 matOf(const Values& v)
{
    Mat3 m;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m(i, j) = v[3 * i + j];
    return m;
}

Values flatVec(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

Values flatMat(const Mat3& m)
{
    Values out;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out.push_back(m(i, j));
    return out;
}

double maxAbs(const Values& v)
{
    double m = 0.0;
    for (double x : v) m = std::max(m, std::abs(x));
    return m;
}

bool matchesWithin(const Values& given, const Values& ref, double tol, const Values& extra)
{
    if (given.size() != ref.size()) return false;
    auto within = [&](double sign) {
        for (size_t i = 0; i < ref.size(); ++i) {
            const double allowed = tol + (extra.empty() ? 0.0 : extra[i]);
            // An infinite reference or tolerance (a denominator near zero upstream:
            // 1.8e8 / 1e-300 overflows) would take every number: it matches none.
            if (!std::isfinite(ref[i]) || !std::isfinite(allowed)) return false;
            if (!(std::abs(given[i] - sign * ref[i]) <= allowed)) return false;
        }
        return true;
    };
    return within(1.0) || (ref.size() == 4 && within(-1.0));
}

bool matches(const Values& given, const Values& ref, double rel, const Values& extra)
{
    return matchesWithin(given, ref, rel * maxAbs(ref), extra);
}

double threeFigureHalfUnit(const Values& ref)
{
    const double m = maxAbs(ref);
    if (!(m > 0.0) || !std::isfinite(m)) return 0.0;
    // 0.5 * 10^(e - 2) with e the decade of the largest component (3.11: e = 0, 0.01)
    return 0.5 * std::pow(10.0, std::floor(std::log10(m)) - 2.0);
}

bool rightToThreeFigures(const Values& given, const Values& ref)
{
    // The factor allows for the binary representation of a tie (0.1025 written 0.103).
    return matchesWithin(given, ref, threeFigureHalfUnit(ref) * (1.0 + 1e-9));
}

} // namespace rbw::checking
