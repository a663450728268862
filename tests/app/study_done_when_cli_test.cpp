// Issue 24's "Done when", end to end with the built binary: one small study that asks its
// questions in ASL (session.questions "asl", signed question and instruction clips) AND has a
// human-video version renders, verifies, shards (2 shards merged equal one run byte for byte)
// and resumes (an interrupted shard, and a changed recording re-rendering only its own unit).
// The "human" recordings are SYNTHETIC: ffmpeg's procedural test pattern (lavfi testsrc2), no
// person. Quick settings (64x64, 2 fps, no MSAA), 3 stories, 2 phase-2 sentences.
#include "tests/app/run_command.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

namespace {

namespace fs = std::filesystem;
using signstim::test::readFile;
using signstim::test::runShell;
using signstim::test::runSignstim;
using signstim::test::shellQuote;

const std::string kScenes = fs::path(SIGNSTIM_SOURCE_DIR).append("scenes").string();

fs::path freshDir(const std::string& name) {
    return signstim::test::freshDir(SIGNSTIM_BINARY_DIR, "study_done_when_cli_test", name, false);
}

// A synthetic "recording" (ffmpeg's test pattern, hue-shifted so each differs).
void syntheticClip(const fs::path& file, double seconds, int hue) {
    const auto r = signstim::test::writeSyntheticRecording(file, "96x72", 25, seconds, hue);
    ASSERT_EQ(r.status, 0) << r.output;
}

// The study: 2 animated versions and the synthetic "human" one in phase 1 (3 stories x 3
// versions), questions and instructions signed; story 2 is a copy in the study's folder (a story
// beside the study file, as a lab keeps its own).
fs::path doneWhenStudy(const fs::path& dir) {
    fs::create_directories(dir);
    for (int i = 1; i <= 3; ++i)
        syntheticClip(dir / "human" / ("synthetic-story-0" + std::to_string(i) + ".mp4"), 1.5, 60 * i);
    fs::copy_file(fs::path(kScenes) / "stories" / "story-02.json", dir / "story-02.json");
    const fs::path file = dir / "done-when.json";
    std::ofstream(file) << R"({
  "format": "signstim-study", "version": 1,
  "title": "ASL questions and a synthetic human-video version, a test", "seed": 5, "participants": 3,
  "versions": ["point", "uninflected"],
  "humanVersions": [{"name": "human", "phase1Clips": "human/synthetic-{story}.mp4"}],
  "stories": [")" + kScenes + R"(/stories/story-01.json", "story-02.json", ")" + kScenes + R"(/stories/story-03.json"],
  "phase2": {"story": ")" + kScenes + R"(/studies/phase2-sentences.json", "sentences": [1, 2]},
  "session": {"questions": "asl", "instructions": {"show": "both"}},
  "render": {"size": "64x64", "fps": 2, "msaa": 1}
})";
    return file;
}

std::string study(const fs::path& file, const fs::path& out, const std::string& extra = "") {
    return "study " + shellQuote(file.string()) + " --scenes " + shellQuote(kScenes) + " --out " + shellQuote(out.string()) + extra;
}

std::map<std::string, std::string> videos(const fs::path& out) {
    std::map<std::string, std::string> sha;
    const nlohmann::json manifest = nlohmann::json::parse(readFile(out / "manifest.json"));
    for (const auto& f : manifest["files"])
        if (f["kind"] == "video") sha[f["path"].get<std::string>()] = f["sha256"].get<std::string>();
    return sha;
}

// Every file of a study folder (its .signstim bookkeeping aside) by relative path.
std::map<std::string, std::string> filesOf(const fs::path& out) {
    std::map<std::string, std::string> bytes;
    for (const auto& e : fs::recursive_directory_iterator(out)) {
        const std::string rel = fs::relative(e.path(), out).generic_string();
        if (e.is_regular_file() && !rel.starts_with(".signstim")) bytes[rel] = readFile(e.path());
    }
    return bytes;
}

}  // namespace

TEST(StudyDoneWhenCli, AslQuestionsAndAHumanVersionRenderVerifyShardAndResume) {
    const fs::path dir = freshDir("study");
    const fs::path file = doneWhenStudy(dir);
    const fs::path one = dir / "one";
    const auto first = runSignstim(study(file, one, " --quiet"));
    ASSERT_EQ(first.status, 0) << first.output;
    const auto clips = videos(one);
    // The signed questions, the instruction pages, the human version and the animated ones are
    // all clips of the study.
    for (const char* path : {"clips/story-01_question-1.mp4", "clips/story-02_question-2.mp4", "clips/instructions-welcome.mp4",
                             "clips/instructions-part2.mp4", "clips/story-03_version-human.mp4",
                             "clips/story-03_version-point.mp4"})
        EXPECT_TRUE(clips.count(path)) << path;
    EXPECT_EQ(runSignstim("study verify " + shellQuote(one.string())).status, 0);
    // Eye-tracking regions for the signer's clips, none for a recording (nothing is known of it).
    EXPECT_TRUE(fs::exists(one / "regions" / "story-01_version-point.csv"));
    EXPECT_FALSE(fs::exists(one / "regions" / "story-01_version-human.csv"));
    EXPECT_FALSE(fs::exists(one / "elan" / "story-01_version-human.eaf"));
    // The exports carry both: the question clips' columns and the human version's clips.
    const std::string conditions = readFile(one / "participants" / "P01" / "P01_conditions.csv");
    EXPECT_NE(conditions.find(",q1_video_file,q1_video_name,"), std::string::npos);
    EXPECT_NE(conditions.find("_question-1.mp4"), std::string::npos);
    EXPECT_NE(conditions.find("_version-human.mp4"), std::string::npos);
    EXPECT_NE(readFile(one / "participants" / "P01" / "P01_gorilla.csv").find("instructions-welcome.mp4"), std::string::npos);

    // Shards: two halves merged are the one run, file for file and byte for byte. The first half
    // interrupted (SIGTERM once the instruction clips' unit, its first, is complete) and resumed:
    // the resumed shard keeps what the cut run finished and renders the rest, and the merge still
    // has the bytes of one run. (One render of the study for both checks; the interrupted run was
    // a third, whole-study render before.)
    const fs::path shard0 = dir / "shard0";
    const auto killed = runShell("SIGNSTIM=" + shellQuote((fs::path(SIGNSTIM_BINARY_DIR) / "signstim").string()) +
                                 "; \"$SIGNSTIM\" " + study(file, shard0, " --quiet --shard 0/2") + " & pid=$!; for i in $(seq 1 600); do [ -e " +
                                 shellQuote((shard0 / ".signstim/units/instructions.json").string()) +
                                 " ] && break; sleep 0.02; done; kill -TERM $pid; wait $pid; echo \"exit $?\"");
    EXPECT_NE(killed.output.find("exit 143"), std::string::npos) << killed.output;
    const auto resumed = runSignstim(study(file, shard0, " --quiet --shard 0/2"));
    ASSERT_EQ(resumed.status, 0) << resumed.output;
    // "N of 5 units rendered, K already complete (shard 0/2)": the cut run finished some, not all.
    const std::size_t of = resumed.output.find(" of 5 units rendered, ");
    ASSERT_NE(of, std::string::npos) << resumed.output;
    const int rendered = std::stoi(resumed.output.substr(resumed.output.rfind(' ', of - 1) + 1));
    const int kept = std::stoi(resumed.output.substr(of + std::string(" of 5 units rendered, ").size()));
    EXPECT_GE(rendered, 1) << resumed.output;
    EXPECT_GE(kept, 1) << resumed.output;
    EXPECT_EQ(rendered + kept, 5) << resumed.output;
    const auto second = runSignstim(study(file, dir / "shard1", " --quiet --shard 1/2"));
    ASSERT_EQ(second.status, 0) << second.output;
    const auto merge = runSignstim("study merge " + shellQuote(shard0.string()) + " " +
                                   shellQuote((dir / "shard1").string()) + " --into " + shellQuote((dir / "merged").string()));
    ASSERT_EQ(merge.status, 0) << merge.output;
    EXPECT_EQ(readFile(dir / "merged" / "manifest.json"), readFile(one / "manifest.json"));
    EXPECT_TRUE(filesOf(dir / "merged") == filesOf(one)) << "the merged folder's files differ from one run's";
    EXPECT_EQ(runSignstim("study verify " + shellQuote((dir / "merged").string())).status, 0);

    // Nothing changed: nothing rendered. Story 2's recording replaced (a question's gloss would be
    // another design, refused for this folder): its story unit only; the question and instruction
    // clips and the other stories are kept.
    const auto again = runSignstim(study(file, one));
    EXPECT_NE(again.output.find("0 of 9 units rendered, 9 already complete"), std::string::npos) << again.output;
    syntheticClip(dir / "human" / "synthetic-story-02.mp4", 2.5, 300);
    const auto changed = runSignstim(study(file, one));
    ASSERT_EQ(changed.status, 0) << changed.output;
    EXPECT_NE(changed.output.find("1 of 9 units rendered, 8 already complete"), std::string::npos) << changed.output;
    const auto after = videos(one);
    EXPECT_NE(after.at("clips/story-02_version-human.mp4"), clips.at("clips/story-02_version-human.mp4"));
    for (const char* kept : {"clips/story-02_question-1.mp4", "clips/story-01_version-human.mp4",
                             "clips/instructions-welcome.mp4", "clips/story-03_question-4.mp4"})
        EXPECT_EQ(after.at(kept), clips.at(kept)) << kept;
    EXPECT_EQ(runSignstim("study verify " + shellQuote(one.string())).status, 0);
}
