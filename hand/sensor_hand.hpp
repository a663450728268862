#pragma once
// The sensor-driven hand (SPEC §2; van Polanen, Bergmann Tiest & Kappers, "A simple model
// of the hand for object exploration"): 16 segment boxes from six 6-DOF sensors, one on
// each nail and one on the back of the hand.
//
// Conventions (SPEC §2.1): R = R_z(azimuth)·R_y(elevation)·R_x(roll − initial roll); a point
// fixed on a sensor's segment is q = R·q_local + s. Sensor frame: x proximal→distal, y
// ulnar→radial (right hand), z palmar→dorsal. All positions in mm in the tracker's frame.
// Segments are named like the McDonald bodies (`Body`), the thumb's three segments being
// ThumbMetacarpal (the paper's "proximal phalanx" of the thumb), ThumbProximal, ThumbDistal.
//
// `synthesizeSensorReadings()` runs the model backwards (McDonald pose -> six readings) so
// the reconstruction can be checked against a known hand (round trip, tests and docs).
#include "hand/contact.hpp"
#include "hand/hand_model.hpp"

#include <array>
#include <cstdint>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace signstim::hand {

// Sensor ids: 0 = back of the hand, 1..5 = nails of thumb..little (digit + 1).
enum class SensorId : std::uint8_t { Hand = 0, Thumb, Index, Middle, Ring, Little };
inline constexpr int kSensorCount = 6;

// SPEC §2.1 [P]: R_z(a)·R_y(e)·R_x(r), the paper's matrix (7.2) entry by entry. Degrees.
glm::mat3 sensorRotation(float azimuthDeg, float elevationDeg, float correctedRollDeg);
// Inverse of sensorRotation for a proper rotation (elevation in [−90°, 90°]).
void sensorAngles(const glm::mat3& rotation, float& azimuthDeg, float& elevationDeg, float& rollDeg);

struct SensorReading {
    glm::vec3 positionMm{0.0f};
    float azimuthDeg = 0.0f;
    float elevationDeg = 0.0f;
    float rollDeg = 0.0f;  // as measured; the calibrated initial roll is subtracted later
};
using SensorReadings = std::array<SensorReading, kSensorCount>;

// SPEC §2.2 [P]: per digit (thumb..little) and for the hand.
struct DigitCalibration {
    std::array<float, 3> lengthMm{};  // proximal, middle, distal phalanx (thumb: metacarpal, proximal, distal)
    std::array<float, 3> widthMm{};
    float tipThicknessMm = 12.0f;          // t_f; 1.5·t_f at the proximal joint
    glm::vec2 knuckleOffsetMm{0.0f};       // (Δx, Δy) of the knuckle from the hand sensor
    float initialRollDeg = 0.0f;           // subtracted from the nail sensor's roll
};
struct SensorCalibration {
    Side side = Side::Right;
    std::array<DigitCalibration, kDigitCount> digits{};
    float handThicknessMm = 27.0f;  // t_h
    float handInitialRollDeg = 0.0f;
    // SPEC §2.3 [P]: bowl form, extra roll of the knuckles thumb..little and of the palm block
    // (sign mirrored for a left hand [D]). Set them to 0 for a flat hand.
    std::array<float, kDigitCount> knuckleBowlRollDeg{0.0f, 15.0f, 30.0f, 45.0f, 60.0f};
    float palmBowlRollDeg = 40.0f;
    float sensorFromTipMm = 5.0f;  // SPEC §2.2: nail sensor ~5 mm from the fingertip
};

// How the proximal joint C was found (SPEC §2.4).
enum class ProximalJointCase : std::uint8_t {
    Triangle,     // the triangle closed; the solution with the larger angle φ
    Straight,     // c > a + b: C = B + a/(a+b)·c⃗
    FullyBent,    // c < |b − a|: C = B − (a/c)·c⃗
    Degenerate,   // c ≈ 0: C = B − a·x̂_f (along the nail sensor's axis) [D]
};
struct ProximalJoint {
    glm::vec3 point{0.0f};
    ProximalJointCase how = ProximalJointCase::Triangle;
};
// A knuckle, B distal joint, D under-nail point, a = middle-phalanx length, b = proximal-
// phalanx length; `nailRotation` supplies the plane when d⃗ ∥ c⃗ (R_f·ŷ is its normal) and
// the fallback direction when c ≈ 0 [D].
ProximalJoint solveProximalJoint(const glm::vec3& A, const glm::vec3& B, const glm::vec3& D, float a,
                                 float b, const glm::mat3& nailRotation);

struct DigitJoints {
    glm::vec3 knuckle{0.0f};        // A
    glm::vec3 distalJoint{0.0f};    // B
    glm::vec3 proximalJoint{0.0f};  // C
    glm::vec3 underNail{0.0f};      // D
    ProximalJointCase proximalCase = ProximalJointCase::Triangle;
};

struct SensorHandFrame {
    std::array<DigitJoints, kDigitCount> joints{};  // thumb..little
    std::array<BoxVertices, kBodyCount> segments{};  // indexed by Body; vertices as SPEC §2.5
};

// SPEC §2.3–§2.5: joints A–D and the 16 boxes from one set of six readings. Throws
// std::invalid_argument for non-positive calibration lengths (programmer error: the file
// parser validates user input first).
SensorHandFrame sensorHand(const SensorCalibration& calibration, const SensorReadings& readings);

// ---- round trip: McDonald hand -> sensors -------------------------------------------------
// A calibration matching a McDonald hand: phalanx lengths and widths from the model, knuckle
// offsets from its MCPs/CMC relative to a hand sensor on the back of the hand in line with
// the middle-finger knuckle, palm bowl roll 0.
//  * ExactKnuckles: each knuckle's bowl roll γ and Δy are fitted so that A lands exactly on
//    the McDonald joint (the MCPs leave the palm plane by up to 1.3 mm, the CMC sits 10 mm
//    palmar, SPEC §1.3–§1.4); the round trip then tests the reconstruction itself.
//  * FlatPalm: bowl rolls 0, knuckles in the palm's mid-plane (what a photo calibration gives).
enum class KnuckleFit : std::uint8_t { ExactKnuckles, FlatPalm };
SensorCalibration calibrationForModel(const HandModel& model, Side side,
                                      KnuckleFit fit = KnuckleFit::ExactKnuckles);
// The six readings that a sensor glove would report on the posed hand (hand frame = tracker
// frame), including the calibration's initial rolls. The palm pose is `pose.bodies[0]`.
SensorReadings synthesizeSensorReadings(const HandModel& model, const HandPose& pose,
                                        const SensorCalibration& calibration);

}  // namespace signstim::hand
