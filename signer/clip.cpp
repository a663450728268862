#include "signer/clip.hpp"

#include <glm/gtc/quaternion.hpp>

namespace signstim::signer {

hand::HandControls relaxedHand() {
    hand::HandControls controls;
    const float bend[] = {0.12f, 0.16f, 0.2f, 0.24f}, hook[] = {0.2f, 0.25f, 0.3f, 0.35f};
    for (int i = 0; i < 4; ++i) {
        controls.fingers[i].bend = bend[i];
        controls.fingers[i].hook = hook[i];
    }
    controls.thumb.bendDeg = 15.0f;
    controls.thumb.spreadDeg = 25.0f;
    controls.thumb.mcpDeg = 10.0f;
    controls.thumb.ipDeg = 10.0f;
    return controls;
}

glm::vec3 blendElbowHints(const glm::vec3& a, const glm::vec3& b, float t) {
    const glm::vec3 v = a + t * (b - a);
    return glm::length(v) > 1e-4f ? glm::normalize(v) : (t < 0.5f ? a : b);
}

hand::ArmTarget blendTargets(const hand::ArmTarget& a, const hand::ArmTarget& b, float t) {
    // Exactly the ends at 0 and 1 (slerp's rounding would make a posture at rest differ in
    // its last bits with the other end, and so the versions of a verb at their common rest).
    if (t <= 0.0f) return a;
    if (t >= 1.0f) return b;
    hand::ArmTarget out;
    out.wristMm = a.wristMm + t * (b.wristMm - a.wristMm);
    out.handRotation = glm::slerp(a.handRotation, glm::dot(a.handRotation, b.handRotation) < 0.0f
                                                      ? -b.handRotation
                                                      : b.handRotation,
                                  t);
    return out;
}

hand::ArmTarget armTargetFromSigningSpace(const stimuli::HandPose& pose) {
    hand::ArmTarget target;
    target.wristMm = bodyFromSigningSpace(glm::vec3(pose.positionMm));
    target.handRotation = handFrameFromSigningSpace(glm::quat(pose.orientation));
    return target;
}

stimuli::HandPose signingSpaceFromArm(const glm::vec3& wristMm, const glm::quat& handRotation) {
    // handFrameFromSigningSpace is S·R·F with S and F their own inverses: R = S·M·F.
    const glm::mat3 s(glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1));
    const glm::mat3 flipY(glm::vec3(1, 0, 0), glm::vec3(0, -1, 0), glm::vec3(0, 0, 1));
    stimuli::HandPose pose;
    pose.positionMm = glm::dvec3(bodyFromSigningSpace(wristMm));  // the mirror is its own inverse
    pose.orientation = glm::dquat(glm::normalize(glm::quat_cast(s * glm::mat3_cast(handRotation) * flipY)));
    return pose;
}

render::Pose ClipPoser::next(double seconds, SignerPosture* posture, PoseReport* report) const {
    const SignerPosture wanted = clip_->postureAt(seconds);
    render::Pose pose = rig_->pose(wanted, report);
    if (posture) *posture = wanted;
    return pose;
}

}  // namespace signstim::signer
