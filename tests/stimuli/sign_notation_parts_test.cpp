// The sign notation's parts and places (docs/lexicon.md): a still base hand after its last
// part, a zigzag's corners passed through, a named finger of the other hand as a place, a
// relation per part (compounds like STUDENT). Lexicons written here are synthetic.
#include "hand/contact.hpp"
#include "hand/hand_model.hpp"
#include "stimuli/story/sign_notation_check.hpp"
#include "stimuli/story/timeline.hpp"
#include "stimuli/verbs/sora.hpp"
#include "tests/stimuli/notation_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace signstim::stimuli {
namespace {

using notation_fixture::model;
using notation_fixture::shapes;
using notation_fixture::lexiconWith;
using notation_fixture::parse;

std::vector<TimelineKey> track(const LexiconSign& sign, std::size_t h) {
    std::vector<TimelineKey> keys;
    for (std::size_t k = 0; k < sign.keyframes[h].size(); ++k) {
        TimelineKey key;
        key.timeSeconds = sign.keyframes[h][k].timeSeconds;
        key.pose = sign.keyframes[h][k].pose;
        key.passThrough = sign.passThrough[h][k];
        keys.push_back(key);
    }
    return keys;
}

glm::dvec3 positionAt(const std::vector<TimelineKey>& keys, double t) {
    const TimelineSample s = sampleTrack(keys, t);
    return glm::mix(s.from->pose.positionMm, s.to->pose.positionMm, s.blend);
}

const NotationCheck* findCheck(const std::vector<NotationCheck>& checks, const std::string& prefix) {
    for (const NotationCheck& c : checks)
        if (c.name.rfind(prefix, 0) == 0) return &c;
    return nullptr;
}

const std::string kBase = R"("base": {"handshape": "B", "fingers": "forward", "palm": "up", "at": "neutral"})";

// Issue 22 follow-up, limit 1: the last part had no base hand, and the compiler read an empty
// handshape (and a pose it did not have).
TEST(SignNotationParts, ABaseHandWithoutALastPartStaysWhereItWas) {
    const Lexicon lexicon = parse(lexiconWith(R"({"hands": "base", "parts": [
        {"seconds": 0.4, "handshape": "1", "fingers": "forward", "palm": "down", "at": "hand:palm", "offset": [0, 30, 0],
         "touch": "index-tip", )" + kBase + R"(},
        {"seconds": 0.4, "transition": 0.2, "handshape": "1", "fingers": "up", "palm": "forward", "at": "chin", "offset": [0, 0, 60]}]})"));
    const LexiconSign& sign = lexicon.signs.front();
    ASSERT_EQ(sign.keyframes.size(), 2u);
    const std::vector<VerbKeyframe>& left = sign.keyframes[1];
    ASSERT_FALSE(left.empty());
    for (const VerbKeyframe& k : left) {
        EXPECT_EQ(k.handshape, "B");
        EXPECT_LT(glm::distance(k.pose.positionMm, left.front().pose.positionMm), 1e-9) << "at " << k.timeSeconds;
    }
    EXPECT_GE(left.back().timeSeconds, sign.keyframes[0].back().timeSeconds - 1e-9);
    const std::vector<NotationCheck> checks = checkSignNotation(sign, lexicon, shapes(), model());
    EXPECT_TRUE(findCheck(checks, "base hand still")->ok) << findCheck(checks, "base hand still")->detail;
}

// Limit 2: a zigzag is one path movement; its corners are turned through, never held.
TEST(SignNotationParts, AZigzagTurnsThroughItsCornersWithoutStopping) {
    const Lexicon lexicon = parse(lexiconWith(R"({"parts": [{"seconds": 0.7, "handshape": "1", "fingers": "up",
        "palm": "forward", "at": "neutral-right", "path": {"shape": "zigzag", "direction": "down", "size": 200, "side": "left"},
        "repeat": {"count": 2}}]})"));
    const LexiconSign& sign = lexicon.signs.front();
    const std::vector<TimelineKey> keys = track(sign, 0);
    int corners = 0;
    for (std::size_t k = 1; k + 1 < keys.size(); ++k) {
        if (!keys[k].passThrough) continue;
        ++corners;
        const double t = keys[k].timeSeconds, dt = 1e-4;
        const double speed = glm::distance(positionAt(keys, t + dt), positionAt(keys, t - dt)) / (2.0 * dt);
        EXPECT_GT(speed, 50.0) << "the hand stops at corner " << k;  // mm/s
    }
    EXPECT_EQ(corners, 6);  // two corners on each of the three passes (forth, back, forth)
    // It zigzags: a corner lies off the chord to each side.
    EXPECT_GT(std::abs(keys[1].pose.positionMm.x - keys[0].pose.positionMm.x), 15.0);
    EXPECT_LT((keys[1].pose.positionMm.x - keys[0].pose.positionMm.x) * (keys[2].pose.positionMm.x - keys[0].pose.positionMm.x), 0.0);
    const std::vector<NotationCheck> checks = checkSignNotation(sign, lexicon, shapes(), model());
    ASSERT_NE(findCheck(checks, "via points passed"), nullptr);
    EXPECT_TRUE(findCheck(checks, "via points passed")->ok) << findCheck(checks, "via points passed")->detail;
    EXPECT_TRUE(findCheck(checks, "repetitions")->ok) << findCheck(checks, "repetitions")->detail;
}

// Limit 3: a named finger of the other hand is a place the check finds.
TEST(SignNotationParts, ANamedFingerOfTheOtherHandIsThePlaceFound) {
    const Lexicon lexicon = parse(lexiconWith(R"({"hands": "base", "parts": [{"seconds": 0.5, "handshape": "1",
        "fingers": "forward", "palm": "down", "at": "hand:index", "touch": "index-tip",
        "base": {"handshape": "1", "fingers": "forward", "palm": "down", "at": "neutral"},
        "contact": [{"when": "start"}]}]})"));
    const std::vector<NotationCheck> checks = checkSignNotation(lexicon.signs.front(), lexicon, shapes(), model());
    const NotationCheck* place = findCheck(checks, "place");
    ASSERT_NE(place, nullptr);
    EXPECT_TRUE(place->ok) << place->detail;
    EXPECT_NE(place->detail.find("hand:index"), std::string::npos) << place->detail;
}

// Limit 4: each part may name its own relation; a one-handed part holds the left hand still.
TEST(SignNotationParts, EachPartKeepsItsOwnRelation) {
    const Lexicon lexicon = parse(lexiconWith(R"({"hands": "base", "parts": [
        {"seconds": 0.3, "handshape": "1", "fingers": "forward", "palm": "down", "at": "hand:palm", "offset": [0, 30, 0],
         "touch": "index-tip", )" + kBase + R"(},
        {"hands": "one", "seconds": 0.3, "transition": 0.15, "handshape": "1", "fingers": "up", "palm": "forward", "at": "chin",
         "offset": [0, 0, 80]},
        {"hands": "mirrored", "seconds": 0.4, "transition": 0.2, "handshape": "B", "fingers": "forward", "palm": "left",
         "at": "neutral-right", "path": {"shape": "straight", "direction": "down", "size": 120}}]})"));
    const LexiconSign& sign = lexicon.signs.front();
    ASSERT_EQ(sign.notation->parts.size(), 3u);
    EXPECT_EQ(sign.notation->parts[0].hands, HandRelation::Base);
    EXPECT_EQ(sign.notation->parts[1].hands, HandRelation::One);
    EXPECT_EQ(sign.notation->parts[2].hands, HandRelation::Mirrored);
    const std::vector<AslLexCode> code = deriveAslLexCode(*sign.notation, shapes());
    EXPECT_EQ(code[0].signType, "AsymmetricalDifferentHandshape");  // 1 on B
    EXPECT_EQ(code[1].signType, "OneHanded");
    EXPECT_EQ(code[2].signType, "SymmetricalOrAlternating");
    ASSERT_EQ(sign.keyframes.size(), 2u);
    const std::vector<TimelineKey> left = track(sign, 1), right = track(sign, 0);
    // The left hand holds through the one-handed part ...
    const CompiledNotation::Stroke &one = sign.strokes[1], &both = sign.strokes[2];
    EXPECT_LT(glm::distance(positionAt(left, one.startSeconds), positionAt(left, one.endSeconds)), 1e-6);
    // ... and mirrors the right in the last.
    for (double t = both.startSeconds; t <= both.endSeconds; t += 0.05) {
        const glm::dvec3 r = positionAt(right, t), l = positionAt(left, t);
        EXPECT_NEAR(l.x, -r.x, 1e-6);
        EXPECT_NEAR(l.y, r.y, 1e-6);
    }
    const std::vector<NotationCheck> checks = checkSignNotation(sign, lexicon, shapes(), model());
    for (const char* name : {"hands mirrored", "hands", "base hand still"}) {
        ASSERT_NE(findCheck(checks, name), nullptr) << name;
        EXPECT_TRUE(findCheck(checks, name)->ok) << name << ": " << findCheck(checks, name)->detail;
    }
}

// Limit 5: mirrored hands touch each other (MORE, FAMILY): they meet on the midline, each
// hand's point the other's mirror image, in neutral space as ASL-LEX codes it.
TEST(SignNotationParts, MirroredHandsMeetEachOtherOnTheMidline) {
    const Lexicon lexicon = parse(lexiconWith(R"({"hands": "mirrored", "parts": [{"seconds": 0.6, "handshape": "flat-O",
        "fingers": "left", "palm": "back", "at": "neutral", "offset": [40, 60, -60], "touch": "fingertips",
        "path": {"shape": "straight", "to": "hand:fingertips", "toOffset": [0, 60, -60]},
        "repeat": {"count": 2, "return": "lifted", "lift": "right"},
        "contact": [{"when": "end", "at": "hand:fingertips"}]}]})"));
    const LexiconSign& sign = lexicon.signs.front();
    const std::vector<NotationCheck> checks = checkSignNotation(sign, lexicon, shapes(), model());
    int reached = 0;
    for (const NotationCheck& c : checks) {
        if (c.name.rfind("contact ", 0) != 0) continue;
        ++reached;
        EXPECT_TRUE(c.ok) << c.name << ": " << c.detail;
    }
    EXPECT_EQ(reached, 2);  // one touch per repetition
    for (const char* name : {"apart between contacts", "hands mirrored", "repetitions"}) {
        ASSERT_NE(findCheck(checks, name), nullptr) << name;
        EXPECT_TRUE(findCheck(checks, name)->ok) << name << ": " << findCheck(checks, name)->detail;
    }
    const std::vector<AslLexCode> code = deriveAslLexCode(*sign.notation, shapes());
    EXPECT_EQ(code[0].majorLocation, "Neutral");
    EXPECT_EQ(code[0].contact, 1);
    // The place names the point that meets, whatever the part's touch: FAMILY's thumbs meet at
    // the start and its little fingers at the end.
    const Lexicon family = parse(lexiconWith(R"({"hands": "mirrored", "parts": [{"seconds": 0.5, "handshape": "F",
        "fingers": "up", "palm": "forward", "endFingers": "up", "endPalm": "back", "at": "hand:thumb", "offset": [0, 40, 0],
        "path": {"shape": "arc", "to": "hand:little", "toOffset": [0, 40, -80], "side": "right", "bulge": 70},
        "contact": [{"when": "start", "at": "hand:thumb", "by": "thumb"}, {"when": "end", "at": "hand:little", "by": "little"}]}]})"));
    const std::vector<NotationCheck> familyChecks = checkSignNotation(family.signs.front(), family, shapes(), model());
    for (const char* name : {"contact 1", "contact 2"}) {
        ASSERT_NE(findCheck(familyChecks, name), nullptr) << name;
        EXPECT_TRUE(findCheck(familyChecks, name)->ok) << name << ": " << findCheck(familyChecks, name)->detail;
    }
    // Its arc bulges as far as it says (70 mm out to the side at its middle).
    const std::vector<VerbKeyframe>& keys = family.signs.front().keyframes.front();
    ASSERT_EQ(keys.size(), 7u);
    EXPECT_NEAR(keys[3].pose.positionMm.x - 0.5 * (keys.front().pose.positionMm.x + keys.back().pose.positionMm.x), 70.0, 1e-6);
}

// Limit 6: an open-close repeats over a still hand (BOY, NO), ending in its end handshape.
TEST(SignNotationParts, AnOpenCloseRepeatsItsCount) {
    const Lexicon lexicon = parse(lexiconWith(R"({"parts": [{"seconds": 0.45, "handshape": "flat-O", "endHandshape": "bent-B",
        "fingers": "forward", "palm": "down", "at": "chin", "offset": [0, 0, 60], "local": {"kind": "open-close", "count": 3}}]})"));
    const LexiconSign& sign = lexicon.signs.front();
    const std::vector<VerbKeyframe>& keys = sign.keyframes.front();
    ASSERT_EQ(keys.size(), 6u);  // 2 × 3 − 1 changes
    for (std::size_t k = 0; k < keys.size(); ++k) EXPECT_EQ(keys[k].handshape, k % 2 ? "bent-B" : "flat-O") << k;
    const std::vector<NotationCheck> checks = checkSignNotation(sign, lexicon, shapes(), model());
    EXPECT_TRUE(findCheck(checks, "repetitions")->ok) << findCheck(checks, "repetitions")->detail;
    EXPECT_EQ(deriveAslLexCode(*sign.notation, shapes())[0].repeated, 1);
    // With a path it would be two movements at once: refused, at its field.
    try {
        parse(lexiconWith(R"({"parts": [{"seconds": 0.45, "handshape": "flat-O", "endHandshape": "bent-B",
            "fingers": "forward", "palm": "down", "at": "chin", "path": {"shape": "straight", "direction": "down", "size": 50},
            "local": {"kind": "open-close", "count": 2}}]})"));
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), "/signs/0/notation/parts/0/local/count");
    }
}

// Limit 7: the wrist's front, the elbow's front, the back of the fingers and the clavicle are
// places, found by the place check and mapped to ASL-LEX 2.0's minor locations.
TEST(SignNotationParts, TheNewPlacesAreFoundAndCodedAsAslLexCodesThem) {
    for (const auto& [place, minor] : std::vector<std::pair<std::string, std::string>>{
             {"arm:wrist-front", "WristFront"}, {"hand:finger-back", "FingerBack"}, {"hand:finger-front", "FingerFront"}}) {
        const Lexicon lexicon = parse(lexiconWith(R"({"hands": "base", "parts": [{"seconds": 0.5, "handshape": "1",
            "fingers": "forward", "palm": "down", "at": ")" + place + R"(", "touch": "index-tip",
            "base": {"handshape": "B", "fingers": "right", "palm": "up", "at": "neutral"},
            "contact": [{"when": "start"}]}]})"));
        const std::vector<NotationCheck> checks = checkSignNotation(lexicon.signs.front(), lexicon, shapes(), model());
        const NotationCheck* found = findCheck(checks, "place");
        ASSERT_NE(found, nullptr);
        EXPECT_TRUE(found->ok) << place << ": " << found->detail;
        EXPECT_NE(found->detail.find(minor), std::string::npos) << place << ": " << found->detail;
        EXPECT_TRUE(findCheck(checks, "contact 1")->ok) << place << ": " << findCheck(checks, "contact 1")->detail;
    }
    EXPECT_EQ(aslLexLocation("arm:elbow-front", 0.0).second, "ElbowBack");  // ASL-LEX 2.0 has no ElbowFront
    const Lexicon shipped = loadLexicon(std::string(SIGNSTIM_SOURCE_DIR) + "/scenes/lexicon", shapes(), model());
    for (const char* side : {"clavicle-right", "clavicle-left"}) {
        ASSERT_TRUE(shipped.locations.count(side)) << side;
        EXPECT_EQ(aslLexLocation(side, 0.0), (std::pair<std::string, std::string>{"Body", "Clavicle"}));
    }
}

// Issue 22: the back of the fingers (hand:finger-back) is on the fingers' surface in every
// handshape: on the middle finger's capsules halfway along the finger, and inside no bone of the
// hand (a fist's is the front of the fist over the middle joints; the chord's midpoint it was
// before lay inside a fist, 20-30 mm from its surface, and inside a C's curve). The pad
// (finger-front) is on its bone's surface; in a bent finger that is the crease.
TEST(SignNotationParts, TheBackOfTheFingersIsOnTheFingersSurfaceInEveryHandshape) {
    const int first = hand::firstBodyOf(hand::Digit::Middle);
    for (const Handshape& shape : shapes().shapes)
        for (const hand::Side side : {hand::Side::Right, hand::Side::Left})
            for (const std::string name : {"finger-back", "finger-front"}) {
                const std::optional<glm::dvec3> point = handPointMm(model(), shape.controls, side, name);
                ASSERT_TRUE(point.has_value()) << name;
                const glm::vec3 p(*point);
                const std::array<hand::Capsule, hand::kBodyCount> capsules =
                    hand::boneCapsules(model(), hand::forwardKinematics(model(), shape.controls, side));
                float union_ = 1e9f, onOne = 1e9f, deepest = 1e9f;
                int deepestBody = 0;
                for (int b = 1; b < hand::kBodyCount; ++b) {
                    const hand::Capsule& c = capsules[static_cast<std::size_t>(b)];
                    const float gap = hand::distancePointSegment(p, c.start, c.end) - c.radiusMm;
                    if (b >= first && b < first + 3) union_ = std::min(union_, gap), onOne = std::min(onOne, std::abs(gap));
                    else if (gap < deepest) deepest = gap, deepestBody = b;
                }
                if (name == "finger-front") {
                    EXPECT_LT(onOne, 0.1f) << shape.name << " finger-front: off its bone's surface by " << onOne << " mm";
                    continue;
                }
                EXPECT_LT(std::abs(union_), 0.1f) << shape.name << " finger-back: " << union_ << " mm from the middle finger's surface";
                EXPECT_GT(deepest, -0.5f) << shape.name << " finger-back: inside body " << deepestBody << " by " << -deepest << " mm";
            }
}

// Issue 22 (HELP): a carried base hand moves with the dominant hand's path, keeping its place
// against it (the palm lifts the fist), where a plain base hand holds still.
TEST(SignNotationParts, ACarriedBaseHandMovesWithTheDominantHand) {
    const std::string part = R"({"hands": "base", "parts": [{"seconds": 0.5, "handshape": "A", "fingers": "forward",
        "palm": "left", "at": "hand:palm", "offset": [0, 25, 0], "touch": "ulnar",
        "path": {"shape": "straight", "direction": "up", "size": 100},
        "base": {"handshape": "B", "fingers": "forward", "palm": "up", "at": "neutral"CARRIED},
        "contact": [{"when": "start"}]}]})";
    const auto with = [&](const std::string& carried) {
        std::string text = part;
        text.replace(text.find("CARRIED"), 7, carried);
        return parse(lexiconWith(text));
    };
    const Lexicon carried = with(R"(, "carried": true)");
    const LexiconSign& sign = carried.signs.front();
    const std::vector<TimelineKey> right = track(sign, 0), left = track(sign, 1);
    const double end = right.back().timeSeconds;
    const glm::dvec3 rise = positionAt(left, end) - positionAt(left, 0.0);
    EXPECT_NEAR(rise.y, 100.0, 1.0) << "the base hand rises with the fist";
    EXPECT_NEAR(glm::distance(positionAt(left, 0.5 * end) - positionAt(right, 0.5 * end), positionAt(left, 0.0) - positionAt(right, 0.0)), 0.0, 0.5);
    const std::vector<NotationCheck> checks = checkSignNotation(sign, carried, shapes(), model());
    ASSERT_NE(findCheck(checks, "base hand carried"), nullptr);
    EXPECT_TRUE(findCheck(checks, "base hand carried")->ok) << findCheck(checks, "base hand carried")->detail;
    EXPECT_EQ(findCheck(checks, "base hand still"), nullptr);

    const Lexicon still = with("");
    const std::vector<TimelineKey> held = track(still.signs.front(), 1);
    EXPECT_LT(glm::distance(positionAt(held, end), positionAt(held, 0.0)), 1e-6) << "without \"carried\" the base hand holds still";
}

// Issue 22 (posed orientation): a flip of the palm (COOK) turns the forearm through its neutral
// rotation, palm toward the midline halfway, as a signer does: never the other way round, palm
// out, which asks a forearm to pronate 180° beyond its limits. Each hand of a mirrored pair
// turns its own way (the left hand's midline is to its right).
TEST(SignNotationParts, AFlipOfThePalmTurnsThroughTheForearmsNeutralRotation) {
    for (const char* palms : {R"("palm": "down", "endPalm": "up")", R"("palm": "up", "endPalm": "down")"}) {
        const Lexicon lexicon = parse(lexiconWith(std::string(R"({"hands": "mirrored", "parts": [{"seconds": 0.6, "handshape": "B",
            "fingers": "forward", "endFingers": "forward", )") + palms + R"(, "at": "neutral", "offset": [90, 0, 0],
            "path": {"shape": "arc", "direction": "right", "size": 60, "side": "up"}}]})"));
        const LexiconSign& sign = lexicon.signs.front();
        ASSERT_EQ(sign.keyframes.size(), 2u);
        for (std::size_t h = 0; h < 2; ++h) {
            const double midline = h == 0 ? -1.0 : 1.0;  // +x is the signer's right
            const auto& keys = sign.keyframes[h];
            ASSERT_GE(keys.size(), 3u);
            double most = -1.0;
            for (const VerbKeyframe& k : keys) {
                const double toward = midline * palmDirection(k.pose.orientation).x;
                EXPECT_GT(toward, -0.05) << palms << " hand " << h << ": the palm turns out at " << k.timeSeconds << " s";
                most = std::max(most, toward);
            }
            EXPECT_GT(most, 0.85) << palms << " hand " << h << ": the palm never faces the midline on its way over";
        }
    }
}

// A half turn that also swings the fingers (BAD: fingers up, palm to the chin; then fingers
// forward, palm down) swings the fingers the short way, in their own plane, and twists the palm
// through the midline: never the fingers out to the side, as the one-axis half turn takes them.
TEST(SignNotationParts, AHalfTurnThatSwingsTheFingersTwistsThroughTheMidline) {
    const Lexicon lexicon = parse(lexiconWith(R"({"parts": [{"seconds": 0.4, "handshape": "B", "fingers": "up", "palm": "back",
        "endFingers": "forward", "endPalm": "down", "at": "neutral-right", "path": {"shape": "arc", "direction": "forward",
        "size": 80, "side": "up"}}]})"));
    const auto& keys = lexicon.signs.front().keyframes.front();
    ASSERT_GE(keys.size(), 3u);
    double most = -1.0;
    for (const VerbKeyframe& k : keys) {
        EXPECT_LT(std::abs(fingersDirection(k.pose.orientation).x), 1e-6) << "the fingers swing out of their plane at " << k.timeSeconds << " s";
        most = std::max(most, -palmDirection(k.pose.orientation).x);
    }
    EXPECT_GT(most, 0.85) << "the palm never faces the midline on its way";
}

}  // namespace
}  // namespace signstim::stimuli
