#include "common/number_format.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace signstim {

std::string formatNumber(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char buffer[512];
    if (value == 0.0) return "0";
    // std::to_chars without a precision gives the shortest text that reads back as `value`:
    // in plain notation for everyday magnitudes (100000, not 1e+05), else the shorter form.
    const double magnitude = std::abs(value);
    const auto result = magnitude >= 1e-5 && magnitude < 1e16
                            ? std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed)
                            : std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::string formatFixed(double value, int decimals) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    if (decimals < 0 || decimals > 17) throw std::invalid_argument("formatFixed: decimals must be 0 to 17");
    // 309 integer digits at most, a sign, a point and the decimals.
    char buffer[340];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
    std::string text(buffer, result.ptr);
    // -0.0004 at 3 decimals reads "-0.000": a sign on zero says nothing but "differs from 0.000".
    if (text.front() == '-' && text.find_first_not_of("-0.") == std::string::npos) text.erase(0, 1);
    return text;
}

std::string rangeMessage(double minimum, double maximum, const std::string& unit, double value) {
    return "expected " + formatNumber(minimum) + " to " + formatNumber(maximum) + (unit.empty() ? "" : " " + unit) +
           ", got " + formatNumber(value);
}

}  // namespace signstim
