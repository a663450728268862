#include "analysis/text_format.hpp"

#include "common/number_format.hpp"

#include <charconv>
#include <cmath>

namespace signstim::analysis {

std::string formatPValue(double p) {
    if (!std::isfinite(p)) return "";
    if (p < 0.001) return "< 0.001";
    if (p >= 0.9995) return "1";
    return formatFixed(p, p < 0.01 ? 4 : 3);
}

std::string formatP(double p) {
    const std::string value = formatPValue(p);
    if (value.empty()) return "";
    return value[0] == '<' ? "p " + value : "p = " + value;
}

std::string fixedOrEmpty(double value, int decimals) { return std::isfinite(value) ? formatFixed(value, decimals) : ""; }

std::string significant6(double value) {
    if (!std::isfinite(value)) return "";
    if (value == 0.0) return "0";  // also -0
    char text[64];
    const auto result = std::to_chars(text, text + sizeof text, value, std::chars_format::general, 6);
    return std::string(text, result.ptr);  // like printf's %.6g: "0.123457", "1.5e-07"
}

double roundSignificant6(double value) {
    if (!std::isfinite(value)) return value;
    const std::string text = significant6(value);
    double rounded = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), rounded);
    return rounded;
}

std::string percent(double proportion) {
    if (!std::isfinite(proportion)) return "";
    return formatFixed(proportion * 100.0, 0) + "%";
}

}  // namespace signstim::analysis
