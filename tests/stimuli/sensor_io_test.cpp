// Sensor files (SPEC §2): calibration JSON and samples CSV parse strictly, name the line and
// the field of every mistake, and round-trip through their writers.
#include "common/error.hpp"
#include "stimuli/verbs/sensor_io.hpp"

#include <gtest/gtest.h>

#include <string>

namespace signstim::stimuli {
namespace {

std::string goodSamples() {
    const hand::HandModel model = hand::buildHandModel();
    const hand::SensorCalibration cal = hand::calibrationForModel(model, hand::Side::Right);
    std::vector<SensorSample> samples;
    for (int i = 0; i < 3; ++i) {
        hand::HandControls c;
        for (auto& f : c.fingers) f.bend = 0.2f * i;
        samples.push_back({0.01 * i, 0, hand::synthesizeSensorReadings(model, hand::forwardKinematics(model, c, hand::Side::Right), cal)});
    }
    return formatSensorSamples(samples);
}

InputError sampleError(const std::string& text) {
    try {
        parseSensorSamples(text, "samples.csv");
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return InputError("none");
}

// Replaces the n-th line (1-based) of text.
std::string withLine(const std::string& text, int n, const std::string& replacement) {
    std::size_t start = 0;
    for (int i = 1; i < n; ++i) start = text.find('\n', start) + 1;
    const std::size_t end = text.find('\n', start);
    return text.substr(0, start) + replacement + text.substr(end);
}

TEST(SensorSamplesTest, WrittenSamplesParseBack) {
    const std::string text = goodSamples();
    const auto samples = parseSensorSamples(text, "samples.csv");
    ASSERT_EQ(samples.size(), 3u);
    EXPECT_EQ(samples[1].line, 8);
    EXPECT_DOUBLE_EQ(samples[2].timeS, 0.02);
    EXPECT_EQ(formatSensorSamples(samples), text);
    // Numeric sensor ids and reordered columns are accepted.
    const std::string numeric = "sensor,time,x,y,z,azimuth,elevation,roll\n"
                                "0,0,1,2,3,4,5,6\n1,0,1,2,3,4,5,6\n2,0,1,2,3,4,5,6\n"
                                "3,0,1,2,3,4,5,6\n4,0,1,2,3,4,5,6\n5,0,1,2,3,4,5,6\n";
    const auto parsed = parseSensorSamples(numeric, "n.csv");
    ASSERT_EQ(parsed.size(), 1u);
    EXPECT_FLOAT_EQ(parsed[0].readings[5].rollDeg, 6.0f);
}

TEST(SensorSamplesTest, MissingColumnIsReportedOnTheHeaderLine) {
    const InputError e = sampleError(withLine(goodSamples(), 1, "time,sensor,x,y,z,azimuth,roll"));
    EXPECT_EQ(e.line(), 1);
    EXPECT_EQ(e.field(), "elevation");
}

TEST(SensorSamplesTest, NonNumericCellNamesLineAndColumn) {
    const std::string text = goodSamples();
    const InputError e = sampleError(withLine(text, 5, "0.0000,middle,1,2,abc,0,0,0"));
    EXPECT_EQ(e.line(), 5);
    EXPECT_EQ(e.field(), "z");
}

TEST(SensorSamplesTest, UnknownSensorIdIsRejected) {
    const InputError e = sampleError(withLine(goodSamples(), 4, "0.0000,pinky,1,2,3,0,0,0"));
    EXPECT_EQ(e.line(), 4);
    EXPECT_EQ(e.field(), "sensor");
    EXPECT_NE(std::string(e.what()).find("pinky"), std::string::npos);
}

TEST(SensorSamplesTest, NanAndInfinityAreRejected) {
    InputError e = sampleError(withLine(goodSamples(), 9, "0.0100,index,1,2,3,nan,0,0"));
    EXPECT_EQ(e.line(), 9);
    EXPECT_EQ(e.field(), "azimuth");
    e = sampleError(withLine(goodSamples(), 10, "0.0100,middle,1,2,3,0,0,inf"));
    EXPECT_EQ(e.line(), 10);
    EXPECT_EQ(e.field(), "roll");
}

TEST(SensorSamplesTest, IncompleteDuplicateAndBackwardSamplesAreRejected) {
    const std::string text = goodSamples();
    InputError e = sampleError(withLine(text, 7, "0.0000,little,1,2,3,0,0,0\n0.0000,little,1,2,3,0,0,0"));
    EXPECT_EQ(e.line(), 8);
    EXPECT_NE(std::string(e.what()).find("twice"), std::string::npos);
    e = sampleError(withLine(text, 7, "0.0050,little,1,2,3,0,0,0"));
    EXPECT_EQ(e.line(), 2) << "the first sample lacks the little finger";
    e = sampleError(withLine(text, 8, "-1,hand,1,2,3,0,0,0"));
    EXPECT_EQ(e.line(), 8);
    EXPECT_EQ(e.field(), "time");
    e = sampleError(withLine(text, 3, "0.0000,thumb,1,2,3,0,0"));
    EXPECT_EQ(e.line(), 3);
    e = sampleError("");
    EXPECT_NE(std::string(e.what()).find("empty"), std::string::npos);
}

// ---- calibration ----
TEST(SensorCalibrationTest, WrittenCalibrationParsesBack) {
    const hand::SensorCalibration cal = hand::calibrationForModel(hand::buildHandModel(), hand::Side::Left);
    const hand::SensorCalibration back = parseSensorCalibration(formatSensorCalibration(cal), "cal.json");
    EXPECT_EQ(back.side, hand::Side::Left);
    EXPECT_FLOAT_EQ(back.handThicknessMm, cal.handThicknessMm);
    for (int d = 0; d < hand::kDigitCount; ++d) {
        EXPECT_FLOAT_EQ(back.digits[d].lengthMm[1], cal.digits[d].lengthMm[1]);
        EXPECT_FLOAT_EQ(back.digits[d].knuckleOffsetMm.y, cal.digits[d].knuckleOffsetMm.y);
        EXPECT_FLOAT_EQ(back.knuckleBowlRollDeg[d], cal.knuckleBowlRollDeg[d]);
    }
}

TEST(SensorCalibrationTest, BadFieldsNameTheFieldAndLine) {
    const std::string good = formatSensorCalibration(hand::calibrationForModel(hand::buildHandModel(), hand::Side::Right));
    auto error = [](const std::string& text) {
        try {
            parseSensorCalibration(text, "cal.json");
        } catch (const InputError& e) {
            return e;
        }
        ADD_FAILURE() << "no error";
        return InputError("none");
    };
    std::string text = good;
    text.replace(text.find("\"tipThicknessMm\""), 16, "\"tipThicknesMm\"");
    InputError e = error(text);
    EXPECT_NE(e.field().find("tipThicknesMm"), std::string::npos) << e.field();
    EXPECT_GT(e.line(), 1);
    text = good;
    const std::size_t at = text.find("\"handThicknessMm\": ") + 19;
    text.replace(at, text.find(',', at) - at, "\"thick\"");
    e = error(text);
    EXPECT_EQ(e.field(), "handThicknessMm");
    EXPECT_GT(e.line(), 1);
    e = error("{\"handThicknessMm\": 27}");
    EXPECT_EQ(e.field(), "digits");
    e = error("{\"handThicknessMm\": 27,");
    EXPECT_NE(std::string(e.what()).find("JSON"), std::string::npos);
}

}  // namespace
}  // namespace signstim::stimuli
