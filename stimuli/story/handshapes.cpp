#include "stimuli/story/handshapes.hpp"

#include "common/error.hpp"
#include "common/number_format.hpp"
#include "stimuli/json_source.hpp"
#include "stimuli/scenes_path.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

namespace signstim::stimuli {
namespace {

using nlohmann::json;

constexpr std::array<std::string_view, 4> kFingerKeys = {"index", "middle", "ring", "little"};

std::string jsonKey(std::string_view s) { return "\"" + std::string(s) + "\""; }

// Every value of ASL-LEX 2.0's dominant-handshape column Handshape.2.0 (2,723 signs; Caselli et al.
// 2017, Sehyr et al. 2021; docs/hand.md), spelled as ASL-LEX spells them, so that a label the
// dataset does not use (a capital letter, bent_B for flat_b) is caught when the file is read.
constexpr std::array<std::string_view, 58> kAslLexHandshapes = {
    "1", "3", "4", "5", "7", "8", "a", "baby_o", "bent_1", "bent_l", "bent_v", "c", "closed_b", "closed_e",
    "curved_1", "curved_4", "curved_5", "curved_h", "curved_l", "curved_v", "d", "e", "f", "flat_1", "flat_4",
    "flat_b", "flat_h", "flat_horns", "flat_ily", "flat_m", "flat_n", "flat_o", "flat_v", "flatspread_5", "g",
    "goody_goody", "h", "horns", "i", "ily", "k", "l", "o", "open_8", "open_b", "open_e", "open_f", "open_h", "p",
    "r", "s", "spread_e", "spread_open_e", "stacked_5", "t", "v", "w", "y"};

class Parser {
public:
    Parser(const JsonSource& source, const hand::HandModel& model) : source_(source), model_(model) {}

    HandshapeLibrary parse() {
        const json& root = source_.root;
        if (!root.is_object()) fail({}, "", "the top level must be an object");
        for (const auto& [key, value] : root.items()) {
            static const std::set<std::string> known = {"format", "version", "about", "fingerPresets",
                                                        "thumbPresets", "handshapes"};
            if (!known.count(key)) fail({jsonKey(key)}, key, "unknown key (expected one of format, version, about, fingerPresets, thumbPresets, handshapes)");
            (void)value;
        }
        if (const auto format = root.find("format"); format != root.end() && *format != "signstim-handshapes")
            fail({"\"format\""}, "format", "expected \"signstim-handshapes\", got " + format->dump() + " (a file of another kind?)");
        // Version 2: thumbs for the spin-free thumb swing (docs/hand.md). Version 1 thumbs were
        // tuned for SPEC §1.4's literal chain and would now be rolled by θ.
        // A file without "version" predates the field being checked: it is a version 1 file.
        const json version = root.contains("version") ? root["version"] : json(1);
        if (!version.is_number_integer() || version.get<int>() != 2) {
            const bool one = version.is_number_integer() && version.get<int>() == 1;
            fail(root.contains("version") ? std::vector<std::string>{"\"version\""} : std::vector<std::string>{}, "version",
                 one ? std::string(root.contains("version") ? "version 1" : "no \"version\" (version 1)") +
                           ": its thumbs were tuned for the SPEC's literal thumb chain, which this signstim replaced "
                           "with a swing without spin: retune the thumbs (signstim handshapes --gallery F.png --view "
                           "60,0 helps; docs/hand.md) and set \"version\": 2"
                     : "expected 2, got " + version.dump());
        }
        if (root.contains("fingerPresets")) parseFingerPresets(root["fingerPresets"]);
        if (root.contains("thumbPresets")) parseThumbPresets(root["thumbPresets"]);
        if (!root.contains("handshapes") || !root["handshapes"].is_array()) {
            fail({"\"handshapes\""}, "handshapes", "required: an array of handshapes");
        }
        HandshapeLibrary library;
        library.file = source_.file;
        std::set<std::string> names;
        int index = 0;
        for (const json& shape : root["handshapes"]) {
            Handshape parsed = parseShape(shape, index++);
            if (!names.insert(parsed.name).second) {
                fail({"\"handshapes\"", "\"name\"", jsonKey(parsed.name), "\"name\"", jsonKey(parsed.name)},
                     "handshapes[" + std::to_string(index - 1) + "].name",
                     "duplicate handshape name '" + parsed.name + "'");
            }
            library.shapes.push_back(std::move(parsed));
        }
        if (library.shapes.empty()) fail({"\"handshapes\""}, "handshapes", "no handshapes defined");
        return library;
    }

private:
    // The line is that of the JSON pointer the anchors spell (keys, and "name": "X" for the
    // handshape named X), recorded while parsing, so it is right whatever the key order and
    // layout; text anchors where they spell no recorded value.
    [[noreturn]] void fail(const std::vector<std::string>& anchors, const std::string& field,
                           const std::string& message) const {
        std::string pointer;
        bool spelled = true;
        for (const std::string& anchor : anchors) {
            const bool quoted = anchor.size() >= 2 && anchor.front() == '"' && anchor.back() == '"';
            if (quoted && anchor.find('"', 1) == anchor.size() - 1) {
                pointer += "/" + jsonPointerToken(anchor.substr(1, anchor.size() - 2));
                continue;
            }
            const std::string prefix = "\"name\": \"";
            spelled = quoted && anchor.rfind(prefix, 0) == 0 && pointer == "/handshapes" && source_.root.is_object();
            if (!spelled) break;
            spelled = false;
            const std::string name = anchor.substr(prefix.size(), anchor.size() - prefix.size() - 1);
            const auto list = source_.root.find("handshapes");
            if (list == source_.root.end() || !list->is_array()) break;
            const json& shapes = *list;
            std::size_t index = 0;
            while (index < shapes.size() && !(shapes[index].is_object() && shapes[index].value("name", json()) == name)) ++index;
            spelled = index < shapes.size();
            if (!spelled) break;
            pointer += "/" + std::to_string(index);
        }
        if (spelled && !pointer.empty() && source_.has(pointer))
            throw InputError(source_.file, source_.lineAt(pointer), field, message);
        source_.fail(anchors, field, message);
    }

    float number(const json& value, const std::vector<std::string>& anchors, const std::string& field,
                 float minimum, float maximum) const {
        if (!value.is_number()) fail(anchors, field, "must be a number, got " + std::string(value.type_name()));
        const double v = value.get<double>();
        if (!(v >= minimum && v <= maximum)) fail(anchors, field, "out of range: " + rangeMessage(minimum, maximum, "", v));
        return static_cast<float>(v);
    }

    void parseFingerPresets(const json& presets) {
        if (!presets.is_object()) fail({"\"fingerPresets\""}, "fingerPresets", "must be an object");
        for (const auto& [name, value] : presets.items()) {
            const std::vector<std::string> at = {"\"fingerPresets\"", jsonKey(name)};
            const std::string field = "fingerPresets." + name;
            if (!value.is_object()) fail(at, field, "must be an object {\"bend\", \"hook\"}");
            hand::FingerControls c;
            for (const auto& [key, v] : value.items()) {
                auto here = at;
                here.push_back(jsonKey(key));
                if (key == "bend") c.bend = number(v, here, field + ".bend", -1.0f, 1.0f);
                else if (key == "hook") c.hook = number(v, here, field + ".hook", -1.0f, 1.0f);
                else if (key == "about") continue;
                else fail(here, field + "." + key, "unknown key (expected bend, hook, about)");
            }
            fingerPresets_[name] = c;
        }
    }

    void parseThumbPresets(const json& presets) {
        if (!presets.is_object()) fail({"\"thumbPresets\""}, "thumbPresets", "must be an object");
        for (const auto& [name, value] : presets.items()) {
            const std::vector<std::string> at = {"\"thumbPresets\"", jsonKey(name)};
            const std::string field = "thumbPresets." + name;
            if (!value.is_object()) fail(at, field, "must be an object {\"bendDeg\", \"spreadDeg\", \"mcpDeg\", \"ipDeg\"}");
            hand::ThumbControls c;
            applyThumbFields(value, at, field, c, /*allowPreset=*/false);
            thumbPresets_[name] = c;
        }
    }

    void applyThumbFields(const json& value, const std::vector<std::string>& at, const std::string& field,
                          hand::ThumbControls& c, bool allowPreset) const {
        const hand::HandLimits& lim = model_.limits;
        for (const auto& [key, v] : value.items()) {
            auto here = at;
            here.push_back(jsonKey(key));
            const std::string f = field + "." + key;
            if (key == "bendDeg") c.bendDeg = number(v, here, f, lim.thumbBend.minDeg, lim.thumbBend.maxDeg);
            else if (key == "spreadDeg") c.spreadDeg = number(v, here, f, lim.thumbSpread.minDeg, lim.thumbSpread.maxDeg);
            else if (key == "mcpDeg") c.mcpDeg = number(v, here, f, lim.thumbMcp.minDeg, lim.thumbMcp.maxDeg);
            else if (key == "ipDeg") c.ipDeg = number(v, here, f, lim.thumbIp.minDeg, lim.thumbIp.maxDeg);
            else if (key == "about" || (allowPreset && key == "preset")) continue;
            else fail(here, f, "unknown key (expected bendDeg, spreadDeg, mcpDeg, ipDeg" +
                                   std::string(allowPreset ? ", preset)" : ")"));
        }
    }

    hand::FingerControls parseFinger(const json& value, int finger, const std::vector<std::string>& at,
                                     const std::string& field) const {
        if (value.is_string()) return fingerPreset(value.get<std::string>(), at, field);
        if (!value.is_object()) fail(at, field, "must be a preset name or an object");
        hand::FingerControls c;
        if (value.contains("preset")) {
            const json& preset = value["preset"];
            if (!preset.is_string()) fail(at, field + ".preset", "must be a preset name");
            c = fingerPreset(preset.get<std::string>(), at, field + ".preset");
        }
        if (value.contains("spreadDeg") && value.contains("abductionDeg")) {
            fail(at, field, "give spreadDeg or abductionDeg, not both");
        }
        const hand::HandLimits& lim = model_.limits;
        for (const auto& [key, v] : value.items()) {
            auto here = at;
            here.push_back(jsonKey(key));
            const std::string f = field + "." + key;
            if (key == "bend") c.bend = number(v, here, f, -1.0f, 1.0f);
            else if (key == "hook") c.hook = number(v, here, f, -1.0f, 1.0f);
            else if (key == "spreadDeg") c.spreadDeg = number(v, here, f, lim.fingerSpread.minDeg, lim.fingerSpread.maxDeg);
            else if (key == "abductionDeg") {
                // SPEC §1.6: σ = α − ρ.
                const float radiation = model_.radiationDeg[finger];
                c.spreadDeg = number(v, here, f, lim.fingerSpread.minDeg + radiation,
                                     lim.fingerSpread.maxDeg + radiation) - radiation;
            } else if (key == "preset" || key == "about") continue;
            else fail(here, f, "unknown key (expected preset, bend, hook, spreadDeg, abductionDeg)");
        }
        return c;
    }

    hand::FingerControls fingerPreset(const std::string& name, const std::vector<std::string>& at,
                                      const std::string& field) const {
        const auto it = fingerPresets_.find(name);
        if (it == fingerPresets_.end()) fail(at, field, "unknown finger preset '" + name + "'" + known(fingerPresets_));
        return it->second;
    }

    template <class Map>
    static std::string known(const Map& map) {
        std::string list;
        for (const auto& [name, value] : map) list += (list.empty() ? "" : ", ") + name;
        return list.empty() ? " (no presets defined)" : " (known: " + list + ")";
    }

    Handshape parseShape(const json& shape, int index) {
        const std::string base = "handshapes[" + std::to_string(index) + "]";
        if (!shape.is_object()) fail({"\"handshapes\""}, base, "must be an object");
        if (!shape.contains("name") || !shape["name"].is_string() || shape["name"].get<std::string>().empty()) {
            fail({"\"handshapes\""}, base + ".name", "required: a non-empty string");
        }
        Handshape out;
        out.name = shape["name"].get<std::string>();
        const std::vector<std::string> at = {"\"handshapes\"", "\"name\": " + jsonKey(out.name)};
        const std::string field = "handshape '" + out.name + "' ";
        for (const auto& [key, value] : shape.items()) {
            auto here = at;
            here.push_back(jsonKey(key));
            if (key == "name") continue;
            if (key == "aslLex") {
                if (value.is_null()) continue;
                if (!value.is_string()) fail(here, field + key, "must be a string or null");
                out.aslLexLabel = value.get<std::string>();
                if (std::find(kAslLexHandshapes.begin(), kAslLexHandshapes.end(), out.aslLexLabel) ==
                    kAslLexHandshapes.end()) {
                    fail(here, field + key,
                         "'" + out.aslLexLabel +
                             "' is not an ASL-LEX 2.0 handshape label (lower case as ASL-LEX writes them, e.g. "
                             "open_b, closed_b, flat_b, bent_1; null where none fits)");
                }
            } else if (key == "description") {
                if (!value.is_string()) fail(here, field + key, "must be a string");
                out.description = value.get<std::string>();
            } else if (key == "fingers") {
                if (!value.is_object()) fail(here, field + key, "must be an object with index, middle, ring, little");
                for (const auto& [finger, spec] : value.items()) {
                    if (std::find(kFingerKeys.begin(), kFingerKeys.end(), finger) == kFingerKeys.end()) {
                        auto f = here;
                        f.push_back(jsonKey(finger));
                        fail(f, field + "fingers." + finger, "unknown finger (expected index, middle, ring, little)");
                    }
                    (void)spec;
                }
                for (int f = 0; f < hand::kFingerCount; ++f) {
                    const std::string name(kFingerKeys[f]);
                    auto fingerAt = here;
                    fingerAt.push_back(jsonKey(name));
                    if (!value.contains(name)) fail(here, field + "fingers." + name, "required");
                    out.controls.fingers[f] = parseFinger(value[name], f, fingerAt, field + "fingers." + name);
                }
            } else if (key == "thumb") {
                if (value.is_string()) {
                    const auto it = thumbPresets_.find(value.get<std::string>());
                    if (it == thumbPresets_.end()) {
                        fail(here, field + "thumb", "unknown thumb preset '" + value.get<std::string>() + "'" + known(thumbPresets_));
                    }
                    out.controls.thumb = it->second;
                } else if (value.is_object()) {
                    if (value.contains("preset")) {
                        const json& preset = value["preset"];
                        const auto it = preset.is_string() ? thumbPresets_.find(preset.get<std::string>()) : thumbPresets_.end();
                        if (it == thumbPresets_.end()) fail(here, field + "thumb.preset", "unknown thumb preset" + known(thumbPresets_));
                        out.controls.thumb = it->second;
                    }
                    applyThumbFields(value, here, field + "thumb", out.controls.thumb, /*allowPreset=*/true);
                } else {
                    fail(here, field + "thumb", "must be a preset name or an object");
                }
            } else if (key == "contact") {
                if (!value.is_string()) fail(here, field + key, "must name a finger (index, middle, ring, little)");
                const auto it = std::find(kFingerKeys.begin(), kFingerKeys.end(), value.get<std::string>());
                if (it == kFingerKeys.end()) fail(here, field + key, "unknown finger '" + value.get<std::string>() + "' (expected index, middle, ring, little)");
                out.thumbContact = static_cast<hand::Digit>(1 + (it - kFingerKeys.begin()));
            } else {
                fail(here, field + key, "unknown key (expected name, aslLex, description, fingers, thumb, contact)");
            }
        }
        if (!shape.contains("fingers")) fail(at, field + "fingers", "required");
        if (!shape.contains("thumb")) fail(at, field + "thumb", "required");
        return out;
    }

    const JsonSource& source_;
    const hand::HandModel& model_;
    std::map<std::string, hand::FingerControls> fingerPresets_;
    std::map<std::string, hand::ThumbControls> thumbPresets_;
};

}  // namespace

const Handshape* HandshapeLibrary::find(std::string_view name) const {
    for (const Handshape& shape : shapes) {
        if (shape.name == name) return &shape;
    }
    return nullptr;
}

const Handshape& HandshapeLibrary::at(std::string_view name) const {
    if (const Handshape* shape = find(name)) return *shape;
    std::string names;
    for (const Handshape& shape : shapes) names += (names.empty() ? "" : " ") + shape.name;
    throw InputError("<command line>", 0, "--shape",
                     "unknown handshape '" + std::string(name) + "' (known: " + names + ")");
}

HandshapeLibrary parseHandshapes(const std::string& text, const std::string& fileName,
                                 const hand::HandModel& model) {
    const JsonSource source = parseJsonText(text, fileName);
    return withJsonErrors(source, [&] { return Parser(source, model).parse(); });
}

std::filesystem::path handshapesFile(const std::filesystem::path& explicitFile,
                                     const std::filesystem::path& scenesDir) {
    return explicitFile.empty() ? resolveScenesDir(scenesDir) / "handshapes.json" : explicitFile;
}

HandshapeLibrary loadHandshapes(const std::filesystem::path& file, const hand::HandModel& model) {
    const JsonSource source = readJsonFile(file);
    return withJsonErrors(source, [&] { return Parser(source, model).parse(); });
}

}  // namespace signstim::stimuli
