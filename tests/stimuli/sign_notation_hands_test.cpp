// The notation's two-hand relations where both hands move (docs/lexicon.md, issue 22): hands
// moving together as one rigid unit, a base hand with its own path, alternating circles that
// orbit each other; and a curved stroke timed by its length. Lexicons written here are synthetic.
#include "stimuli/story/sign_notation_check.hpp"
#include "stimuli/story/timeline.hpp"
#include "stimuli/verbs/sora.hpp"
#include "tests/stimuli/notation_fixture.hpp"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <string>

namespace signstim::stimuli {
namespace {

constexpr double kStep = 1.0 / 240.0;  // the checks' sampling (sign_notation_check.cpp)

using notation_fixture::model;
using notation_fixture::shapes;
using notation_fixture::lexiconWith;
using notation_fixture::parse;
using notation_fixture::errorOf;

// A hand's track as the timeline keeps it (every inner key passed through, as for a story).
std::vector<TimelineKey> track(const LexiconSign& sign, std::size_t h) {
    std::vector<TimelineKey> keys;
    for (std::size_t k = 0; k < sign.keyframes[h].size(); ++k) {
        TimelineKey key;
        key.timeSeconds = sign.keyframes[h][k].timeSeconds;
        key.pose = sign.keyframes[h][k].pose;
        key.passThrough = k > 0 && k + 1 < sign.keyframes[h].size();
        keys.push_back(key);
    }
    return keys;
}

HandPose poseAt(const std::vector<TimelineKey>& keys, double t) {
    const TimelineSample s = sampleTrack(keys, t);
    HandPose p;
    p.positionMm = glm::mix(s.from->pose.positionMm, s.to->pose.positionMm, s.blend);
    p.orientation = slerpShortest(s.from->pose.orientation, s.to->pose.orientation, s.blend);
    return p;
}

const NotationCheck* findCheck(const std::vector<NotationCheck>& checks, const std::string& prefix) {
    for (const NotationCheck& c : checks)
        if (c.name.rfind(prefix, 0) == 0) return &c;
    return nullptr;
}

// BABY's cradle: the arms rock side to side as one unit, turning a little as they go.
const std::string kTogether = R"({"hands": "together", "parts": [
    {"seconds": 0.8, "handshape": "B", "fingers": [-1, 0, 0.4], "palm": "up", "endFingers": [-1, 0.25, 0.4], "endPalm": [0.25, 1, 0],
     "at": "neutral", "offset": [0, 20, 0], "touch": "back",
     "path": {"shape": "straight", "direction": "right", "size": 60}, "repeat": {"count": 2, "return": "retrace"},
     "base": {"handshape": "B", "fingers": [1, 0, 0.35], "palm": "up", "at": "neutral", "offset": [30, 0, -40]}}]})";

TEST(SignNotationHands, HandsMovingTogetherKeepTheirRelativePoseAndBothMove) {
    const Lexicon lexicon = parse(lexiconWith(kTogether));
    const LexiconSign& sign = lexicon.signs.front();
    ASSERT_EQ(sign.keyframes.size(), 2u);
    const std::vector<TimelineKey> right = track(sign, 0), left = track(sign, 1);
    const auto relative = [&](double t, const glm::dvec3& pointInLeft) {
        const HandPose r = poseAt(right, t), l = poseAt(left, t);
        return glm::inverse(r.orientation) * (l.positionMm + l.orientation * pointInLeft - r.positionMm);
    };
    const double end = sign.durationSeconds();
    double drift = 0.0, travelled = 0.0;
    for (double t = 0.0; t <= end + 1e-9; t += kStep) {
        // The left palm origin and a point 90 mm along its fingers (the fingertips' reach).
        for (const glm::dvec3& p : {glm::dvec3(0.0), glm::dvec3(0.0, 0.0, 90.0)})
            drift = std::max(drift, glm::distance(relative(t, p), relative(0.0, p)));
        travelled = std::max(travelled, glm::distance(poseAt(left, t).positionMm, poseAt(left, 0.0).positionMm));
    }
    EXPECT_LT(drift, 0.5) << "the left hand leaves its pose relative to the right";
    EXPECT_GT(travelled, 50.0) << "the left hand must move with the right";
    const std::vector<NotationCheck> checks = checkSignNotation(sign, lexicon, shapes(), model());
    const NotationCheck* rigid = findCheck(checks, "hands rigid");
    ASSERT_NE(rigid, nullptr);
    EXPECT_TRUE(rigid->ok) << rigid->detail;
    const AslLexCode code = deriveAslLexCode(*sign.notation, shapes()).front();
    EXPECT_EQ(code.signType, "SymmetricalOrAlternating");  // both hands move, one handshape
    EXPECT_EQ(code.nondominant, code.handshape);
}

TEST(SignNotationHands, ABaseHandWithItsOwnPathMovesAndIsMetWhereItArrives) {
    const auto sign = [](const std::string& baseShape) {
        return lexiconWith(R"({"hands": "base", "parts": [
            {"seconds": 0.6, "handshape": "1", "fingers": "forward", "palm": "left", "at": "hand:radial", "offset": [0, 70, 0],
             "touch": "ulnar", "path": {"shape": "straight", "to": "hand:radial", "toOffset": [0, 14, 0]},
             "base": {"handshape": ")" + baseShape + R"(", "fingers": "forward", "palm": "right", "at": "neutral", "offset": [-25, -30, 0],
                      "path": {"shape": "straight", "direction": "up", "size": 25}},
             "contact": [{"when": "end"}]}]})");
    };
    const Lexicon lexicon = parse(sign("1"));
    const LexiconSign& s = lexicon.signs.front();
    const std::vector<VerbKeyframe>& left = s.keyframes[1];
    EXPECT_NEAR(left.back().pose.positionMm.y - left.front().pose.positionMm.y, 25.0, 1e-6);
    const std::vector<NotationCheck> checks = checkSignNotation(s, lexicon, shapes(), model());
    const NotationCheck* contact = findCheck(checks, "contact 1");
    ASSERT_NE(contact, nullptr);
    EXPECT_TRUE(contact->ok) << contact->detail;  // the right meets the base where it has risen to
    EXPECT_EQ(findCheck(checks, "base hand still"), nullptr);
    const AslLexCode same = deriveAslLexCode(*s.notation, shapes()).front();
    EXPECT_EQ(same.signType, "SymmetricalOrAlternating");
    EXPECT_EQ(same.majorLocation, "Neutral");  // two moving hands that touch: neutral space, as ASL-LEX codes them
    // Both hands moving with different handshapes break Battison's symmetry condition.
    const AslLexCode different = deriveAslLexCode(*parse(sign("B")).signs.front().notation, shapes()).front();
    EXPECT_EQ(different.signType, "DominanceViolation");
    EXPECT_EQ(different.nondominant, "DominanceViolation");
}

TEST(SignNotationHands, AlternatingCirclesOrbitHalfATurnApartTheSameWayAndClose) {
    const Lexicon lexicon = parse(lexiconWith(R"({"hands": "alternating", "parts": [
        {"seconds": 0.8, "handshape": "S", "fingers": "forward", "palm": "left", "at": "neutral", "offset": [40, 0, 0],
         "path": {"shape": "circle", "plane": "sagittal", "turn": "clockwise", "start": "up", "size": 80},
         "repeat": {"count": 2, "return": "continue"}}]})"));
    const LexiconSign& sign = lexicon.signs.front();
    const std::vector<TimelineKey> right = track(sign, 0), left = track(sign, 1);
    const double end = sign.durationSeconds();
    // The circle's centre (y, z): the right hand starts at its top.
    const glm::dvec3 start = poseAt(right, 0.0).positionMm;
    const glm::dvec2 centre(start.y - 40.0, start.z);
    double worst = 0.0, turnR = 0.0, turnL = 0.0;
    glm::dvec2 lastR(0.0), lastL(0.0);
    for (double t = 0.0; t <= end + 1e-9; t += kStep) {
        const glm::dvec3 r = poseAt(right, t).positionMm, l = poseAt(left, t).positionMm;
        const glm::dvec2 rr(r.y - centre.x, r.z - centre.y), ll(l.y - centre.x, l.z - centre.y);
        worst = std::max(worst, glm::length(rr + ll));  // opposite each other on the circle
        if (t > 0.0) {
            turnR += lastR.x * rr.y - lastR.y * rr.x;
            turnL += lastL.x * ll.y - lastL.y * ll.x;
        }
        lastR = rr, lastL = ll;
    }
    // Between keys both hands cut the same chords, so they stay opposite within a few mm.
    EXPECT_LT(worst, 3.0) << "the hands do not orbit each other half a turn apart";
    EXPECT_GT(turnR * turnL, 0.0) << "the hands circle in opposite directions";
    for (const std::vector<TimelineKey>* hand : {&right, &left})
        EXPECT_LT(glm::distance(poseAt(*hand, end).positionMm, poseAt(*hand, 0.0).positionMm), 0.5) << "a circle does not close";
    const std::vector<NotationCheck> checks = checkSignNotation(sign, lexicon, shapes(), model());
    const NotationCheck* apart = findCheck(checks, "hands apart");
    ASSERT_NE(apart, nullptr);
    EXPECT_TRUE(apart->ok) << apart->detail;
}

TEST(SignNotationHands, ABaseCircleOrbitsTheRightOneAndCloses) {
    // YEAR: the right S circles around the left, which circles small the other way round.
    const Lexicon lexicon = parse(lexiconWith(R"({"hands": "base", "parts": [
        {"seconds": 0.67, "handshape": "S", "fingers": [-0.2, 0, 1], "palm": "left", "at": "hand:radial", "offset": [0, 16, 0],
         "touch": "ulnar", "path": {"shape": "circle", "plane": "sagittal", "turn": "counterclockwise", "start": "up", "size": 130},
         "base": {"handshape": "S", "fingers": [0.2, 0, 1], "palm": "right", "at": "neutral", "offset": [-25, 0, -30],
                  "path": {"shape": "circle", "plane": "sagittal", "turn": "counterclockwise", "start": "down", "size": 40}},
         "contact": [{"when": "start"}, {"when": "end"}]}]})"));
    const LexiconSign& sign = lexicon.signs.front();
    const std::vector<TimelineKey> left = track(sign, 1);
    const double end = sign.durationSeconds();
    double reach = 0.0;
    for (double t = 0.0; t <= end + 1e-9; t += kStep)
        reach = std::max(reach, glm::distance(poseAt(left, t).positionMm, poseAt(left, 0.0).positionMm));
    EXPECT_NEAR(reach, 40.0, 1.0);  // across its own circle
    EXPECT_LT(glm::distance(poseAt(left, end).positionMm, poseAt(left, 0.0).positionMm), 0.5);
    for (const NotationCheck& c : checkSignNotation(sign, lexicon, shapes(), model())) EXPECT_TRUE(c.ok) << c.name << ": " << c.detail;
}

TEST(SignNotationHands, ACurvedStrokeKeepsOneSpeedBetweenItsKeys) {
    // An arc whose side leans against its chord (MARRY: up while the hand comes down): sampled
    // evenly along the curve's parameter, its first spans are short and its last long.
    const Lexicon lexicon = parse(lexiconWith(R"({"parts": [
        {"seconds": 0.9, "handshape": "5", "fingers": "forward", "palm": "down", "at": "neutral", "offset": [60, 150, 0],
         "path": {"shape": "arc", "to": "neutral", "toOffset": [0, 0, 0], "side": [0.3, 0.8, 0.5]}}]})"));
    const std::vector<VerbKeyframe>& keys = lexicon.signs.front().keyframes.front();
    ASSERT_GE(keys.size(), 7u);
    double slowest = 1e18, fastest = 0.0;
    for (std::size_t k = 0; k + 1 < keys.size(); ++k) {
        const double speed = glm::distance(keys[k + 1].pose.positionMm, keys[k].pose.positionMm) /
                             (keys[k + 1].timeSeconds - keys[k].timeSeconds);
        slowest = std::min(slowest, speed), fastest = std::max(fastest, speed);
    }
    EXPECT_LT(fastest / slowest, 1.01);
}

TEST(SignNotationHands, AStillBaseInTheDominantsOwnMarkedHandshapeIsADominanceViolation) {
    // NAME: the H taps the still base H. ASL-LEX 2.0 codes a marked base of the same handshape
    // a dominance violation in a sign's first part (B on B stays Asymmetrical), never in a later one.
    const auto code = [](const std::string& shape, bool secondPart) {
        const std::string tap = R"({"seconds": 0.5, "handshape": ")" + shape + R"(", "fingers": "forward", "palm": "left",
            "at": "hand:radial", "offset": [0, 40, 0], "touch": "ulnar",
            "base": {"handshape": ")" + shape + R"(", "fingers": "forward", "palm": "right", "at": "neutral"}})";
        const std::string one = R"({"seconds": 0.3, "handshape": "1", "fingers": "up", "palm": "forward", "at": "chin", "offset": [0, 0, 80]})";
        const Lexicon lexicon = parse(lexiconWith(R"({"hands": "base", "parts": [)" + (secondPart ? one + ", " + tap : tap) + "]}"));
        return deriveAslLexCode(*lexicon.signs.front().notation, shapes()).back();
    };
    EXPECT_EQ(code("H", false).signType, "DominanceViolation");
    EXPECT_EQ(code("H", false).nondominant, "DominanceViolation");
    EXPECT_EQ(code("B", false).signType, "AsymmetricalSameHandshape");
    EXPECT_EQ(code("H", true).signType, "AsymmetricalSameHandshape");
}

TEST(SignNotationHands, MistakesInTheNewRelationsAreNamedAtTheirField) {
    struct Case {
        std::string notation, field, words;
    };
    const std::string part = R"("seconds": 0.5, "handshape": "S", "fingers": "forward", "palm": "left", "at": "neutral")";
    const std::vector<Case> cases{
        {R"({"hands": "together", "parts": [{)" + part + R"(}]})", "/signs/0/notation/parts/0/base", "left hand's start"},
        {R"({"hands": "together", "parts": [{)" + part + R"(, "base": {"handshape": "S", "fingers": "forward", "palm": "right",
            "at": "neutral", "path": {"shape": "straight", "direction": "up", "size": 20}}}]})",
         "/signs/0/notation/parts/0/base/path", "follow the right hand's path"},
        {R"({"hands": "base", "parts": [{)" + part + R"(, "base": {"handshape": "S", "fingers": "forward", "palm": "right",
            "at": "neutral", "path": {"shape": "straight", "to": "chin"}}}]})",
         "/signs/0/notation/parts/0/base/path/to", "a base hand's own path"},
        {R"({"hands": "base", "parts": [{)" + part + R"(, "base": {"handshape": "S", "fingers": "forward", "palm": "right",
            "at": "neutral", "path": {"shape": "spiral"}}}]})",
         "/signs/0/notation/parts/0/base/path/shape", "'spiral' is not one of"},
        {R"({"hands": "base", "parts": [{)" + part + R"(, "base": {"handshape": "S", "fingers": "forward", "palm": "right",
            "at": "neutral", "path": {"shape": "straight", "direction": "up"}}}]})",
         "/signs/0/notation/parts/0/base/path/size", "size in mm"},
        {R"({"hands": "mirrored", "parts": [{)" + part + R"(, "base": {"handshape": "S", "fingers": "forward", "palm": "right",
            "at": "neutral"}}]})",
         "/signs/0/notation/parts/0/base", "\"together\""},
    };
    for (const Case& c : cases) {
        const InputError e = errorOf(lexiconWith(c.notation));
        EXPECT_EQ(e.file(), "lexicon.json");
        EXPECT_EQ(e.field(), c.field) << e.what();
        EXPECT_NE(std::string(e.what()).find(c.words), std::string::npos) << e.what();
        EXPECT_GE(e.line(), 7) << e.what();
    }
}

// Issue 22 (GET, CHANGE): mirrored hands that meet one above the other. The left hand is its
// mirror image moved by leftOffset at the stroke's start and by endLeftOffset at its end, in
// between along the line joining them; the relation is still checked (and coded) as mirrored;
// the offset is refused on hands that are not mirror images.
TEST(SignNotationHands, MirroredHandsOffsetByLeftOffsetMeetOneAboveTheOther) {
    const std::string notation = R"({"hands": "mirrored", "parts": [
        {"seconds": 0.5, "handshape": "S", "fingers": "forward", "palm": "left", "at": "neutral", "offset": [0, 100, 60], "touch": "ulnar",
         "path": {"shape": "arc", "to": "hand:ulnar", "toOffset": [0, 60, -40], "side": "up"},
         "leftOffset": [-30, -130, -10], "endLeftOffset": [-30, -70, -10]}]})";
    const Lexicon lexicon = parse(lexiconWith(notation));
    const LexiconSign& sign = lexicon.signs.front();
    const std::vector<TimelineKey> right = track(sign, 0), left = track(sign, 1);
    const auto mirrorOf = [](const glm::dvec3& p) { return glm::dvec3(-p.x, p.y, p.z); };
    EXPECT_LT(glm::distance(left.front().pose.positionMm, mirrorOf(right.front().pose.positionMm) + glm::dvec3(-30, -130, -10)), 1e-9);
    EXPECT_LT(glm::distance(left.back().pose.positionMm, mirrorOf(right.back().pose.positionMm) + glm::dvec3(-30, -70, -10)), 1e-9);
    // Halfway along the stroke the offset is between the two, on the line joining them.
    const double mid = 0.5 * sign.durationSeconds();
    const glm::dvec3 offset = poseAt(left, mid).positionMm - mirrorOf(poseAt(right, mid).positionMm);
    EXPECT_NEAR(offset.x, -30.0, 1.0);
    EXPECT_NEAR(offset.z, -10.0, 1.0);
    EXPECT_GT(offset.y, -125.0);
    EXPECT_LT(offset.y, -75.0);
    const std::vector<NotationCheck> checks = checkSignNotation(sign, lexicon, shapes(), model());
    ASSERT_NE(findCheck(checks, "hands mirrored"), nullptr);
    EXPECT_TRUE(findCheck(checks, "hands mirrored")->ok) << findCheck(checks, "hands mirrored")->detail;
    EXPECT_EQ(deriveAslLexCode(*sign.notation, shapes())[0].signType, "SymmetricalOrAlternating");
    // Without endLeftOffset the offset is held: leftOffset at the end too.
    std::string held = notation;
    held.replace(held.find(R"("leftOffset")"), std::string(R"("leftOffset": [-30, -130, -10], "endLeftOffset": [-30, -70, -10])").size(),
                 R"("leftOffset": [-30, -130, -10])");
    const Lexicon heldLexicon = parse(lexiconWith(held));
    const std::vector<TimelineKey> heldRight = track(heldLexicon.signs.front(), 0), heldLeft = track(heldLexicon.signs.front(), 1);
    EXPECT_LT(glm::distance(heldLeft.back().pose.positionMm, mirrorOf(heldRight.back().pose.positionMm) + glm::dvec3(-30, -130, -10)), 1e-9);
    // Refused where the hands are not mirror images, at its field.
    const InputError e = errorOf(lexiconWith(R"({"hands": "base", "parts": [{"seconds": 0.5, "handshape": "S", "fingers": "forward",
        "palm": "left", "at": "hand:back", "leftOffset": [0, -50, 0],
        "base": {"handshape": "S", "fingers": "right", "palm": "down", "at": "neutral"}}]})"));
    EXPECT_EQ(e.field(), "/signs/0/notation/parts/0/leftOffset") << e.what();
}

// Issue 22 (MARRY): a hold at the end of the movement. The strokes take the part's time less the
// hold, the hand stays where they ended until the part's end, and the contact comes at the
// stroke's end; a hold without a path, or as long as the part, is refused at its field.
TEST(SignNotationHands, AHoldEndsTheMovementAndTheHandStaysUntilThePartsEnd) {
    const std::string part = R"("handshape": "C", "fingers": "forward", "palm": "down", "at": "hand:palm", "offset": [0, 150, 0],
        "touch": "palm", "path": {"shape": "arc", "to": "hand:palm", "toOffset": [0, 20, 0], "side": "forward"},
        "base": {"handshape": "C", "fingers": "right", "palm": "up", "at": "neutral", "offset": [-20, -60, -40]},
        "contact": [{"when": "end"}])";
    const Lexicon lexicon = parse(lexiconWith(R"({"hands": "base", "parts": [{"seconds": 0.9, "hold": 0.4, )" + part + "}]}"));
    const LexiconSign& sign = lexicon.signs.front();
    EXPECT_NEAR(sign.durationSeconds(), 0.9, 1e-9);
    const std::vector<TimelineKey> right = track(sign, 0);
    const glm::dvec3 landed = poseAt(right, 0.5).positionMm;
    EXPECT_LT(glm::distance(poseAt(right, 0.7).positionMm, landed), 1e-6);
    EXPECT_LT(glm::distance(poseAt(right, 0.9).positionMm, landed), 1e-6);
    EXPECT_GT(glm::distance(poseAt(right, 0.25).positionMm, landed), 20.0);  // still on its way halfway through the movement
    ASSERT_EQ(sign.contactEvents.size(), 1u);
    EXPECT_NEAR(sign.contactEvents.front().timeSeconds, 0.5, 1e-9);
    const std::vector<NotationCheck> checks = checkSignNotation(sign, lexicon, shapes(), model());
    for (const NotationCheck& c : checks) EXPECT_TRUE(c.ok) << c.name << ": " << c.detail;
    EXPECT_EQ(errorOf(lexiconWith(R"({"hands": "base", "parts": [{"seconds": 0.9, "hold": 0.9, )" + part + "}]}")).field(),
              "/signs/0/notation/parts/0/hold");
    EXPECT_EQ(errorOf(lexiconWith(R"({"hands": "one", "parts": [{"seconds": 0.5, "hold": 0.2, "handshape": "C", "fingers": "forward",
        "palm": "down", "at": "neutral"}]})")).field(), "/signs/0/notation/parts/0/hold");
}

}  // namespace
}  // namespace signstim::stimuli
