#include "hand/gaze.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace signstim::hand {
namespace {
constexpr float kDeg = 3.14159265358979323846f / 180.0f;

// Looking along +z, turned by yaw (toward +x) then pitch (up).
glm::quat look(float yawDeg, float pitchDeg) {
    return glm::angleAxis(yawDeg * kDeg, glm::vec3(0, 1, 0)) *
           glm::angleAxis(-pitchDeg * kDeg, glm::vec3(1, 0, 0));
}

void yawPitch(const glm::vec3& d, float& yawDeg, float& pitchDeg) {
    yawDeg = std::atan2(d.x, d.z) / kDeg;
    pitchDeg = std::atan2(d.y, std::sqrt(d.x * d.x + d.z * d.z)) / kDeg;
}
}  // namespace

GazePose solveGaze(const GazeModel& model, const glm::vec3& targetMm) {
    const glm::vec3 d = targetMm - model.eyesMm;
    if (glm::length(d) < 1e-3f) return GazePose{};  // looking at its own eyes: keep straight ahead
    float yaw = 0.0f, pitch = 0.0f;
    yawPitch(glm::normalize(d), yaw, pitch);
    // Head takes its share; if the eyes cannot make up the rest, the head turns further.
    const auto split = [](float total, float share, const AngleRange& head, const AngleRange& eye) {
        float h = head.clamp(total * share);
        const float e = eye.clamp(total - h);
        h = head.clamp(total - e);
        return h;
    };
    return solveGazeWithHead(model, targetMm, split(yaw, model.headShare, model.headYaw, model.eyeYaw),
                             split(pitch, model.headShare, model.headPitch, model.eyePitch));
}

GazePose solveGazeWithHead(const GazeModel& model, const glm::vec3& targetMm, float headYawDeg, float headPitchDeg) {
    GazePose pose;
    const glm::vec3 d = targetMm - model.eyesMm;
    if (glm::length(d) < 1e-3f) return pose;
    const glm::vec3 dir = glm::normalize(d);
    pose.headYawDeg = model.headYaw.clamp(headYawDeg);
    pose.headPitchDeg = model.headPitch.clamp(headPitchDeg);
    pose.head = look(pose.headYawDeg, pose.headPitchDeg);
    pose.neck = look(model.neckShare * pose.headYawDeg, model.neckShare * pose.headPitchDeg);

    // Eyes: the remaining direction in the head's frame, clamped.
    const glm::vec3 inHead = glm::inverse(pose.head) * dir;
    float eyeYaw = 0.0f, eyePitch = 0.0f;
    yawPitch(inHead, eyeYaw, eyePitch);
    pose.eyeYawDeg = model.eyeYaw.clamp(eyeYaw);
    pose.eyePitchDeg = model.eyePitch.clamp(eyePitch);
    pose.eyes = look(pose.eyeYawDeg, pose.eyePitchDeg);

    const glm::vec3 achieved = pose.head * (pose.eyes * glm::vec3(0, 0, 1));
    pose.errorDeg = std::acos(std::clamp(glm::dot(achieved, dir), -1.0f, 1.0f)) / kDeg;
    pose.reachable = pose.errorDeg < 0.5f;
    return pose;
}

}  // namespace signstim::hand
