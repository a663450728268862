#include "hand/sensor_hand.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

namespace signstim::hand {
namespace {

constexpr float kDegToRad = 0.017453292519943295f;
constexpr float kRadToDeg = 1.0f / kDegToRad;

glm::vec3 onSensor(const glm::mat3& rotation, const glm::vec3& position, const glm::vec3& local) {
    return rotation * local + position;  // SPEC §2.1: q = R·q_local + s
}

// The sensor axes on a McDonald body: x distal (body +z), z dorsal (body −x), y = z × x.
glm::mat3 sensorFrameOnBody(const glm::quat& body) {
    const glm::vec3 distal = body * glm::vec3(0, 0, 1);
    const glm::vec3 dorsal = -(body * glm::vec3(1, 0, 0));
    return glm::mat3(distal, glm::cross(dorsal, distal), dorsal);
}

// Hand sensor on the back of the hand in line with the middle knuckle [D]: 60 % of the way
// from the base of the palm to the middle MCP.
constexpr float kHandSensorHeightFraction = 0.6f;

}  // namespace

glm::mat3 sensorRotation(float azimuthDeg, float elevationDeg, float correctedRollDeg) {
    const float ca = std::cos(azimuthDeg * kDegToRad), sa = std::sin(azimuthDeg * kDegToRad);
    const float ce = std::cos(elevationDeg * kDegToRad), se = std::sin(elevationDeg * kDegToRad);
    const float cr = std::cos(correctedRollDeg * kDegToRad), sr = std::sin(correctedRollDeg * kDegToRad);
    // SPEC §2.1 / paper eq. 7.2, written row by row; glm::mat3 is column-major, so transpose.
    const glm::mat3 rows(ca * ce, -cr * sa + ca * se * sr, ca * cr * se + sa * sr,
                         ce * sa, ca * cr + sa * se * sr, cr * sa * se - ca * sr,
                         -se, ce * sr, ce * cr);
    return glm::transpose(rows);
}

void sensorAngles(const glm::mat3& r, float& azimuthDeg, float& elevationDeg, float& rollDeg) {
    // r[col][row]: R(2,0) = −sin e, R(1,0) = cos e sin a, R(0,0) = cos a cos e,
    // R(2,1) = cos e sin r, R(2,2) = cos e cos r.
    elevationDeg = -std::asin(std::clamp(r[0][2], -1.0f, 1.0f)) * kRadToDeg;
    azimuthDeg = std::atan2(r[0][1], r[0][0]) * kRadToDeg;
    rollDeg = std::atan2(r[1][2], r[2][2]) * kRadToDeg;
}

ProximalJoint solveProximalJoint(const glm::vec3& A, const glm::vec3& B, const glm::vec3& D, float a,
                                 float b, const glm::mat3& nailRotation) {
    const glm::vec3 cVec = A - B;  // from B to A
    const float c = glm::length(cVec);
    if (c < 1e-4f) {
        // [D] knuckle on the distal joint: put C one middle-phalanx length back along the nail.
        return {B - a * nailRotation[0], ProximalJointCase::Degenerate};
    }
    if (c > a + b) return {B + (a / (a + b)) * cVec, ProximalJointCase::Straight};       // eq. 7.7
    if (c < std::abs(b - a)) return {B - (a / c) * cVec, ProximalJointCase::FullyBent};  // eq. 7.8
    const glm::vec3 cHat = cVec / c;
    const glm::vec3 d = D - B;
    glm::vec3 perpendicular = d - glm::dot(d, cHat) * cHat;
    const glm::vec3 dorsal = nailRotation[2];
    if (glm::length(perpendicular) < 1e-4f * std::max(1.0f, glm::length(d))) {
        // [D] d⃗ ∥ c⃗: the finger's plane is the one normal to the nail sensor's y-axis; pick the
        // dorsal side (a flexed proximal joint bulges dorsally).
        perpendicular = glm::cross(nailRotation[1], cHat);
        if (glm::dot(perpendicular, dorsal) < 0.0f) perpendicular = -perpendicular;
        const glm::vec3 p = glm::normalize(perpendicular);
        const float u = (a * a - b * b + c * c) / (2.0f * c);
        const float h = std::sqrt(std::max(0.0f, a * a - u * u));
        return {B + u * cHat + h * p, ProximalJointCase::Triangle};
    }
    const glm::vec3 p = glm::normalize(perpendicular);
    const float u = (a * a - b * b + c * c) / (2.0f * c);
    const float h = std::sqrt(std::max(0.0f, a * a - u * u));
    const glm::vec3 first = B + u * cHat + h * p, second = B + u * cHat - h * p;
    // SPEC §2.4 [P]: keep the solution with the larger angle φ between d⃗ and C − B (the distal
    // phalanx cannot fold sharply): the smaller cosine.
    const float dLength = std::max(glm::length(d), 1e-6f);
    const float cosFirst = glm::dot(d, first - B) / (dLength * a);
    const float cosSecond = glm::dot(d, second - B) / (dLength * a);
    return {cosFirst <= cosSecond ? first : second, ProximalJointCase::Triangle};
}

SensorHandFrame sensorHand(const SensorCalibration& cal, const SensorReadings& readings) {
    const float mirror = cal.side == Side::Right ? 1.0f : -1.0f;  // SPEC §2.3: bowl sign [D]
    const SensorReading& hand = readings[static_cast<int>(SensorId::Hand)];
    const float handRoll = hand.rollDeg - cal.handInitialRollDeg;
    auto handRotation = [&](float bowlDeg) {
        return sensorRotation(hand.azimuthDeg, hand.elevationDeg, handRoll + mirror * bowlDeg);
    };
    const float th = cal.handThicknessMm;
    SensorHandFrame out;
    for (int digit = 0; digit < kDigitCount; ++digit) {
        const DigitCalibration& dc = cal.digits[digit];
        for (int k = 0; k < 3; ++k) {
            if (!(dc.lengthMm[k] > 0.0f) || !(dc.widthMm[k] > 0.0f)) {
                throw std::invalid_argument("sensorHand: phalanx lengths and widths must be > 0");
            }
        }
        const SensorReading& nail = readings[digit + 1];
        const glm::mat3 Rf = sensorRotation(nail.azimuthDeg, nail.elevationDeg, nail.rollDeg - dc.initialRollDeg);
        const glm::mat3 Rk = handRotation(cal.knuckleBowlRollDeg[digit]);
        const float tf = dc.tipThicknessMm;
        const float lDist = dc.lengthMm[2], lMid = dc.lengthMm[1], lProx = dc.lengthMm[0];
        const float back = -lDist + cal.sensorFromTipMm;  // distal joint, along the sensor x
        DigitJoints& j = out.joints[digit];
        // SPEC §2.3 [P]: eqs. 7.3a–c.
        j.knuckle = onSensor(Rk, hand.positionMm, {dc.knuckleOffsetMm.x, dc.knuckleOffsetMm.y, -0.5f * th});
        j.distalJoint = onSensor(Rf, nail.positionMm, {back, 0.0f, -0.5f * tf});
        j.underNail = onSensor(Rf, nail.positionMm, {0.0f, 0.0f, -0.5f * tf});
        const ProximalJoint C = solveProximalJoint(j.knuckle, j.distalJoint, j.underNail, lMid, lProx, Rf);
        j.proximalJoint = C.point;
        j.proximalCase = C.how;

        // SPEC §2.5 [P]: distal box around the nail sensor (eq. 7.9).
        const int first = firstBodyOf(static_cast<Digit>(digit));
        BoxVertices& distal = out.segments[first + 2];
        const float wd = 0.5f * dc.widthMm[2];
        const float front = cal.sensorFromTipMm;
        const std::array<glm::vec3, 4> face = {glm::vec3(front, -wd, 0), glm::vec3(front, wd, 0),
                                               glm::vec3(back, wd, 0), glm::vec3(back, -wd, 0)};
        for (int v = 0; v < 4; ++v) {
            distal[v] = onSensor(Rf, nail.positionMm, face[v]);
            distal[v + 4] = onSensor(Rf, nail.positionMm, face[v] + glm::vec3(0, 0, -tf));
        }
        // Middle box: 1,2,5,6 = distal 4,3,8,7; 3,4,7,8 around C (eq. 7.10; 1.5·t_f thick).
        BoxVertices& middle = out.segments[first + 1];
        middle[0] = distal[3];
        middle[1] = distal[2];
        middle[4] = distal[7];
        middle[5] = distal[6];
        const glm::vec3 toDistal = j.distalJoint - j.proximalJoint;
        glm::vec3 normal = glm::cross(distal[3] - j.proximalJoint, distal[2] - j.proximalJoint);
        if (glm::dot(normal, Rf[2]) < 0.0f) normal = -normal;  // dorsal: n̂·R_f ẑ > 0
        if (glm::length(normal) < 1e-6f) normal = Rf[2];
        const glm::vec3 n = glm::normalize(normal);
        glm::vec3 lateral = glm::cross(n, toDistal);
        lateral = glm::length(lateral) < 1e-6f ? Rf[1] : glm::normalize(lateral);  // radial
        const float wm = 0.5f * dc.widthMm[1];
        const float tm = 0.75f * tf;
        middle[2] = j.proximalJoint + wm * lateral + tm * n;
        middle[3] = j.proximalJoint - wm * lateral + tm * n;
        middle[6] = j.proximalJoint + wm * lateral - tm * n;
        middle[7] = j.proximalJoint - wm * lateral - tm * n;
        // Proximal box: 1,2,5,6 = middle 4,3,8,7; 3,4,7,8 at the knuckle (eq. 7.11).
        BoxVertices& proximal = out.segments[first];
        proximal[0] = middle[3];
        proximal[1] = middle[2];
        proximal[4] = middle[7];
        proximal[5] = middle[6];
        const float wp = 0.5f * dc.widthMm[0];
        const glm::vec2 k = dc.knuckleOffsetMm;
        proximal[2] = onSensor(Rk, hand.positionMm, {k.x, k.y + wp, 0.0f});
        proximal[3] = onSensor(Rk, hand.positionMm, {k.x, k.y - wp, 0.0f});
        proximal[6] = onSensor(Rk, hand.positionMm, {k.x, k.y + wp, -th});
        proximal[7] = onSensor(Rk, hand.positionMm, {k.x, k.y - wp, -th});
    }
    // Palm block (eq. 7.12): little, index and thumb knuckles and (Δx₁, Δy₅), with the 40° roll.
    const glm::mat3 Rp = handRotation(cal.palmBowlRollDeg);
    const glm::vec2 k1 = cal.digits[0].knuckleOffsetMm, k2 = cal.digits[1].knuckleOffsetMm,
                    k5 = cal.digits[4].knuckleOffsetMm;
    const std::array<glm::vec2, 4> corners = {k5, k2, k1, glm::vec2(k1.x, k5.y)};
    BoxVertices& palm = out.segments[0];
    for (int v = 0; v < 4; ++v) {
        palm[v] = onSensor(Rp, hand.positionMm, {corners[v].x, corners[v].y, 0.0f});
        palm[v + 4] = onSensor(Rp, hand.positionMm, {corners[v].x, corners[v].y, -th});
    }
    return out;
}

// ---- round trip -----------------------------------------------------------------------------
namespace {
glm::vec3 handSensorPosition(const HandModel& model, float thickness) {
    return {-0.5f * thickness, 0.0f, kHandSensorHeightFraction * model.dimensions.middleMcpHeightMm};
}
}  // namespace

SensorCalibration calibrationForModel(const HandModel& model, Side side, KnuckleFit fit) {
    SensorCalibration cal;
    cal.side = side;
    cal.knuckleBowlRollDeg = {0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
    cal.palmBowlRollDeg = 0.0f;
    const HandDimensions& d = model.dimensions;
    const glm::vec3 sensor = handSensorPosition(model, cal.handThicknessMm);
    for (int digit = 0; digit < kDigitCount; ++digit) {
        DigitCalibration& dc = cal.digits[digit];
        dc.lengthMm = d.boneLengthMm[digit];
        for (int k = 0; k < 3; ++k) {
            dc.widthMm[k] = 2.0f * boneRadiusMm(model, static_cast<Body>(firstBodyOf(static_cast<Digit>(digit)) + k));
        }
        dc.tipThicknessMm = 0.75f * dc.widthMm[2];  // [D] fingertip ~3/4 as thick as wide
        glm::vec3 knuckle = digit == 0 ? d.thumbCmcMm : model.mcpPositionMm[digit - 1];
        if (side == Side::Left) knuckle = mirrorToLeft(knuckle);
        // Hand sensor axes in the palm frame: x = +z (distal), y = +y, z = −x (dorsal).
        dc.knuckleOffsetMm = {knuckle.z - sensor.z, knuckle.y - sensor.y};
        if (fit == KnuckleFit::ExactKnuckles) {
            // Solve R_x(γ)·(Δy, −t_h/2) = (target y, target z) in the sensor's y–z plane.
            const float half = 0.5f * cal.handThicknessMm;
            const float ty = knuckle.y - sensor.y;
            const float tz = sensor.x - knuckle.x;  // sensor z = −palm x
            const float dy = std::copysign(std::sqrt(std::max(0.0f, ty * ty + tz * tz - half * half)), ty);
            const float gamma = std::atan2(tz, ty) - std::atan2(-half, dy);
            dc.knuckleOffsetMm.y = dy;
            const float mirror = side == Side::Right ? 1.0f : -1.0f;
            cal.knuckleBowlRollDeg[digit] = mirror * std::remainder(gamma * kRadToDeg, 360.0f);
        }
    }
    return cal;
}

SensorReadings synthesizeSensorReadings(const HandModel& model, const HandPose& pose,
                                        const SensorCalibration& cal) {
    SensorReadings readings{};
    const RigidTransform& palm = pose.bodies[0];
    auto reading = [](const glm::mat3& frame, const glm::vec3& position, float initialRoll) {
        SensorReading r;
        r.positionMm = position;
        sensorAngles(frame, r.azimuthDeg, r.elevationDeg, r.rollDeg);
        r.rollDeg += initialRoll;
        return r;
    };
    readings[0] = reading(sensorFrameOnBody(palm.rotation),
                          transformPoint(palm, handSensorPosition(model, cal.handThicknessMm)),
                          cal.handInitialRollDeg);
    for (int digit = 0; digit < kDigitCount; ++digit) {
        const DigitCalibration& dc = cal.digits[digit];
        const RigidTransform& distal = pose.bodies[firstBodyOf(static_cast<Digit>(digit)) + 2];
        const glm::mat3 frame = sensorFrameOnBody(distal.rotation);
        // Inverse of eq. 7.3b: the sensor sits on the nail, (l − 5) past the distal joint.
        const glm::vec3 position = distal.position +
                                   frame * glm::vec3(dc.lengthMm[2] - cal.sensorFromTipMm, 0.0f, 0.5f * dc.tipThicknessMm);
        readings[digit + 1] = reading(frame, position, dc.initialRollDeg);
    }
    return readings;
}

}  // namespace signstim::hand
