#pragma once
// A clip: anything that gives the signer's posture over time (a verb clip, signer/verb_clip.hpp;
// a story timeline, signer/timeline_clip.hpp), what poses it frame by frame, and the pieces
// clips are made of (arm targets from the signing space, the relaxed hand, blends).
#include "signer/signer_pose.hpp"
#include "stimuli/verbs/verbs.hpp"

namespace signstim::signer {

// Anything that gives the signer's posture over time: a verb clip, a story timeline.
class Clip {
public:
    virtual ~Clip() = default;
    virtual double durationSeconds() const = 0;
    // The signer's posture `seconds` after the clip starts (clamped to the clip).
    virtual SignerPosture postureAt(double seconds) const = 0;
};

// Poses a clip at any instant: the pose is a function of the clip and the time alone (issue 21:
// no state carried from frame to frame, so every frame rate draws the same signer at the same
// instant, and a story's frames outside its verbs are the same in every version). The arms'
// elbows follow a rule of the target (hand/arm_ik.hpp, the natural swivel), not the last frame.
// Anything that must see the frames the renderer draws (the clearance check,
// signer/clearance.hpp) poses them with one too.
class ClipPoser {
public:
    ClipPoser(const SignerRig& rig, const Clip& clip) : rig_(&rig), clip_(&clip) {}
    // The pose at `seconds`; `posture` and `report`, when given, receive what was posed and the
    // arm solution.
    render::Pose next(double seconds, SignerPosture* posture = nullptr, PoseReport* report = nullptr) const;

private:
    const SignerRig* rig_;
    const Clip* clip_;
};

// Hand pose of the signing-space frame (SPEC §3.1) -> arm target in the body frame.
hand::ArmTarget armTargetFromSigningSpace(const stimuli::HandPose& pose);
// Its inverse: a wrist and hand frame of the body frame (where the arm solution put the hand,
// hand::ArmPose::wristMm and hand) as a hand pose of the signing-space frame, so that what a
// sign asks can be judged on the hand as posed (`signstim sign`, issue 22).
stimuli::HandPose signingSpaceFromArm(const glm::vec3& wristMm, const glm::quat& handRotation);

// [D] A hand that takes no part in what is signed hangs relaxed: fingers gently curled, more
// so toward the little finger, thumb resting beside the index (not the flat bind pose).
hand::HandControls relaxedHand();

// Elbow hints (SignerPosture::rightElbowHint) blended, t in [0, 1]: the normalised linear blend.
glm::vec3 blendElbowHints(const glm::vec3& a, const glm::vec3& b, float t);

// Arm targets blended: position linearly, rotation by the shortest slerp; t in [0, 1].
hand::ArmTarget blendTargets(const hand::ArmTarget& a, const hand::ArmTarget& b, float t);

}  // namespace signstim::signer
