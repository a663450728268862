// `signstim study` as an experimenter (and a lab's CI, and Slurm) runs it: the default study
// checks; bad study files are refused naming file, line and field; a small study renders
// under the validation layer into playable MP4s, posters, exports and a manifest; a re-run
// skips everything; verify catches a changed byte; shards merged equal one run byte for byte;
// an interrupted run leaves no broken file and resumes to the same bytes.
#include "stimuli/study/study_experiment.hpp"
#include "tests/app/run_command.hpp"
#include "tests/app/study_reference_run.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using signstim::test::Capture;
using signstim::test::runShell;
using signstim::test::runSignstim;
using signstim::test::readFile;
using signstim::test::shellQuote;

const std::string kScenes = fs::path(SIGNSTIM_SOURCE_DIR).append("scenes").string();
const std::string kSmall = fs::path(SIGNSTIM_SOURCE_DIR).append("tests/app/data/small-study.json").string();

fs::path freshDir(const std::string& name) {
    return signstim::test::freshDir(SIGNSTIM_BINARY_DIR, "study_cli_test", name, false);
}

std::string study(const std::string& arguments) { return "study " + arguments + " --scenes " + shellQuote(kScenes); }

// One uninterrupted run of the small study, shared with the annotations test
// (tests/app/study_reference_run.hpp).
const fs::path& referenceRun() { return signstim::test::smallStudyReferenceRun(); }

TEST(StudyCli, DefaultStudyChecksWithTheDesignOfThePaper) {
    const auto r = runSignstim(study("--check"));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("12 stories x 4 versions, 24 participants in 4 groups"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("each version 3 times"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("8 side-by-side sentences"), std::string::npos) << r.output;
}

// Issue 22: an animator file marked "draft" is refused by a study unless
// --allow-draft-animator; then the manifest and the review page list it.
TEST(StudyCli, DraftAnimatorFilesAreRefusedUnlessAllowedAndThenListed) {
    const fs::path dir = freshDir("draft-animator");
    fs::create_directories(dir);
    const fs::path scenes = dir / "scenes";
    fs::create_directories(scenes / "animator");
    for (const auto& entry : fs::directory_iterator(kScenes))
        if (entry.path().filename() != "animator") fs::create_directory_symlink(entry.path(), scenes / entry.path().filename());
    for (const auto& entry : fs::directory_iterator(fs::path(kScenes) / "animator"))
        fs::copy_file(entry.path(), scenes / "animator" / entry.path().filename());
    // story-01 (Tom at 0.9 asks Ann at -0.6) uses ASK_s0.9_o-0.6.json.
    std::string ask = readFile(scenes / "animator" / "ASK_s0.9_o-0.6.json");
    ask.replace(ask.find('{'), 1, "{\n  \"draft\": true,");
    std::ofstream(scenes / "animator" / "ASK_s0.9_o-0.6.json", std::ios::trunc) << ask;
    // A study of story-01 and story-02 in the animator and uninflected versions (half the small
    // study's render): the draft file is one of those its animator version reads.
    const std::string file = fs::path(SIGNSTIM_SOURCE_DIR).append("tests/app/data/draft-animator-study.json").string();
    const std::string base = "study " + shellQuote(file) + " --scenes " + shellQuote(scenes.string());

    const auto refused = runSignstim(base + " --check");
    EXPECT_EQ(refused.status, 2) << refused.output;
    EXPECT_NE(refused.output.find("ASK_s0.9_o-0.6.json:2: field '/draft'"), std::string::npos) << refused.output;
    EXPECT_NE(refused.output.find("--allow-draft-animator"), std::string::npos) << refused.output;

    const auto allowed = runSignstim(base + " --allow-draft-animator --quick --quiet --out " + shellQuote((dir / "out").string()));
    ASSERT_EQ(allowed.status, 0) << allowed.output;
    const nlohmann::json manifest = nlohmann::json::parse(readFile(dir / "out" / "manifest.json"));
    EXPECT_EQ(manifest["study"]["draftAnimator"], nlohmann::json::array({"ASK_s0.9_o-0.6.json"})) << manifest["study"].dump();
    const std::string page = readFile(dir / "out" / "index.html");
    EXPECT_NE(page.find("Draft animator files"), std::string::npos);
    EXPECT_NE(page.find("<code>ASK_s0.9_o-0.6.json</code>"), std::string::npos);
}

TEST(StudyCli, BadStudyFilesAreRefusedNamingFileLineAndField) {
    const fs::path dir = freshDir("bad");
    fs::create_directories(dir);
    const std::string good = readFile(kSmall);
    struct Case {
        std::string from, to, expect;
    };
    const std::vector<Case> cases = {
        // 3 stories over 4 versions: the design says why and what would work.
        {"    \"../../../scenes/stories/story-04.json\"\n", "", "use a multiple of 4 stories such as 4"},
        {"\"vector\",", "\"vectr\",", "/versions/1"},
        {"story-02.json", "story-99.json", "bad.json:10: field '/stories/1'"},
        {"\"96x72\"", "\"95x72\"", "/render/size"},
        {"\"participants\": 4", "\"participants\": 0", "/participants"},
        {"\"seed\": 7", "\"seed\": 7, \"sead\": 8", "unknown field 'sead'"},
        {"\"notes\"", "\"outputs\": {\"experiment\": \"psychopy\"}, \"notes\"", "/outputs/experiment"},
        {"[1, 4, 6, 8]", "[1, 4, 6, 9]", "sentence 9 does not exist"},
        {"[1, 4, 6, 8]", "[1, 4, 6]", "3 side-by-side sentences cannot put every version in every panel equally often"},
    };
    for (const Case& c : cases) {
        std::string text = good;
        const std::size_t at = text.find(c.from);
        ASSERT_NE(at, std::string::npos) << c.from;
        text.replace(at, c.from.size(), c.to);
        if (c.from.find("story-04") != std::string::npos) text.replace(text.find("story-03.json\","), 15, "story-03.json\"");
        // The bad file lives in the build tree: its story paths made absolute.
        for (std::size_t p = text.find("../../../scenes/"); p != std::string::npos; p = text.find("../../../scenes/"))
            text.replace(p, 16, kScenes + "/");
        const fs::path bad = dir / "bad.json";
        std::ofstream(bad) << text;
        const auto r = runSignstim(study(shellQuote(bad.string()) + " --check"));
        EXPECT_EQ(r.status, 2) << c.to << "\n" << r.output;
        EXPECT_NE(r.output.find("bad.json:"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(c.expect), std::string::npos) << "expected '" << c.expect << "' in:\n" << r.output;
    }
    // A command-line mistake is exit 1.
    EXPECT_EQ(runSignstim(study(shellQuote(kSmall) + " --out x --shard 3/3")).status, 1);
    EXPECT_EQ(runSignstim(study(shellQuote(kSmall))).status, 1);
}

TEST(StudyCli, RendersPlayableClipsResumesAndVerifyCatchesAChangedByte) {
    const fs::path& dir = referenceRun();
    const nlohmann::json manifest = nlohmann::json::parse(readFile(dir / "manifest.json"));
    EXPECT_EQ(manifest["seed"], 7);
    EXPECT_EQ(manifest["units"].size(), 13u);  // 4 stories, 4 sentences, 4 of signed questions, the instructions (issue 24)
    std::set<std::string> kinds;
    int videos = 0;
    for (const auto& f : manifest["files"]) {
        kinds.insert(f["kind"].get<std::string>());
        ASSERT_TRUE(fs::exists(dir / f["path"].get<std::string>())) << f["path"];
        if (f["kind"] != "video") continue;
        ++videos;
        // Every clip opens in ffprobe as H.264 yuv420p at the manifest's size, rate and frame count.
        const auto probe = runShell("ffprobe -v error -select_streams v:0 -count_frames -show_entries "
                                    "stream=codec_name,pix_fmt,width,height,r_frame_rate,nb_read_frames -of csv=p=0 " +
                                    shellQuote((dir / f["path"].get<std::string>()).string()));
        ASSERT_EQ(probe.status, 0) << probe.output;
        const std::string expected = "h264,96,72,yuv420p,4/1," + std::to_string(f["frames"].get<int>());
        EXPECT_EQ(probe.output.substr(0, probe.output.find('\n')), expected) << f["path"];
    }
    // Stories x versions, sentences, and (issue 24) the 16 questions and 2 instruction pages
    // signed, one clip each whatever the version.
    EXPECT_EQ(videos, 4 * 4 + 4 + 4 * 4 + 2);
    EXPECT_TRUE(fs::exists(dir / "clips" / "story-02_question-3.mp4"));
    EXPECT_TRUE(fs::exists(dir / "clips" / "instructions-welcome.mp4"));
    EXPECT_TRUE(kinds.count("poster"));
    // Names as SPEC §5.
    EXPECT_TRUE(fs::exists(dir / "clips" / "story-03_version-point.mp4"));
    bool likertNamed = false;
    for (const auto& e : fs::directory_iterator(dir / "clips"))
        likertNamed |= e.path().filename().string().rfind("likert-01_panels-", 0) == 0;
    EXPECT_TRUE(likertNamed);

    // A re-run renders nothing.
    const fs::path copy = freshDir("resume");
    fs::copy(dir, copy, fs::copy_options::recursive);
    const auto again = runSignstim(study(shellQuote(kSmall) + " --quiet --out " + shellQuote(copy.string())));
    ASSERT_EQ(again.status, 0) << again.output;
    EXPECT_NE(again.output.find("0 of 13 units rendered, 13 already complete"), std::string::npos) << again.output;
    EXPECT_EQ(readFile(copy / "manifest.json"), readFile(dir / "manifest.json"));

    const auto verified = runSignstim("study verify " + shellQuote(copy.string()));
    EXPECT_EQ(verified.status, 0) << verified.output;
    // One changed byte in one clip: verify names it, exit 2.
    const fs::path clip = copy / "clips" / "story-02_version-vector.mp4";
    std::string bytes = readFile(clip);
    bytes[bytes.size() / 2] ^= 0x01;
    std::ofstream(clip, std::ios::binary | std::ios::trunc) << bytes;
    const auto tampered = runSignstim("study verify " + shellQuote(copy.string()));
    EXPECT_EQ(tampered.status, 2) << tampered.output;
    EXPECT_NE(tampered.output.find("clips/story-02_version-vector.mp4: SHA-256 differs"), std::string::npos)
        << tampered.output;
    // The next run renders that unit again (its unit only): a changed byte of the same size is
    // found as a missing clip is. Until it has, the folder has no manifest.
    const auto repaired = runSignstim(study(shellQuote(kSmall) + " --quiet --out " + shellQuote(copy.string())));
    ASSERT_EQ(repaired.status, 0) << repaired.output;
    EXPECT_NE(repaired.output.find("1 of 13 units rendered, 12 already complete"), std::string::npos) << repaired.output;
    EXPECT_EQ(readFile(copy / "manifest.json"), readFile(dir / "manifest.json"));
}

TEST(StudyCli, ThreeShardsMergedEqualOneRunByteForByte) {
    const fs::path& reference = referenceRun();
    std::vector<std::string> shards;
    for (int i = 0; i < 3; ++i) {
        const fs::path dir = freshDir("shard" + std::to_string(i));
        const auto r = runSignstim(study(shellQuote(kSmall) + " --quiet --shard " + std::to_string(i) + "/3 --out " +
                                         shellQuote(dir.string())));
        ASSERT_EQ(r.status, 0) << r.output;
        EXPECT_NE(r.output.find("units are still missing"), std::string::npos) << r.output;
        EXPECT_FALSE(fs::exists(dir / "manifest.json"));
        shards.push_back(shellQuote(dir.string()));
    }
    // verify refuses an incomplete folder, naming what is missing.
    const auto incomplete = runSignstim("study verify " + shards[0]);
    EXPECT_EQ(incomplete.status, 2) << incomplete.output;
    EXPECT_NE(incomplete.output.find("units missing"), std::string::npos) << incomplete.output;

    const fs::path merged = freshDir("merged");
    const auto merge = runSignstim("study merge " + shards[0] + " " + shards[1] + " " + shards[2] + " --into " +
                                   shellQuote(merged.string()));
    ASSERT_EQ(merge.status, 0) << merge.output;
    EXPECT_EQ(readFile(merged / "manifest.json"), readFile(reference / "manifest.json"));
    EXPECT_EQ(runSignstim("study verify " + shellQuote(merged.string())).status, 0);

    // Two of the three shards are not the whole study: merge says which units are missing (and
    // has copied those it has into the folder).
    const fs::path shared = freshDir("shared");
    const auto two = runSignstim("study merge " + shards[0] + " " + shards[1] + " --into " + shellQuote(shared.string()));
    EXPECT_EQ(two.status, 2) << two.output;
    EXPECT_NE(two.output.find("units are in none of the folders"), std::string::npos) << two.output;
    EXPECT_FALSE(fs::exists(shared / "manifest.json"));

    // The missing shard in Slurm's environment form (task 3 of an array 1-3: shard 2/3), into
    // that shared folder: it renders only the missing units (had it taken the task for another
    // shard, its units would all be there and the set would stay incomplete), and as it
    // completes the set its run writes the manifest. Then merge of that one folder. (The shard
    // alone, not the whole study again as two tasks of an array 1-2 did: a third of the render.)
    const auto last = runSignstim(study(shellQuote(kSmall) + " --quiet --out " + shellQuote(shared.string())),
                                  Capture::StdoutAndStderr, "SLURM_ARRAY_TASK_ID=3 SLURM_ARRAY_TASK_COUNT=3 SLURM_ARRAY_TASK_MIN=1");
    ASSERT_EQ(last.status, 0) << last.output;
    EXPECT_NE(last.output.find("4 of 4 units rendered, 0 already complete (shard 2/3)"), std::string::npos) << last.output;
    EXPECT_NE(last.output.find("study complete"), std::string::npos) << last.output;
    EXPECT_EQ(readFile(shared / "manifest.json"), readFile(reference / "manifest.json"));
    EXPECT_EQ(runSignstim("study merge " + shellQuote(shared.string())).status, 0);
}

TEST(StudyCli, InterruptedRunLeavesNoBrokenFileAndResumesToTheSameBytes) {
    const fs::path& reference = referenceRun();
    const fs::path dir = freshDir("interrupted");
    // SIGTERM (what Slurm sends) once the first unit is complete, while others are in flight.
    const std::string command =
        "SIGNSTIM=" + shellQuote((fs::path(SIGNSTIM_BINARY_DIR) / "signstim").string()) + "; \"$SIGNSTIM\" " +
        study(shellQuote(kSmall) + " --quiet --out " + shellQuote(dir.string())) + " & pid=$!; " +
        "for i in $(seq 1 600); do [ -e " + shellQuote((dir / ".signstim/units/likert-01.json").string()) +
        " ] && break; sleep 0.02; done; kill -TERM $pid; wait $pid; echo \"exit $?\"";
    const auto r = runShell(command);
    EXPECT_NE(r.output.find("exit 143"), std::string::npos) << r.output;
    // Nothing half-written: no temporaries, and every clip there is a whole MP4.
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        EXPECT_EQ(name.find(".tmp-"), std::string::npos) << e.path();
        if (e.path().extension() == ".mp4") {
            const auto probe = runShell("ffprobe -v error -count_frames -show_entries stream=nb_read_frames -of csv=p=0 " +
                                        shellQuote(e.path().string()));
            EXPECT_EQ(probe.status, 0) << e.path() << probe.output;
            EXPECT_TRUE(probe.output.find("error") == std::string::npos) << probe.output;
        }
    }
    EXPECT_FALSE(fs::exists(dir / "manifest.json"));
    const auto resumed = runSignstim(study(shellQuote(kSmall) + " --quiet --out " + shellQuote(dir.string())));
    ASSERT_EQ(resumed.status, 0) << resumed.output;
    EXPECT_EQ(readFile(dir / "manifest.json"), readFile(reference / "manifest.json"));
}

// A stand-in for third_party/jspsych (what scripts/fetch-jspsych.sh unpacks): every file the
// experiment copies, with bytes that are easy to recognise and not all text, so this test needs
// no network. The real packages run in Chromium in study_browser_test.cpp.
fs::path fakeJspsych() {
    const fs::path dir = freshDir("fake-jspsych");
    for (const signstim::stimuli::ExperimentLibraryFile& file : signstim::stimuli::jspsychLibraryFiles()) {
        fs::create_directories((dir / file.source).parent_path());
        std::ofstream(dir / file.source, std::ios::binary) << "fake " << file.source << '\n' << std::string(1, '\0') << "\xff";
    }
    return dir;
}

TEST(StudyCli, ExperimentWithoutJsPsychFailsBeforeRenderingAndSaysHowToGetIt) {
    const fs::path dir = freshDir("no-jspsych");
    const auto r = runSignstim(study(shellQuote(kSmall) + " --quiet --experiment jspsych --out " + shellQuote(dir.string())),
                               Capture::StdoutAndStderr, "SIGNSTIM_JSPSYCH=" + shellQuote((dir / "nowhere").string()));
    EXPECT_EQ(r.status, 3) << r.output;
    EXPECT_NE(r.output.find("scripts/setup.sh"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "clips")) << "rendered before finding out";
    // A command-line mistake is exit 1.
    EXPECT_EQ(runSignstim(study(shellQuote(kSmall) + " --experiment psychopy --out " + shellQuote(dir.string()))).status, 1);
}

TEST(StudyCli, OutRefusesTheWorkingDirectoryHomeAndAFolderOfOtherFilesBeforeRendering) {
    const fs::path dir = freshDir("theirs");
    fs::create_directories(dir);
    std::ofstream(dir / "notes.txt") << "someone's notes\n";
    const auto theirs = runSignstim(study(shellQuote(kSmall) + " --quiet --out " + shellQuote(dir.string())));
    EXPECT_EQ(theirs.status, 2) << theirs.output;
    EXPECT_NE(theirs.output.find("notes.txt"), std::string::npos) << theirs.output;
    EXPECT_NE(theirs.output.find("--force"), std::string::npos) << theirs.output;
    EXPECT_FALSE(fs::exists(dir / "clips"));
    EXPECT_FALSE(fs::exists(dir / ".signstim"));
    EXPECT_EQ(readFile(dir / "notes.txt"), "someone's notes\n");
    const auto here = runShell("cd " + shellQuote(dir.string()) + " && " +
                               shellQuote(fs::path(SIGNSTIM_BINARY_DIR).append("signstim").string()) + " " +
                               study(shellQuote(kSmall) + " --quiet --force --out ."));
    EXPECT_EQ(here.status, 2) << here.output;
    EXPECT_NE(here.output.find("working directory"), std::string::npos) << here.output;
    const auto home = runSignstim(study(shellQuote(kSmall) + " --quiet --force --out " + shellQuote(dir.string())),
                                  Capture::StdoutAndStderr, "HOME=" + shellQuote(dir.string()));
    EXPECT_EQ(home.status, 2) << home.output;
    EXPECT_NE(home.output.find("home folder"), std::string::npos) << home.output;
    EXPECT_FALSE(fs::exists(dir / "clips"));
}

TEST(StudyCli, ExperimentIsWrittenWithTheStudyIntoTheManifestAndKeptByLaterRuns) {
    const fs::path jspsych = fakeJspsych();
    const std::string environment = "SIGNSTIM_JSPSYCH=" + shellQuote(jspsych.string());
    const fs::path dir = freshDir("experiment");
    fs::copy(referenceRun(), dir, fs::copy_options::recursive);
    const std::string base = study(shellQuote(kSmall) + " --quiet --out " + shellQuote(dir.string()));
    // On a complete study nothing is rendered: the documents are written again, with the experiment.
    const auto r = runSignstim(base + " --experiment jspsych", Capture::StdoutAndStderr, environment);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("0 of 13 units rendered"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("experiment/index.html?participant=P01"), std::string::npos) << r.output;

    for (const signstim::stimuli::ExperimentLibraryFile& file : signstim::stimuli::jspsychLibraryFiles())
        EXPECT_EQ(readFile(dir / file.path), readFile(jspsych / file.source)) << file.path;  // copied byte for byte
    const std::string timeline = readFile(dir / "participants/P03/P03_timeline_variables.json");
    EXPECT_NE(readFile(dir / "experiment/participants/P03.js")
                  .find("window.signstimTimeline = " + timeline.substr(0, timeline.size() - 1) + ";\n"),
              std::string::npos);

    const nlohmann::json manifest = nlohmann::json::parse(readFile(dir / "manifest.json"));
    std::map<std::string, nlohmann::json> listed;
    for (const auto& f : manifest["files"]) listed[f["path"].get<std::string>()] = f;
    std::size_t onDisk = 0;
    for (const auto& e : fs::recursive_directory_iterator(dir / "experiment")) {
        if (!e.is_regular_file()) continue;
        ++onDisk;
        const std::string relative = e.path().lexically_relative(dir).generic_string();
        ASSERT_TRUE(listed.count(relative)) << relative << " is not in the manifest";
        const std::string kind = listed[relative]["kind"];
        EXPECT_EQ(kind, relative.rfind("experiment/jspsych/", 0) == 0 ? "experiment-library" : "experiment") << relative;
    }
    EXPECT_EQ(onDisk, 4 + 4 + signstim::stimuli::jspsychLibraryFiles().size());  // page, script, style, list; 4 participants
    EXPECT_EQ(listed["experiment/participants/P02.js"]["participant"], "P02");
    EXPECT_EQ(runSignstim("study verify " + shellQuote(dir.string())).status, 0);

    // A later run without the flag keeps the experiment (a resumed run need not repeat it) ...
    const std::string withExperiment = readFile(dir / "manifest.json");
    const auto again = runSignstim(base, Capture::StdoutAndStderr, environment);
    ASSERT_EQ(again.status, 0) << again.output;
    EXPECT_EQ(readFile(dir / "manifest.json"), withExperiment);
    // ... and --experiment none leaves it out of the manifest.
    const auto none = runSignstim(base + " --experiment none");
    ASSERT_EQ(none.status, 0) << none.output;
    EXPECT_EQ(readFile(dir / "manifest.json"), readFile(referenceRun() / "manifest.json"));
}

}  // namespace

namespace {

TEST(StudyCli, ThreeVersionsWithPngFramesRenderAndVerify) {
    const std::string file = fs::path(SIGNSTIM_SOURCE_DIR).append("tests/app/data/three-versions.json").string();
    const fs::path dir = freshDir("three-versions");
    const auto r = runSignstim(study(shellQuote(file) + " --quiet --out " + shellQuote(dir.string())),
                               Capture::StdoutAndStderr, "SIGNSTIM_VALIDATION=1");
    ASSERT_EQ(r.status, 0) << r.output;
    const nlohmann::json manifest = nlohmann::json::parse(readFile(dir / "manifest.json"));
    int folders = 0, videos = 0;
    for (const auto& f : manifest["files"]) {
        if (f["kind"] == "video") ++videos;
        if (f["kind"] != "frames") continue;
        ++folders;
        std::size_t pngs = 0;
        for (const auto& e : fs::directory_iterator(dir / f["path"].get<std::string>())) pngs += e.path().extension() == ".png";
        EXPECT_EQ(pngs, f["files"].get<std::size_t>()) << f["path"];
    }
    EXPECT_EQ(videos, 3 * 3 + 3);
    EXPECT_EQ(folders, videos);
    // Three panels: A, B, C in a 2x2 grid; the file name gives the mapping.
    EXPECT_TRUE(fs::exists(dir / "clips" / "likert-01_panels-APU.mp4")) << r.output;
    EXPECT_EQ(runSignstim("study verify " + shellQuote(dir.string())).status, 0);
    const std::string overview = readFile(dir / "overview.csv");
    EXPECT_NE(overview.find("group_3"), std::string::npos) << overview;
    EXPECT_EQ(overview.find("group_4"), std::string::npos) << overview;
}

}  // namespace
