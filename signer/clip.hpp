#pragma once
// A clip: anything that gives the signer's posture over time (a verb clip, signer/verb_clip.hpp;
// a story timeline, signer/timeline_clip.hpp), what poses it frame by frame, and the pieces
// clips are made of (arm targets from the signing space, the relaxed hand, blends).
#include "signer/signer_pose.hpp"
#include "stimuli/verbs/verbs.hpp"

#include <optional>

namespace signstim::signer {

// Anything that gives the signer's posture over time: a verb clip, a story timeline.
class Clip {
public:
    virtual ~Clip() = default;
    virtual double durationSeconds() const = 0;
    // The signer's posture `seconds` after the clip starts (clamped to the clip).
    virtual SignerPosture postureAt(double seconds) const = 0;
    // True when the arms must be solved afresh at `seconds`, without the previous frame's
    // elbow (which keeps neighbouring frames continuous): a story's frames after a verb slot
    // then depend only on their own posture, so they are the same image in every version.
    virtual bool solveAfresh(double previousSeconds, double seconds) const {
        (void)previousSeconds;
        (void)seconds;
        return false;
    }
};

// Poses a clip frame after frame as renderClips draws it: each frame's arms continue from the
// previous frame's elbows (no flips between neighbours), except where the clip asks for a
// fresh solve (Clip::solveAfresh). Anything that must see the frames the renderer draws (the
// clearance check, signer/clearance.hpp) poses them with one too.
class ClipPoser {
public:
    ClipPoser(const SignerRig& rig, const Clip& clip) : rig_(&rig), clip_(&clip) {}
    // The pose at `seconds`; times increase from call to call. `posture` and `report`, when
    // given, receive what was posed and the arm solution.
    render::Pose next(double seconds, SignerPosture* posture = nullptr, PoseReport* report = nullptr);

private:
    const SignerRig* rig_;
    const Clip* clip_;
    std::optional<PoseReport> previous_;
    double previousSeconds_ = 0.0;
};

// Hand pose of the signing-space frame (SPEC §3.1) -> arm target in the body frame.
hand::ArmTarget armTargetFromSigningSpace(const stimuli::HandPose& pose);

// [D] A hand that takes no part in what is signed hangs relaxed: fingers gently curled, more
// so toward the little finger, thumb resting beside the index (not the flat bind pose).
hand::HandControls relaxedHand();

// Arm targets blended: position linearly, rotation by the shortest slerp; t in [0, 1].
hand::ArmTarget blendTargets(const hand::ArmTarget& a, const hand::ArmTarget& b, float t);

}  // namespace signstim::signer
