// `signstim demo` and `signstim verb --out` as a user runs them: the built binary with the
// Vulkan validation layer on (SIGNSTIM_VALIDATION=1), its files and its manifest.
#include "common/sha256.hpp"
#include "tests/app/run_command.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

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

fs::path freshDir(const std::string& name) {
    return signstim::test::freshDir(SIGNSTIM_BINARY_DIR, "demo_cli_test", name, false);
}

signstim::test::CommandResult demo(const fs::path& out, const std::string& extra = "") {
    const std::string fps = extra.find("--fps") == std::string::npos ? " --fps 10" : "";
    return runSignstim("demo --quiet --verbs SCOLD,MEET --panel-size 128x96" + fps + " --scenes " + shellQuote(kScenes) +
                           " --out " + shellQuote(out.string()) + " " + extra,
                       signstim::test::Capture::StdoutAndStderr, "SIGNSTIM_VALIDATION=1");
}

}  // namespace

TEST(DemoCli, ManifestListsEveryFileWithItsDigestAndRunsAreByteIdentical) {
    const fs::path first = freshDir("first"), second = freshDir("second");
    const auto a = demo(first);
    ASSERT_EQ(a.status, 0) << a.output;
    const auto b = demo(second);
    ASSERT_EQ(b.status, 0) << b.output;
    EXPECT_NE(a.output.find("demo written to"), std::string::npos) << a.output;
    EXPECT_EQ(a.output.find("validation"), std::string::npos) << a.output;

    const std::string manifestText = readFile(first / "manifest.json");
    EXPECT_EQ(manifestText, readFile(second / "manifest.json"));
    const nlohmann::json manifest = nlohmann::json::parse(manifestText);
    // Gallery + (video + still) per verb.
    ASSERT_EQ(manifest["files"].size(), 5u);
    std::size_t files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(first))
        if (entry.is_regular_file() && entry.path().filename() != "manifest.json") ++files;
    EXPECT_EQ(files, manifest["files"].size()) << "a file on disk is missing from the manifest (or left over)";
    for (const auto& entry : manifest["files"]) {
        const fs::path file = first / entry["path"].get<std::string>();
        ASSERT_TRUE(fs::exists(file)) << file;
        EXPECT_EQ(signstim::sha256File(file), entry["sha256"].get<std::string>()) << file;
        EXPECT_EQ(readFile(file), readFile(second / entry["path"].get<std::string>())) << "not byte-identical: " << file;
    }
    EXPECT_TRUE(fs::exists(first / "verbs" / "verb-SCOLD_object--0.6_panels-PVAU.mp4"));
    EXPECT_TRUE(fs::exists(first / "verbs" / "verb-MEET_subject-0.9_object--0.6_panels-PVAU.mp4"));
}

TEST(DemoCli, BadInputIsRefusedBeforeAnythingIsWritten) {
    const struct {
        std::string extra, mentions;
    } cases[] = {
        {"--subject 1.5", "--subject"},
        {"--verbs WAVE", "WAVE"},
        {"--fps 0", "--fps"},
        {"--verbs MEET,MEET", "MEET is listed twice"},
        {"--msaa 3", "--msaa"},
    };
    for (const auto& c : cases) {
        const fs::path out = freshDir("bad");
        const auto r = demo(out, c.extra);
        EXPECT_EQ(r.status, 1) << c.extra << ": " << r.output;  // flag mistakes: usage errors
        EXPECT_NE(r.output.find(c.mentions), std::string::npos) << c.extra << ": " << r.output;
        EXPECT_FALSE(fs::exists(out)) << c.extra << " left output behind";
    }
}

TEST(VerbOutCli, RendersAVideoAStillAndAFrameDirectory) {
    const fs::path dir = freshDir("verb");
    const std::string common = "verb COPY --subject 0.9 --object -0.6 --version animator --quiet --size 160x120 --fps 10 "
                               "--scenes " + shellQuote(kScenes) + " --out ";
    for (const std::string name : {"copy.mp4", "copy.png", "frames"}) {
        const auto r = runSignstim(common + shellQuote((dir / name).string()), signstim::test::Capture::StdoutAndStderr,
                                   "SIGNSTIM_VALIDATION=1");
        ASSERT_EQ(r.status, 0) << name << ": " << r.output;
    }
    EXPECT_GT(fs::file_size(dir / "copy.mp4"), 1000u);
    EXPECT_GT(fs::file_size(dir / "copy.png"), 1000u);
    EXPECT_TRUE(fs::exists(dir / "frames" / "frame_00001.png"));
    const auto probe = signstim::test::runShell(
        "ffprobe -v error -select_streams v:0 -count_frames -show_entries stream=codec_name,nb_read_frames "
        "-of csv=p=0 " + shellQuote((dir / "copy.mp4").string()));
    ASSERT_EQ(probe.status, 0) << probe.output;
    std::size_t pngFrames = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir / "frames")) ++pngFrames;
    EXPECT_EQ(probe.output, "h264," + std::to_string(pngFrames) + "\n");
}
