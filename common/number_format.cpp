#include "common/number_format.hpp"

#include <charconv>
#include <cmath>

namespace signstim {

std::string formatNumber(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char buffer[64];
    // std::to_chars without a format or precision gives the shortest round-trip form.
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value == 0.0 ? 0.0 : value);
    return std::string(buffer, result.ptr);
}

std::string rangeMessage(double minimum, double maximum, const std::string& unit, double value) {
    return "expected " + formatNumber(minimum) + " to " + formatNumber(maximum) + (unit.empty() ? "" : " " + unit) +
           ", got " + formatNumber(value);
}

}  // namespace signstim
