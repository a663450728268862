#pragma once
// A verb performance (stimuli/verbs/verb_synthesis.hpp) as a clip of the signer.
//
// A clip is: a lead-in in which the hands rise from rest to the verb's first keyframe, the
// verb itself, a hold on its last keyframe, and nothing else — so that the four versions of
// a verb (point, vector, animator, uninflected) differ only in the verb.
//
// The elbows follow an elbow track as a story's do (signer/elbow_track.hpp; issue 21: the
// swivel changes smoothly): the arm solver's elbow near the keyframes' elbows, blended across
// its jumps. The track is a function of the clip alone, so the pose stays a function of t.
#include "signer/clip.hpp"
#include "signer/elbow_track.hpp"
#include "stimuli/story/handshapes.hpp"
#include "stimuli/verbs/verb_synthesis.hpp"

#include <vector>

namespace signstim::signer {

struct ClipTiming {
    double leadInSeconds = 0.5;  // rest -> first keyframe
    double holdSeconds = 0.5;    // on the last keyframe
};

class VerbClip final : public Clip {
public:
    // Throws InputError when a keyframe names a handshape the library lacks.
    VerbClip(const SignerRig& rig, const stimuli::HandshapeLibrary& shapes,
             stimuli::VerbPerformance performance, ClipTiming timing = {});

    double durationSeconds() const override;
    // Halfway through the verb itself (after the lead-in): where a still of the clip is taken.
    double middleOfVerbSeconds() const { return timing_.leadInSeconds + 0.5 * performance_.durationSeconds; }
    const stimuli::VerbPerformance& performance() const { return performance_; }

    SignerPosture postureAt(double seconds) const override;

private:
    const SignerRig* rig_;
    const stimuli::HandshapeLibrary* shapes_;
    stimuli::VerbPerformance performance_;
    ClipTiming timing_;
    // Per hand track: the solver's elbow at rest and at each keyframe (SignerPosture's hints).
    std::vector<glm::vec3> restElbows_;
    std::vector<std::vector<glm::vec3>> keyElbows_;
    ElbowTrack elbows_;  // empty while it is made (the postures it samples are the solver's own)
};

}  // namespace signstim::signer
