#pragma once
// Files of the sensor-driven hand (SPEC §2): the calibration (JSON), the recorded samples
// (CSV) and the reconstructed hand (JSON or CSV). Every user mistake is an InputError
// naming the file, the line and the field; nothing is written for a bad input.
//
// Samples CSV: a header naming the columns time,sensor,x,y,z,azimuth,elevation,roll (any
// order; extra columns are an error), then one row per sensor and time; a leading UTF-8 BOM
// is skipped. Sensor ids: hand,
// thumb, index, middle, ring, little, or 0..5 in that order. Rows with the same time form one
// sample, which must hold each of the six sensors exactly once; times must increase.
// Units: seconds, millimetres, degrees.
//
// Calibration JSON (SPEC §2.2):
//   {"side": "right", "handThicknessMm": 27, "handInitialRollDeg": 0,
//    "knuckleBowlRollDeg": [0, 15, 30, 45, 60], "palmBowlRollDeg": 40, "sensorFromTipMm": 5,
//    "digits": {"thumb": {"lengthMm": [prox, mid, dist], "widthMm": [prox, mid, dist],
//                         "tipThicknessMm": 12, "knuckleMm": [dx, dy], "initialRollDeg": 0},
//               "index": {...}, "middle": {...}, "ring": {...}, "little": {...}}}
// The bowl rolls, palm roll and sensor distance are optional (paper defaults).
#include "hand/sensor_hand.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace signstim::stimuli {

struct SensorSample {
    double timeS = 0.0;
    int line = 0;  // line of the sample's first row, for messages
    hand::SensorReadings readings{};
};

std::vector<SensorSample> parseSensorSamples(const std::string& text, const std::string& fileName);
std::vector<SensorSample> loadSensorSamples(const std::filesystem::path& file);

hand::SensorCalibration parseSensorCalibration(const std::string& text, const std::string& fileName);
hand::SensorCalibration loadSensorCalibration(const std::filesystem::path& file);
// The inverse of parseSensorCalibration (round-trips through it).
std::string formatSensorCalibration(const hand::SensorCalibration& calibration);
// Samples as CSV in the format parseSensorSamples reads.
std::string formatSensorSamples(const std::vector<SensorSample>& samples);

// Throws InputError naming `file` (the samples) and the sample's line when a rebuilt frame
// holds a coordinate that is not finite: such a frame is never written.
void checkSensorHandFinite(const std::vector<SensorSample>& samples, const std::vector<hand::SensorHandFrame>& frames,
                           const std::string& file);

// The reconstructed hand, one entry per sample: joints A–D per digit and the 16 boxes.
// JSON: {"side", "samples": [{"time", "joints": {"thumb": {"A": [x,y,z], "B", "C", "D",
//        "proximalCase"}, ...}, "segments": {"rightHand": [[x,y,z] × 8], ...}}]}
// CSV:  time,kind,name,index,x,y,z  (kind = joint|vertex; name = digit or segment; index =
//        A..D or vertex 1..8)
std::string formatSensorHandJson(hand::Side side, const std::vector<SensorSample>& samples,
                                 const std::vector<hand::SensorHandFrame>& frames);
std::string formatSensorHandCsv(hand::Side side, const std::vector<SensorSample>& samples,
                                const std::vector<hand::SensorHandFrame>& frames);

}  // namespace signstim::stimuli
