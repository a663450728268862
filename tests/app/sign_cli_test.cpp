// `signstim sign GLOSS` as a user runs it (issue 22 §4): a notation sign's claimed code and
// checks, a keyframe sign said to be one, an unknown gloss and a failing sign refused with
// exit 2 naming where, and the contact sheet rendered (validation layer on).
#include "tests/app/run_command.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using signstim::test::runSignstim;
using signstim::test::shellQuote;

const std::string kScenes = fs::path(SIGNSTIM_SOURCE_DIR).append("scenes").string();

fs::path freshDir(const std::string& name) { return signstim::test::freshDir(SIGNSTIM_BINARY_DIR, "sign_cli_test", name, true); }

TEST(SignCli, PrintsTheClaimedCodeTheEntryAndEveryCheck) {
    const auto r = runSignstim("sign MOTHER --scenes " + shellQuote(kScenes));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("claims, part 1: handshape 5, OneHanded, movement Straight, Head/Chin, contact, repeated"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("follows ASL-LEX 2.0 entry 'mother'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("ok   contact 2 thumb-tip at chin"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("ok   repetitions: 2"), std::string::npos) << r.output;
    // Judged on the hands as posed too (issue 22: the hand the viewer sees).
    EXPECT_NE(r.output.find("ok   posed contact 2 thumb-tip at chin"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("ok   posed orientation, right hand"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("FAIL"), std::string::npos) << r.output;
    // Every default sign is in the notation (issue 22); a lab's own sign may still be keyframes
    // (synthetic: one still key).
    const fs::path dir = freshDir("keyframes");
    std::ofstream(dir / "lab.json") << R"({"format": "signstim-lexicon", "version": 1, "signs": [
  {"gloss": "STILL-L", "meaning": "synthetic: an L hand held in front of the chest", "hands": ["right"],
   "keyframes": {"right": [{"time": 0, "position": [60, 0, 250], "fingers": [0, 1, 0], "palm": [0, 0, 1], "handshape": "L"},
                           {"time": 0.3, "position": [60, 0, 250], "fingers": [0, 1, 0], "palm": [0, 0, 1], "handshape": "L"}]}}]}
)";
    const auto keyframes =
        runSignstim("sign STILL-L --scenes " + shellQuote(kScenes) + " --lexicon " + shellQuote((dir / "lab.json").string()));
    ASSERT_EQ(keyframes.status, 0) << keyframes.output;
    EXPECT_NE(keyframes.output.find("written as keyframes"), std::string::npos) << keyframes.output;
    const auto unknown = runSignstim("sign NOSUCHSIGN --scenes " + shellQuote(kScenes));
    EXPECT_EQ(unknown.status, 2) << unknown.output;
    EXPECT_NE(unknown.output.find("field 'GLOSS': no sign NOSUCHSIGN"), std::string::npos) << unknown.output;
}

TEST(SignCli, ASignThatDoesNotRealizeItsCodeExitsTwoNamingItsLine) {
    // A lab's sign (synthetic) claiming a circle while its description is a straight stroke.
    const fs::path dir = freshDir("failing");
    std::ofstream(dir / "lab.json") << R"({"format": "signstim-lexicon", "version": 1, "signs": [
  {"gloss": "ROUNDISH", "notation": {"parts": [{"seconds": 0.5, "handshape": "L", "fingers": "up", "palm": "forward",
    "at": "neutral-right", "path": {"shape": "straight", "direction": "right", "size": 50}}],
    "aslLex": {"entry": "library", "durationMs": 500, "code": [{"movement": "Circular"}]}}}]}
)";
    const auto r = runSignstim("sign ROUNDISH --scenes " + shellQuote(kScenes) + " --lexicon " + shellQuote((dir / "lab.json").string()));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("FAIL code, part 1: movement Straight (entry: Circular)"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("lab.json:2: field 'notation': ROUNDISH does not realize the code it claims"), std::string::npos)
        << r.output;
}

TEST(SignCli, RendersAContactSheetOfTheSignsFrames) {
    const fs::path dir = freshDir("sheet");
    const fs::path sheet = dir / "library.png";
    const auto r = runSignstim("sign LIBRARY --quiet --size 160x120 --columns 10 --out " + shellQuote(sheet.string()) +
                               " --scenes " + shellQuote(kScenes));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("contact sheet of"), std::string::npos) << r.output;
    ASSERT_TRUE(fs::exists(sheet));
    // 10 tiles a row of 48x48 (the middle 60 % by the top 80 % of 160x120, halved) with 4 px gaps.
    std::ifstream png(sheet, std::ios::binary);
    unsigned char header[24] = {};
    png.read(reinterpret_cast<char*>(header), sizeof header);
    const unsigned width = (header[16] << 24) | (header[17] << 16) | (header[18] << 8) | header[19];
    EXPECT_EQ(width, 10u * 48u + 9u * 4u);
}

}  // namespace
