// `signstim study` with a human-video version (issue 24 §2) as a lab runs it: its recordings are
// probed (a missing or broken one refused naming the file and the pattern), normalised to the
// study's size and rate, listed in the manifest with their sources' hashes, verified, resumed
// (a changed recording renders its own unit again, nothing else, and is the only one probed
// again), and sharded.
// The "recordings" are SYNTHETIC: ffmpeg's procedural test patterns (lavfi testsrc2), no person.
#include "tests/app/run_command.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

namespace {

namespace fs = std::filesystem;
using signstim::test::Capture;
using signstim::test::readFile;
using signstim::test::runShell;
using signstim::test::runSignstim;
using signstim::test::shellQuote;

const std::string kScenes = fs::path(SIGNSTIM_SOURCE_DIR).append("scenes").string();

fs::path freshDir(const std::string& name) {
    return signstim::test::freshDir(SIGNSTIM_BINARY_DIR, "study_human_cli_test", name, false);
}

// A synthetic clip (ffmpeg's test pattern, hue-shifted so each clip differs).
void syntheticClip(const fs::path& file, const std::string& size, int rate, double seconds, int hue) {
    const auto r = signstim::test::writeSyntheticRecording(file, size, rate, seconds, hue);
    ASSERT_EQ(r.status, 0) << r.output;
}

// A study folder: 2 animated versions and the synthetic "human" one in both phases (3 x 3), its
// questions and instructions in English (no signed clips: study_done_when_cli_test.cpp has both),
// its recordings in human/ beside the study file (story clips 4:3 at 25 fps, sentence clips
// square at 10 fps, so both are normalised).
fs::path studyWithRecordings(const fs::path& dir) {
    fs::create_directories(dir);
    for (int i = 1; i <= 3; ++i) {
        syntheticClip(dir / "human" / ("synthetic-story-0" + std::to_string(i) + ".mp4"), "96x72", 25, 1.5, 40 * i);
        syntheticClip(dir / "human" / ("synthetic-likert-0" + std::to_string(i) + ".mp4"), "80x80", 10, 2.0, 90 * i);
    }
    const fs::path file = dir / "human-study.json";
    std::ofstream(file) << R"({
  "format": "signstim-study", "version": 1,
  "title": "Synthetic human-video version, a test", "seed": 3, "participants": 3,
  "versions": ["point", "uninflected"],
  "humanVersions": [{"name": "human", "phase1Clips": "human/synthetic-{story}.mp4",
                     "phase2Clips": "human/synthetic-{sentence}.mp4"}],
  "stories": [")" + kScenes + R"(/stories/story-01.json", ")" + kScenes + R"(/stories/story-02.json", ")" +
                               kScenes + R"(/stories/story-03.json"],
  "phase2": {"story": ")" + kScenes + R"(/studies/phase2-sentences.json", "sentences": [1, 2, 3]},
  "session": {"questions": "english", "instructions": {"show": "english"}},
  "render": {"size": "64x64", "fps": 2, "msaa": 1}
})";
    return file;
}

std::string run(const fs::path& studyFile, const fs::path& out, const std::string& extra = "") {
    const auto r = runSignstim("study " + shellQuote(studyFile.string()) + " --scenes " + shellQuote(kScenes) + " --out " +
                               shellQuote(out.string()) + " --quiet" + extra);
    EXPECT_EQ(r.status, 0) << r.output;
    return r.output;
}

std::map<std::string, nlohmann::json> videos(const fs::path& out) {
    std::map<std::string, nlohmann::json> byPath;
    const nlohmann::json manifest = nlohmann::json::parse(readFile(out / "manifest.json"));
    for (const auto& f : manifest["files"])
        if (f["kind"] == "video") byPath[f["path"].get<std::string>()] = f;
    return byPath;
}

std::string sha256Of(const fs::path& file) {
    return runShell("sha256sum " + shellQuote(file.string()) + " | cut -c1-64", Capture::StdoutOnly).output.substr(0, 64);
}

}  // namespace

TEST(StudyHumanCli, RecordingsAreNormalisedHashedVerifiedAndAChangedOneRendersOnlyItsUnit) {
    const fs::path dir = freshDir("resume");
    const fs::path file = studyWithRecordings(dir);
    const fs::path out = dir / "out";
    run(file, out);
    auto clips = videos(out);
    ASSERT_EQ(clips.size(), 12u);  // 3 stories x 3 versions, 3 side-by-side sentences
    const nlohmann::json& human = clips.at("clips/story-02_version-human.mp4");
    // Normalised to the study's size and rate: 1.5 s (38 frames at 25 fps, to 1.52 s) at 2 fps shows
    // the recording at 0, 0.5, 1 and 1.5 s.
    EXPECT_EQ(human["width"], 64);
    EXPECT_EQ(human["height"], 64);
    EXPECT_EQ(human["fps"], "2");
    EXPECT_EQ(human["frames"], 4);
    EXPECT_EQ(human["shows"]["version"], "human");
    EXPECT_EQ(human["shows"]["source"]["sha256"], sha256Of(dir / "human" / "synthetic-story-02.mp4"));
    EXPECT_EQ(human["shows"]["source"]["width"], 96);
    EXPECT_EQ(human["shows"]["source"]["fps"], "25/1");
    const auto probe = runShell("ffprobe -v error -select_streams v:0 -count_frames -show_entries "
                                "stream=codec_name,width,height,pix_fmt,r_frame_rate,nb_read_frames -of csv=p=0 " +
                                    shellQuote((out / "clips/story-02_version-human.mp4").string()),
                                Capture::StdoutOnly);
    EXPECT_EQ(probe.output, "h264,64,64,yuv420p,2/1,4\n");
    // The side-by-side clip names its panels and the recording in the human one.
    bool composite = false;
    for (const auto& entry : clips) {
        const nlohmann::json& shows = entry.second["shows"];
        if (shows["phase"] != 2) continue;
        ASSERT_TRUE(shows.contains("sources")) << shows.dump();
        std::string humanPanel;
        for (const auto& panel : shows["panels"].items())
            if (panel.value() == "human") {
                composite = shows["sources"].contains(panel.key());
                humanPanel = panel.key();
            }
        EXPECT_TRUE(composite) << shows.dump();
        // Its eye-tracking regions: rows for the signer's panels, none for the recording's.
        const fs::path stem = fs::path(entry.first).stem();
        const std::string regions = readFile(out / "regions" / (stem.string() + ".csv"));
        EXPECT_EQ(regions.find("," + humanPanel + ",face,"), std::string::npos) << stem;
        EXPECT_NE(regions.find(",face,"), std::string::npos) << stem;
    }
    EXPECT_EQ(runSignstim("study verify " + shellQuote(out.string())).status, 0);
    // The exports and the review page carry the human version like any other.
    EXPECT_NE(readFile(out / "overview.csv").find("story-01,The copied homework,point,uninflected,human"), std::string::npos)
        << readFile(out / "overview.csv");
    EXPECT_NE(readFile(out / "participants" / "P01" / "P01_conditions.csv").find("_version-human.mp4"), std::string::npos);
    EXPECT_NE(readFile(out / "index.html").find("story-02_version-human.mp4"), std::string::npos);

    // Nothing changed: nothing rendered, and no recording probed again (app/study_human.hpp: the
    // probes are kept in the folder by content), shown with an ffprobe on PATH that always fails.
    EXPECT_TRUE(fs::is_regular_file(out / ".signstim" / "human-probes.json"));
    const fs::path failingProbe = dir / "failing-ffprobe";
    fs::create_directories(failingProbe);
    std::ofstream(failingProbe / "ffprobe") << "#!/bin/sh\necho 'a stand-in ffprobe that always fails' >&2\nexit 1\n";
    fs::permissions(failingProbe / "ffprobe", fs::perms::owner_all);
    const std::string withFailingProbe = "PATH=" + shellQuote(failingProbe.string()) + ":\"$PATH\"";
    const std::string manifest = readFile(out / "manifest.json");
    const auto again = runSignstim("study " + shellQuote(file.string()) + " --scenes " + shellQuote(kScenes) + " --out " +
                                       shellQuote(out.string()),
                                   Capture::StdoutAndStderr, withFailingProbe);
    EXPECT_EQ(again.status, 0) << again.output;
    EXPECT_NE(again.output.find("0 of 6 units rendered, 6 already complete"), std::string::npos) << again.output;
    EXPECT_EQ(readFile(out / "manifest.json"), manifest);  // the kept probes say what the fresh ones said
    syntheticClip(dir / "human" / "synthetic-story-02.mp4", "96x72", 25, 2.5, 200);
    // The replaced recording is probed again (and, with the failing ffprobe, refused), the others
    // not: the error names it, not story-01's recording, which is probed first.
    const auto probedAgain = runSignstim("study " + shellQuote(file.string()) + " --scenes " + shellQuote(kScenes) +
                                             " --out " + shellQuote(out.string()),
                                         Capture::StdoutAndStderr, withFailingProbe);
    EXPECT_EQ(probedAgain.status, 2) << probedAgain.output;
    EXPECT_NE(probedAgain.output.find("synthetic-story-02.mp4: not a video ffmpeg can read"), std::string::npos)
        << probedAgain.output;
    const auto changed = runSignstim("study " + shellQuote(file.string()) + " --scenes " + shellQuote(kScenes) + " --out " +
                                     shellQuote(out.string()));
    EXPECT_NE(changed.output.find("1 of 6 units rendered, 5 already complete"), std::string::npos) << changed.output;
    const auto after = videos(out);
    EXPECT_EQ(after.at("clips/story-02_version-human.mp4")["frames"], 6);  // 2.5 s at 2 fps: 0, 0.5, ... 2.5 s
    EXPECT_NE(after.at("clips/story-02_version-human.mp4")["sha256"], human["sha256"]);
    EXPECT_EQ(after.at("clips/story-01_version-human.mp4"), clips.at("clips/story-01_version-human.mp4"));
    EXPECT_EQ(runSignstim("study verify " + shellQuote(out.string())).status, 0);
}

TEST(StudyHumanCli, BadRecordingsAreRefusedNamingTheFileAndThePattern) {
    const fs::path dir = freshDir("bad");
    const fs::path file = studyWithRecordings(dir);
    const auto check = [&] {
        return runSignstim("study " + shellQuote(file.string()) + " --check --scenes " + shellQuote(kScenes));
    };
    ASSERT_EQ(check().status, 0) << check().output;
    fs::remove(dir / "human" / "synthetic-story-03.mp4");
    auto r = check();
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find((dir / "human" / "synthetic-story-03.mp4").string() + ": no such file"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("\"human/synthetic-{story}.mp4\""), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("/humanVersions/0/phase1Clips"), std::string::npos) << r.output;

    std::ofstream(dir / "human" / "synthetic-story-03.mp4") << "not a video\n";
    r = check();
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("synthetic-story-03.mp4: not a video"), std::string::npos) << r.output;

    syntheticClip(dir / "human" / "synthetic-story-03.mp4", "96x72", 25, 1.0, 0);
    const auto empty = runShell("ffmpeg -v error -y -f lavfi -i testsrc=size=64x64:rate=10 -frames:v 0 -c:v libx264 " +
                                shellQuote((dir / "human" / "synthetic-likert-02.mp4").string()) + " </dev/null");
    ASSERT_EQ(empty.status, 0) << empty.output;
    r = check();
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("synthetic-likert-02.mp4: zero duration"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("/humanVersions/0/phase2Clips"), std::string::npos) << r.output;
}

TEST(StudyHumanCli, ShardsMergeToTheBytesOfOneRun) {
    const fs::path dir = freshDir("shards");
    const fs::path file = studyWithRecordings(dir);
    run(file, dir / "one");
    run(file, dir / "shard0", " --shard 0/2");
    run(file, dir / "shard1", " --shard 1/2");
    const auto merge = runSignstim("study merge " + shellQuote((dir / "shard0").string()) + " " +
                                   shellQuote((dir / "shard1").string()) + " --into " + shellQuote((dir / "merged").string()));
    ASSERT_EQ(merge.status, 0) << merge.output;
    EXPECT_EQ(readFile(dir / "merged" / "manifest.json"), readFile(dir / "one" / "manifest.json"));
    EXPECT_EQ(runSignstim("study verify " + shellQuote((dir / "merged").string())).status, 0);
}

// A human version in phase 2 only: phase 1 renders and counterbalances the animated versions
// alone (2 groups, no story clip of the recording), phase 2 composes it into its panel; verified,
// and a changed recording renders its own sentence's unit again, nothing else. SYNTHETIC recordings.
TEST(StudyHumanCli, APhase2OnlyVersionIsInEveryPanelAndNotInPhase1) {
    const fs::path dir = freshDir("phase2-only");
    for (int i = 1; i <= 3; ++i)
        syntheticClip(dir / "human" / ("synthetic-likert-0" + std::to_string(i) + ".mp4"), "80x80", 10, 2.0, 90 * i);
    const fs::path file = dir / "phase2-only.json";
    std::ofstream(file) << R"({
  "format": "signstim-study", "version": 1,
  "title": "Synthetic human-video version in phase 2 only, a test", "seed": 3, "participants": 2,
  "versions": ["point", "uninflected"],
  "humanVersions": [{"name": "human", "phase2Clips": "human/synthetic-{sentence}.mp4"}],
  "stories": [")" + kScenes + R"(/stories/story-01.json", ")" + kScenes + R"(/stories/story-02.json"],
  "phase2": {"story": ")" + kScenes + R"(/studies/phase2-sentences.json", "sentences": [1, 2, 3]},
  "session": {"questions": "english", "instructions": {"show": "english"}},
  "render": {"size": "64x64", "fps": 2, "msaa": 1}
})";
    const fs::path out = dir / "out";
    run(file, out);
    const auto clips = videos(out);
    EXPECT_EQ(clips.size(), 7u);  // 2 stories x 2 animated versions, 3 side-by-side sentences
    for (const auto& entry : clips) {
        const nlohmann::json& shows = entry.second["shows"];
        if (shows["phase"] == 1) {
            EXPECT_NE(shows["version"], "human") << entry.first;
        }
        if (shows["phase"] == 2) {
            EXPECT_EQ(shows["panels"].size(), 3u) << shows.dump();
            EXPECT_EQ(shows["sources"].size(), 1u) << shows.dump();
        }
    }
    EXPECT_EQ(readFile(out / "overview.csv").substr(0, 29), "story,title,group_1,group_2\r\n");
    EXPECT_NE(readFile(out / "participants" / "P01" / "P01_conditions.csv").find("panel_c_version"), std::string::npos);
    EXPECT_EQ(runSignstim("study verify " + shellQuote(out.string())).status, 0);
    syntheticClip(dir / "human" / "synthetic-likert-02.mp4", "80x80", 10, 3.0, 10);
    const auto changed = runSignstim("study " + shellQuote(file.string()) + " --scenes " + shellQuote(kScenes) + " --out " +
                                     shellQuote(out.string()));
    EXPECT_NE(changed.output.find("1 of 5 units rendered, 4 already complete"), std::string::npos) << changed.output;
    EXPECT_EQ(runSignstim("study verify " + shellQuote(out.string())).status, 0);
}
