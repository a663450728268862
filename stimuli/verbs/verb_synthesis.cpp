#include "stimuli/verbs/verb_synthesis.hpp"

#include "common/number_format.hpp"
#include "stimuli/verbs/signing_space.hpp"
#include "stimuli/verbs/sora.hpp"

#include <algorithm>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace signstim::stimuli {
namespace {

using Json = nlohmann::ordered_json;

double roundedTo(double value, double scale) {
    const double r = std::round(value * scale) / scale;
    return r == 0.0 ? 0.0 : r;
}

std::string positionText(double p) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2f", roundedTo(p, 100));
    std::string text = buffer;
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
    return text;
}

}  // namespace

std::string toString(VerbVersion version) {
    switch (version) {
        case VerbVersion::Point: return "point";
        case VerbVersion::Vector: return "vector";
        case VerbVersion::Animator: return "animator";
        case VerbVersion::Uninflected: return "uninflected";
    }
    return "?";
}

std::optional<VerbVersion> parseVerbVersion(std::string_view text) {
    for (VerbVersion v : {VerbVersion::Point, VerbVersion::Vector, VerbVersion::Animator, VerbVersion::Uninflected})
        if (toString(v) == text) return v;
    return std::nullopt;
}

const HandTrack* VerbPerformance::hand(HandSide side) const {
    for (const HandTrack& track : hands)
        if (track.side == side) return &track;
    return nullptr;
}

HandSample sampleHand(const HandTrack& track, double t) {
    const std::vector<PerformanceKeyframe>& keys = track.keyframes;
    if (keys.empty()) return {};
    if (t <= keys.front().timeSeconds || keys.size() == 1)
        return {keys.front().pose, keys.front().handshape, keys.front().handshape, 0.0};
    if (t >= keys.back().timeSeconds) return {keys.back().pose, keys.back().handshape, keys.back().handshape, 0.0};
    std::size_t i = 1;
    while (keys[i].timeSeconds < t) ++i;
    const PerformanceKeyframe& a = keys[i - 1];
    const PerformanceKeyframe& b = keys[i];
    const double u = (t - a.timeSeconds) / (b.timeSeconds - a.timeSeconds);
    const double eased = u * u * (3.0 - 2.0 * u);
    HandSample sample;
    // About the torso's axis, not along the chord (signing_space.hpp, sweptPathPoint).
    sample.pose.positionMm = sweptPathPoint(a.pose.positionMm, b.pose.positionMm, eased);
    sample.pose.orientation = slerpShortest(a.pose.orientation, b.pose.orientation, eased);
    sample.handshapeFrom = a.handshape;
    sample.handshapeTo = b.handshape;
    sample.handshapeBlend = eased;
    return sample;
}

VerbPerformance performanceFromPoses(const VerbDefinition& verb, VerbVersion version, double subject, double object,
                                     const std::vector<std::vector<HandPose>>& poses) {
    VerbPerformance performance;
    performance.verb = verb.name;
    performance.version = version;
    performance.contact = verb.contact;
    performance.subject = verb.objectOnly() ? 0.0 : subject;
    performance.object = object;
    const std::size_t keyframes = verb.keyframeCount();
    const double pathSeconds = verb.citation[0].back().timeSeconds;
    for (std::size_t h = 0; h < verb.handCount(); ++h) {
        HandTrack track;
        track.side = verb.hands[h];
        for (int pass = 0; pass < verb.passes; ++pass) {
            const bool backward = pass % 2 == 1;
            for (std::size_t j = (pass == 0 ? 0 : 1); j < keyframes; ++j) {
                const std::size_t k = backward ? keyframes - 1 - j : j;
                const double local = backward ? pathSeconds - verb.citation[h][k].timeSeconds : verb.citation[h][k].timeSeconds;
                track.keyframes.push_back({pass * pathSeconds + local, poses[h][k], verb.citation[h][k].handshape,
                                           verb.citation[h][k].handshapeLine, verb.citation[h][k].handshapeField});
            }
        }
        performance.hands.push_back(std::move(track));
    }
    performance.durationSeconds = verb.passes * pathSeconds;
    return performance;
}

std::string animatorFileName(const VerbDefinition& verb, double subject, double object) {
    if (verb.objectOnly()) return verb.name + "_o" + positionText(object) + ".json";
    return verb.name + "_s" + positionText(subject) + "_o" + positionText(object) + ".json";
}

namespace {

bool finite(const HandPose& pose) {
    return std::isfinite(pose.positionMm.x) && std::isfinite(pose.positionMm.y) && std::isfinite(pose.positionMm.z) &&
           std::isfinite(pose.orientation.w) && std::isfinite(pose.orientation.x) && std::isfinite(pose.orientation.y) &&
           std::isfinite(pose.orientation.z);
}

// A model's prediction must be a pose in the signing space: coefficients within their ranges
// can still add up, at some (s, o), to a position no arm reaches.
void checkPredictedPoses(const VerbModel& model, const std::string& modelsFile, const VerbDefinition& verb,
                         double subject, double object, const std::vector<std::vector<HandPose>>& poses) {
    for (std::size_t h = 0; h < poses.size(); ++h)
        for (std::size_t k = 0; k < poses[h].size(); ++k) {
            const HandPose& pose = poses[h][k];
            bool inside = finite(pose);
            for (int axis = 0; axis < 3 && inside; ++axis) inside = kSigningSpacePositionRange.contains(pose.positionMm[axis]);
            if (inside) continue;
            const glm::dvec3& p = pose.positionMm;
            throw InputError(modelsFile, model.sourceLine, "verb " + verb.name,
                             "the model predicts, for subject " + formatNumber(subject) + " object " + formatNumber(object) +
                                 ", the " + toString(verb.hands[h]) + " hand at keyframe " + std::to_string(k) + " at (" +
                                 formatNumber(p.x) + ", " + formatNumber(p.y) + ", " + formatNumber(p.z) +
                                 ") mm; positions must be finite and within " +
                                 formatNumber(kSigningSpacePositionRange.minimum) + " to " +
                                 formatNumber(kSigningSpacePositionRange.maximum) +
                                 " mm: retrain with `signstim train`");
        }
}

void checkHandshapes(const VerbPerformance& performance, const HandshapeLibrary& library) {
    for (const HandTrack& track : performance.hands)
        for (const PerformanceKeyframe& key : track.keyframes) {
            if (library.find(key.handshape)) continue;
            std::string names;
            for (const Handshape& shape : library.shapes) names += (names.empty() ? "" : " ") + shape.name;
            throw InputError(performance.handshapeFile, key.handshapeLine, key.handshapeField,
                             "unknown handshape '" + key.handshape + "' (known in " + library.file + ": " + names + ")");
        }
}

}  // namespace

VerbPerformance synthesizeVerb(const VerbSources& sources, const std::string& verbName, VerbVersion version,
                               double subject, double object, const std::string& subjectField,
                               const std::string& objectField) {
    VerbPerformance performance =
        synthesizeUncheckedVerb(sources, verbName, version, subject, object, subjectField, objectField);
    if (sources.handshapes) checkHandshapes(performance, *sources.handshapes);
    return performance;
}

VerbPerformance synthesizeUncheckedVerb(const VerbSources& sources, const std::string& verbName, VerbVersion version,
                                        double subject, double object, const std::string& subjectField,
                                        const std::string& objectField) {
    const VerbDefinition& verb = sources.verbs->get(verbName);
    checkArcPosition(object, "<command line>", objectField);
    if (!verb.objectOnly()) checkArcPosition(subject, "<command line>", subjectField);
    switch (version) {
        case VerbVersion::Uninflected: {
            std::vector<std::vector<HandPose>> poses;
            for (const auto& track : verb.citation) {
                poses.emplace_back();
                for (const VerbKeyframe& key : track) poses.back().push_back(key.pose);
            }
            VerbPerformance performance = performanceFromPoses(verb, version, subject, object, poses);
            performance.handshapeFile = sources.verbs->sourceFile;
            return performance;
        }
        case VerbVersion::Point:
        case VerbVersion::Vector: {
            const VerbModel* model = sources.models ? sources.models->find(verb.name) : nullptr;
            if (!model)
                throw InputError(sources.models && !sources.models->sourceFile.empty() ? sources.models->sourceFile
                                                                                        : std::string("<verb models>"),
                                 0, "verb",
                                 "no trained model for " + verb.name + "; run `signstim train CORPUS.csv --out MODELS.json`");
            // A verb whose hands come each from its referent's side (verbs.json "handsBySide",
            // MEET): where the subject is left of the object, the pair the other way round, so
            // the arms do not cross and the hands do not start in each other (issue 21).
            const bool swapped = verb.handsBySide && subject < object;
            const double asked = swapped ? object : subject, toward = swapped ? subject : object;
            const auto poses = version == VerbVersion::Point ? predictPoint(*model, asked, toward)
                                                             : predictVector(*model, asked, toward);
            checkPredictedPoses(*model, sources.models->sourceFile, verb, asked, toward, poses);
            VerbPerformance performance = performanceFromPoses(verb, version, subject, object, poses);
            performance.handshapeFile = sources.verbs->sourceFile;
            return performance;
        }
        case VerbVersion::Animator: {
            const std::filesystem::path file = sources.animatorDir / animatorFileName(verb, subject, object);
            if (!std::filesystem::exists(file))
                throw MissingAnimatorFile(file.string(),
                                 "no animator keyframes for " + verb.name +
                                     (verb.objectOnly() ? "" : " subject " + positionText(subject)) + " object " +
                                     positionText(object) +
                                     ": author this file (start from `signstim verb ... --version point --json`; "
                                     "see docs/verbs.md)",
                                         file.string());
            return loadAnimatorPerformance(file, verb, subject, object);
        }
    }
    throw InputError("<command line>", 0, "--version", "unknown version");
}

std::string formatPerformanceJson(const VerbPerformance& performance) {
    Json root = Json::object();
    root["format"] = "signstim-verb-keyframes";
    root["verb"] = performance.verb;
    root["version"] = toString(performance.version);
    root["subject"] = roundedTo(performance.subject, 1e6);
    root["object"] = roundedTo(performance.object, 1e6);
    root["frame"] = "signing space: origin chest centre, +x signer's right, +y up, +z forward; mm. orientation: "
                    "unit quaternion [w, x, y, z] of the palm frame; fingers (+z) and palm (+x) directions given for "
                    "reading and editing (keep them consistent or delete one)";
    root["durationSeconds"] = roundedTo(performance.durationSeconds, 1e6);
    if (performance.draft) {
        root["draft"] = true;
        root["about"] = "a draft from the point model (signstim animator draft): edit the keyframes, then delete "
                        "\"draft\" and this line; a study refuses drafts unless --allow-draft-animator";
    }
    Json hands = Json::object();
    for (const HandTrack& track : performance.hands) {
        Json keys = Json::array();
        for (const PerformanceKeyframe& key : track.keyframes) {
            Json k = Json::object();
            k["time"] = roundedTo(key.timeSeconds, 1e6);
            const glm::dvec3& p = key.pose.positionMm;
            k["position"] = Json::array({roundedTo(p.x, 100), roundedTo(p.y, 100), roundedTo(p.z, 100)});
            glm::dquat q = glm::normalize(key.pose.orientation);
            if (q.w < 0) q = -q;
            k["orientation"] = Json::array({roundedTo(q.w, 1e6), roundedTo(q.x, 1e6), roundedTo(q.y, 1e6), roundedTo(q.z, 1e6)});
            const glm::dvec3 f = fingersDirection(q);
            const glm::dvec3 palm = palmDirection(q);
            k["fingers"] = Json::array({roundedTo(f.x, 1e4), roundedTo(f.y, 1e4), roundedTo(f.z, 1e4)});
            k["palm"] = Json::array({roundedTo(palm.x, 1e4), roundedTo(palm.y, 1e4), roundedTo(palm.z, 1e4)});
            k["handshape"] = key.handshape;
            keys.push_back(k);
        }
        hands[toString(track.side)] = keys;
    }
    root["hands"] = hands;
    // One keyframe per line keeps the file easy to edit by hand.
    std::string text = root.dump(2);
    return text + "\n";
}

std::string formatAnimatorDraft(const VerbSources& sources, const std::string& verb, double subject, double object) {
    VerbPerformance performance = synthesizeVerb(sources, verb, VerbVersion::Point, subject, object);
    performance.draft = true;
    return formatPerformanceJson(performance);
}

bool sameKeyframes(const VerbPerformance& a, const VerbPerformance& b) {
    // The precision formatPerformanceJson writes: 0.01 mm, 1e-6 of a quaternion or a second.
    constexpr double kMm = 0.011, kUnit = 2e-6;
    if (a.hands.size() != b.hands.size()) return false;
    for (std::size_t h = 0; h < a.hands.size(); ++h) {
        const auto& ka = a.hands[h].keyframes;
        const auto& kb = b.hands[h].keyframes;
        if (a.hands[h].side != b.hands[h].side || ka.size() != kb.size()) return false;
        for (std::size_t k = 0; k < ka.size(); ++k) {
            if (std::abs(ka[k].timeSeconds - kb[k].timeSeconds) > kUnit || ka[k].handshape != kb[k].handshape) return false;
            if (glm::length(ka[k].pose.positionMm - kb[k].pose.positionMm) > kMm) return false;
            // q and -q are the same rotation.
            if (1.0 - std::abs(glm::dot(glm::normalize(ka[k].pose.orientation), glm::normalize(kb[k].pose.orientation))) > 4 * kUnit)
                return false;
        }
    }
    return true;
}

VerbPerformance loadAnimatorPerformance(const std::filesystem::path& file, const VerbDefinition& verb, double subject,
                                        double object) {
    const JsonSource source = readJsonFile(file);
    return withJsonErrors(source, [&] { return parseAnimatorPerformance(source, verb, subject, object); });
}

VerbPerformance parseAnimatorPerformance(const JsonSource& source, const VerbDefinition& verb, double subject,
                                         double object) {
    const nlohmann::json& root = source.root;
    if (!root.is_object()) source.fail({}, "", "expected a JSON object");
    if (const auto format = root.find("format"); format != root.end() && *format != "signstim-verb-keyframes")
        source.failAt("/format", "expected \"signstim-verb-keyframes\", got " + format->dump() + " (a file of another kind?)");
    if (const auto version = root.find("version");
        version != root.end() && !(version->is_string() && parseVerbVersion(version->get<std::string>())))
        source.failAt("/version", "expected the version the keyframes were made as: \"point\", \"vector\", \"animator\" "
                                  "or \"uninflected\", got " + version->dump());
    if (const auto draft = root.find("draft"); draft != root.end() && !draft->is_boolean())
        source.failAt("/draft", "expected true (a starting point no animator has worked on yet) or false, got " +
                                    draft->dump());
    if (root.value("verb", "") != verb.name)
        source.fail({"\"verb\""}, "/verb", "the file is for verb '" + root.value("verb", "") + "', expected " + verb.name);
    const auto positionMatches = [&](const char* key, double expected) {
        if (!root.contains(key) || !root[key].is_number() || std::abs(root[key].get<double>() - expected) > 1e-6)
            source.fail({std::string("\"") + key + "\""}, std::string("/") + key,
                        std::string("expected ") + key + " " + positionText(expected) + " (the file name says so)" +
                            (root.contains(key) && root[key].is_number() ? ", got " + formatNumber(root[key].get<double>())
                                                                          : std::string()));
    };
    if (!verb.objectOnly()) positionMatches("subject", subject);
    positionMatches("object", object);
    if (!root.contains("hands") || !root["hands"].is_object()) source.fail({"\"hands\""}, "/hands", "expected {\"right\": [...], ...}");
    VerbPerformance performance;
    performance.verb = verb.name;
    performance.version = VerbVersion::Animator;
    performance.contact = verb.contact;
    performance.subject = verb.objectOnly() ? 0.0 : subject;
    performance.object = object;
    performance.handshapeFile = source.file;
    performance.draft = root.value("draft", false);
    for (auto it = root["hands"].begin(); it != root["hands"].end(); ++it)
        if (!parseHandSide(it.key()) || verb.handIndex(*parseHandSide(it.key())) < 0)
            source.fail({"\"hands\"", "\"" + it.key() + "\""}, "/hands/" + it.key(),
                        verb.name + " uses the hands: " + (verb.handCount() == 2 ? "right, left" : "right"));
    for (HandSide side : verb.hands) {
        const std::string name = toString(side);
        const std::vector<std::string> handAt{"\"hands\"", "\"" + name + "\""};
        const std::string pointer = "/hands/" + name;
        if (!root["hands"].contains(name)) source.fail({"\"hands\""}, pointer, verb.name + " needs the " + name + " hand");
        const nlohmann::json& keys = root["hands"][name];
        if (!keys.is_array() || keys.size() < 2) source.fail(handAt, pointer, "expected at least 2 keyframes");
        HandTrack track;
        track.side = side;
        std::vector<std::string> keyAt = handAt;
        for (std::size_t k = 0; k < keys.size(); ++k) {
            keyAt.push_back("\"time\"");
            const std::string keyPointer = pointer + "/" + std::to_string(k);
            const nlohmann::json& key = keys[k];
            if (!key.is_object() || !key.contains("time") || !key["time"].is_number())
                source.fail(keyAt, keyPointer + "/time", "expected a time in seconds");
            PerformanceKeyframe frame;
            frame.timeSeconds = source.number(key["time"], keyPointer + "/time", kKeyframeTimeRange);
            if ((k == 0 && frame.timeSeconds != 0.0) || (k > 0 && !(frame.timeSeconds > track.keyframes.back().timeSeconds)))
                source.fail(keyAt, keyPointer + "/time", "times start at 0 and increase");
            std::vector<std::string> positionAt = keyAt;
            positionAt.push_back("\"position\"");
            if (!key.contains("position")) source.fail(keyAt, keyPointer + "/position", "missing field 'position'");
            frame.pose.positionMm = readVector3(source, key["position"], positionAt, keyPointer + "/position", kSigningSpacePositionRange);
            frame.pose.orientation = readOrientation(source, key, keyAt, keyPointer);
            if (!key.contains("handshape") || !key["handshape"].is_string() || key["handshape"].get<std::string>().empty())
                source.fail(keyAt, keyPointer + "/handshape", "expected a handshape name");
            frame.handshape = key["handshape"].get<std::string>();
            frame.handshapeField = keyPointer + "/handshape";
            frame.handshapeLine = source.lineAt(frame.handshapeField);
            track.keyframes.push_back(std::move(frame));
        }
        performance.durationSeconds = std::max(performance.durationSeconds, track.keyframes.back().timeSeconds);
        performance.hands.push_back(std::move(track));
    }
    return performance;
}

}  // namespace signstim::stimuli
