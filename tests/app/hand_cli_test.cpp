// The `signstim hand` commands as a user runs them: the built binary, its stdout, stderr,
// exit status and files.
#include "hand/sensor_hand.hpp"
#include "stimuli/verbs/sensor_io.hpp"
#include "tests/app/run_command.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;

using signstim::test::Capture;
using signstim::test::CommandResult;
using signstim::test::runSignstim;

fs::path scratchDir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("signstim_hand_cli_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void writeText(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

const std::string kScenes = std::string("--scenes ") + SIGNSTIM_SOURCE_DIR + "/scenes";

TEST(HandCliTest, PoseJsonListsSixteenVrmBonesAndFiveTips) {
    const CommandResult r = runSignstim("hand pose --shape O --json " + kScenes, Capture::StdoutOnly);
    ASSERT_EQ(r.status, 0) << r.output;
    const nlohmann::json out = nlohmann::json::parse(r.output);
    EXPECT_EQ(out["side"], "right");
    ASSERT_EQ(out["joints"].size(), 16u);
    EXPECT_EQ(out["joints"][0]["name"], "rightHand");
    EXPECT_EQ(out["joints"][5]["name"], "rightIndexIntermediate");
    EXPECT_EQ(out["joints"][15]["name"], "rightLittleDistal");
    for (const auto& joint : out["joints"]) {
        ASSERT_EQ(joint["position"].size(), 3u);
        const auto& q = joint["rotation"];
        ASSERT_EQ(q.size(), 4u);
        const double norm = std::sqrt(double(q[0]) * double(q[0]) + double(q[1]) * double(q[1]) +
                                      double(q[2]) * double(q[2]) + double(q[3]) * double(q[3]));
        EXPECT_NEAR(norm, 1.0, 1e-5) << joint["name"];
    }
    // O: the thumb tip meets the index tip (centres a couple of finger radii apart at most).
    const auto& tips = out["tips"];
    for (const char* digit : {"thumb", "index", "middle", "ring", "little"}) ASSERT_TRUE(tips.contains(digit)) << digit;
    double distance = 0.0;
    for (int i = 0; i < 3; ++i) distance += std::pow(double(tips["thumb"][i]) - double(tips["index"][i]), 2.0);
    EXPECT_LT(std::sqrt(distance), 30.0);
}

TEST(HandCliTest, LeftPoseIsTheMirrorOfTheRight) {
    const CommandResult right = runSignstim("hand pose --shape 5 --json " + kScenes, Capture::StdoutOnly);
    const CommandResult left = runSignstim("hand pose --shape 5 --side left --json " + kScenes, Capture::StdoutOnly);
    ASSERT_EQ(right.status, 0);
    ASSERT_EQ(left.status, 0);
    const auto r = nlohmann::json::parse(right.output), l = nlohmann::json::parse(left.output);
    EXPECT_EQ(l["joints"][4]["name"], "leftIndexProximal");
    for (int j = 0; j < 16; ++j) {
        EXPECT_NEAR(double(l["joints"][j]["position"][1]), -double(r["joints"][j]["position"][1]), 1e-3);
        EXPECT_NEAR(double(l["joints"][j]["position"][2]), double(r["joints"][j]["position"][2]), 1e-3);
    }
}

TEST(HandCliTest, ShapesListsNamesWithLabels) {
    const CommandResult r = runSignstim("hand shapes " + kScenes);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("bent-B\tflat_b\n"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("open-B\topen_b\n"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("10\t-\n"), std::string::npos);
}

TEST(HandCliTest, UnknownShapeIsAnInputError) {
    const CommandResult r = runSignstim("hand pose --shape J " + kScenes);
    EXPECT_EQ(r.status, 1) << r.output;  // a flag's value: usage
    EXPECT_NE(r.output.find("unknown handshape 'J'"), std::string::npos) << r.output;
}

class FromSensorsTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir = scratchDir(::testing::UnitTest::GetInstance()->current_test_info()->name());
        const signstim::hand::HandModel model = signstim::hand::buildHandModel();
        const auto calibration = signstim::hand::calibrationForModel(model, signstim::hand::Side::Right);
        writeText(dir / "cal.json", signstim::stimuli::formatSensorCalibration(calibration));
        std::vector<signstim::stimuli::SensorSample> samples;
        for (int i = 0; i < 2; ++i) {
            signstim::hand::HandControls c;
            for (auto& f : c.fingers) f.bend = 0.3f * i;
            samples.push_back({0.5 * i, 0,
                               signstim::hand::synthesizeSensorReadings(
                                   model, signstim::hand::forwardKinematics(model, c, signstim::hand::Side::Right), calibration)});
        }
        goodCsv = signstim::stimuli::formatSensorSamples(samples);
    }
    void TearDown() override { fs::remove_all(dir); }
    fs::path dir;
    std::string goodCsv;
};

TEST_F(FromSensorsTest, WritesJointsAndBoxesForEverySample) {
    writeText(dir / "samples.csv", goodCsv);
    const CommandResult r = runSignstim("hand from-sensors " + (dir / "samples.csv").string() + " --calibration " +
                                        (dir / "cal.json").string() + " --out " + (dir / "hand.json").string());
    ASSERT_EQ(r.status, 0) << r.output;
    std::ifstream in(dir / "hand.json");
    const nlohmann::json out = nlohmann::json::parse(in);
    ASSERT_EQ(out["samples"].size(), 2u);
    EXPECT_EQ(out["samples"][1]["segments"]["rightIndexDistal"].size(), 8u);
    EXPECT_EQ(out["samples"][1]["joints"]["index"]["C"].size(), 3u);
    const CommandResult csv = runSignstim("hand from-sensors " + (dir / "samples.csv").string() + " --calibration " +
                                          (dir / "cal.json").string() + " --out " + (dir / "hand.csv").string());
    ASSERT_EQ(csv.status, 0) << csv.output;
    EXPECT_TRUE(fs::exists(dir / "hand.csv"));
}

TEST_F(FromSensorsTest, MalformedCsvNamesTheLineAndWritesNothing) {
    std::string bad = goodCsv;
    // Line 5 (the 4th reading of the first sample): a non-numeric elevation.
    std::size_t start = 0;
    for (int i = 1; i < 5; ++i) start = bad.find('\n', start) + 1;
    bad.replace(start, bad.find('\n', start) - start, "0.0000,middle,1,2,3,0,high,0");
    writeText(dir / "samples.csv", bad);
    const fs::path out = dir / "hand.json";
    const CommandResult r = runSignstim("hand from-sensors " + (dir / "samples.csv").string() + " --calibration " +
                                        (dir / "cal.json").string() + " --out " + out.string());
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("samples.csv:5"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("elevation"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
    for (const auto& entry : fs::directory_iterator(dir)) {
        EXPECT_EQ(entry.path().filename().string().find("hand"), std::string::npos) << "partial output " << entry.path();
    }
}

}  // namespace
