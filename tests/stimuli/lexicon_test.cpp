// The lexicon (docs/lexicon.md): body locations, touch points placed by the hand model, and
// every kind of mistake named at its file, line and field.
#include "stimuli/story/lexicon.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace signstim::stimuli {
namespace {

const hand::HandModel& model() {
    static const hand::HandModel m = hand::buildHandModel();
    return m;
}

const HandshapeLibrary& shapes() {
    static const HandshapeLibrary library =
        loadHandshapes(std::string(SIGNSTIM_SOURCE_DIR) + "/scenes/handshapes.json", model());
    return library;
}

// A lexicon with one sign whose right-hand keyframes are `keys` (JSON array text).
std::string lexiconText(const std::string& keys, const std::string& extraSignFields = "") {
    return "{\n"
           "  \"format\": \"signstim-lexicon\",\n"
           "  \"version\": 1,\n"
           "  \"locations\": {\n"
           "    \"chin\": [0, 255, 95],\n"
           "    \"chest\": [0, 0, 110]\n"
           "  },\n"
           "  \"signs\": [\n"
           "    {\"gloss\": \"THANK-YOU\", \"hands\": [\"right\"]," + extraSignFields + "\n"
           "     \"keyframes\": {\"right\": " + keys + "}}\n"
           "  ]\n"
           "}\n";
}

const std::string kGoodKeys =
    "[\n"
    "      {\"time\": 0, \"at\": \"chin\", \"touch\": \"fingertips\", \"fingers\": [0, 1, 0], \"palm\": [0, 0, -1], \"handshape\": \"B\"},\n"
    "      {\"time\": 0.4, \"at\": \"chin\", \"offset\": [0, -80, 200], \"touch\": \"fingertips\", \"fingers\": [0, 0.5, 1], \"palm\": [0, 1, 0], \"handshape\": \"B\"}\n"
    "     ]";

Lexicon parse(const std::string& text) { return parseLexicon(parseJsonText(text, "lexicon.json"), shapes(), model()); }

InputError errorOf(const std::string& text) {
    try {
        parse(text);
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return InputError("none");
}

TEST(Lexicon, ATouchPointLandsOnItsLocation) {
    const Lexicon lexicon = parse(lexiconText(kGoodKeys));
    const LexiconSign& sign = *lexicon.find("THANK-YOU");
    ASSERT_EQ(sign.keyframes.size(), 1u);
    const VerbKeyframe& first = sign.keyframes[0][0];
    const glm::dvec3 tip = *touchPointMm(model(), shapes().at("B").controls, hand::Side::Right, "fingertips");
    // Fingers up, so the palm's origin is a hand's length below the chin.
    const glm::dvec3 origin = first.pose.positionMm;
    EXPECT_NEAR(origin.y, 255.0 - tip.z, 1.0);
    EXPECT_NEAR(glm::length(palmOriginForTouch(glm::dvec3(0, 255, 95), first.pose.orientation, tip) - origin), 0.0, 1e-9);
    const VerbKeyframe& second = sign.keyframes[0][1];
    // The fingertips moved out from the chin by the offset (forward and down).
    const glm::dvec3 tipThen = second.pose.positionMm + second.pose.orientation * glm::dvec3(tip.x, -tip.y, tip.z);
    EXPECT_NEAR(glm::length(tipThen - glm::dvec3(0, 175, 295)), 0.0, 1e-6);
    EXPECT_DOUBLE_EQ(sign.durationSeconds(), 0.4);
}

// The handedness of the signing-space orientation convention: a right hand held up with the
// palm toward the viewer has its thumb on the signer's left (-x); a left hand, on the right.
TEST(Lexicon, TheThumbIsOnTheMidlineSideOfAnUprightHandFacingTheViewer) {
    const std::string keys = "[{\"time\": 0, \"position\": [0, 0, 300], \"touch\": \"thumb-tip\", \"fingers\": [0, 1, 0], "
                             "\"palm\": [0, 0, 1], \"handshape\": \"5\"},"
                             " {\"time\": 0.2, \"position\": [0, 0, 300], \"fingers\": [0, 1, 0], \"palm\": [0, 0, 1], "
                             "\"handshape\": \"5\"}]";
    const Lexicon lexicon = parse(lexiconText(keys));
    const LexiconSign& sign = lexicon.signs.front();
    // Keyframe 0 puts the thumb tip at x = 0, so the palm's origin lies to the signer's right of it.
    EXPECT_GT(sign.keyframes[0][0].pose.positionMm.x, 30.0);
    // The left hand mirrored: its thumb is on the signer's right.
    const glm::dvec3 leftThumb = *touchPointMm(model(), shapes().at("5").controls, hand::Side::Left, "thumb-tip");
    const glm::dvec3 leftOrigin = palmOriginForTouch(glm::dvec3(0, 0, 300), sign.keyframes[0][1].pose.orientation, leftThumb);
    EXPECT_LT(leftOrigin.x, -30.0);
}

TEST(Lexicon, EachMistakeNamesFileLineAndField) {
    struct Case {
        std::string text;
        int line;
        const char* field;
        const char* says;
    };
    std::string unknownShape = kGoodKeys;
    unknownShape.replace(unknownShape.find("\"B\""), 3, "\"BB\"");
    std::string unknownLocation = kGoodKeys;
    unknownLocation.replace(unknownLocation.find("\"chin\""), 6, "\"nose\"");
    std::string unknownTouch = kGoodKeys;
    unknownTouch.replace(unknownTouch.find("\"fingertips\""), 12, "\"elbow\"");
    std::string bothPlaces = kGoodKeys;
    bothPlaces.replace(bothPlaces.find("\"at\": \"chin\""), 12, "\"at\": \"chin\", \"position\": [0, 0, 0]");
    std::string farAway = kGoodKeys;
    farAway.replace(farAway.find("[0, -80, 200]"), 13, "[0, -80, 2000]");
    const Case cases[] = {
        {lexiconText(unknownShape), 11, "/signs/0/keyframes/right/0/handshape", "unknown handshape 'BB'"},
        {lexiconText(unknownLocation), 11, "/signs/0/keyframes/right/0/at", "known: chest, chin"},
        {lexiconText(unknownTouch), 11, "/signs/0/keyframes/right/0/touch", "unknown touch point 'elbow'"},
        {lexiconText(bothPlaces), 11, "/signs/0/keyframes/right/0", "either"},
        {lexiconText(farAway), 12, "/signs/0/keyframes/right/1/offset", "at most 400 mm"},
        {lexiconText(kGoodKeys, " \"passes\": 0,"), 9, "/signs/0/passes", "1 to 8"},
        {lexiconText(kGoodKeys, " \"contact\": [\"hand\"],"), 9, "/signs/0/contact/0", "[\"hands\", \"body\"]"},
        {lexiconText(kGoodKeys, " \"contact\": \"body\","), 9, "/signs/0/contact", "touches on purpose"},
        {lexiconText(kGoodKeys, " \"contact\": [\"body\", \"body\"],"), 9, "/signs/0/contact/1", "touches on purpose"},
    };
    for (const Case& c : cases) {
        const InputError e = errorOf(c.text);
        EXPECT_EQ(e.file(), "lexicon.json");
        EXPECT_EQ(e.line(), c.line) << e.what();
        EXPECT_EQ(e.field(), c.field) << e.what();
        EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
    }
    std::string wrongFormat = lexiconText(kGoodKeys);
    wrongFormat.replace(wrongFormat.find("signstim-lexicon"), 16, "signstim-verbs");
    EXPECT_EQ(errorOf(wrongFormat).line(), 2);
}

TEST(Lexicon, ASignSaysWhatItsCitationFormTouches) {
    // THANK-YOU touches the chin: the clearance check lets the hand touch the body there.
    const Lexicon touching = parse(lexiconText(kGoodKeys, " \"contact\": [\"body\"],"));
    EXPECT_TRUE(touching.signs.front().contact.body);
    EXPECT_FALSE(touching.signs.front().contact.hands);
    const Lexicon both = parse(lexiconText(kGoodKeys, " \"contact\": [\"hands\", \"body\"],"));
    EXPECT_TRUE(both.signs.front().contact.hands && both.signs.front().contact.body);
    const Lexicon none = parse(lexiconText(kGoodKeys));
    EXPECT_FALSE(none.signs.front().contact.hands || none.signs.front().contact.body);
}

}  // namespace
}  // namespace signstim::stimuli

namespace signstim::stimuli {
namespace {

TEST(Lexicon, AFolderIsReadInNameOrderWithSharedLocationsAndEachSignOnce) {
    const std::filesystem::path dir = std::filesystem::path(SIGNSTIM_BINARY_DIR) / "lexicon_test" / "folder";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string header = "{\"format\": \"signstim-lexicon\", \"version\": 1,\n";
    std::ofstream(dir / "00-locations.json") << header << "\"locations\": {\"chin\": [0, 255, 95]}}\n";
    const std::string sign = "\"signs\": [{\"gloss\": \"THANK-YOU\", \"hands\": [\"right\"], \"keyframes\": {\"right\": [\n"
                             "{\"time\": 0, \"at\": \"chin\", \"fingers\": [0, 1, 0], \"palm\": [0, 0, -1], \"handshape\": \"B\"},\n"
                             "{\"time\": 0.4, \"at\": \"chin\", \"offset\": [0, 0, 100], \"fingers\": [0, 1, 0], \"palm\": [0, 0, -1], \"handshape\": \"B\"}]}}]}\n";
    std::ofstream(dir / "a.json") << header << sign;
    const Lexicon lexicon = loadLexicon(dir, shapes(), model());
    EXPECT_EQ(lexicon.glosses(), std::vector<std::string>{"THANK-YOU"});
    EXPECT_EQ(lexicon.file, dir.string());

    std::ofstream(dir / "b.json") << header << sign;  // the same sign again
    try {
        loadLexicon(dir, shapes(), model());
        ADD_FAILURE() << "a sign defined twice was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(e.file().find("b.json"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("defined twice"), std::string::npos) << e.what();
    }
    std::filesystem::remove(dir / "b.json");
    std::ofstream(dir / "c.json") << header << "\"locations\": {\"chin\": [0, 250, 95]}}\n";
    EXPECT_THROW(loadLexicon(dir, shapes(), model()), InputError);
}

}  // namespace
}  // namespace signstim::stimuli

namespace signstim::stimuli {
namespace {

// A lab's own lexicon (--lexicon) on top of the default one: it adds signs and overrides the
// default's signs and locations of the same name, each override listed; within the lab's own
// files a sign is still defined once.
TEST(Lexicon, ALabLexiconAddsToAndOverridesTheDefaultOne) {
    const std::filesystem::path root = std::filesystem::path(SIGNSTIM_BINARY_DIR) / "lexicon_test" / "overlay";
    std::filesystem::remove_all(root);
    std::filesystem::create_directories(root / "base");
    std::filesystem::create_directories(root / "lab");
    const std::string header = "{\"format\": \"signstim-lexicon\", \"version\": 1,\n";
    const auto sign = [](const std::string& gloss, const std::string& at, double seconds) {
        return "{\"gloss\": \"" + gloss + "\", \"hands\": [\"right\"], \"keyframes\": {\"right\": [\n"
               "{\"time\": 0, \"at\": \"" + at + "\", \"fingers\": [0, 1, 0], \"palm\": [0, 0, -1], \"handshape\": \"B\"},\n"
               "{\"time\": " + std::to_string(seconds) + ", \"at\": \"" + at +
               "\", \"offset\": [0, 0, 100], \"fingers\": [0, 1, 0], \"palm\": [0, 0, -1], \"handshape\": \"B\"}]}}";
    };
    std::ofstream(root / "base" / "00-locations.json") << header << "\"locations\": {\"chin\": [0, 255, 95], \"chest\": [0, 0, 110]}}\n";
    std::ofstream(root / "base" / "signs.json")
        << header << "\"signs\": [\n" << sign("THANK-YOU", "chin", 0.4) << ",\n" << sign("MY", "chest", 0.3) << "]}\n";
    std::ofstream(root / "lab" / "ours.json") << header << "\"locations\": {\"chin\": [0, 250, 95]},\n\"signs\": [\n"
                                              << sign("STUDENT", "chest", 0.5) << ",\n"
                                              << sign("MY", "chest", 0.6) << "]}\n";

    const Lexicon lexicon = loadLexicon(root / "base", root / "lab" / "ours.json", shapes(), model());
    EXPECT_EQ(lexicon.glosses(), (std::vector<std::string>{"THANK-YOU", "MY", "STUDENT"}))
        << "added at the end, an override in the default's place";
    EXPECT_DOUBLE_EQ(lexicon.find("MY")->durationSeconds(), 0.6) << "the lab's MY replaces the default's";
    EXPECT_NE(lexicon.find("MY")->file.find("ours.json"), std::string::npos);
    EXPECT_DOUBLE_EQ(lexicon.locations.at("chin").y, 250.0) << "the lab may move a location";
    ASSERT_EQ(lexicon.overrides.size(), 2u);
    EXPECT_EQ(lexicon.overrides[0].what, "location chin");
    EXPECT_EQ(lexicon.overrides[1].what, "sign MY");
    EXPECT_NE(lexicon.overrides[1].file.find("ours.json"), std::string::npos);
    EXPECT_EQ(lexicon.overrides[1].line, 7);
    EXPECT_NE(lexicon.overrides[1].replacedFile.find("signs.json"), std::string::npos);
    EXPECT_EQ(lexicon.overrides[1].replacedLine, 6);

    // Without a lab lexicon: the default alone, nothing overridden.
    const Lexicon base = loadLexicon(root / "base", {}, shapes(), model());
    EXPECT_EQ(base.glosses(), (std::vector<std::string>{"THANK-YOU", "MY"}));
    EXPECT_TRUE(base.overrides.empty());

    // Twice within the lab's own files is still a mistake, naming both places.
    std::ofstream(root / "lab" / "more.json") << header << "\"signs\": [\n" << sign("STUDENT", "chest", 0.5) << "]}\n";
    try {
        loadLexicon(root / "base", root / "lab", shapes(), model());
        ADD_FAILURE() << "a lab sign defined twice was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(e.file().find("ours.json"), std::string::npos) << e.what();
        EXPECT_EQ(e.line(), 4);
        EXPECT_NE(std::string(e.what()).find("defined twice (also "), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("more.json:3"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace signstim::stimuli
