#pragma once
// From verb performances (stimuli/verb_synthesis.hpp) to frames of the signer.
//
// A clip is: a lead-in in which the hands rise from rest to the verb's first keyframe, the
// verb itself, a hold on its last keyframe, and nothing else — so that the four versions of
// a verb (point, vector, animator, uninflected) differ only in the verb. Several clips can be
// shown side by side in one frame (SPEC §4.3): every view samples the same clip time, so the
// panels stay in sync; a shorter clip holds its last posture.
#include "app/signer_pose.hpp"
#include "renderer/frame.hpp"
#include "renderer/frame_sink.hpp"
#include "renderer/renderer.hpp"
#include "stimuli/handshapes.hpp"
#include "stimuli/verb_synthesis.hpp"

#include <functional>
#include <string>
#include <vector>

namespace signstim::app {

struct ClipTiming {
    double leadInSeconds = 0.5;  // rest -> first keyframe
    double holdSeconds = 0.5;    // on the last keyframe
};

class VerbClip {
public:
    // Throws InputError when a keyframe names a handshape the library lacks.
    VerbClip(const SignerRig& rig, const stimuli::HandshapeLibrary& shapes,
             stimuli::VerbPerformance performance, ClipTiming timing = {});

    double durationSeconds() const;
    const stimuli::VerbPerformance& performance() const { return performance_; }

    // The signer's posture `seconds` after the clip starts (clamped to the clip).
    SignerPosture postureAt(double seconds) const;

private:
    struct Track {
        const stimuli::HandTrack* track = nullptr;
        hand::Side side = hand::Side::Right;
    };
    const SignerRig* rig_;
    const stimuli::HandshapeLibrary* shapes_;
    stimuli::VerbPerformance performance_;
    ClipTiming timing_;
};

// Hand pose of the signing-space frame (SPEC §3.1) -> arm target in the body frame.
hand::ArmTarget armTargetFromSigningSpace(const stimuli::HandPose& pose);

struct ClipRenderOptions {
    double framesPerSecond = 30.0;
    std::uint32_t columns = 1, rows = 1;  // grid of the views
};

// Renders `clips` side by side (one view each, labelled by `labels` when given) into `sink`,
// one frame per 1/fps from 0 to the longest clip's end inclusive. The camera is the
// waist-up view of the rest pose, fixed for the whole clip. `progress(done, total)` is called
// after each frame. Returns the number of frames.
std::uint64_t renderClips(render::Renderer& renderer, int sceneHandle, const render::Scene& avatar,
                          const SignerRig& rig, const std::vector<const VerbClip*>& clips,
                          const std::vector<std::string>& labels, const ClipRenderOptions& options,
                          render::FrameSink& sink,
                          const std::function<void(std::uint64_t, std::uint64_t)>& progress = {});

}  // namespace signstim::app
