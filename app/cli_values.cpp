#include "app/cli_values.hpp"

#include "common/number_format.hpp"

#include <charconv>
#include <cmath>
#include <string_view>

namespace signstim::app {
namespace {

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

// Whole of `s` as a finite float; false otherwise.
bool toFloat(std::string_view s, float& value) {
    s = trimmed(s);
    if (s.empty()) return false;
    const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
    return error == std::errc() && end == s.data() + s.size() && std::isfinite(value);
}

// Whole of `s` as a decimal unsigned integer; false otherwise (or when it overflows).
bool toUnsigned(std::string_view s, std::uint32_t& value) {
    if (s.empty()) return false;
    const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
    return error == std::errc() && end == s.data() + s.size();
}

std::string got(const std::string& text) { return ", got '" + text + "'"; }

std::string countText(std::size_t minCount, std::size_t maxCount) {
    if (minCount == maxCount) return std::to_string(minCount);
    if (maxCount == minCount + 1) return std::to_string(minCount) + " or " + std::to_string(maxCount);
    return std::to_string(minCount) + " to " + std::to_string(maxCount);
}

// The numbers of a comma-separated list; false when an item is not a finite number or the
// count is outside minCount..maxCount.
bool toNumbers(const std::string& text, std::size_t minCount, std::size_t maxCount, std::vector<float>& values) {
    values.clear();
    std::string_view rest = text;
    while (true) {
        const std::size_t comma = rest.find(',');
        float v = 0.0f;
        if (!toFloat(rest.substr(0, comma), v)) return false;
        values.push_back(v);
        if (comma == std::string_view::npos) break;
        rest.remove_prefix(comma + 1);
    }
    return values.size() >= minCount && values.size() <= maxCount;
}

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

int hexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

}  // namespace

InputError commandLineError(const std::string& flag, const std::string& message) {
    return InputError(kCommandLine, 0, flag, message);
}

ImageSize parseImageSize(const std::string& text, const std::string& flag, const SizeLimits& limits) {
    const std::size_t x = text.find_first_of("xX");
    ImageSize size;
    const bool ok = x != std::string::npos && toUnsigned(std::string_view(text).substr(0, x), size.width) &&
                    toUnsigned(std::string_view(text).substr(x + 1), size.height);
    auto inside = [&](std::uint32_t side) {
        return side >= limits.minimum && side <= limits.maximum && (!limits.even || side % 2 == 0);
    };
    if (!ok || !inside(size.width) || !inside(size.height))
        throw commandLineError(flag, std::string("expected ") + (limits.even ? "even " : "") + "WxH between " +
                                         std::to_string(limits.minimum) + " and " + std::to_string(limits.maximum) +
                                         got(text));
    return size;
}

float parseNumber(const std::string& text, const std::string& flag) {
    float value = 0.0f;
    if (!toFloat(text, value)) throw commandLineError(flag, "expected a number" + got(text));
    return value;
}

std::vector<float> parseNumbers(const std::string& text, const std::string& flag, std::size_t minCount,
                                std::size_t maxCount) {
    std::vector<float> values;
    if (!toNumbers(text, minCount, maxCount, values))
        throw commandLineError(flag, "expected " + countText(minCount, maxCount) + " comma-separated numbers" + got(text));
    return values;
}

glm::vec3 parseTriple(const std::string& text, const std::string& flag) {
    std::vector<float> v;
    if (!toNumbers(text, 3, 3, v)) throw commandLineError(flag, "expected three numbers x,y,z" + got(text));
    return glm::vec3(v[0], v[1], v[2]);
}

glm::vec4 parseColour(const std::string& text, const std::string& flag) {
    if (text == "transparent") return glm::vec4(0.0f);
    auto refuse = [&]() -> InputError {
        return commandLineError(flag, "expected #rrggbb, r,g,b[,a] (0..1) or transparent" + got(text));
    };
    glm::vec4 srgb(1.0f);
    if (!text.empty() && text[0] == '#') {
        if (text.size() != 7) throw refuse();
        for (int c = 0; c < 3; ++c) {
            const int high = hexDigit(text[1 + 2 * c]), low = hexDigit(text[2 + 2 * c]);
            if (high < 0 || low < 0) throw refuse();
            srgb[c] = static_cast<float>(high * 16 + low) / 255.0f;
        }
    } else {
        std::vector<float> v;
        if (!toNumbers(text, 3, 4, v)) throw refuse();
        for (std::size_t i = 0; i < v.size(); ++i) {
            if (v[i] < 0.0f || v[i] > 1.0f) throw refuse();
            srgb[static_cast<int>(i)] = v[i];
        }
    }
    return glm::vec4(srgbToLinear(srgb.r), srgbToLinear(srgb.g), srgbToLinear(srgb.b), srgb.a);
}

std::uint32_t requireSampleCount(std::uint32_t count, const std::string& flag) {
    // VkSampleCountFlagBits: powers of two up to 64.
    if (count < 1 || count > 64 || (count & (count - 1)) != 0)
        throw commandLineError(flag, "expected 1, 2, 4, 8, 16, 32 or 64 samples (lavapipe has 1 and 4), got " +
                                         std::to_string(count));
    return count;
}

double requireInRange(double value, double minimum, double maximum, const std::string& flag, const std::string& unit) {
    if (!(value >= minimum && value <= maximum)) {
        // formatNumber: enough digits to show why 1.0000001 is past a limit of 1.
        throw commandLineError(flag, "expected " + formatNumber(minimum) + " to " + formatNumber(maximum) +
                                         (unit.empty() ? "" : " ") + unit + got(formatNumber(value)));
    }
    return value;
}

signer::GalleryView parseGalleryView(const std::string& text) {
    if (text == "palm") return {0.0f, 0.0f};
    if (text == "thumb") return {90.0f, 0.0f};
    if (text == "little") return {-90.0f, 0.0f};
    if (text == "back") return {180.0f, 0.0f};
    if (text == "top") return {0.0f, 60.0f};
    if (text.find_first_of("0123456789") == std::string::npos) {
        throw commandLineError("--view", "expected palm, thumb, little, back, top or AZIMUTH,ELEVATION in degrees, got '" +
                                             text + "'");
    }
    const std::vector<float> values = parseNumbers(text, "--view", 2, 2);
    signer::GalleryView view{values[0], values[1]};
    requireInRange(view.elevationDeg, -89.0f, 89.0f, "--view elevation");
    return view;
}

}  // namespace signstim::app

namespace signstim::app {

std::pair<std::size_t, std::size_t> parseArrayTaskShard(const char* id, const char* count, const char* minimum) {
    if (!id || !count) return {0, 1};
    // The value as it may be quoted in a message: short, and no control character from the
    // environment reaches the terminal.
    const auto quoted = [](const char* value) {
        std::string text;
        for (const char* c = value; *c && text.size() < 40; ++c)
            text += static_cast<unsigned char>(*c) < 0x20 || *c == 0x7F ? '?' : *c;
        return "'" + text + "'";
    };
    const auto number = [&](const char* variable, const char* value) {
        std::uint32_t parsed = 0;
        if (!toUnsigned(value, parsed))
            throw InputError(kEnvironment, 0, variable,
                             std::string("expected a whole number (as Slurm sets it for an array job), got ") + quoted(value) +
                                 "; unset it or give --shard I/N");
        return parsed;
    };
    const std::uint32_t task = number("SLURM_ARRAY_TASK_ID", id);
    const std::uint32_t tasks = number("SLURM_ARRAY_TASK_COUNT", count);
    const std::uint32_t first = minimum ? number("SLURM_ARRAY_TASK_MIN", minimum) : 0;
    // The same bound as --shard's N (study_runner.cpp, parseShard).
    if (tasks == 0 || tasks > 100000)
        throw InputError(kEnvironment, 0, "SLURM_ARRAY_TASK_COUNT",
                         "expected 1 to 100000 array tasks, got " + quoted(count) + "; give --shard I/N");
    if (task < first || task - first >= tasks)
        throw InputError(kEnvironment, 0, "SLURM_ARRAY_TASK_ID",
                         std::string("task ") + id + " of " + count + " (min " + (minimum ? minimum : "0") +
                             ") is not a shard: expected SLURM_ARRAY_TASK_MIN <= ID < MIN + COUNT (an array of consecutive "
                             "tasks); give --shard I/N");
    return {task - first, tasks};
}

}  // namespace signstim::app
