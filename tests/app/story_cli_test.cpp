// `signstim story` as a user runs it: check, timeline, and the signer rendered in two
// versions whose frames outside the verb slots are byte-identical (validation layer on).
#include "tests/app/run_command.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using signstim::test::runSignstim;
using signstim::test::readFile;
using signstim::test::shellQuote;

const std::string kScenes = fs::path(SIGNSTIM_SOURCE_DIR).append("scenes").string();
const std::string kExample = fs::path(kScenes).append("stories/examples/the-question.json").string();

fs::path freshDir(const std::string& name) {
    return signstim::test::freshDir(SIGNSTIM_BINARY_DIR, "story_cli_test", name, true);
}

TEST(StoryCli, CheckSaysOkForTheExampleAndNamesLineAndColumnOfAnUnknownSign) {
    const auto ok = runSignstim("story " + shellQuote(kExample) + " --check --scenes " + shellQuote(kScenes));
    EXPECT_EQ(ok.status, 0) << ok.output;
    EXPECT_NE(ok.output.find("ok: \"The question"), std::string::npos) << ok.output;
    // Then how close the hands come in each version. They never interpenetrate at a transition
    // and never touch where the sign does not; the one warning is HELP's contact, still deeper
    // than a touch (a known case: tests/signer/clearance_test.cpp, kKnownTooDeep).
    EXPECT_NE(ok.output.find("closest approach of the hands"), std::string::npos) << ok.output;
    EXPECT_NE(ok.output.find("uninflected: at transitions"), std::string::npos) << ok.output;
    // (The clearance report ends where the timing report begins.)
    const std::string clearance = ok.output.substr(0, ok.output.find("timing ("));
    std::istringstream lines(clearance);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("warning:", 0) == 0) {
            EXPECT_NE(line.find("HELP (sentence 3): the hands sink into each other"), std::string::npos) << line;
        }

    const fs::path dir = freshDir("check");
    std::string text = readFile(kExample);
    text.replace(text.find("NOT KNOW"), 8, "NOT KNOWW");
    std::ofstream(dir / "bad.json") << text;
    const auto bad = runSignstim("story " + shellQuote((dir / "bad.json").string()) + " --check --scenes " + shellQuote(kScenes));
    EXPECT_EQ(bad.status, 2) << bad.output;
    EXPECT_NE(bad.output.find("bad.json:11:19:"), std::string::npos) << bad.output;
    EXPECT_NE(bad.output.find("unknown gloss 'KNOWW' (closest known: KNOW"), std::string::npos) << bad.output;

    const auto noVersion = runSignstim("story " + shellQuote(kExample) + " --json --scenes " + shellQuote(kScenes));
    EXPECT_EQ(noVersion.status, 1) << noVersion.output;
}

TEST(StoryCli, CheckReportsEachVersionsPaceAndPeakWristSpeedWithinTheLimit) {
    // docs/stories.md, "What story --check measures": per version, duration, signs/s, letters/s,
    // pause share, peak wrist and head speeds of the posed signer.
    for (const std::string& file : {kExample, fs::path(kScenes).append("stories/story-05.json").string()}) {
        const auto r = runSignstim("story " + shellQuote(file) + " --check --scenes " + shellQuote(kScenes));
        ASSERT_EQ(r.status, 0) << r.output;
        ASSERT_NE(r.output.find("timing (natural)"), std::string::npos) << r.output;
        int versions = 0;
        std::istringstream lines(r.output.substr(r.output.find("timing (natural)")));
        for (std::string line; std::getline(lines, line);) {
            double duration = 0, telling = 0, signs = 0, wrist = 0;
            const std::size_t at = line.find(": ");
            if (line.rfind("  ", 0) != 0 || at == std::string::npos) continue;
            ASSERT_EQ(std::sscanf(line.c_str() + at + 2, "%lf s (telling %lf s): %lf signs/s", &duration, &telling, &signs), 3)
                << line;
            const std::size_t peak = line.find("peak wrist ");
            ASSERT_NE(peak, std::string::npos) << line;
            ASSERT_EQ(std::sscanf(line.c_str() + peak, "peak wrist %lf m/s", &wrist), 1) << line;
            EXPECT_NE(line.find("pauses "), std::string::npos) << line;
            EXPECT_NE(line.find("peak head "), std::string::npos) << line;
            EXPECT_GT(duration, telling);
            EXPECT_GT(signs, 1.3) << line;
            // SPEC §6.2 bounds the wrist at 2.5 m/s; the timeline keeps the hand's reference point
            // under 2.3 m/s (tests/stimuli/story_timing_test.cpp), and the posed wrist, with the
            // arm solution and the detours, peaks up to ~3.2 m/s in a few transitions and verb
            // paths (docs/stories.md): reported, and bounded here against regressions.
            EXPECT_LE(wrist, 3.5) << file << ": " << line;
            EXPECT_GT(wrist, 0.5) << line;
            ++versions;
        }
        EXPECT_EQ(versions, 4) << r.output;
    }
    // The legacy timing, 1 sign a second, is slower than conversational signing: a warning,
    // and with --strict exit 2.
    const auto legacy = runSignstim("story " + shellQuote(kExample) + " --check --timing legacy --scenes " + shellQuote(kScenes));
    EXPECT_EQ(legacy.status, 0) << legacy.output;
    EXPECT_NE(legacy.output.find("slower than conversational signing"), std::string::npos) << legacy.output;
    // ... and its wrists peak faster than the natural timing's (no speed limit).
    const auto peakOf = [](const std::string& output) {
        double wrist = 0.0;
        const std::size_t at = output.find("  point: ");
        const std::size_t peak = output.find("peak wrist ", at);
        if (at != std::string::npos && peak != std::string::npos) std::sscanf(output.c_str() + peak, "peak wrist %lf", &wrist);
        return wrist;
    };
    const auto natural = runSignstim("story " + shellQuote(kExample) + " --check --scenes " + shellQuote(kScenes));
    EXPECT_GT(peakOf(legacy.output), peakOf(natural.output)) << legacy.output << natural.output;
    const auto strict =
        runSignstim("story " + shellQuote(kExample) + " --check --strict --timing legacy --scenes " + shellQuote(kScenes));
    EXPECT_EQ(strict.status, 2) << strict.output;
    EXPECT_NE(strict.output.find("a timing limit is broken"), std::string::npos) << strict.output;
}

TEST(StoryCli, JsonTimelineListsTheVerbSlots) {
    const auto r = runSignstim("story " + shellQuote(kExample) + " --version vector --json --scenes " + shellQuote(kScenes),
                               signstim::test::Capture::StdoutOnly);
    ASSERT_EQ(r.status, 0) << r.output;
    const nlohmann::json timeline = nlohmann::json::parse(r.output);
    int verbs = 0;
    for (const auto& span : timeline["spans"]) verbs += span["kind"] == "verb";
    EXPECT_EQ(verbs, 2);
    EXPECT_EQ(timeline["version"], "vector");
}

// The property the study relies on to render shared frames once: every frame outside the
// verb slots is the same image in every version.
TEST(StoryCli, RenderedFramesOutsideTheVerbSlotsAreByteIdenticalAcrossVersions) {
    const fs::path dir = freshDir("render");
    const std::string common = "story " + shellQuote(kExample) + " --quiet --size 96x72 --fps 5 --msaa 1 --scenes " +
                               shellQuote(kScenes);
    for (const std::string version : {"point", "uninflected"}) {
        const auto r = runSignstim(common + " --version " + version + " --out " + shellQuote((dir / version).string()),
                                   signstim::test::Capture::StdoutAndStderr, "SIGNSTIM_VALIDATION=1");
        ASSERT_EQ(r.status, 0) << r.output;
        EXPECT_EQ(r.output.find("Validation"), std::string::npos) << r.output;
    }
    const auto json = runSignstim(common + " --version point --json", signstim::test::Capture::StdoutOnly);
    const nlohmann::json timeline = nlohmann::json::parse(json.output);
    auto insideVerb = [&](double t) {
        for (const auto& span : timeline["spans"])
            if (span["kind"] == "verb" && t >= span["start"].get<double>() - 1e-3 && t <= span["end"].get<double>() + 1e-3)
                return true;
        return false;
    };
    int same = 0, differ = 0;
    for (int frame = 1;; ++frame) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%05d.png", frame);
        if (!fs::exists(dir / "point" / name)) break;
        const bool equal = readFile(dir / "point" / name) == readFile(dir / "uninflected" / name);
        const double t = (frame - 1) / 5.0;
        if (insideVerb(t)) {
            differ += !equal;
        } else {
            EXPECT_TRUE(equal) << name << " at " << t << " s differs outside the verb slots";
            same += equal;
        }
    }
    // (At 5 fps the example's ~10 s, ~2.5 s of them in its two verb slots, share ~40 frames.)
    EXPECT_GT(same, 30);
    EXPECT_GT(differ, 2) << "the versions must differ inside the verb slots";
}

}  // namespace
