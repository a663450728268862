// The sensor-driven hand (SPEC §2): the paper's rotation matrix entry by entry, the proximal
// joint triangle with its edge cases, the boxes, and the round trip McDonald hand -> six
// synthetic sensor readings -> rebuilt joints.
#include "hand/sensor_hand.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

namespace signstim::hand {
namespace {

constexpr float kDeg = 0.017453292519943295f;

TEST(SensorRotationTest, MatchesThePapersMatrixEntryByEntry) {
    const float angles[][3] = {{0, 0, 0}, {30, 20, 10}, {-75, 40, -120}, {170, -60, 45}, {10, 89, 5}};
    for (const auto& t : angles) {
        const float a = t[0] * kDeg, e = t[1] * kDeg, r = t[2] * kDeg;
        using std::cos, std::sin;
        // Paper eq. 7.2, rows as printed.
        const float paper[3][3] = {
            {cos(a) * cos(e), -cos(r) * sin(a) + cos(a) * sin(e) * sin(r), cos(a) * cos(r) * sin(e) + sin(a) * sin(r)},
            {cos(e) * sin(a), cos(a) * cos(r) + sin(a) * sin(e) * sin(r), cos(r) * sin(a) * sin(e) - cos(a) * sin(r)},
            {-sin(e), cos(e) * sin(r), cos(e) * cos(r)}};
        const glm::mat3 R = sensorRotation(t[0], t[1], t[2]);
        for (int row = 0; row < 3; ++row) {
            for (int col = 0; col < 3; ++col) {
                EXPECT_NEAR(R[col][row], paper[row][col], 1e-6f) << "entry " << row << "," << col;
            }
        }
        // And it is R_z(a)·R_y(e)·R_x(r).
        const glm::mat3 composed = glm::mat3_cast(glm::angleAxis(a, glm::vec3(0, 0, 1)) *
                                                  glm::angleAxis(e, glm::vec3(0, 1, 0)) *
                                                  glm::angleAxis(r, glm::vec3(1, 0, 0)));
        for (int col = 0; col < 3; ++col) EXPECT_NEAR(glm::distance(R[col], composed[col]), 0.0f, 1e-5f);
        float a2, e2, r2;
        sensorAngles(R, a2, e2, r2);
        EXPECT_NEAR(a2, t[0], 1e-2f);
        EXPECT_NEAR(e2, t[1], 1e-2f);
        EXPECT_NEAR(r2, t[2], 1e-2f);
    }
}

// A finger lying in the x–z plane: knuckle A, proximal joint C, distal joint B, nail point D.
struct Finger {
    glm::vec3 A, C, B, D;
    float a, b;  // middle, proximal lengths
};
Finger bentFinger(float pipDeg, float dipDeg) {
    const float b = 50.0f, a = 30.0f, dist = 12.0f;
    Finger f;
    f.A = {0, 0, 0};
    f.C = f.A + b * glm::vec3(1, 0, 0);
    const float p = pipDeg * kDeg, q = (pipDeg + dipDeg) * kDeg;
    f.B = f.C + a * glm::vec3(std::cos(p), 0, -std::sin(p));  // flexion toward −z (palmar)
    f.D = f.B + dist * glm::vec3(std::cos(q), 0, -std::sin(q));
    f.a = a;
    f.b = b;
    return f;
}
const glm::mat3 kNail(1.0f);  // nail sensor axes = world axes (y is the flexion axis)

TEST(ProximalJointTest, TriangleRecoversTheJointWithTheStraighterDistalPhalanx) {
    for (float pip : {10.0f, 45.0f, 90.0f, 110.0f}) {
        for (float dip : {0.0f, 30.0f, 60.0f}) {
            const Finger f = bentFinger(pip, dip);
            const ProximalJoint C = solveProximalJoint(f.A, f.B, f.D, f.a, f.b, kNail);
            EXPECT_EQ(C.how, ProximalJointCase::Triangle);
            EXPECT_NEAR(glm::distance(C.point, f.C), 0.0f, 1e-3f) << pip << " " << dip;
        }
    }
}

TEST(ProximalJointTest, StraightFingerWhenTheTriangleCannotClose) {
    // c > a + b (the measured finger got longer): C on c⃗ at a/(a+b) from B.
    const glm::vec3 A(0, 0, 0), B(90, 0, 0), D(100, 0, 0);
    const ProximalJoint C = solveProximalJoint(A, B, D, 30.0f, 50.0f, kNail);
    EXPECT_EQ(C.how, ProximalJointCase::Straight);
    EXPECT_NEAR(glm::distance(C.point, glm::vec3(90.0f - 90.0f * 30.0f / 80.0f, 0, 0)), 0.0f, 1e-4f);
}

TEST(ProximalJointTest, FullyBentFingerWhenTheKnuckleIsTooClose) {
    // c < |b − a|: C = B − (a/c)·c⃗, i.e. a millimetres from B, away from A.
    const glm::vec3 A(0, 0, 0), B(10, 0, 0), D(10, 0, -12);
    const ProximalJoint C = solveProximalJoint(A, B, D, 30.0f, 50.0f, kNail);
    EXPECT_EQ(C.how, ProximalJointCase::FullyBent);
    EXPECT_NEAR(glm::distance(C.point, glm::vec3(40, 0, 0)), 0.0f, 1e-4f);
}

TEST(ProximalJointTest, DegenerateInputsStayFinite) {
    // c ≈ 0: knuckle on the distal joint.
    ProximalJoint C = solveProximalJoint({5, 5, 5}, {5, 5, 5}, {15, 5, 5}, 30.0f, 50.0f, kNail);
    EXPECT_EQ(C.how, ProximalJointCase::Degenerate);
    EXPECT_NEAR(glm::distance(C.point, glm::vec3(-25, 5, 5)), 0.0f, 1e-4f);
    // d⃗ ∥ c⃗ with a closable triangle: the plane comes from the nail sensor's y-axis and the
    // joint bulges dorsally (+z of the nail sensor).
    const glm::vec3 A(0, 0, 0), B(60, 0, 0), D(72, 0, 0);
    C = solveProximalJoint(A, B, D, 30.0f, 50.0f, kNail);
    EXPECT_EQ(C.how, ProximalJointCase::Triangle);
    EXPECT_NEAR(glm::distance(C.point, A), 50.0f, 1e-3f);
    EXPECT_NEAR(glm::distance(C.point, B), 30.0f, 1e-3f);
    EXPECT_NEAR(C.point.y, 0.0f, 1e-4f);
    EXPECT_GT(C.point.z, 0.0f);
}

// ---- whole hand -------------------------------------------------------------------------
struct RoundTripErrors {
    float knuckleFinger = 0, proximalFinger = 0, distal = 0, knuckleThumb = 0, proximalThumb = 0;
};

// Worst joint errors over a set of postures, for a hand placed anywhere in the tracker frame.
enum class Calibration { Exact, FlatPalm, PaperBowl };
RoundTripErrors roundTrip(Side side, Calibration kind) {
    const HandModel model = buildHandModel();
    SensorCalibration cal =
        calibrationForModel(model, side, kind == Calibration::Exact ? KnuckleFit::ExactKnuckles : KnuckleFit::FlatPalm);
    for (int d = 0; d < kDigitCount; ++d) cal.digits[d].initialRollDeg = 7.0f * d - 12.0f;
    cal.handInitialRollDeg = 9.0f;
    if (kind == Calibration::PaperBowl) {
        cal.knuckleBowlRollDeg = {0.0f, 15.0f, 30.0f, 45.0f, 60.0f};
        cal.palmBowlRollDeg = 40.0f;
    }
    const RigidTransform world{{120.0f, -40.0f, 300.0f},
                               glm::normalize(glm::angleAxis(0.9f, glm::normalize(glm::vec3(0.3f, -1.0f, 0.5f))))};
    RoundTripErrors worst;
    const float bends[] = {0.0f, 0.3f, 0.6f, 0.9f};
    const float hooks[] = {0.0f, 0.5f, 1.0f};
    for (float bend : bends) {
        for (float hook : hooks) {
            HandControls c;
            for (int f = 0; f < kFingerCount; ++f) c.fingers[f] = {6.0f * f - 8.0f, bend, hook};
            c.thumb = {20.0f + 60.0f * bend, 30.0f + 40.0f * hook, 30.0f * bend, 50.0f * hook};
            HandPose pose = forwardKinematics(model, c, side);
            for (auto& body : pose.bodies) body = compose(world, body);
            const SensorReadings readings = synthesizeSensorReadings(model, pose, cal);
            const SensorHandFrame frame = sensorHand(cal, readings);
            for (int d = 0; d < kDigitCount; ++d) {
                const int first = firstBodyOf(Digit(d));
                const DigitJoints& j = frame.joints[d];
                const float eA = glm::distance(j.knuckle, pose.bodies[first].position);
                const float eC = glm::distance(j.proximalJoint, pose.bodies[first + 1].position);
                const float eB = glm::distance(j.distalJoint, pose.bodies[first + 2].position);
                worst.distal = std::max(worst.distal, eB);
                if (d == 0) {
                    worst.knuckleThumb = std::max(worst.knuckleThumb, eA);
                    worst.proximalThumb = std::max(worst.proximalThumb, eC);
                } else {
                    worst.knuckleFinger = std::max(worst.knuckleFinger, eA);
                    worst.proximalFinger = std::max(worst.proximalFinger, eC);
                }
            }
        }
    }
    return worst;
}

void report(const char* label, const RoundTripErrors& e) {
    std::printf("[round trip %s] max joint error, mm: fingers A %.3f C %.3f; all B %.3f; thumb A %.3f C %.3f\n",
                label, e.knuckleFinger, e.proximalFinger, e.distal, e.knuckleThumb, e.proximalThumb);
}

TEST(SensorHandTest, RoundTripFromAMcDonaldHandRecoversTheJoints) {
    for (Side side : {Side::Right, Side::Left}) {
        const RoundTripErrors e = roundTrip(side, Calibration::Exact);
        report(side == Side::Right ? "right, fitted knuckles" : "left, fitted knuckles", e);
        // With the knuckles calibrated onto the McDonald joints, every joint comes back to
        // within float rounding, through arbitrary tracker placement and initial rolls.
        EXPECT_LT(e.distal, 0.01f);
        EXPECT_LT(e.knuckleFinger, 0.01f);
        EXPECT_LT(e.knuckleThumb, 0.01f);
        EXPECT_LT(e.proximalFinger, 0.1f);
        EXPECT_LT(e.proximalThumb, 0.1f);
    }
}

TEST(SensorHandTest, FlatPalmCalibrationErrorComesFromTheKnuckles) {
    const RoundTripErrors e = roundTrip(Side::Right, Calibration::FlatPalm);
    report("right, flat-palm calibration", e);
    report("right, paper's fixed bowl rolls", roundTrip(Side::Right, Calibration::PaperBowl));
    EXPECT_LT(e.distal, 0.01f);
    // The sensor model puts the knuckles in the palm's mid-plane; McDonald's MCP curve leaves
    // it by < 1.3 mm, and its CMC sits 10 mm palmar (SPEC §1.4).
    EXPECT_LT(e.knuckleFinger, 1.3f);
    EXPECT_NEAR(e.knuckleThumb, buildHandModel().dimensions.thumbCmcMm.x, 0.01f);
    // Near-straight fingers amplify a knuckle error in the triangle (h = √(a² − u²)).
    EXPECT_LT(e.proximalFinger, 6.0f);
    EXPECT_LT(e.proximalThumb, 15.0f);
}

TEST(SensorHandTest, BoxesShareFacesAlongEachDigit) {
    const HandModel model = buildHandModel();
    const SensorCalibration cal = calibrationForModel(model, Side::Right);
    HandControls c;
    for (auto& f : c.fingers) f = {0.0f, 0.6f, 0.4f};
    const SensorHandFrame frame = sensorHand(cal, synthesizeSensorReadings(model, forwardKinematics(model, c, Side::Right), cal));
    for (int d = 0; d < kDigitCount; ++d) {
        const int first = firstBodyOf(Digit(d));
        const BoxVertices& distal = frame.segments[first + 2];
        const BoxVertices& middle = frame.segments[first + 1];
        const BoxVertices& proximal = frame.segments[first];
        // Distal box: length l, width w, thickness t_f (eq. 7.9).
        EXPECT_NEAR(glm::distance(distal[0], distal[3]), cal.digits[d].lengthMm[2], 1e-3f);
        EXPECT_NEAR(glm::distance(distal[0], distal[1]), cal.digits[d].widthMm[2], 1e-3f);
        EXPECT_NEAR(glm::distance(distal[0], distal[4]), cal.digits[d].tipThicknessMm, 1e-3f);
        EXPECT_EQ(middle[0], distal[3]);
        EXPECT_EQ(middle[1], distal[2]);
        EXPECT_EQ(proximal[0], middle[3]);
        EXPECT_EQ(proximal[5], middle[6]);
        // Around C: width of the middle phalanx, 1.5 × fingertip thickness.
        EXPECT_NEAR(glm::distance(middle[2], middle[3]), cal.digits[d].widthMm[1], 1e-3f);
        EXPECT_NEAR(glm::distance(middle[2], middle[6]), 1.5f * cal.digits[d].tipThicknessMm, 1e-3f);
        // The distal joint is the centre of the box's proximal face; the nail point is inside.
        EXPECT_NEAR(signedDistanceToBox(distal, frame.joints[d].distalJoint), 0.0f, 1e-3f);
        EXPECT_LT(signedDistanceToBox(distal, frame.joints[d].underNail), -1.0f);
    }
    const BoxVertices& palm = frame.segments[0];
    EXPECT_NEAR(glm::distance(palm[0], palm[4]), cal.handThicknessMm, 1e-3f);
}

TEST(SensorHandTest, BowlRollIsMirroredForTheLeftHand) {
    const HandModel model = buildHandModel();
    SensorCalibration cal = calibrationForModel(model, Side::Right);
    cal.knuckleBowlRollDeg = {0.0f, 15.0f, 30.0f, 45.0f, 60.0f};
    SensorReadings readings{};
    for (auto& r : readings) r.positionMm = {0, 0, 0};
    const SensorHandFrame right = sensorHand(cal, readings);
    cal.side = Side::Left;
    const SensorHandFrame left = sensorHand(cal, readings);
    for (int d = 0; d < kDigitCount; ++d) {
        const glm::vec2 k = cal.digits[d].knuckleOffsetMm;
        const float g = cal.knuckleBowlRollDeg[d] * kDeg, h = -0.5f * cal.handThicknessMm;
        // R_x(±γ)·(Δx, Δy, −t_h/2) with the hand sensor at the origin, unrotated.
        const glm::vec3 expectedRight(k.x, k.y * std::cos(g) - h * std::sin(g), k.y * std::sin(g) + h * std::cos(g));
        const glm::vec3 expectedLeft(k.x, k.y * std::cos(g) + h * std::sin(g), -k.y * std::sin(g) + h * std::cos(g));
        EXPECT_NEAR(glm::distance(right.joints[d].knuckle, expectedRight), 0.0f, 1e-3f);
        EXPECT_NEAR(glm::distance(left.joints[d].knuckle, expectedLeft), 0.0f, 1e-3f);
    }
}

}  // namespace
}  // namespace signstim::hand
