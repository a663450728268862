// Data-file mistakes as a user meets them (issue 15): the built binary exits 2 with a message
// naming the file and the line, never 4 ("internal error"), never 0 with null or nan written,
// and never hangs on a FIFO.
#include "hand/sensor_hand.hpp"
#include "stimuli/verbs/sensor_io.hpp"
#include "tests/app/run_command.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

namespace hand = signstim::hand;
using signstim::test::Capture;
using signstim::test::CommandResult;
using signstim::test::runSignstim;
using signstim::test::shellQuote;

const fs::path kScenes = fs::path(SIGNSTIM_SOURCE_DIR) / "scenes";

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

fs::path scratchDir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("signstim_data_errors_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

int lineOfText(const std::string& text, const std::string& needle) {
    const std::size_t at = text.find(needle);
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

TEST(DataErrorsCli, AnOverflowingNumberInAHandshapeFileExitsTwoNamingFileAndLine) {
    const fs::path dir = scratchDir("overflow");
    const std::string text = replaced(readFile(kScenes / "handshapes.json"), "\"bend\": 0,", "\"bend\": 1e400,");
    std::ofstream(dir / "shapes.json") << text;
    const CommandResult r = runSignstim("hand shapes --shapes " + shellQuote((dir / "shapes.json").string()));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("shapes.json:" + std::to_string(lineOfText(text, "1e400")) + ":"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
    fs::remove_all(dir);
}

TEST(DataErrorsCli, AnUnknownHandshapeInAnAnimatorFileIsBlamedOnThatFile) {
    const fs::path dir = scratchDir("animator");
    const fs::path scenes = dir / "scenes";
    fs::create_directories(scenes / "animator");
    fs::copy_file(kScenes / "verbs.json", scenes / "verbs.json");
    fs::copy_file(kScenes / "handshapes.json", scenes / "handshapes.json");
    const std::string text =
        replaced(readFile(kScenes / "animator" / "ASK_s0.9_o-0.6.json"), "\"handshape\": \"X\"", "\"handshape\": \"bogus\"");
    std::ofstream(scenes / "animator" / "ASK_s0.9_o-0.6.json") << text;
    const CommandResult r = runSignstim("verb ASK --subject 0.9 --object -0.6 --version animator --json --scenes " +
                                        shellQuote(scenes.string()));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("ASK_s0.9_o-0.6.json:" + std::to_string(lineOfText(text, "bogus")) +
                            ": field '/hands/right/1/handshape': unknown handshape 'bogus'"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("--shape"), std::string::npos) << r.output;
    fs::remove_all(dir);
}

TEST(DataErrorsCli, AHugeAnimatorPositionExitsTwoInsteadOfWritingNull) {
    const fs::path dir = scratchDir("huge");
    const fs::path scenes = dir / "scenes";
    fs::create_directories(scenes / "animator");
    fs::copy_file(kScenes / "verbs.json", scenes / "verbs.json");
    fs::copy_file(kScenes / "handshapes.json", scenes / "handshapes.json");
    std::ofstream(scenes / "animator" / "ASK_s0.9_o-0.6.json")
        << replaced(readFile(kScenes / "animator" / "ASK_s0.9_o-0.6.json"), "[-190, 0, 330]", "[-190, 0, 1e308]");
    const CommandResult r = runSignstim("verb ASK --subject 0.9 --object -0.6 --version animator --json --scenes " +
                                        shellQuote(scenes.string()));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("expected -2000 to 2000 mm, got 1e+308"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("null"), std::string::npos) << r.output;
    fs::remove_all(dir);
}

TEST(DataErrorsCli, AFifoAsInputExitsTwoAtOnce) {
    const fs::path dir = scratchDir("fifo");
    const fs::path fifo = dir / "samples.csv";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const auto start = std::chrono::steady_clock::now();
    // `timeout` turns a hang into status 124 instead of a test that never ends.
    const CommandResult r = runSignstim("hand shapes --shapes " + shellQuote(fifo.string()), Capture::StdoutAndStderr,
                                        "timeout 20");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("is a FIFO"), std::string::npos) << r.output;
    EXPECT_LT(seconds, 10.0);
    const CommandResult directory = runSignstim("hand shapes --shapes " + shellQuote(dir.string()));
    EXPECT_EQ(directory.status, 2) << directory.output;
    EXPECT_NE(directory.output.find("is a directory"), std::string::npos) << directory.output;
    fs::remove_all(dir);
}

TEST(DataErrorsCli, AFailedReadExitsThree) {
    // read() of /proc/self/mem fails with EIO: the system's fault, not the user's.
    const CommandResult r = runSignstim("hand shapes --shapes /proc/self/mem");
    EXPECT_EQ(r.status, 3) << r.output;
    EXPECT_NE(r.output.find("Input/output error"), std::string::npos) << r.output;
}

TEST(DataErrorsCli, AHugeSensorSampleExitsTwoAndWritesNothing) {
    const fs::path dir = scratchDir("sensor");
    std::string samples = "time,sensor,x,y,z,azimuth,elevation,roll\n";
    for (const char* sensor : {"hand", "thumb", "index", "middle", "ring", "little"})
        samples += std::string("0,") + sensor + ",1,2,3,4,5,6\n";
    // With a BOM, as Excel writes it: accepted, and the error is still on line 4.
    std::ofstream(dir / "samples.csv") << "\xEF\xBB\xBF" + replaced(samples, "0,index,1,2,3", "0,index,1e300,2,3");
    const hand::HandModel model = hand::buildHandModel();
    std::ofstream(dir / "cal.json") << signstim::stimuli::formatSensorCalibration(hand::calibrationForModel(model, hand::Side::Right));
    const CommandResult r = runSignstim("hand from-sensors " + shellQuote((dir / "samples.csv").string()) + " --calibration " +
                                        shellQuote((dir / "cal.json").string()) + " --out " +
                                        shellQuote((dir / "out.json").string()));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("samples.csv:4: field 'x': expected -10000 to 10000 mm, got 1e+300"), std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(dir / "out.json"));
    const CommandResult device = runSignstim("hand from-sensors " + shellQuote((dir / "samples.csv").string()) +
                                             " --calibration /dev/null --out " + shellQuote((dir / "out.json").string()));
    EXPECT_EQ(device.status, 2) << device.output;
    EXPECT_NE(device.output.find("/dev/null: is a character device"), std::string::npos) << device.output;
    EXPECT_FALSE(fs::exists(dir / "out.json"));
    fs::remove_all(dir);
}

// ---- bounded input (issue 25 §10; docs/errors.md, Limits) ----------------------------------

TEST(DataErrorsCli, AHundredThousandLevelsOfNestingExitTwoAtOnce) {
    const fs::path dir = scratchDir("deep");
    std::ofstream(dir / "deep.json") << std::string(100000, '[') << std::string(100000, ']');  // synthetic
    const auto start = std::chrono::steady_clock::now();
    const CommandResult r = runSignstim("hand shapes --shapes " + shellQuote((dir / "deep.json").string()));
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 20.0);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("deep.json:1: field '/0/0/0"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("nested more than 64 deep"), std::string::npos) << r.output;
    fs::remove_all(dir);
}

TEST(DataErrorsCli, ANulInAStoryTitleExitsTwoNamingLineAndField) {
    const fs::path dir = scratchDir("nul");
    const std::string text = replaced(readFile(kScenes / "stories" / "story-01.json"), "\"title\": \"The copied homework\"",
                                      "\"title\": \"The copied\\u0000 homework\"");
    std::ofstream(dir / "story.json") << text;
    const CommandResult r = runSignstim("story " + shellQuote((dir / "story.json").string()) + " --check");
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("story.json:" + std::to_string(lineOfText(text, "\"title\"")) + ": field '/title': "),
              std::string::npos)
        << r.output;
    // The whole message reaches the terminal: no NUL cuts it short.
    EXPECT_NE(r.output.find("U+0000 (NUL)"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("remove the invisible character"), std::string::npos) << r.output;
    fs::remove_all(dir);
}

TEST(DataErrorsCli, ASlurmTaskIdThatIsNotANumberExitsOneInsteadOfShardZero) {
    const CommandResult r = runSignstim("study " + shellQuote((kScenes / "studies" / "default.json").string()) + " --check",
                                        Capture::StdoutAndStderr, "SLURM_ARRAY_TASK_ID=x SLURM_ARRAY_TASK_COUNT=2");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("signstim: error: <environment>: field 'SLURM_ARRAY_TASK_ID': expected a whole number"),
              std::string::npos)
        << r.output;
}

}  // namespace
