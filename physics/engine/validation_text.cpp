// How validate() writes numbers and names in its messages (validation_detail.h).
#include "physics/engine/validation_detail.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

namespace rbw::validation {

std::string num(double x)
{
    char buffer[64];
    const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof buffer, x);
    return std::string(buffer, r.ptr);
}

std::string approx(double x)
{
    char buffer[64];
    const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::general, 3);
    return std::string(buffer, r.ptr);
}

std::string limit(double x, bool lower)
{
    if (!(std::isfinite(x) && x > 0.0)) {
        return num(x);
    }
    char buffer[64];
    const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::scientific, 1);
    const std::string text(buffer, r.ptr);   // "d.de±XX"
    int mantissa = (text[0] - '0') * 10 + (text[2] - '0');   // 10 ... 99, times 10^(exponent - 1)
    int exponent = std::atoi(text.c_str() + 4);
    auto value = [&] {
        return std::strtod((std::to_string(mantissa) + "e" + std::to_string(exponent - 1)).c_str(), nullptr);
    };
    // Rounded to nearest, the two digits are off by at most one unit.
    if (lower && value() < x && ++mantissa == 100) {
        mantissa = 10;
        ++exponent;
    }
    if (!lower && value() > x && --mantissa == 9) {
        mantissa = 99;
        --exponent;
    }
    return approx(value());
}

std::string vec(const Vec3& v)
{
    std::string out = "[";   // appended, as in quoted()
    out += num(v.x());
    out += ", ";
    out += num(v.y());
    out += ", ";
    out += num(v.z());
    out += ']';
    return out;
}

std::string quoted(const std::string& name)
{
    // Appended, not "\"" + text + "\"": GCC 12 warns (-Wrestrict) about the inlined
    // insert of operator+(const char*, std::string&&), a known false positive (GCC bug 105329).
    std::string out = "\"";
    out += messageText(name);
    out += '"';
    return out;
}

} // namespace rbw::validation
