#include "stimuli/verbs/reference_performer.hpp"

#include "common/random.hpp"
#include "stimuli/verbs/signing_space.hpp"
#include "stimuli/verbs/sora.hpp"

#include <cmath>
#include <numbers>

namespace signstim::stimuli {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

glm::dquat aboutVertical(double angleRad) { return glm::dquat(std::cos(0.5 * angleRad), 0.0, std::sin(0.5 * angleRad), 0.0); }

// Heading of a horizontal direction: 0 = forward (+z), positive toward the signer's right.
double heading(const glm::dvec3& v) { return std::atan2(v.x, v.z); }

double readNumber(const JsonSource& source, const nlohmann::json& object, const std::string& key,
                  const std::vector<std::string>& anchors, const std::string& pointer, double fallback,
                  const NumberRange& range) {
    if (!object.contains(key)) return fallback;
    const nlohmann::json& value = object[key];
    if (!value.is_number()) {
        std::vector<std::string> at = anchors;
        at.push_back("\"" + key + "\"");
        source.fail(at, pointer + "/" + key, "expected a number");
    }
    return source.number(value, pointer + "/" + key, range);
}

// [D] ranges of the performer's parameters (docs/verbs.md "Ranges of numbers"): gains are
// fractions of the arc angle or of the reach, a few times either way at most.
constexpr NumberRange kGainRange{-10.0, 10.0, ""};
constexpr NumberRange kReachGainRange{0.1, 10.0, ""};
constexpr NumberRange kNoisePositionRange{0.0, 100.0, "mm"};
constexpr NumberRange kNoiseOrientationRange{0.0, 90.0, "degrees"};
constexpr NumberRange kPathFractionRange{0.0, 1.0, ""};

}  // namespace

ReferencePerformer parseReferencePerformer(const JsonSource& source, const VerbLibrary& verbs) {
    return withJsonErrors(source, [&] {
    source.checkFormat("signstim-reference-performer", 1);
    const nlohmann::json& root = source.root;
    ReferencePerformer performer;
    if (!root.is_object() || root.value("synthetic", false) != true)
        source.fail({"\"synthetic\""}, "/synthetic", "the reference performer must say \"synthetic\": true");
    if (root.contains("seed")) {
        if (!root["seed"].is_number_unsigned()) source.fail({"\"seed\""}, "/seed", "expected an unsigned integer");
        performer.seed = root["seed"].get<std::uint64_t>();
    }
    if (root.contains("description") && root["description"].is_array())
        for (const auto& line : root["description"])
            if (line.is_string()) performer.description.push_back(line.get<std::string>());
    if (root.contains("torsoPivotMm"))
        performer.torsoPivotMm = readVector3(source, root["torsoPivotMm"], {"\"torsoPivotMm\""}, "/torsoPivotMm",
                                             kSigningSpacePositionRange);
    if (!root.contains("arcPositions") || !root["arcPositions"].is_array() || root["arcPositions"].size() < 2)
        source.fail({"\"arcPositions\""}, "/arcPositions", "expected an array of arc positions");
    for (const auto& p : root["arcPositions"]) {
        if (!p.is_number()) source.fail({"\"arcPositions\""}, "/arcPositions", "expected numbers");
        try {
            checkArcPosition(p.get<double>(), source.file, "/arcPositions");
        } catch (const InputError& e) {
            source.fail({"\"arcPositions\""}, "/arcPositions", e.detail());
        }
        performer.arcPositions.push_back(p.get<double>());
    }
    const nlohmann::json bias = root.value("bias", nlohmann::json::object());
    if (bias.contains("offsetMm")) performer.biasOffsetMm = readVector3(source, bias["offsetMm"], {"\"bias\"", "\"offsetMm\""}, "/bias/offsetMm",
                                                                        kSigningSpacePositionRange);
    performer.biasReachGain = readNumber(source, bias, "reachGain", {"\"bias\""}, "/bias", 1.0, kReachGainRange);
    performer.biasYawDeg = readNumber(source, bias, "yawDeg", {"\"bias\""}, "/bias", 0.0, kAngleDegreesRange);
    const nlohmann::json noise = root.value("noise", nlohmann::json::object());
    performer.noisePositionMm = readNumber(source, noise, "positionMm", {"\"noise\""}, "/noise", 0.0, kNoisePositionRange);
    performer.noiseOrientationDeg = readNumber(source, noise, "orientationDeg", {"\"noise\""}, "/noise", 0.0, kNoiseOrientationRange);
    if (performer.noisePositionMm < 0 || performer.noiseOrientationDeg < 0)
        source.fail({"\"noise\""}, "/noise", "noise levels must be >= 0");

    if (!root.contains("verbs") || !root["verbs"].is_object()) source.fail({"\"verbs\""}, "/verbs", "expected an object of verbs");
    for (const VerbDefinition& verb : verbs.verbs) {
        const std::string pointer = "/verbs/" + verb.name;
        if (!root["verbs"].contains(verb.name))
            source.fail({"\"verbs\""}, pointer, "no performer rules for verb " + verb.name + " (scenes/verbs.json has it)");
        const nlohmann::json& entry = root["verbs"][verb.name];
        std::vector<std::vector<PerformerRule>> perHand;
        for (std::size_t h = 0; h < verb.hands.size(); ++h) {
            const std::string hand = toString(verb.hands[h]);
            const std::vector<std::string> handAt{"\"verbs\"", "\"" + verb.name + "\"", "\"" + hand + "\""};
            if (!entry.contains(hand) || !entry[hand].is_array() || entry[hand].size() != verb.keyframeCount())
                source.fail(handAt, pointer + "/" + hand,
                            "expected one rule per keyframe (" + std::to_string(verb.keyframeCount()) + ")");
            std::vector<PerformerRule> rules;
            for (std::size_t k = 0; k < verb.keyframeCount(); ++k) {
                const nlohmann::json& item = entry[hand][k];
                const std::string rulePointer = pointer + "/" + hand + "/" + std::to_string(k);
                if (!item.is_object()) source.fail(handAt, rulePointer, "expected an object");
                PerformerRule rule;
                if (item.contains("rigidWithRight")) {
                    rule.kind = PerformerRule::Kind::RigidWithRight;
                    if (h == 0 || !item["rigidWithRight"].is_number_integer() || item["rigidWithRight"].get<int>() < 0 ||
                        item["rigidWithRight"].get<std::size_t>() >= verb.keyframeCount())
                        source.fail(handAt, rulePointer + "/rigidWithRight", "a left-hand rule naming a right-hand keyframe");
                    rule.rightKeyframe = item["rigidWithRight"].get<int>();
                } else if (item.contains("followsRightPath")) {
                    rule.kind = PerformerRule::Kind::FollowsRightPath;
                    rule.pathFraction = readNumber(source, item, "followsRightPath", handAt, rulePointer, 0.0, kPathFractionRange);
                    if (h == 0) source.fail(handAt, rulePointer, "only the left hand can follow the right hand's path");
                } else {
                    rule.towardSubject = readNumber(source, item, "towardSubject", handAt, rulePointer, 0.0, kGainRange);
                    rule.towardObject = readNumber(source, item, "towardObject", handAt, rulePointer, 0.0, kGainRange);
                    rule.reachMm = readNumber(source, item, "reachMm", handAt, rulePointer, 0.0, kSigningSpacePositionRange);
                    if (item.contains("yaw")) {
                        if (item["yaw"] != "path") source.fail(handAt, rulePointer + "/yaw", "\"yaw\" can only be \"path\"");
                        rule.yawFollowsPath = true;
                    }
                    rule.yawTowardSubject = readNumber(source, item, "yawTowardSubject", handAt, rulePointer, 0.0, kGainRange);
                    rule.yawTowardObject = readNumber(source, item, "yawTowardObject", handAt, rulePointer, 0.0, kGainRange);
                    if (verb.objectOnly() && (rule.towardSubject != 0.0 || rule.yawTowardSubject != 0.0))
                        source.fail(handAt, rulePointer, verb.name + " inflects for the object only: no subject terms");
                }
                rules.push_back(rule);
            }
            perHand.push_back(std::move(rules));
        }
        performer.rules[verb.name] = std::move(perHand);
    }
    return performer;
    });
}

ReferencePerformer loadReferencePerformer(const std::filesystem::path& path, const VerbLibrary& verbs) {
    return parseReferencePerformer(readJsonFile(path), verbs);
}

std::vector<std::vector<HandPose>> performVerb(const ReferencePerformer& performer, const VerbDefinition& verb,
                                               double subject, double object) {
    checkArcPosition(object, "<reference performer>", "object");
    if (verb.objectOnly()) subject = 0.0;  // the subject does not change an object-only verb
    checkArcPosition(subject, "<reference performer>", "subject");
    const auto rulesIt = performer.rules.find(verb.name);
    if (rulesIt == performer.rules.end()) throw InputError("<reference performer>", 0, "verb", "no rules for " + verb.name);
    const std::vector<std::vector<PerformerRule>>& rules = rulesIt->second;
    const double psiS = arcAngleRadians(subject);
    const double psiO = arcAngleRadians(object);
    const double separation = 0.5 * (subject - object);
    const std::size_t keyframes = verb.keyframeCount();
    std::vector<std::vector<HandPose>> result(verb.handCount(), std::vector<HandPose>(keyframes));

    const auto arcPose = [&](const VerbKeyframe& citation, const PerformerRule& rule) {
        const double angle = rule.towardSubject * psiS + rule.towardObject * psiO;
        glm::dvec3 relative = aboutVertical(angle) * (citation.pose.positionMm - performer.torsoPivotMm);
        const glm::dvec3 horizontal(relative.x, 0.0, relative.z);
        if (glm::length(horizontal) > 1e-9) relative += rule.reachMm * separation * separation * glm::normalize(horizontal);
        const double yaw = rule.yawTowardSubject * psiS + rule.yawTowardObject * psiO;
        return HandPose{performer.torsoPivotMm + relative, aboutVertical(yaw) * citation.pose.orientation};
    };

    // The right hand first: every other rule refers to it.
    for (std::size_t k = 0; k < keyframes; ++k) result[0][k] = arcPose(verb.citation[0][k], rules[0][k]);
    const glm::dvec3 citationStart = verb.citation[0].front().pose.positionMm;
    const glm::dvec3 citationEnd = verb.citation[0].back().pose.positionMm;
    const glm::dvec3 start = result[0].front().positionMm;
    const glm::dvec3 end = result[0].back().positionMm;
    const double citationHeading = heading(citationEnd - citationStart);
    const double pathTurn = heading(end - start) - citationHeading;
    for (std::size_t k = 0; k < keyframes; ++k)
        if (rules[0][k].yawFollowsPath)
            result[0][k].orientation = aboutVertical(pathTurn) * verb.citation[0][k].pose.orientation;

    for (std::size_t h = 1; h < verb.handCount(); ++h) {
        for (std::size_t k = 0; k < keyframes; ++k) {
            const PerformerRule& rule = rules[h][k];
            const VerbKeyframe& citation = verb.citation[h][k];
            HandPose& pose = result[h][k];
            switch (rule.kind) {
                case PerformerRule::Kind::Arc:
                    pose = arcPose(citation, rule);
                    if (rule.yawFollowsPath) pose.orientation = aboutVertical(pathTurn) * citation.pose.orientation;
                    break;
                case PerformerRule::Kind::RigidWithRight: {
                    const std::size_t r = static_cast<std::size_t>(rule.rightKeyframe);
                    const HandPose& rightCitation = verb.citation[0][r].pose;
                    const HandPose& rightNow = result[0][r];
                    const glm::dquat change = rightNow.orientation * glm::inverse(rightCitation.orientation);
                    pose.positionMm = rightNow.positionMm + change * (citation.pose.positionMm - rightCitation.positionMm);
                    pose.orientation = glm::normalize(change * citation.pose.orientation);
                    break;
                }
                case PerformerRule::Kind::FollowsRightPath: {
                    const double f = rule.pathFraction;
                    const glm::dvec3 citationOrigin = (1.0 - f) * citationStart + f * citationEnd;
                    const glm::dvec3 origin = (1.0 - f) * start + f * end;
                    const glm::dquat turn = aboutVertical(pathTurn);
                    pose.positionMm = origin + turn * (citation.pose.positionMm - citationOrigin);
                    pose.orientation = glm::normalize(turn * citation.pose.orientation);
                    break;
                }
            }
        }
    }
    return result;
}

Corpus generateReferenceCorpus(const ReferencePerformer& performer, const VerbLibrary& verbs) {
    Corpus corpus;
    corpus.sourceFile = "<reference performer>";
    corpus.comments.push_back(" SYNTHETIC DATA: the signstim reference corpus, generated by a parametric performer,");
    corpus.comments.push_back(" not recorded from a human signer. Regenerate: signstim reference-corpus --out FILE.");
    for (const std::string& line : performer.description) corpus.comments.push_back(" " + line);
    char buffer[256];
    std::snprintf(buffer, sizeof buffer,
                  " performer: seed %llu; bias offset (%.1f, %.1f, %.1f) mm, reach gain %.3f, yaw %.1f deg; "
                  "noise %.1f mm, %.1f deg per axis",
                  static_cast<unsigned long long>(performer.seed), performer.biasOffsetMm.x, performer.biasOffsetMm.y,
                  performer.biasOffsetMm.z, performer.biasReachGain, performer.biasYawDeg, performer.noisePositionMm,
                  performer.noiseOrientationDeg);
    corpus.comments.emplace_back(buffer);
    corpus.comments.push_back(
        " frame: torso-fixed signing space, origin chest centre, +x signer's right, +y up, +z forward; "
        "x, y, z in millimetres; roll, pitch, yaw in degrees, R = Rz(yaw) Ry(pitch) Rx(roll)");
    const glm::dquat yawBias = aboutVertical(performer.biasYawDeg * kDegree);
    for (const VerbDefinition& verb : verbs.verbs) {
        // One stream per verb: adding or editing one verb leaves the others' examples unchanged.
        SplitMix64 rng(mixSeed(performer.seed, hashString(verb.name)));
        long number = 0;
        for (double subject : performer.arcPositions) {
            for (double object : performer.arcPositions) {
                if (subject == object) continue;
                CorpusExample example;
                example.verb = verb.name;
                example.example = ++number;
                example.subject = subject;
                example.object = object;
                example.poses = performVerb(performer, verb, subject, object);
                for (auto& track : example.poses) {
                    for (HandPose& pose : track) {
                        pose.positionMm = performer.torsoPivotMm +
                                          performer.biasReachGain * (pose.positionMm - performer.torsoPivotMm) +
                                          performer.biasOffsetMm;
                        pose.orientation = yawBias * pose.orientation;
                        const double nx = rng.normal(), ny = rng.normal(), nz = rng.normal();
                        pose.positionMm += performer.noisePositionMm * glm::dvec3(nx, ny, nz);
                        const double rx = rng.normal(), ry = rng.normal(), rz = rng.normal();
                        const Sora jitter = performer.noiseOrientationDeg * kDegree * glm::dvec3(rx, ry, rz);
                        pose.orientation = glm::normalize(soraToQuaternion(jitter) * pose.orientation);
                    }
                }
                corpus.examples.push_back(std::move(example));
            }
        }
    }
    return corpus;
}

}  // namespace signstim::stimuli
