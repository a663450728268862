#include "stimuli/story/lexicon.hpp"

#include "stimuli/story/gloss.hpp"

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <algorithm>
#include <set>

namespace signstim::stimuli {
namespace {

using nlohmann::json;

// [D] Body locations lie within this box around the chest (mm): from below the waist to above
// the head, an arm's reach forward. A number outside is a typo, not a place.
constexpr double kLocationLimitMm = 900.0;
// [D] A citation form lasts well under two seconds; ten is far past any sign.
constexpr double kMaximumSignSeconds = 10.0;

// Reads one lexicon file into `lexicon`, which may already hold other files' locations and
// signs (a lexicon folder): locations first (readHeaderAndLocations for every file), then
// signs (readSigns), so a sign may use a location another file defines.
// Where each location and sign was defined, and in which layer: 0 the default lexicon, 1 a lab's
// own (--lexicon), which may redefine what layer 0 defines (an override, listed) but not what
// its own files define.
struct Origins {
    struct Origin {
        int layer = 0;
        std::string file;
        int line = 0;
    };
    std::map<std::string, Origin> locations, signs;
};

class LexiconReader {
public:
    LexiconReader(const JsonSource& source, const HandshapeLibrary& shapes, const hand::HandModel& model, Lexicon& lexicon,
                  Origins& origins, int layer)
        : source_(source), shapes_(shapes), model_(model), lexicon_(lexicon), origins_(origins), layer_(layer) {}

    void readHeaderAndLocations() {
        const json& root = source_.root;
        if (!root.is_object()) source_.fail({}, "", "a lexicon is a JSON object {\"format\": \"signstim-lexicon\", ...}");
        for (const auto& [key, value] : root.items())
            if (key != "format" && key != "version" && key != "about" && key != "locations" && key != "signs")
                source_.fail({"\"" + key + "\""}, "/" + key, "unknown field '" + key + "' (known: format, version, about, locations, signs)");
        if (!root.contains("format") || root["format"] != "signstim-lexicon")
            source_.fail({"\"format\""}, "/format", "expected \"format\": \"signstim-lexicon\"");
        if (!root.contains("version") || !root["version"].is_number_integer() || root["version"].get<long long>() != 1)
            source_.fail({"\"version\""}, "/version", "this signstim reads lexicon files of version 1");
        if (!root.contains("locations")) return;
        if (!root["locations"].is_object())
            source_.fail({"\"locations\""}, "/locations", "expected {\"chin\": [x, y, z], ...} in signing-space mm");
        for (const auto& [name, value] : root["locations"].items()) {
            const std::vector<std::string> anchors{"\"locations\"", "\"" + name + "\""};
            const glm::dvec3 p = readVector3(source_, value, anchors, "/locations/" + name, kSigningSpacePositionRange);
            for (int i = 0; i < 3; ++i)
                if (std::abs(p[i]) > kLocationLimitMm)
                    source_.fail(anchors, "/locations/" + name,
                                 "expected each coordinate within -900 to 900 mm of the chest, got " + json(p[i]).dump());
            const int line = source_.lineOf(anchors);
            const auto [at, inserted] = lexicon_.locations.emplace(name, p);
            const auto origin = origins_.locations.find(name);
            if (!inserted && origin != origins_.locations.end() && origin->second.layer < layer_) {
                if (at->second != p)
                    lexicon_.overrides.push_back({"location " + name, source_.file, line, origin->second.file, origin->second.line});
                at->second = p;
            } else if (!inserted && at->second != p) {
                source_.fail(anchors, "/locations/" + name, "location '" + name + "' is defined differently in another lexicon file");
            }
            if (inserted || origin == origins_.locations.end() || origin->second.layer < layer_)
                origins_.locations[name] = {layer_, source_.file, line};
        }
    }

    void readSigns() {
        if (!source_.root.contains("signs")) return;
        const json& signs = source_.root["signs"];
        if (!signs.is_array()) source_.fail({"\"signs\""}, "/signs", "expected an array of signs");
        for (std::size_t s = 0; s < signs.size(); ++s) {
            const json& item = signs[s];
            const std::string pointer = "/signs/" + std::to_string(s);
            std::vector<std::string> anchors{"\"signs\""};
            if (!item.is_object() || !item.contains("gloss") || !item["gloss"].is_string())
                source_.fail(anchors, pointer + "/gloss", "each sign needs its \"gloss\"");
            LexiconSign sign;
            sign.gloss = item["gloss"].get<std::string>();
            anchors.push_back("\"gloss\": \"" + sign.gloss + "\"");
            sign.line = source_.lineAt(pointer + "/gloss");
            const GlossParse parsed = parseGloss(sign.gloss);
            if (parsed.error || parsed.items.size() != 1 || parsed.items[0].kind != GlossItemKind::Word ||
                parsed.items[0].hasArgumentList || sign.gloss == "IX" || sign.gloss == "HOLD")
                source_.fail(anchors, pointer + "/gloss", "'" + sign.gloss + "' is not a sign gloss (capitals, digits, inner hyphens)");
            const auto origin = origins_.signs.find(sign.gloss);
            const bool overrides = origin != origins_.signs.end() && origin->second.layer < layer_;
            if (origin != origins_.signs.end() && !overrides)
                source_.fail(anchors, pointer + "/gloss",
                             sign.gloss + " is defined twice (also " + origin->second.file + ":" +
                                 std::to_string(origin->second.line) + ")");
            for (const auto& [key, value] : item.items())
                if (key != "gloss" && key != "meaning" && key != "hands" && key != "passes" && key != "keyframes" &&
                    key != "notes" && key != "contact" && key != "notation")
                    source_.fail(anchors, pointer + "/" + key,
                                 "unknown field '" + key + "' (known: gloss, meaning, hands, passes, contact, keyframes, notation, notes)");
            sign.meaning = item.value("meaning", "");
            if (item.contains("notation")) {
                readNotation(item, sign, pointer);
            } else {
                sign.contact = readSignContact(source_, item, anchors, pointer);
                readHands(item, sign, anchors, pointer);
                if (item.contains("passes")) {
                    if (!item["passes"].is_number_integer() || item["passes"].get<long long>() < 1 || item["passes"].get<long long>() > 8)
                        source_.fail(anchors, pointer + "/passes", "expected a whole number of passes, 1 to 8");
                    sign.passes = item["passes"].get<int>();
                }
                const json& keyframes = item.contains("keyframes") ? item["keyframes"] : json();
                if (!keyframes.is_object()) source_.fail(anchors, pointer + "/keyframes", "expected {\"right\": [...], \"left\": [...]}");
                for (HandSide side : sign.hands) readTrack(keyframes, side, sign, anchors, pointer);
                if (sign.durationSeconds() * sign.passes > kMaximumSignSeconds)
                    source_.fail(anchors, pointer + "/keyframes", "a sign lasting over 10 s is a typo in a time");
            }
            sign.file = source_.file;
            if (overrides) {
                // The lab's sign takes the default one's place (and its place in the list).
                lexicon_.overrides.push_back(
                    {"sign " + sign.gloss, source_.file, sign.line, origin->second.file, origin->second.line});
                origins_.signs[sign.gloss] = {layer_, source_.file, sign.line};
                for (LexiconSign& old : lexicon_.signs)
                    if (old.gloss == sign.gloss) old = std::move(sign);
            } else {
                origins_.signs[sign.gloss] = {layer_, source_.file, sign.line};
                lexicon_.signs.push_back(std::move(sign));
            }
        }
    }

private:
    // A sign in the notation (sign_notation.hpp): compiled to keyframes; its hands, contact and
    // timing come from the description, not from fields of their own.
    void readNotation(const json& item, LexiconSign& sign, const std::string& pointer) {
        for (const char* key : {"hands", "passes", "contact", "keyframes"})
            if (item.contains(key))
                source_.failAt(pointer + "/" + key, std::string("a sign written in the notation derives \"") + key +
                                                        "\" from it; give either \"notation\" or keyframes");
        auto notation = std::make_shared<SignNotation>(readSignNotation(source_, pointer, shapes_));
        CompiledNotation compiled = compileSignNotation(*notation, lexicon_.locations, shapes_, model_, source_, pointer);
        if (compiled.keyframes.front().size() < 2) source_.failAt(pointer + "/notation", "the notation compiles to a single key");
        if (compiled.keyframes.front().back().timeSeconds > kMaximumSignSeconds)
            source_.failAt(pointer + "/notation", "a sign lasting over 10 s is a typo in a time");
        sign.hands = compiled.hands;
        sign.contact = compiled.contact;
        sign.keyframes = std::move(compiled.keyframes);
        sign.passThrough = std::move(compiled.passThrough);
        sign.contactEvents = std::move(compiled.contacts);
        sign.strokes = std::move(compiled.parts);
        sign.notation = std::move(notation);
    }

    void readHands(const json& item, LexiconSign& sign, const std::vector<std::string>& anchors, const std::string& pointer) {
        const json& hands = item.contains("hands") ? item["hands"] : json();
        if (!hands.is_array() || hands.empty() || hands.size() > 2)
            source_.fail(anchors, pointer + "/hands", "expected [\"right\"] or [\"right\", \"left\"]");
        for (const json& hand : hands) {
            const std::optional<HandSide> side = hand.is_string() ? parseHandSide(hand.get<std::string>()) : std::nullopt;
            if (!side) source_.fail(anchors, pointer + "/hands", "hands are \"right\" or \"left\"");
            sign.hands.push_back(*side);
        }
        if (sign.hands.front() != HandSide::Right || (sign.hands.size() == 2 && sign.hands[1] != HandSide::Left))
            source_.fail(anchors, pointer + "/hands", "the right (dominant) hand comes first: [\"right\"] or [\"right\", \"left\"]");
    }

    void readTrack(const json& keyframes, HandSide side, LexiconSign& sign, const std::vector<std::string>& anchors,
                   const std::string& pointer) {
        const std::string handName = toString(side);
        const std::string handPointer = pointer + "/keyframes/" + handName;
        std::vector<std::string> handAt = anchors;
        handAt.push_back("\"" + handName + "\"");
        if (!keyframes.contains(handName) || !keyframes[handName].is_array() || keyframes[handName].size() < 2)
            source_.fail(handAt, handPointer, "expected at least 2 keyframes for the " + handName + " hand");
        const json& list = keyframes[handName];
        std::vector<VerbKeyframe> track;
        std::vector<std::string> keyAt = handAt;
        for (std::size_t k = 0; k < list.size(); ++k) {
            const json& key = list[k];
            const std::string keyPointer = handPointer + "/" + std::to_string(k);
            keyAt.push_back("\"time\"");
            if (!key.is_object()) source_.fail(keyAt, keyPointer, "a keyframe is an object {\"time\": ..., \"at\": ..., ...}");
            for (const auto& [field, value] : key.items())
                if (field != "time" && field != "at" && field != "position" && field != "offset" && field != "touch" &&
                    field != "fingers" && field != "palm" && field != "orientation" && field != "handshape")
                    source_.fail(keyAt, keyPointer + "/" + field,
                                 "unknown field '" + field +
                                     "' (known: time, at, position, offset, touch, fingers, palm, orientation, handshape)");
            VerbKeyframe frame;
            if (!key.contains("time") || !key["time"].is_number() || !(key["time"].get<double>() >= 0.0) ||
                !(key["time"].get<double>() <= kMaximumSignSeconds))
                source_.fail(keyAt, keyPointer + "/time", "expected a time in seconds, 0 to 10");
            frame.timeSeconds = key["time"].get<double>();
            if (k == 0 && frame.timeSeconds != 0.0) source_.fail(keyAt, keyPointer + "/time", "the first keyframe is at time 0");
            if (k > 0 && !(frame.timeSeconds > track.back().timeSeconds))
                source_.fail(keyAt, keyPointer + "/time", "keyframe times must increase");
            if (!key.contains("handshape") || !key["handshape"].is_string())
                source_.fail(keyAt, keyPointer + "/handshape", "each keyframe names its handshape");
            frame.handshape = key["handshape"].get<std::string>();
            const Handshape* shape = shapes_.find(frame.handshape);
            if (!shape)
                source_.fail(keyAt, keyPointer + "/handshape",
                             "unknown handshape '" + frame.handshape + "' (not in " + shapes_.file + ")");
            frame.pose.orientation = readOrientation(source_, key, keyAt, keyPointer);
            frame.pose.positionMm = readPlace(key, *shape, side, frame.pose.orientation, keyAt, keyPointer);
            track.push_back(std::move(frame));
        }
        if (!sign.keyframes.empty()) {
            const std::vector<VerbKeyframe>& first = sign.keyframes.front();
            bool same = first.size() == track.size();
            for (std::size_t k = 0; same && k < track.size(); ++k) same = first[k].timeSeconds == track[k].timeSeconds;
            if (!same) source_.fail(handAt, handPointer, "both hands need the same keyframe count and times");
        }
        sign.keyframes.push_back(std::move(track));
    }

    // The palm frame's origin from "position" or "at" (+ "offset"), and "touch".
    glm::dvec3 readPlace(const json& key, const Handshape& shape, HandSide side, const glm::dquat& orientation,
                         const std::vector<std::string>& keyAt, const std::string& keyPointer) const {
        const bool hasAt = key.contains("at"), hasPosition = key.contains("position");
        if (hasAt == hasPosition)
            source_.fail(keyAt, keyPointer, "give the hand's place either as \"at\": a location name or as \"position\": [x, y, z]");
        glm::dvec3 target;
        if (hasAt) {
            if (!key["at"].is_string()) source_.fail(keyAt, keyPointer + "/at", "expected a location name");
            const std::string name = key["at"].get<std::string>();
            const auto found = lexicon_.locations.find(name);
            if (found == lexicon_.locations.end()) {
                std::string known;
                for (const auto& [location, point] : lexicon_.locations) known += (known.empty() ? "" : ", ") + location;
                source_.fail(keyAt, keyPointer + "/at", "unknown location '" + name + "' (known: " + known + ")");
            }
            target = found->second;
        } else {
            std::vector<std::string> at = keyAt;
            at.push_back("\"position\"");
            target = readVector3(source_, key["position"], at, keyPointer + "/position", kSigningSpacePositionRange);
        }
        if (key.contains("offset")) {
            std::vector<std::string> at = keyAt;
            at.push_back("\"offset\"");
            const glm::dvec3 offset = readVector3(source_, key["offset"], at, keyPointer + "/offset", kSigningSpacePositionRange);
            if (glm::length(offset) > 400.0)
                source_.fail(at, keyPointer + "/offset", "an offset from a location is at most 400 mm");
            target += offset;
        }
        for (int i = 0; i < 3; ++i)
            if (std::abs(target[i]) > kLocationLimitMm)
                source_.fail(keyAt, keyPointer, "the hand's place lies more than 900 mm from the chest");
        const std::string touch = key.contains("touch") && key["touch"].is_string() ? key["touch"].get<std::string>()
                                  : key.contains("touch")                          ? std::string("?")
                                                                                   : std::string("base");
        const std::optional<glm::dvec3> point =
            touchPointMm(model_, shape.controls, side == HandSide::Right ? hand::Side::Right : hand::Side::Left, touch);
        if (!point) {
            std::string known;
            for (const std::string& name : touchPointNames()) known += (known.empty() ? "" : ", ") + name;
            source_.fail(keyAt, keyPointer + "/touch", "unknown touch point '" + touch + "' (known: " + known + ")");
        }
        return palmOriginForTouch(target, orientation, *point);
    }

    const JsonSource& source_;
    const HandshapeLibrary& shapes_;
    const hand::HandModel& model_;
    Lexicon& lexicon_;
    Origins& origins_;
    int layer_ = 0;
};

// Lexicon files read into one lexicon, layer by layer (the default lexicon, then a lab's own);
// at least one sign in all.
Lexicon readLexicon(const std::vector<std::pair<JsonSource, int>>& sources, const std::string& name,
                    const HandshapeLibrary& shapes, const hand::HandModel& model) {
    Lexicon lexicon;
    lexicon.file = name;
    Origins origins;
    for (const auto& [source, layer] : sources)
        LexiconReader(source, shapes, model, lexicon, origins, layer).readHeaderAndLocations();
    for (const auto& [source, layer] : sources) LexiconReader(source, shapes, model, lexicon, origins, layer).readSigns();
    if (lexicon.signs.empty()) throw InputError(name, 0, "/signs", "the lexicon holds no sign");
    return lexicon;
}

// A lexicon file, or every .json file of a lexicon folder in name order.
std::vector<JsonSource> readLexiconSources(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::is_directory(path, ec)) return {readJsonFile(path)};
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(path, ec))
        if (entry.path().extension() == ".json") files.push_back(entry.path());
    if (ec) throw IoError(path.string(), "cannot read the lexicon folder", ec.value());
    std::sort(files.begin(), files.end());  // the same order on every machine
    if (files.empty()) throw InputError(path.string(), 0, "", "the lexicon folder holds no .json file");
    std::vector<JsonSource> sources;
    for (const auto& file : files) sources.push_back(readJsonFile(file));
    return sources;
}

}  // namespace

double LexiconSign::durationSeconds() const {
    return keyframes.empty() || keyframes.front().empty() ? 0.0 : keyframes.front().back().timeSeconds;
}

const LexiconSign* Lexicon::find(std::string_view gloss) const {
    for (const LexiconSign& sign : signs)
        if (sign.gloss == gloss) return &sign;
    return nullptr;
}

std::vector<std::string> Lexicon::glosses() const {
    std::vector<std::string> names;
    for (const LexiconSign& sign : signs) names.push_back(sign.gloss);
    return names;
}

const std::vector<std::string>& touchPointNames() {
    static const std::vector<std::string> names{"base",      "palm",      "knuckles",   "thumb-tip", "index-tip",
                                                "middle-tip", "ring-tip", "little-tip", "fingertips"};
    return names;
}

std::optional<glm::dvec3> touchPointMm(const hand::HandModel& model, const hand::HandControls& controls,
                                       hand::Side side, std::string_view touch) {
    const int tip = touch == "thumb-tip" ? 0 : touch == "index-tip" ? 1 : touch == "middle-tip" || touch == "fingertips" ? 2
                  : touch == "ring-tip"  ? 3 : touch == "little-tip" ? 4 : -1;
    if (tip >= 0) return glm::dvec3(hand::forwardKinematics(model, controls, side).tips[static_cast<std::size_t>(tip)]);
    if (touch == "base") return glm::dvec3(0.0);
    if (touch == "knuckles") {
        glm::vec3 p = model.mcpPositionMm[1];  // the middle finger's MCP
        return glm::dvec3(side == hand::Side::Right ? p : hand::mirrorToLeft(p));
    }
    if (touch == "palm") {
        // The middle of the palmar surface, halfway from the wrist to the knuckle line.
        const float z = 0.5f * hand::palmKnuckleZMm(model);
        return glm::dvec3(hand::palmarSurfaceXMm(model, z), 0.0, z);
    }
    return std::nullopt;
}

glm::dvec3 palmOriginForTouch(const glm::dvec3& targetMm, const glm::dquat& orientation, const glm::dvec3& touchInPalmMm) {
    // Signing-space orientations are written with y = z × x computed in these (physically
    // left-handed) coordinates, so the hand model's y (toward the thumb) appears as -y here
    // (signer/signer_pose.hpp, handFrameFromSigningSpace).
    const glm::dvec3 local(touchInPalmMm.x, -touchInPalmMm.y, touchInPalmMm.z);
    return targetMm - orientation * local;
}

Lexicon parseLexicon(const JsonSource& source, const HandshapeLibrary& shapes, const hand::HandModel& model) {
    return readLexicon({{source, 0}}, source.file, shapes, model);
}

Lexicon loadLexicon(const std::filesystem::path& path, const HandshapeLibrary& shapes, const hand::HandModel& model) {
    return loadLexicon(path, {}, shapes, model);
}

Lexicon loadLexicon(const std::filesystem::path& base, const std::filesystem::path& lab, const HandshapeLibrary& shapes,
                    const hand::HandModel& model) {
    std::vector<std::pair<JsonSource, int>> sources;
    for (JsonSource& source : readLexiconSources(base)) sources.emplace_back(std::move(source), 0);
    if (!lab.empty())
        for (JsonSource& source : readLexiconSources(lab)) sources.emplace_back(std::move(source), 1);
    return readLexicon(sources, lab.empty() ? base.string() : lab.string(), shapes, model);
}

}  // namespace signstim::stimuli
