// The handshape library (SPEC §1.6): complete, labelled, physically plausible (contact
// checks of SPEC §2.6 on the McDonald hand's bone capsules), and strict about bad files.
#include "common/error.hpp"
#include "hand/contact.hpp"
#include "stimuli/story/handshapes.hpp"
#include "stimuli/scenes_path.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>

namespace signstim::stimuli {
namespace {

using hand::Digit;
using hand::Side;

// Capsules are a crude stand-in for soft fingers: allow this much overlap (skin compresses).
constexpr float kInterpenetrationToleranceMm = 1.0f;
// "Touching": the thumb-tip and fingertip spheres meet within a few millimetres.
constexpr float kContactMinGapMm = -1.5f;
constexpr float kContactMaxGapMm = 3.0f;

class HandshapeLibraryTest : public ::testing::Test {
protected:
    hand::HandModel model = hand::buildHandModel();
    HandshapeLibrary library =
        loadHandshapes(std::string(SIGNSTIM_SOURCE_DIR) + "/scenes/handshapes.json", model);
};

TEST_F(HandshapeLibraryTest, HasEveryStaticLetterAndTheVerbHandshapes) {
    const std::string letters = "ABCDEFGHIKLMNOPQRSTUVWXY";  // no J, Z (they move)
    for (char letter : letters) EXPECT_NE(library.find(std::string(1, letter)), nullptr) << letter;
    for (const char* name : {"1", "X", "B", "bent-B", "C", "flat-O", "O", "5"}) {
        EXPECT_NE(library.find(name), nullptr) << name;
    }
    for (const char* name : {"2", "3", "4", "6", "7", "8", "9", "10", "claw-5", "open-8", "ILY"}) {
        EXPECT_NE(library.find(name), nullptr) << name;
    }
    EXPECT_EQ(library.find("J"), nullptr);
    EXPECT_EQ(library.find("Z"), nullptr);
    EXPECT_THROW(library.at("Z"), InputError);
}

TEST_F(HandshapeLibraryTest, ShapesCarryAslLexLabelsWhereOneExists) {
    for (const Handshape& shape : library.shapes) {
        if (shape.name == "10" || shape.name == "closed-H") {
            // The thumb-up fist: ASL-LEX 2.0 has no label of its own for it, and which one it is
            // coded under (probably a, the thumb-selected fist) is not known here. closed-H is
            // only ever an end handshape (NO's snap): ASL-LEX codes a sign by its first
            // handshape and the closing as a flexion change, so it has no label either.
            EXPECT_TRUE(shape.aslLexLabel.empty()) << shape.name;
        } else {
            EXPECT_FALSE(shape.aslLexLabel.empty()) << shape.name;
        }
    }
    // ASL-LEX 2.0's exact labels (Handshape.2.0): B with the thumb across the palm is closed_b,
    // with the thumb alongside open_b; fingers bent at the knuckles only are flat_*; X is bent_1.
    EXPECT_EQ(library.at("B").aslLexLabel, "closed_b");
    EXPECT_EQ(library.at("open-B").aslLexLabel, "open_b");
    EXPECT_EQ(library.at("bent-B").aslLexLabel, "flat_b");
    EXPECT_EQ(library.at("flat-O").aslLexLabel, "flat_o");
    EXPECT_EQ(library.at("X").aslLexLabel, "bent_1");
    EXPECT_EQ(library.at("open-8").aslLexLabel, "open_8");
}

TEST_F(HandshapeLibraryTest, EveryAslLexHandshapeOfTwoOrMoreSignsIsFormed) {
    // Every ASL-LEX 2.0 dominant handshape (Handshape.2.0) that two or more of its 2,723 signs
    // use (docs/hand.md); t, k, 7, flat_ily, closed_e and spread_e have one sign each.
    for (const char* label :
         {"1", "open_b", "s", "a", "curved_5", "5", "baby_o", "c", "f", "flat_b", "o", "h", "closed_b", "v",
          "open_8", "bent_1", "p", "flat_o", "y", "l", "flatspread_5", "g", "bent_v", "4", "r", "curved_v", "i",
          "curved_l", "flat_1", "3", "flat_h", "8", "d", "bent_l", "e", "w", "horns", "flat_v", "spread_open_e",
          "stacked_5", "open_h", "curved_1", "ily", "flat_m", "open_e", "curved_h", "flat_n", "flat_horns",
          "flat_4", "curved_4", "open_f", "goody_goody"}) {
        const bool formed = std::any_of(library.shapes.begin(), library.shapes.end(),
                                        [&](const Handshape& shape) { return shape.aslLexLabel == label; });
        EXPECT_TRUE(formed) << label;
    }
}

TEST_F(HandshapeLibraryTest, OpenBKeepsTheThumbOutOfThePalmWhereBCrossesIt) {
    // B (closed_b) folds the thumb across the palm; open-B lays it alongside the index. The thumb
    // tip of B lies over the palm (toward the little finger past the index MCP), open-B's does not.
    const hand::HandPose b = hand::forwardKinematics(model, library.at("B").controls, Side::Right);
    const hand::HandPose openB = hand::forwardKinematics(model, library.at("open-B").controls, Side::Right);
    const float indexMcpY = model.mcpPositionMm[0].y;
    EXPECT_LT(b.tips[int(Digit::Thumb)].y, indexMcpY);
    EXPECT_GT(openB.tips[int(Digit::Thumb)].y, indexMcpY);
    for (int f = 0; f < hand::kFingerCount; ++f) {
        EXPECT_EQ(library.at("B").controls.fingers[f].bend, library.at("open-B").controls.fingers[f].bend);
    }
}

TEST_F(HandshapeLibraryTest, ThumbTipTouchesTheNamedFingertip) {
    const std::pair<const char*, Digit> expected[] = {
        {"O", Digit::Index}, {"F", Digit::Index}, {"D", Digit::Middle}, {"flat-O", Digit::Index}, {"T", Digit::Index},
        {"6", Digit::Little}, {"7", Digit::Ring}, {"8", Digit::Middle}, {"9", Digit::Index},
        {"baby-O", Digit::Index}};
    for (const auto& [name, digit] : expected) {
        const Handshape& shape = library.at(name);
        ASSERT_TRUE(shape.thumbContact.has_value()) << name;
        EXPECT_EQ(*shape.thumbContact, digit) << name;
    }
    int checked = 0;
    for (const Handshape& shape : library.shapes) {
        if (!shape.thumbContact) continue;
        for (Side side : {Side::Right, Side::Left}) {
            const hand::HandPose pose = hand::forwardKinematics(model, shape.controls, side);
            const hand::Capsule thumb = hand::fingertipSphere(model, pose, Digit::Thumb);
            const hand::Capsule finger = hand::fingertipSphere(model, pose, *shape.thumbContact);
            const float gap = glm::distance(thumb.start, finger.start) - thumb.radiusMm - finger.radiusMm;
            EXPECT_GE(gap, kContactMinGapMm) << shape.name << ": thumb tip pushed into the fingertip";
            EXPECT_LE(gap, kContactMaxGapMm) << shape.name << ": thumb tip does not reach the fingertip";
            ++checked;
        }
    }
    EXPECT_GE(checked, 20);
}

TEST_F(HandshapeLibraryTest, NoTwoDigitsInterpenetrateInAnyShape) {
    for (const Handshape& shape : library.shapes) {
        const hand::HandPose pose = hand::forwardKinematics(model, shape.controls, Side::Right);
        const hand::BoneGap gap = hand::closestInterDigitGap(hand::boneCapsules(model, pose));
        EXPECT_GE(gap.gapMm, -kInterpenetrationToleranceMm)
            << shape.name << ": " << hand::boneName(Side::Right, gap.first) << " and "
            << hand::boneName(Side::Right, gap.second) << " overlap by " << -gap.gapMm << " mm";
    }
}

TEST_F(HandshapeLibraryTest, NoDigitSinksIntoThePalm) {
    // Every bone but the first of each digit (whose base is inside the hand by construction)
    // stays in front of the palm's soft tissue, within the same tolerance.
    for (const Handshape& shape : library.shapes) {
        for (Side side : {Side::Right, Side::Left}) {
            const hand::HandPose pose = hand::forwardKinematics(model, shape.controls, side);
            const auto capsules = hand::boneCapsules(model, pose);
            for (int body = 1; body < hand::kBodyCount; ++body) {
                if ((body - 1) % 3 == 0) continue;
                EXPECT_GE(hand::palmClearanceMm(model, capsules[body], side), -kInterpenetrationToleranceMm)
                    << shape.name << ": " << hand::boneName(side, static_cast<hand::Body>(body)) << " inside the palm";
            }
        }
    }
}

// M and N: the folded fingers lie over the thumb, whose tip comes out between the last folded
// finger and the next one: between the palm and the folded fingers' middle phalanges.
void expectThumbUnderFolded(const hand::HandModel& model, const Handshape& shape, int foldedFingers) {
    const hand::HandPose pose = hand::forwardKinematics(model, shape.controls, Side::Right);
    const auto capsules = hand::boneCapsules(model, pose);
    const glm::vec3 tip = pose.tips[int(Digit::Thumb)];
    // Between the MCPs of the last folded finger and the next (fingers 0 = index .. 3 = little).
    const float yFolded = model.mcpPositionMm[foldedFingers - 1].y, yNext = model.mcpPositionMm[foldedFingers].y;
    EXPECT_LT(tip.y, yFolded) << shape.name;
    EXPECT_GT(tip.y, yNext) << shape.name;
    EXPECT_LT(tip.z, hand::palmKnuckleZMm(model)) << shape.name << ": below the knuckle line";
    EXPECT_GE(hand::palmClearanceMm(model, capsules[int(hand::Body::ThumbDistal)], Side::Right), 0.0f) << shape.name;
    for (int f = 0; f < foldedFingers; ++f) {
        const hand::Capsule& middlePhalanx = capsules[hand::firstBodyOf(static_cast<Digit>(f + 1)) + 1];
        EXPECT_GT(std::min(middlePhalanx.start.x, middlePhalanx.end.x), tip.x)
            << shape.name << ": finger " << f + 1 << " is not over the thumb";
    }
}

TEST_F(HandshapeLibraryTest, MAndNFoldTheirFingersOverTheThumb) {
    expectThumbUnderFolded(model, library.at("M"), 3);
    expectThumbUnderFolded(model, library.at("N"), 2);
}

TEST_F(HandshapeLibraryTest, AbductionIsStoredAsSpreadAfterRadiation) {
    // SPEC §1.6: 5 = abduction (−20°, 0°, 12°, 25°), σ = α − ρ with ρ = (−8°, 0°, 4°, 14°).
    const hand::HandControls& five = library.at("5").controls;
    EXPECT_FLOAT_EQ(five.fingers[0].spreadDeg, -12.0f);
    EXPECT_FLOAT_EQ(five.fingers[1].spreadDeg, 0.0f);
    EXPECT_FLOAT_EQ(five.fingers[2].spreadDeg, 8.0f);
    EXPECT_FLOAT_EQ(five.fingers[3].spreadDeg, 11.0f);
    // Presets: A = FC on every finger.
    EXPECT_FLOAT_EQ(library.at("A").controls.fingers[3].bend, 0.95f);
    EXPECT_FLOAT_EQ(library.at("A").controls.fingers[3].hook, 0.8f);
}

// ---- malformed files --------------------------------------------------------------------
const char* kGood = R"({
  "version": 2,
  "fingerPresets": {"E0": {"bend": 0, "hook": 0}},
  "thumbPresets": {"side": {"bendDeg": 5, "spreadDeg": 12, "mcpDeg": 0, "ipDeg": 0}},
  "handshapes": [
    {"name": "B",
     "fingers": {"index": "E0", "middle": "E0", "ring": "E0", "little": "E0"},
     "thumb": "side"},
    {"name": "Bad",
     "fingers": {"index": "E0", "middle": "E0", "ring": "E0", "little": "E0"},
     "thumb": "side"}
  ]
})";

InputError parseError(const std::string& text) {
    try {
        parseHandshapes(text, "shapes.json", hand::buildHandModel());
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return InputError("none");
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.rfind(from);  // the second shape ("Bad") is the last match
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
}

TEST(HandshapeFileTest, GoodFileParses) {
    const HandshapeLibrary library = parseHandshapes(kGood, "shapes.json", hand::buildHandModel());
    EXPECT_EQ(library.shapes.size(), 2u);
}

TEST(HandshapeFileTest, UnknownPresetNamesFileLineShapeAndField) {
    const InputError e = parseError(replaced(kGood, "\"little\": \"E0\"", "\"little\": \"E9\""));
    EXPECT_EQ(e.file(), "shapes.json");
    EXPECT_EQ(e.line(), 10);
    EXPECT_NE(e.field().find("Bad"), std::string::npos) << e.field();
    EXPECT_NE(e.field().find("little"), std::string::npos) << e.field();
    EXPECT_NE(std::string(e.what()).find("E9"), std::string::npos);
}

TEST(HandshapeFileTest, VersionOneAndUnknownVersionsAreRefused) {
    InputError e = parseError(replaced(kGood, "\"version\": 2", "\"version\": 1"));
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.field(), "version");
    EXPECT_NE(std::string(e.what()).find("retune the thumbs"), std::string::npos) << e.what();
    e = parseError(replaced(kGood, "\"version\": 2", "\"version\": \"2\""));
    EXPECT_NE(std::string(e.what()).find("expected 2"), std::string::npos) << e.what();
    e = parseError(replaced(kGood, "\"version\": 2,", ""));
    EXPECT_EQ(e.field(), "version");
    EXPECT_NE(std::string(e.what()).find("retune the thumbs"), std::string::npos) << e.what();
}

TEST(HandshapeFileTest, NonNumericAndOutOfRangeValuesAreRejected) {
    InputError e = parseError(replaced(kGood, "\"ring\": \"E0\"", "\"ring\": {\"bend\": \"much\"}"));
    EXPECT_EQ(e.line(), 10);
    EXPECT_NE(e.field().find("ring.bend"), std::string::npos) << e.field();
    e = parseError(replaced(kGood, "\"ring\": \"E0\"", "\"ring\": {\"spreadDeg\": 80}"));
    EXPECT_NE(std::string(e.what()).find("out of range"), std::string::npos) << e.what();
    e = parseError(replaced(kGood, "\"thumb\": \"side\"", "\"thumb\": {\"bendDeg\": 5, \"spredDeg\": 3}"));
    EXPECT_NE(e.field().find("spredDeg"), std::string::npos) << e.field();
    EXPECT_EQ(e.line(), 11);
}

TEST(HandshapeFileTest, MissingFingerDuplicateNameAndBrokenJsonAreRejected) {
    InputError e = parseError(replaced(kGood, ", \"little\": \"E0\"", ""));
    EXPECT_NE(e.field().find("little"), std::string::npos);
    e = parseError(replaced(kGood, "\"name\": \"Bad\"", "\"name\": \"B\""));
    EXPECT_NE(std::string(e.what()).find("duplicate"), std::string::npos);
    e = parseError(replaced(kGood, "\"thumb\": \"side\"}", "\"thumb\": \"side\""));
    EXPECT_GE(e.line(), 10);
    EXPECT_NE(std::string(e.what()).find("JSON"), std::string::npos);
    e = parseError(replaced(kGood, "\"thumb\": \"side\"", "\"thumb\": \"side\", \"contact\": \"pinky\""));
    EXPECT_NE(std::string(e.what()).find("pinky"), std::string::npos);
}

TEST(HandshapeFileTest, AnAslLexLabelTheDatasetDoesNotUseIsRejected) {
    // bent_B was this library's own spelling of ASL-LEX 2.0's flat_b.
    const InputError e =
        parseError(replaced(kGood, "{\"name\": \"Bad\",", "{\"name\": \"Bad\", \"aslLex\": \"bent_B\","));
    EXPECT_EQ(e.file(), "shapes.json");
    EXPECT_EQ(e.line(), 9);
    EXPECT_NE(e.field().find("aslLex"), std::string::npos) << e.field();
    EXPECT_NE(std::string(e.what()).find("not an ASL-LEX 2.0 handshape label"), std::string::npos) << e.what();
    EXPECT_NO_THROW(parseHandshapes(replaced(kGood, "{\"name\": \"Bad\",", "{\"name\": \"Bad\", \"aslLex\": \"flat_b\","),
                                    "shapes.json", hand::buildHandModel()));
}

TEST(ScenesPathTest, ExplicitDirectoryWinsAndMissingOnesAreErrors) {
    const std::string source = std::string(SIGNSTIM_SOURCE_DIR) + "/scenes";
    EXPECT_EQ(resolveScenesDir(source), source);
    EXPECT_THROW(resolveScenesDir("/nonexistent/scenes"), InputError);
    ::setenv("SIGNSTIM_SCENES", source.c_str(), 1);
    EXPECT_EQ(resolveScenesDir(), source);
    ::setenv("SIGNSTIM_SCENES", "/nonexistent/scenes", 1);
    EXPECT_THROW(resolveScenesDir(), InputError);
    ::unsetenv("SIGNSTIM_SCENES");
    EXPECT_TRUE(std::filesystem::is_directory(resolveScenesDir()));
}

}  // namespace
}  // namespace signstim::stimuli
