#pragma once
// A story timeline (stimuli/timeline.hpp) as a clip of the signer: each frame samples the
// timeline's hands and gaze and resolves them on the rig — a resting hand goes to the rig's
// resting place, relaxed; a keyed hand to its wrist target and handshape; gaze toward the
// viewer or a referent.
#include "signer/verb_render.hpp"
#include "stimuli/timeline.hpp"

namespace signstim::signer {

class TimelineClip final : public Clip {
public:
    // Throws InputError when a key names a handshape the library lacks.
    TimelineClip(const SignerRig& rig, const stimuli::HandshapeLibrary& shapes, stimuli::Timeline timeline);

    double durationSeconds() const override { return timeline_.durationSeconds; }
    SignerPosture postureAt(double seconds) const override;
    // Right after a verb slot ends: the frames that follow are shared by every version.
    bool solveAfresh(double previousSeconds, double seconds) const override;
    const stimuli::Timeline& timeline() const { return timeline_; }

private:
    const SignerRig* rig_;
    const stimuli::HandshapeLibrary* shapes_;
    stimuli::Timeline timeline_;
};

// Where the eyes go for a referent at a signing-space point: toward it horizontally, a little
// below eye level (a signer glances at the locus, not down at the chest), body frame.
glm::vec3 gazePointForReferent(const glm::dvec3& signingSpaceMm);
// Straight at the viewer (the camera), body frame.
glm::vec3 gazePointForViewer();

}  // namespace signstim::signer
