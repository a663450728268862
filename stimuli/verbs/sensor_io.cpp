#include "stimuli/verbs/sensor_io.hpp"

#include "common/error.hpp"
#include "common/number_format.hpp"
#include "stimuli/json_source.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>

namespace signstim::stimuli {
namespace {

using nlohmann::json;

constexpr std::array<std::string_view, hand::kSensorCount> kSensorNames = {"hand",   "thumb", "index",
                                                                           "middle", "ring",  "little"};
constexpr std::array<std::string_view, 8> kColumns = {"time", "sensor", "x", "y", "z", "azimuth", "elevation", "roll"};

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

std::vector<std::string_view> splitCells(std::string_view line) {
    std::vector<std::string_view> cells;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        cells.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    return cells;
}

double parseNumber(std::string_view cell, const std::string& file, int line, std::string_view column) {
    double value = 0.0;
    const char* end = cell.data() + cell.size();
    const auto [ptr, ec] = std::from_chars(cell.data(), end, value);
    if (ec == std::errc::result_out_of_range && ptr == end) {
        throw InputError(file, line, std::string(column), "'" + std::string(cell) + "' is out of the range of a double");
    }
    if (cell.empty() || ec != std::errc() || ptr != end) {
        throw InputError(file, line, std::string(column), "not a number: '" + std::string(cell) + "'");
    }
    if (!std::isfinite(value)) {
        throw InputError(file, line, std::string(column), "must be finite, got '" + std::string(cell) + "'");
    }
    return value;
}

int parseSensorId(std::string_view cell, const std::string& file, int line) {
    for (int i = 0; i < hand::kSensorCount; ++i) {
        if (cell == kSensorNames[i] || cell == std::to_string(i)) return i;
    }
    throw InputError(file, line, "sensor",
                     "unknown sensor id '" + std::string(cell) + "' (expected hand, thumb, index, middle, ring, little or 0..5)");
}

// Output numbers: 4 decimals (0.1 µm, s to 0.1 ms).
std::string fixed4(double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.4f", v);
    std::string s = buffer;
    if (s == "-0.0000") s = "0.0000";
    return s;
}

// ---- JSON helpers for the calibration ----
// `path` is a list of keys: the field is "digits.index.lengthMm", the line that of the last key.
struct JsonReader {
    const JsonSource& source;

    [[noreturn]] void fail(const std::vector<std::string>& path, const std::string& message) const {
        std::string field;
        std::vector<std::string> anchors;
        for (const auto& p : path) {
            field += (field.empty() ? "" : ".") + p;
            anchors.push_back("\"" + p + "\"");
        }
        source.fail(anchors, field, message);
    }
    float number(const json& parent, const std::vector<std::string>& path, float minimum, float maximum,
                 bool required = true, float fallback = 0.0f) const {
        const std::string& key = path.back();
        if (!parent.contains(key)) {
            if (required) fail(path, "required");
            return fallback;
        }
        const json& v = parent[key];
        if (!v.is_number() || !std::isfinite(v.get<double>())) fail(path, "must be a finite number");
        const double value = v.get<double>();
        if (value < minimum || value > maximum) {
            fail(path, "out of range: " + rangeMessage(minimum, maximum, "", value));
        }
        return static_cast<float>(value);
    }
    template <std::size_t N>
    std::array<float, N> numbers(const json& parent, const std::vector<std::string>& path, float minimum,
                                 float maximum) const {
        const std::string& key = path.back();
        if (!parent.contains(key)) fail(path, "required");
        const json& v = parent[key];
        if (!v.is_array() || v.size() != N) fail(path, "must be an array of " + std::to_string(N) + " numbers");
        std::array<float, N> out{};
        for (std::size_t i = 0; i < N; ++i) {
            if (!v[i].is_number() || !std::isfinite(v[i].get<double>())) fail(path, "element " + std::to_string(i) + " is not a finite number");
            const double value = v[i].get<double>();
            if (value < minimum || value > maximum)
                fail(path, "element " + std::to_string(i) + " out of range: " + rangeMessage(minimum, maximum, "", value));
            out[i] = static_cast<float>(value);
        }
        return out;
    }
    void onlyKeys(const json& object, const std::vector<std::string>& path, std::initializer_list<std::string_view> keys) const {
        for (const auto& [key, value] : object.items()) {
            (void)value;
            if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
                auto p = path;
                p.push_back(key);
                fail(p, "unknown key");
            }
        }
    }
};

hand::SensorCalibration parseCalibration(const JsonSource& source);

}  // namespace

std::vector<SensorSample> parseSensorSamples(const std::string& text, const std::string& file) {
    std::vector<SensorSample> samples;
    std::istringstream in(std::string(withoutByteOrderMark(text)));
    std::string lineText;
    int line = 0;
    std::array<int, kColumns.size()> columnOf{};
    bool haveHeader = false;
    std::array<bool, hand::kSensorCount> seen{};
    auto finishSample = [&]() {
        if (samples.empty()) return;
        for (int i = 0; i < hand::kSensorCount; ++i) {
            if (!seen[i]) {
                throw InputError(file, samples.back().line, "sensor",
                                 "sample at time " + formatNumber(samples.back().timeS) + " has no reading for sensor '" +
                                     std::string(kSensorNames[i]) + "' (each time needs all six sensors)");
            }
        }
    };
    while (std::getline(in, lineText)) {
        ++line;
        const std::string_view content = trim(lineText);
        if (content.empty() || content.front() == '#') continue;
        const auto cells = splitCells(content);
        if (!haveHeader) {
            columnOf.fill(-1);
            for (std::size_t c = 0; c < cells.size(); ++c) {
                const auto it = std::find(kColumns.begin(), kColumns.end(), cells[c]);
                if (it == kColumns.end()) {
                    throw InputError(file, line, std::string(cells[c]),
                                     "unknown column (expected time,sensor,x,y,z,azimuth,elevation,roll)");
                }
                columnOf[it - kColumns.begin()] = static_cast<int>(c);
            }
            for (std::size_t k = 0; k < kColumns.size(); ++k) {
                if (columnOf[k] < 0) throw InputError(file, line, std::string(kColumns[k]), "missing column in the header");
            }
            if (cells.size() != kColumns.size()) throw InputError(file, line, "", "duplicate column in the header");
            haveHeader = true;
            continue;
        }
        if (cells.size() != kColumns.size()) {
            throw InputError(file, line, "", "expected " + std::to_string(kColumns.size()) + " cells, found " +
                                                 std::to_string(cells.size()));
        }
        auto cell = [&](int k) { return cells[columnOf[k]]; };
        const auto number = [&](int k, const NumberRange& range) {
            const double value = parseNumber(cell(k), file, line, kColumns[static_cast<std::size_t>(k)]);
            checkInRange(value, range, file, line, std::string(kColumns[static_cast<std::size_t>(k)]));
            return value;
        };
        const double time = number(0, kSampleTimeRange);
        const int sensor = parseSensorId(cell(1), file, line);
        hand::SensorReading reading;
        reading.positionMm = {static_cast<float>(number(2, kSensorPositionRange)),
                              static_cast<float>(number(3, kSensorPositionRange)),
                              static_cast<float>(number(4, kSensorPositionRange))};
        reading.azimuthDeg = static_cast<float>(number(5, kAngleDegreesRange));
        reading.elevationDeg = static_cast<float>(number(6, kAngleDegreesRange));
        reading.rollDeg = static_cast<float>(number(7, kAngleDegreesRange));
        if (samples.empty() || time != samples.back().timeS) {
            if (!samples.empty() && time < samples.back().timeS) {
                throw InputError(file, line, "time", "time goes backwards (" + formatNumber(time) + " after " +
                                                         formatNumber(samples.back().timeS) + ")");
            }
            finishSample();
            samples.push_back({time, line, {}});
            seen.fill(false);
        }
        if (seen[sensor]) {
            throw InputError(file, line, "sensor", "sensor '" + std::string(kSensorNames[sensor]) +
                                                       "' appears twice at time " + formatNumber(time));
        }
        seen[sensor] = true;
        samples.back().readings[sensor] = reading;
    }
    if (!haveHeader) throw InputError(file, 0, "", "empty file: expected a header time,sensor,x,y,z,azimuth,elevation,roll");
    if (samples.empty()) throw InputError(file, line, "", "no samples after the header");
    finishSample();
    return samples;
}

std::vector<SensorSample> loadSensorSamples(const std::filesystem::path& file) {
    return parseSensorSamples(readTextFile(file), file.string());
}

hand::SensorCalibration parseSensorCalibration(const std::string& text, const std::string& file) {
    const JsonSource source = parseJsonText(text, file);
    return withJsonErrors(source, [&] { return parseCalibration(source); });
}

namespace {
hand::SensorCalibration parseCalibration(const JsonSource& source) {
    const json& root = source.root;
    const JsonReader r{source};
    if (!root.is_object()) r.fail({}, "the top level must be an object");
    r.onlyKeys(root, {}, {"about", "side", "handThicknessMm", "handInitialRollDeg", "knuckleBowlRollDeg",
                          "palmBowlRollDeg", "sensorFromTipMm", "digits"});
    hand::SensorCalibration cal;
    if (root.contains("side")) {
        const json& side = root["side"];
        if (side == "right") cal.side = hand::Side::Right;
        else if (side == "left") cal.side = hand::Side::Left;
        else r.fail({"side"}, "must be \"right\" or \"left\"");
    }
    cal.handThicknessMm = r.number(root, {"handThicknessMm"}, 1.0f, 100.0f);
    cal.handInitialRollDeg = r.number(root, {"handInitialRollDeg"}, -360.0f, 360.0f, false, 0.0f);
    if (root.contains("knuckleBowlRollDeg")) cal.knuckleBowlRollDeg = r.numbers<5>(root, {"knuckleBowlRollDeg"}, -180.0f, 180.0f);
    cal.palmBowlRollDeg = r.number(root, {"palmBowlRollDeg"}, -180.0f, 180.0f, false, cal.palmBowlRollDeg);
    cal.sensorFromTipMm = r.number(root, {"sensorFromTipMm"}, 0.0f, 30.0f, false, cal.sensorFromTipMm);
    if (!root.contains("digits") || !root["digits"].is_object()) r.fail({"digits"}, "required: an object with thumb, index, middle, ring, little");
    const json& digits = root["digits"];
    r.onlyKeys(digits, {"digits"}, {"thumb", "index", "middle", "ring", "little"});
    for (int d = 0; d < hand::kDigitCount; ++d) {
        const std::string name(kSensorNames[d + 1]);
        if (!digits.contains(name) || !digits[name].is_object()) r.fail({"digits", name}, "required: an object");
        const json& digit = digits[name];
        r.onlyKeys(digit, {"digits", name}, {"lengthMm", "widthMm", "tipThicknessMm", "knuckleMm", "initialRollDeg"});
        hand::DigitCalibration& dc = cal.digits[d];
        dc.lengthMm = r.numbers<3>(digit, {"digits", name, "lengthMm"}, 1.0f, 200.0f);
        dc.widthMm = r.numbers<3>(digit, {"digits", name, "widthMm"}, 1.0f, 60.0f);
        dc.tipThicknessMm = r.number(digit, {"digits", name, "tipThicknessMm"}, 1.0f, 60.0f);
        const auto knuckle = r.numbers<2>(digit, {"digits", name, "knuckleMm"}, -300.0f, 300.0f);
        dc.knuckleOffsetMm = {knuckle[0], knuckle[1]};
        dc.initialRollDeg = r.number(digit, {"digits", name, "initialRollDeg"}, -360.0f, 360.0f, false, 0.0f);
    }
    return cal;
}
}  // namespace

hand::SensorCalibration loadSensorCalibration(const std::filesystem::path& file) {
    return parseSensorCalibration(readTextFile(file), file.string());
}

std::string formatSensorCalibration(const hand::SensorCalibration& cal) {
    json root;
    root["side"] = cal.side == hand::Side::Right ? "right" : "left";
    root["handThicknessMm"] = cal.handThicknessMm;
    root["handInitialRollDeg"] = cal.handInitialRollDeg;
    root["knuckleBowlRollDeg"] = cal.knuckleBowlRollDeg;
    root["palmBowlRollDeg"] = cal.palmBowlRollDeg;
    root["sensorFromTipMm"] = cal.sensorFromTipMm;
    for (int d = 0; d < hand::kDigitCount; ++d) {
        const hand::DigitCalibration& dc = cal.digits[d];
        json digit;
        digit["lengthMm"] = dc.lengthMm;
        digit["widthMm"] = dc.widthMm;
        digit["tipThicknessMm"] = dc.tipThicknessMm;
        digit["knuckleMm"] = {dc.knuckleOffsetMm.x, dc.knuckleOffsetMm.y};
        digit["initialRollDeg"] = dc.initialRollDeg;
        root["digits"][std::string(kSensorNames[d + 1])] = digit;
    }
    return root.dump(2) + "\n";
}

std::string formatSensorSamples(const std::vector<SensorSample>& samples) {
    std::string out = "time,sensor,x,y,z,azimuth,elevation,roll\n";
    for (const SensorSample& s : samples) {
        for (int i = 0; i < hand::kSensorCount; ++i) {
            const hand::SensorReading& r = s.readings[i];
            out += fixed4(s.timeS) + "," + std::string(kSensorNames[i]) + "," + fixed4(r.positionMm.x) + "," +
                   fixed4(r.positionMm.y) + "," + fixed4(r.positionMm.z) + "," + fixed4(r.azimuthDeg) +
                   "," + fixed4(r.elevationDeg) + "," + fixed4(r.rollDeg) + "\n";
        }
    }
    return out;
}

namespace {
const char* caseName(hand::ProximalJointCase c) {
    switch (c) {
        case hand::ProximalJointCase::Triangle: return "triangle";
        case hand::ProximalJointCase::Straight: return "straight";
        case hand::ProximalJointCase::FullyBent: return "fully-bent";
        case hand::ProximalJointCase::Degenerate: return "degenerate";
    }
    return "?";
}
json point(const glm::vec3& p) { return json::array({std::round(p.x * 1e4) / 1e4, std::round(p.y * 1e4) / 1e4, std::round(p.z * 1e4) / 1e4}); }
}  // namespace

void checkSensorHandFinite(const std::vector<SensorSample>& samples, const std::vector<hand::SensorHandFrame>& frames,
                           const std::string& file) {
    const auto finite = [](const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); };
    for (std::size_t i = 0; i < samples.size() && i < frames.size(); ++i) {
        bool ok = true;
        for (const hand::DigitJoints& j : frames[i].joints)
            ok = ok && finite(j.knuckle) && finite(j.distalJoint) && finite(j.proximalJoint) && finite(j.underNail);
        for (const auto& segment : frames[i].segments)
            for (const glm::vec3& v : segment) ok = ok && finite(v);
        if (!ok)
            throw InputError(file, samples[i].line, "",
                             "the hand rebuilt from the sample at time " + formatNumber(samples[i].timeS) +
                                 " is not finite (readings that no hand can take?); nothing is written");
    }
}

std::string formatSensorHandJson(hand::Side side, const std::vector<SensorSample>& samples,
                                 const std::vector<hand::SensorHandFrame>& frames) {
    json root;
    root["side"] = side == hand::Side::Right ? "right" : "left";
    root["units"] = "mm";
    json list = json::array();
    for (std::size_t i = 0; i < samples.size() && i < frames.size(); ++i) {
        json sample;
        sample["time"] = samples[i].timeS;
        for (int d = 0; d < hand::kDigitCount; ++d) {
            const hand::DigitJoints& j = frames[i].joints[d];
            sample["joints"][std::string(kSensorNames[d + 1])] = {{"A", point(j.knuckle)},
                                                                   {"B", point(j.distalJoint)},
                                                                   {"C", point(j.proximalJoint)},
                                                                   {"D", point(j.underNail)},
                                                                   {"proximalCase", caseName(j.proximalCase)}};
        }
        for (int b = 0; b < hand::kBodyCount; ++b) {
            json vertices = json::array();
            for (const glm::vec3& v : frames[i].segments[b]) vertices.push_back(point(v));
            sample["segments"][std::string(hand::boneName(side, static_cast<hand::Body>(b)))] = vertices;
        }
        list.push_back(sample);
    }
    root["samples"] = list;
    return root.dump(1) + "\n";
}

std::string formatSensorHandCsv(hand::Side side, const std::vector<SensorSample>& samples,
                                const std::vector<hand::SensorHandFrame>& frames) {
    std::string out = "time,kind,name,index,x,y,z\n";
    auto row = [&](double t, const char* kind, std::string_view name, const std::string& index, const glm::vec3& p) {
        out += fixed4(t) + "," + kind + "," + std::string(name) + "," + index + "," + fixed4(p.x) + "," +
               fixed4(p.y) + "," + fixed4(p.z) + "\n";
    };
    for (std::size_t i = 0; i < samples.size() && i < frames.size(); ++i) {
        const double t = samples[i].timeS;
        for (int d = 0; d < hand::kDigitCount; ++d) {
            const hand::DigitJoints& j = frames[i].joints[d];
            row(t, "joint", kSensorNames[d + 1], "A", j.knuckle);
            row(t, "joint", kSensorNames[d + 1], "B", j.distalJoint);
            row(t, "joint", kSensorNames[d + 1], "C", j.proximalJoint);
            row(t, "joint", kSensorNames[d + 1], "D", j.underNail);
        }
        for (int b = 0; b < hand::kBodyCount; ++b) {
            for (int v = 0; v < 8; ++v) {
                row(t, "vertex", hand::boneName(side, static_cast<hand::Body>(b)), std::to_string(v + 1), frames[i].segments[b][v]);
            }
        }
    }
    return out;
}

}  // namespace signstim::stimuli
