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

hand::ArmTarget blendTargets(const hand::ArmTarget& a, const hand::ArmTarget& b, float t) {
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

render::Pose ClipPoser::next(double seconds, SignerPosture* posture, PoseReport* report) {
    if (previous_ && clip_->solveAfresh(previousSeconds_, seconds)) previous_.reset();
    const SignerPosture wanted = clip_->postureAt(seconds);
    PoseReport solved;
    render::Pose pose = rig_->pose(wanted, &solved, previous_ ? &*previous_ : nullptr);
    previous_ = solved;
    previousSeconds_ = seconds;
    if (posture) *posture = wanted;
    if (report) *report = solved;
    return pose;
}

}  // namespace signstim::signer
