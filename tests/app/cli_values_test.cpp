// Command-line values (app/cli_values.hpp): what each parser accepts, what it refuses, and the
// message of a refusal (file "<command line>", line 0, the flag, "expected ..., got '...'").
#include "app/cli_values.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>

namespace signstim::app {
namespace {

// The InputError `call` throws (fails the test when it throws none).
InputError refusal(const std::function<void()>& call) {
    try {
        call();
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "no InputError thrown";
    return InputError("");
}

void expectRefused(const std::function<void()>& call, const std::string& flag, const std::string& detail) {
    const InputError e = refusal(call);
    EXPECT_EQ(e.file(), "<command line>");
    EXPECT_EQ(e.line(), 0);
    EXPECT_EQ(e.field(), flag);
    EXPECT_EQ(e.detail(), detail);
}

TEST(CliValues, CommandLineErrorNamesTheFlag) {
    const InputError e = commandLineError("--frames", "must be at least 1");
    EXPECT_STREQ(e.what(), "<command line>: field '--frames': must be at least 1");
}

TEST(CliValues, ImageSizeAcceptsWxHWithinLimits) {
    const ImageSize s = parseImageSize("640x480", "--size");
    EXPECT_EQ(s.width, 640u);
    EXPECT_EQ(s.height, 480u);
    const ImageSize upper = parseImageSize("1280X720", "--size");
    EXPECT_EQ(upper.width, 1280u);
    EXPECT_EQ(upper.height, 720u);
    const SizeLimits limits{.minimum = 16, .maximum = 8192};
    EXPECT_EQ(parseImageSize("16x8192", "--size", limits).width, 16u);
    EXPECT_EQ(parseImageSize("16x8192", "--size", limits).height, 8192u);
    EXPECT_EQ(parseImageSize("1x16384", "--size").height, 16384u);  // default limits 1..16384
}

TEST(CliValues, ImageSizeRefusesMalformedText) {
    for (const char* text : {"", "640", "640x", "x480", "640x480x2", " 640x480", "640x480 ", "640*480", "-640x480",
                             "+640x480", "640.5x480", "0x10", "99999999999x480"}) {
        expectRefused([&] { parseImageSize(text, "--size"); }, "--size",
                      "expected WxH between 1 and 16384, got '" + std::string(text) + "'");
    }
}

TEST(CliValues, ImageSizeRefusesSidesOutsideTheLimits) {
    const SizeLimits limits{.minimum = 16, .maximum = 8192};
    for (const char* text : {"15x16", "16x15", "8193x16", "16x8193"})
        expectRefused([&] { parseImageSize(text, "--size", limits); }, "--size",
                      "expected WxH between 16 and 8192, got '" + std::string(text) + "'");
    EXPECT_THROW(parseImageSize("16385x1", "--size"), InputError);
}

TEST(CliValues, ImageSizeCanRequireEvenSides) {
    const SizeLimits even{.minimum = 64, .maximum = 4096, .even = true};
    EXPECT_EQ(parseImageSize("480x360", "--panel-size", even).width, 480u);
    expectRefused([&] { parseImageSize("481x360", "--panel-size", even); }, "--panel-size",
                  "expected even WxH between 64 and 4096, got '481x360'");
    EXPECT_THROW(parseImageSize("480x361", "--panel-size", even), InputError);
    EXPECT_THROW(parseImageSize("62x360", "--panel-size", even), InputError);
}

TEST(CliValues, NumberIsOneFiniteDecimal) {
    EXPECT_FLOAT_EQ(parseNumber("0.5", "--x"), 0.5f);
    EXPECT_FLOAT_EQ(parseNumber(" -3 ", "--x"), -3.0f);
    EXPECT_FLOAT_EQ(parseNumber("1e-2", "--x"), 0.01f);
    for (const char* text : {"", " ", "abc", "1.5x", "1,2", "nan", "inf", "-inf", "1e99"})
        expectRefused([&] { parseNumber(text, "--camera fov"); }, "--camera fov",
                      "expected a number, got '" + std::string(text) + "'");
}

TEST(CliValues, NumbersCountsCommaSeparatedItems) {
    EXPECT_EQ(parseNumbers("1,2,3", "--v", 3, 4), (std::vector<float>{1, 2, 3}));
    EXPECT_EQ(parseNumbers("1, 2, 3, 0.5", "--v", 3, 4), (std::vector<float>{1, 2, 3, 0.5f}));
    EXPECT_EQ(parseNumbers("7", "--v", 1, 1), (std::vector<float>{7}));
    expectRefused([] { parseNumbers("1,2", "--v", 3, 4); }, "--v", "expected 3 or 4 comma-separated numbers, got '1,2'");
    expectRefused([] { parseNumbers("1,2", "--v", 3, 3); }, "--v", "expected 3 comma-separated numbers, got '1,2'");
    expectRefused([] { parseNumbers("1", "--v", 2, 5); }, "--v", "expected 2 to 5 comma-separated numbers, got '1'");
    for (const char* text : {"1,,2", "1,2,", ",1,2", "1,two,3", "1,2,nan", "1;2;3"})
        EXPECT_THROW(parseNumbers(text, "--v", 3, 3), InputError) << text;
}

TEST(CliValues, TripleIsThreeNumbers) {
    const glm::vec3 v = parseTriple("0,100,-400.5", "--gaze");
    EXPECT_EQ(v, glm::vec3(0.0f, 100.0f, -400.5f));
    EXPECT_EQ(parseTriple("1, 2, 3", "--gaze"), glm::vec3(1, 2, 3));  // spaces after commas
    for (const char* text : {"1,2", "1,2,3,4", "1 2 3", "x,y,z", "1,2,inf", ""})
        expectRefused([&] { parseTriple(text, "--right-wrist"); }, "--right-wrist",
                      "expected three numbers x,y,z, got '" + std::string(text) + "'");
}

TEST(CliValues, ColourFormsGiveLinearRgba) {
    EXPECT_EQ(parseColour("transparent", "--background"), glm::vec4(0.0f));
    EXPECT_EQ(parseColour("#ffffff", "--background"), glm::vec4(1.0f));
    EXPECT_EQ(parseColour("#000000", "--background"), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    // sRGB 0x80 = 0.50196 -> linear ((0.50196 + 0.055) / 1.055)^2.4 = 0.21586.
    const glm::vec4 grey = parseColour("#80FF00", "--background");
    EXPECT_NEAR(grey.r, 0.21586, 1e-5);
    EXPECT_FLOAT_EQ(grey.g, 1.0f);
    EXPECT_FLOAT_EQ(grey.b, 0.0f);
    EXPECT_FLOAT_EQ(grey.a, 1.0f);
    const glm::vec4 listed = parseColour("0.5,0.02,1,0.25", "--background");
    EXPECT_NEAR(listed.r, 0.21404, 1e-5);
    EXPECT_NEAR(listed.g, 0.02 / 12.92, 1e-7);  // the linear segment below 0.04045
    EXPECT_FLOAT_EQ(listed.b, 1.0f);
    EXPECT_FLOAT_EQ(listed.a, 0.25f);  // alpha is not gamma-encoded
    EXPECT_FLOAT_EQ(parseColour("1,0,0", "--background").a, 1.0f);
}

TEST(CliValues, ColourRefusesOtherText) {
    for (const char* text : {"", "red", "#fff", "#fffffff", "#ffffff00", "#gg0000", "ffffff", "1,0", "1,0,0,0,1",
                             "1.2,0,0", "0,-0.1,0", "0,0,0,2", "Transparent"})
        expectRefused([&] { parseColour(text, "--background"); }, "--background",
                      "expected #rrggbb, r,g,b[,a] (0..1) or transparent, got '" + std::string(text) + "'");
}

TEST(CliValues, RangeIsInclusiveAndRefusesNaN) {
    EXPECT_EQ(requireInRange(100.0, 100.0, 300.0, "--hand-length", "mm"), 100.0);
    EXPECT_EQ(requireInRange(300.0, 100.0, 300.0, "--hand-length", "mm"), 300.0);
    expectRefused([] { requireInRange(350.0, 100.0, 300.0, "--hand-length", "mm"); }, "--hand-length",
                  "expected 100 to 300 mm, got '350'");
    expectRefused([] { requireInRange(-1.5, 0.0, 1.0, "--subject"); }, "--subject", "expected 0 to 1, got '-1.5'");
    // Past the 6th digit: the message shows why (it printed 1 before).
    expectRefused([] { requireInRange(1.0000001, 0.0, 1.0, "--subject"); }, "--subject", "expected 0 to 1, got '1.0000001'");
    EXPECT_THROW(requireInRange(std::numeric_limits<double>::quiet_NaN(), 0.0, 1.0, "--x"), InputError);
}

TEST(SlurmArrayTask, UnsetVariablesMeanOneShard) {
    EXPECT_EQ(parseArrayTaskShard(nullptr, nullptr, nullptr), (std::pair<std::size_t, std::size_t>{0, 1}));
    EXPECT_EQ(parseArrayTaskShard("3", nullptr, nullptr), (std::pair<std::size_t, std::size_t>{0, 1}));
}

TEST(SlurmArrayTask, TheShardIsTheTaskLessTheMinimumOfTheCount) {
    EXPECT_EQ(parseArrayTaskShard("3", "8", nullptr), (std::pair<std::size_t, std::size_t>{3, 8}));
    EXPECT_EQ(parseArrayTaskShard("8", "8", "1"), (std::pair<std::size_t, std::size_t>{7, 8}));
}

TEST(SlurmArrayTask, AValueThatIsNotANumberIsRefusedNotShardZero) {
    for (const char* id : {"x", "", " 1", "1 ", "+1", "-1", "1.0", "0x1", "99999999999"}) {
        const InputError e = refusal([&] { parseArrayTaskShard(id, "2", nullptr); });
        EXPECT_EQ(e.file(), "<environment>") << id;
        EXPECT_TRUE(e.isUsage()) << id;  // exit status 1, like --shard
        EXPECT_EQ(e.field(), "SLURM_ARRAY_TASK_ID") << id;
        EXPECT_NE(e.detail().find("expected a whole number"), std::string::npos) << e.what();
    }
    EXPECT_EQ(refusal([] { parseArrayTaskShard("0", "two", nullptr); }).field(), "SLURM_ARRAY_TASK_COUNT");
    EXPECT_EQ(refusal([] { parseArrayTaskShard("0", "2", "x"); }).field(), "SLURM_ARRAY_TASK_MIN");
    // A control character from the environment is not echoed to the terminal.
    EXPECT_EQ(refusal([] { parseArrayTaskShard("\x1b[2J", "2", nullptr); }).detail().find('\x1b'), std::string::npos);
}

TEST(SlurmArrayTask, ATaskOutsideTheArrayOrAnEmptyArrayIsRefused) {
    EXPECT_EQ(refusal([] { parseArrayTaskShard("2", "2", nullptr); }).field(), "SLURM_ARRAY_TASK_ID");
    EXPECT_EQ(refusal([] { parseArrayTaskShard("0", "2", "1"); }).field(), "SLURM_ARRAY_TASK_ID");
    EXPECT_EQ(refusal([] { parseArrayTaskShard("0", "0", nullptr); }).field(), "SLURM_ARRAY_TASK_COUNT");
    EXPECT_EQ(refusal([] { parseArrayTaskShard("0", "100001", nullptr); }).field(), "SLURM_ARRAY_TASK_COUNT");
}

}  // namespace
}  // namespace signstim::app
