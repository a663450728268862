#include "signer/elbow_track.hpp"

#include "signer/clip.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace signstim::signer {
namespace {

// Turns `from` toward `to` by at most `maxRad` (unit vectors).
glm::vec3 turnToward(const glm::vec3& from, const glm::vec3& to, float maxRad) {
    const float angle = std::acos(std::clamp(glm::dot(from, to), -1.0f, 1.0f));
    if (angle <= maxRad) return to;
    glm::vec3 axis = glm::cross(from, to);
    if (glm::length(axis) < 1e-6f)  // opposite: turn about any axis across `from`
        axis = glm::cross(from, std::fabs(from.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0));
    return glm::normalize(glm::angleAxis(maxRad, glm::normalize(axis)) * from);
}

}  // namespace

ElbowTrack::ElbowTrack(const SignerRig& rig, double durationSeconds, const std::function<SignerPosture(double)>& posture) {
    const auto samples = static_cast<std::size_t>(std::ceil(std::max(0.0, durationSeconds) * kElbowTrackHz)) + 1;
    const auto step = static_cast<float>(kElbowTurnDegPerSecond / kElbowTrackHz * 3.14159265358979323846 / 180.0);
    right_.reserve(samples);
    left_.reserve(samples);
    for (std::size_t k = 0; k < samples; ++k) {
        const SignerPosture p = posture(std::min(durationSeconds, static_cast<double>(k) / kElbowTrackHz));
        const glm::vec3 r = rig.solveArm(hand::Side::Right, p).elbowDirection;
        const glm::vec3 l = rig.solveArm(hand::Side::Left, p).elbowDirection;
        right_.push_back(k == 0 ? r : turnToward(right_.back(), r, step));
        left_.push_back(k == 0 ? l : turnToward(left_.back(), l, step));
    }
}

void ElbowTrack::apply(double seconds, SignerPosture& posture) const {
    if (right_.empty()) return;
    double at = std::clamp(seconds * kElbowTrackHz, 0.0, static_cast<double>(right_.size() - 1));
    // An instant every rate shares (a 60 fps frame) is a sample, whatever the rounding of t.
    if (std::fabs(at - std::round(at)) < 1e-6) at = std::round(at);
    const auto k = std::min(static_cast<std::size_t>(at), right_.size() - 1);
    const std::size_t next = std::min(k + 1, right_.size() - 1);
    const auto u = static_cast<float>(at - static_cast<double>(k));
    posture.rightElbowHint = u > 0.0f ? blendElbowHints(right_[k], right_[next], u) : right_[k];
    posture.leftElbowHint = u > 0.0f ? blendElbowHints(left_[k], left_[next], u) : left_[k];
    posture.followElbowHint = true;
}

}  // namespace signstim::signer
