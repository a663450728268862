// The non-manual channels on the body (issue 23 §2): head nod, shake, tilt and jut, torso lean,
// turn and shift, shoulder raise — their rotations, and the arm model of a raised shoulder.
#include "signer/signer_pose.hpp"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace signstim::signer {
namespace {

constexpr float kDeg = 3.14159265358979323846f / 180.0f;
const glm::vec3 kRight(1.0f, 0.0f, 0.0f), kUp(0.0f, 1.0f, 0.0f), kForward(0.0f, 0.0f, 1.0f);

bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

float raiseOf(hand::Side side, const NonManualPosture& nm) {
    return std::clamp(side == hand::Side::Left ? nm.shoulderRaiseLeft : nm.shoulderRaiseRight, 0.0f, 1.0f);
}

}  // namespace

bool NonManualPosture::neutral() const {
    return face.empty() && headNodRad == 0.0f && headShakeRad == 0.0f && headTiltRad == 0.0f && headJutMm == 0.0f &&
           torsoLeanRad == 0.0f && torsoTurnRad == 0.0f && torsoShiftMm == 0.0f && shoulderRaiseLeft == 0.0f &&
           shoulderRaiseRight == 0.0f;
}

bool setNonManualChannel(NonManualPosture& p, const std::string& channel, double value) {
    const auto v = static_cast<float>(value);
    if (channel == "head.nod") p.headNodRad = v;
    else if (channel == "head.shake") p.headShakeRad = v;
    else if (channel == "head.tilt") p.headTiltRad = v;
    else if (channel == "head.jut") p.headJutMm = v;
    else if (channel == "torso.lean") p.torsoLeanRad = v;
    else if (channel == "torso.turn") p.torsoTurnRad = v;
    else if (channel == "torso.shift") p.torsoShiftMm = v;
    // Both shoulders' channel adds to each side's own.
    else if (channel == "shoulders.raise") { p.shoulderRaiseLeft += v; p.shoulderRaiseRight += v; }
    else if (channel == "shoulder.raiseLeft") p.shoulderRaiseLeft += v;
    else if (channel == "shoulder.raiseRight") p.shoulderRaiseRight += v;
    else if (startsWith(channel, "head.") || startsWith(channel, "torso.") || startsWith(channel, "shoulder")) return false;
    else p.face[channel] = std::clamp(v, 0.0f, 1.0f);
    return true;
}

glm::quat headNonManualRotation(const NonManualPosture& nm) {
    // Body frame (+x the signer's left, +y up, +z forward): + nod turns the face down (about
    // +x), + shake toward the signer's left (about +y), + tilt the crown toward the left
    // shoulder (about -z). Shake, then nod, then tilt, like the head's yaw-pitch-roll.
    return glm::normalize(glm::angleAxis(nm.headShakeRad, kUp) * glm::angleAxis(nm.headNodRad, kRight) *
                          glm::angleAxis(-nm.headTiltRad, kForward));
}

float jutLeanRad(float jutMm, float neckLengthMm) {
    // The neck leans so the head bone moves `jut` forward; at most 40° (beyond it a jut is a bow).
    return std::asin(std::clamp(jutMm / neckLengthMm, -0.64f, 0.64f));
}

std::optional<glm::quat> shoulderRaiseRotation(hand::Side side, const NonManualPosture& nm) {
    const float w = raiseOf(side, nm);
    if (w == 0.0f) return std::nullopt;
    // The left shoulder (+x) rises turning about +z, the right about -z.
    const float sign = side == hand::Side::Left ? 1.0f : -1.0f;
    return glm::angleAxis(sign * w * kShoulderRaiseMaxDeg * kDeg, kForward);
}

std::optional<glm::quat> torsoRotation(const NonManualPosture& nm, float torsoLengthMm) {
    if (nm.torsoLeanRad == 0.0f && nm.torsoTurnRad == 0.0f && nm.torsoShiftMm == 0.0f) return std::nullopt;
    // Shift: a sideways bend of the spine that carries the shoulders `shift` mm toward the
    // signer's left (+x): about -z.
    const float bend = std::asin(std::clamp(nm.torsoShiftMm / torsoLengthMm, -0.5f, 0.5f));
    return glm::normalize(glm::angleAxis(nm.torsoTurnRad, kUp) * glm::angleAxis(nm.torsoLeanRad, kRight) *
                          glm::angleAxis(-bend, kForward));
}

void addLidFollow(float eyeUpDeg, const std::set<std::string>& targets, std::map<std::string, float>& face) {
    // [S] The upper lid follows the eye's vertical rotation nearly one to one (lid-eye
    // coordination: Becker & Fuchs 1988, J Neurophysiol 60:1227). The default signer's blink
    // carries the lid's edge ~56° (27° above the eye's axis to 29° below, avatar_face_mesh.cpp)
    // and eyeWide ~20° up.
    constexpr float kBlinkTravelDeg = 56.0f, kWideTravelDeg = 20.0f;
    const float down = std::clamp(-eyeUpDeg / kBlinkTravelDeg, 0.0f, 1.0f);
    const float up = std::clamp(eyeUpDeg / kWideTravelDeg, 0.0f, 1.0f) * 0.5f;  // the lid lags looking up
    for (const char* side : {"Left", "Right"}) {
        for (const auto& [shape, amount] : {std::pair<std::string, float>{std::string("eyeBlink") + side, down},
                                            std::pair<std::string, float>{std::string("eyeWide") + side, up}}) {
            if (amount <= 0.0f || !targets.count(shape)) continue;
            float& w = face[shape];
            w = std::min(1.0f, w + amount);
        }
    }
}

hand::ArmModel SignerRig::raisedArm(hand::Side side, const NonManualPosture& nm) const {
    hand::ArmModel model = arm(side);
    const auto& shoulderBone = shoulderBoneMm_[side == hand::Side::Right ? 0 : 1];
    const auto raise = shoulderRaiseRotation(side, nm);
    if (!raise || !shoulderBone) return model;  // an avatar without shoulder bones cannot shrug
    model.shoulderMm = *shoulderBone + *raise * (model.shoulderMm - *shoulderBone);
    return model;
}

}  // namespace signstim::signer
