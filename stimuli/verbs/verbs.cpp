#include "stimuli/verbs/verbs.hpp"

#include "common/number_format.hpp"
#include "stimuli/verbs/sora.hpp"

#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>

namespace signstim::stimuli {

std::string toString(HandSide side) { return side == HandSide::Left ? "left" : "right"; }

std::optional<HandSide> parseHandSide(std::string_view text) {
    if (text == "right") return HandSide::Right;
    if (text == "left") return HandSide::Left;
    return std::nullopt;
}

int VerbDefinition::handIndex(HandSide side) const {
    for (std::size_t i = 0; i < hands.size(); ++i)
        if (hands[i] == side) return static_cast<int>(i);
    return -1;
}

const VerbDefinition* VerbLibrary::find(std::string_view name) const {
    for (const VerbDefinition& verb : verbs)
        if (verb.name == name) return &verb;
    return nullptr;
}

const VerbDefinition& VerbLibrary::get(std::string_view name, const std::string& file, int line,
                                       const std::string& field) const {
    if (const VerbDefinition* verb = find(name)) return *verb;
    throw InputError(file, line, field,
                     "unknown verb '" + std::string(name) + "' (known: " + knownNames() + "; defined in " +
                         sourceFile + ")");
}

std::string VerbLibrary::knownNames() const {
    std::string names;
    for (const VerbDefinition& verb : verbs) names += (names.empty() ? "" : ", ") + verb.name;
    return names;
}

glm::dvec3 readVector3(const JsonSource& source, const nlohmann::json& value,
                       const std::vector<std::string>& anchors, const std::string& field, const NumberRange& range) {
    if (!value.is_array() || value.size() != 3) source.fail(anchors, field, "expected [x, y, z]");
    glm::dvec3 result;
    for (int i = 0; i < 3; ++i) {
        const nlohmann::json& element = value[static_cast<std::size_t>(i)];
        if (!element.is_number()) source.fail(anchors, field, "expected three numbers [x, y, z]");
        result[i] = source.number(element, field + "/" + std::to_string(i), range);
    }
    return result;
}

glm::dquat readOrientation(const JsonSource& source, const nlohmann::json& object,
                           const std::vector<std::string>& anchors, const std::string& field) {
    const bool hasQuaternion = object.contains("orientation");
    const bool hasDirections = object.contains("fingers") || object.contains("palm");
    if (!hasQuaternion && !hasDirections) {
        source.fail(anchors, field,
                    "needs an orientation: \"fingers\": [x, y, z] and \"palm\": [x, y, z] directions, "
                    "or \"orientation\": [w, x, y, z]");
    }
    std::optional<glm::dquat> fromQuaternion;
    std::optional<glm::dquat> fromDirections;
    if (hasQuaternion) {
        const nlohmann::json& q = object["orientation"];
        std::vector<std::string> at = anchors;
        at.push_back("\"orientation\"");
        if (!q.is_array() || q.size() != 4) source.fail(at, field + "/orientation", "expected [w, x, y, z]");
        double v[4];
        for (std::size_t i = 0; i < 4; ++i) {
            if (!q[i].is_number()) source.fail(at, field + "/orientation", "expected four numbers [w, x, y, z]");
            v[i] = source.number(q[i], field + "/orientation/" + std::to_string(i), NumberRange{-1.0, 1.0, ""});
        }
        const double norm = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3]);
        if (std::abs(norm - 1.0) > 1e-3)
            source.fail(at, field + "/orientation", "a unit quaternion [w, x, y, z] is required (length " +
                                                        formatNumber(norm) + ")");
        fromQuaternion = glm::normalize(glm::dquat(v[0], v[1], v[2], v[3]));
    }
    if (hasDirections) {
        if (!object.contains("fingers") || !object.contains("palm"))
            source.fail(anchors, field, "\"fingers\" and \"palm\" must be given together");
        std::vector<std::string> fingersAt = anchors;
        fingersAt.push_back("\"fingers\"");
        std::vector<std::string> palmAt = anchors;
        palmAt.push_back("\"palm\"");
        const glm::dvec3 fingers = readVector3(source, object["fingers"], fingersAt, field + "/fingers", kDirectionComponentRange);
        const glm::dvec3 palm = readVector3(source, object["palm"], palmAt, field + "/palm", kDirectionComponentRange);
        try {
            fromDirections = orientationFromFingersPalm(fingers, palm);
        } catch (const std::invalid_argument& e) {
            source.fail(palmAt, field + "/palm", e.what());
        }
    }
    if (fromQuaternion && fromDirections) {
        const double degrees = rotationAngleBetween(*fromQuaternion, *fromDirections) * 180.0 / std::numbers::pi;
        if (degrees > 1.0) {
            source.fail(anchors, field,
                        "\"orientation\" and \"fingers\"/\"palm\" disagree by " + formatNumber(degrees) +
                            "°; keep only one of them");
        }
    }
    return fromQuaternion ? *fromQuaternion : *fromDirections;
}

SignContact readSignContact(const JsonSource& source, const nlohmann::json& object,
                            const std::vector<std::string>& anchors, const std::string& pointer) {
    SignContact contact;
    if (!object.is_object() || !object.contains("contact")) return contact;
    std::vector<std::string> at = anchors;
    at.push_back("\"contact\"");
    const nlohmann::json& list = object["contact"];
    const std::string expected = "expected a list of what the sign touches on purpose: [\"hands\"], [\"body\"] or [\"hands\", \"body\"]";
    if (!list.is_array() || list.empty()) source.fail(at, pointer + "/contact", expected);
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string what = list[i].is_string() ? list[i].get<std::string>() : std::string();
        bool& flag = what == "hands" ? contact.hands : contact.body;
        if ((what != "hands" && what != "body") || flag) source.fail(at, pointer + "/contact/" + std::to_string(i), expected);
        flag = true;
    }
    return contact;
}

namespace {

const nlohmann::json& member(const JsonSource& source, const nlohmann::json& object, const std::string& key,
                             const std::vector<std::string>& anchors, const std::string& pointer) {
    if (!object.is_object() || !object.contains(key))
        source.fail(anchors, pointer + "/" + key, "missing field '" + key + "'");
    return object[key];
}

std::string readString(const JsonSource& source, const nlohmann::json& object, const std::string& key,
                       std::vector<std::string> anchors, const std::string& pointer) {
    const nlohmann::json& value = member(source, object, key, anchors, pointer);
    anchors.push_back("\"" + key + "\"");
    if (!value.is_string() || value.get<std::string>().empty())
        source.fail(anchors, pointer + "/" + key, "expected a non-empty string");
    return value.get<std::string>();
}

}  // namespace

VerbLibrary parseVerbLibrary(const JsonSource& source) {
    return withJsonErrors(source, [&] {
    source.checkFormat("signstim-verbs", 1);
    VerbLibrary library;
    library.sourceFile = source.file;
    const nlohmann::json& root = source.root;
    if (!root.is_object() || !root.contains("verbs") || !root["verbs"].is_array() || root["verbs"].empty())
        source.fail({"\"verbs\""}, "/verbs", "expected an object with a non-empty array \"verbs\"");
    std::set<std::string> names;
    for (std::size_t v = 0; v < root["verbs"].size(); ++v) {
        const nlohmann::json& item = root["verbs"][v];
        const std::string pointer = "/verbs/" + std::to_string(v);
        std::vector<std::string> anchors{"\"verbs\""};
        VerbDefinition verb;
        verb.name = readString(source, item, "name", anchors, pointer);
        anchors.push_back("\"" + verb.name + "\"");
        if (!names.insert(verb.name).second) source.fail(anchors, pointer + "/name", "verb '" + verb.name + "' is defined twice");
        for (char c : verb.name)
            if (!((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_'))
                source.fail(anchors, pointer + "/name", "verb names are upper-case glosses (A-Z, 0-9, '-', '_')");
        verb.meaning = item.value("meaning", "");
        verb.movement = item.value("movement", "");
        const std::string inflects = readString(source, item, "inflects", anchors, pointer);
        if (inflects == "subject-object") verb.inflection = Inflection::SubjectObject;
        else if (inflects == "object") verb.inflection = Inflection::ObjectOnly;
        else source.fail({"\"" + verb.name + "\"", "\"inflects\""}, pointer + "/inflects",
                         "expected \"subject-object\" or \"object\", not '" + inflects + "'");
        const nlohmann::json& hands = member(source, item, "hands", anchors, pointer);
        std::vector<std::string> handsAt = anchors;
        handsAt.push_back("\"hands\"");
        if (!hands.is_array() || hands.empty() || hands.size() > 2)
            source.fail(handsAt, pointer + "/hands", "expected [\"right\"] or [\"right\", \"left\"]");
        for (const nlohmann::json& hand : hands) {
            const std::optional<HandSide> side = hand.is_string() ? parseHandSide(hand.get<std::string>()) : std::nullopt;
            if (!side) source.fail(handsAt, pointer + "/hands", "hands are \"right\" or \"left\"");
            verb.hands.push_back(*side);
        }
        if (verb.hands.front() != HandSide::Right || (verb.hands.size() == 2 && verb.hands[1] != HandSide::Left))
            source.fail(handsAt, pointer + "/hands", "the right (dominant) hand comes first: [\"right\"] or [\"right\", \"left\"]");
        if (item.contains("passes")) {
            const nlohmann::json& passes = item["passes"];
            if (!passes.is_number_integer() || passes.get<int>() < 1 || passes.get<int>() > 20)
                source.fail({"\"" + verb.name + "\"", "\"passes\""}, pointer + "/passes", "expected an integer 1..20");
            verb.passes = passes.get<int>();
        }
        verb.contact = readSignContact(source, item, anchors, pointer);
        if (item.contains("handsBySide")) {
            const nlohmann::json& bySide = item["handsBySide"];
            if (!bySide.is_boolean())
                source.fail({"\"" + verb.name + "\"", "\"handsBySide\""}, pointer + "/handsBySide", "expected true or false");
            verb.handsBySide = bySide.get<bool>();
            if (verb.handsBySide && (verb.hands.size() != 2 || verb.objectOnly()))
                source.fail({"\"" + verb.name + "\"", "\"handsBySide\""}, pointer + "/handsBySide",
                            "only a two-handed verb with a subject and an object has a hand for each referent");
        }
        const nlohmann::json& citation = member(source, item, "citation", anchors, pointer);
        for (HandSide side : verb.hands) {
            const std::string handName = toString(side);
            std::vector<std::string> handAt = anchors;
            handAt.push_back("\"citation\"");
            const nlohmann::json& keyframes = member(source, citation, handName, handAt, pointer + "/citation");
            handAt.push_back("\"" + handName + "\"");
            const std::string handPointer = pointer + "/citation/" + handName;
            if (!keyframes.is_array() || keyframes.size() < 2)
                source.fail(handAt, handPointer, "expected an array of at least 2 keyframes");
            std::vector<VerbKeyframe> track;
            std::vector<std::string> keyAt = handAt;
            for (std::size_t k = 0; k < keyframes.size(); ++k) {
                const nlohmann::json& key = keyframes[k];
                const std::string keyPointer = handPointer + "/" + std::to_string(k);
                keyAt.push_back("\"time\"");
                VerbKeyframe frame;
                const nlohmann::json& time = member(source, key, "time", keyAt, keyPointer);
                frame.timeSeconds = source.number(time, keyPointer + "/time", kKeyframeTimeRange);
                if (k == 0 && frame.timeSeconds != 0.0) source.fail(keyAt, keyPointer + "/time", "the first keyframe is at time 0");
                if (k > 0 && !(frame.timeSeconds > track.back().timeSeconds))
                    source.fail(keyAt, keyPointer + "/time", "keyframe times must increase");
                std::vector<std::string> positionAt = keyAt;
                positionAt.push_back("\"position\"");
                frame.pose.positionMm = readVector3(source, member(source, key, "position", keyAt, keyPointer), positionAt,
                                                    keyPointer + "/position", kSigningSpacePositionRange);
                frame.pose.orientation = readOrientation(source, key, keyAt, keyPointer);
                frame.handshape = readString(source, key, "handshape", keyAt, keyPointer);
                frame.handshapeField = keyPointer + "/handshape";
                frame.handshapeLine = source.lineAt(frame.handshapeField);
                track.push_back(std::move(frame));
            }
            if (!verb.citation.empty()) {
                const std::vector<VerbKeyframe>& first = verb.citation.front();
                bool same = first.size() == track.size();
                for (std::size_t k = 0; same && k < track.size(); ++k) same = first[k].timeSeconds == track[k].timeSeconds;
                if (!same) source.fail(handAt, handPointer, "both hands need the same keyframe count and times");
            }
            verb.citation.push_back(std::move(track));
        }
        // The whole verb, all passes, within the keyframe time range: SCOLD's 3 wags of 0.3 s
        // are 0.9 s; 20 passes of a minute would render for 20 minutes.
        const double total = verb.passes * verb.citation.front().back().timeSeconds;
        if (!kKeyframeTimeRange.contains(total))
            source.failAt(pointer + (item.contains("passes") ? "/passes" : "/citation"),
                          "the verb lasts " + formatNumber(total) + " s in all (passes × the last keyframe's time); " +
                              rangeMessage(kKeyframeTimeRange.minimum, kKeyframeTimeRange.maximum, kKeyframeTimeRange.unit, total));
        library.verbs.push_back(std::move(verb));
    }
    return library;
    });
}

VerbLibrary loadVerbLibrary(const std::filesystem::path& path) { return parseVerbLibrary(readJsonFile(path)); }

void checkHandshapeNames(const VerbLibrary& library, const std::function<bool(const std::string&)>& isKnown) {
    for (const VerbDefinition& verb : library.verbs) {
        for (std::size_t h = 0; h < verb.hands.size(); ++h)
            for (std::size_t k = 0; k < verb.citation[h].size(); ++k)
                if (!isKnown(verb.citation[h][k].handshape))
                    throw InputError(library.sourceFile, verb.citation[h][k].handshapeLine,
                                     verb.citation[h][k].handshapeField,
                                     "unknown handshape '" + verb.citation[h][k].handshape + "' in " + verb.name);
    }
}

}  // namespace signstim::stimuli
