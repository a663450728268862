#pragma once
// From verb performances (stimuli/verbs/verb_synthesis.hpp) to frames of the signer.
//
// A clip is: a lead-in in which the hands rise from rest to the verb's first keyframe, the
// verb itself, a hold on its last keyframe, and nothing else — so that the four versions of
// a verb (point, vector, animator, uninflected) differ only in the verb. Several clips can be
// shown side by side in one frame (SPEC §4.3): every view samples the same clip time, so the
// panels stay in sync; a shorter clip holds its last posture.
#include "signer/signer_pose.hpp"
#include "renderer/frame.hpp"
#include "renderer/frame_sink.hpp"
#include "renderer/renderer.hpp"
#include "stimuli/story/handshapes.hpp"
#include "stimuli/verbs/verb_synthesis.hpp"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace signstim::signer {

// The default signer (or a user's avatar) with its rig and the handshape library, loaded
// once. Not copyable: the rig refers to the avatar scene.
class Signer {
public:
    // scenes/avatar/signer.glb unless `avatarFile` is given; scenes/handshapes.json.
    // Throws InputError naming the file for any problem.
    explicit Signer(const std::filesystem::path& scenesDir, const std::filesystem::path& avatarFile = {},
                    const BoneMapping& mapping = {});
    Signer(const Signer&) = delete;
    Signer& operator=(const Signer&) = delete;

    const render::Scene& avatar() const { return avatar_; }
    const SignerRig& rig() const { return rig_; }
    const stimuli::HandshapeLibrary& shapes() const { return shapes_; }

private:
    render::Scene avatar_;
    SignerRig rig_;
    stimuli::HandshapeLibrary shapes_;
};

// Forwards every frame to `next` and keeps a copy of frame `keep` (0-based): the still of a clip.
class StillCapturingSink : public render::FrameSink {
public:
    StillCapturingSink(render::FrameSink& next, std::uint64_t keep) : next_(next), keep_(keep) {}
    void push(render::Image&& frame) override;
    void finish() override { next_.finish(); }
    std::uint64_t framesPushed() const override { return count_; }
    bool recycle(render::Image& out) override { return next_.recycle(out); }
    const render::Image& still() const { return still_; }

private:
    render::FrameSink& next_;
    std::uint64_t keep_;
    std::uint64_t count_ = 0;
    render::Image still_;
};

struct ClipTiming {
    double leadInSeconds = 0.5;  // rest -> first keyframe
    double holdSeconds = 0.5;    // on the last keyframe
};

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

struct ClipRenderOptions {
    double framesPerSecond = 30.0;
    std::uint32_t columns = 1, rows = 1;  // grid of the views
};

// Renders `clips` (verb clips, story timelines) side by side (one view each, labelled by `labels` when given) into `sink`,
// one frame per 1/fps from 0 to the longest clip's end inclusive. The camera is the
// waist-up view of the rest pose, fixed for the whole clip. `progress(done, total)` is called
// after each frame. Returns the number of frames.
std::uint64_t renderClips(render::Renderer& renderer, int sceneHandle, const render::Scene& avatar,
                          const SignerRig& rig, const std::vector<const Clip*>& clips,
                          const std::vector<std::string>& labels, const ClipRenderOptions& options,
                          render::FrameSink& sink,
                          const std::function<void(std::uint64_t, std::uint64_t)>& progress = {});

// What renderClipsSharingFrames did: frames per clip, images actually rendered, and the
// frames rendered once for all clips.
struct SharedRenderStats {
    std::uint64_t frames = 0;          // per clip
    std::uint64_t renderedImages = 0;  // draws: shared frames once, the others once per clip
    std::uint64_t sharedFrames = 0;    // frames whose posed skeletons were identical in every clip
};

// The versions of one story, each into its own sink (sinks[i] receives clips[i]'s frames, in
// order, one per 1/fps from 0 to the longest clip's end). A frame at which every clip gives
// the same posed skeleton (outside the verb slots, where the versions are identical by
// construction) is drawn once and its image passed to every sink, so a story's four versions
// cost little more than one. The camera and continuity rules are those of renderClips, so
// each sink receives exactly the images renderClips would give for its clip alone.
SharedRenderStats renderClipsSharingFrames(render::Renderer& renderer, int sceneHandle, const render::Scene& avatar,
                                           const SignerRig& rig, const std::vector<const Clip*>& clips,
                                           double framesPerSecond, const std::vector<render::FrameSink*>& sinks,
                                           const std::function<void(std::uint64_t, std::uint64_t)>& progress = {});

}  // namespace signstim::signer
