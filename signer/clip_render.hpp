#pragma once
// Clips (signer/clip.hpp) to frames of the signer. Several clips can be shown side by side in
// one frame (SPEC §4.3): every view samples the same clip time, so the panels stay in sync; a
// shorter clip holds its last posture.
#include "signer/avatar_render.hpp"
#include "signer/clip.hpp"
#include "renderer/frame_sink.hpp"
#include "renderer/renderer.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace signstim::signer {

struct ClipRenderOptions {
    double framesPerSecond = 30.0;
    std::uint32_t columns = 1, rows = 1;  // grid of the views
    CameraFraming framing = CameraFraming::WaistUp;  // the camera preset (avatar_render.hpp)
};

// Renders `clips` (verb clips, story timelines) side by side (one view each, labelled by `labels` when given) into `sink`,
// one frame per 1/fps from 0 to the longest clip's end inclusive. The camera is the
// options' preset (waist-up or the face) on the rest pose, fixed for the whole clip. `progress(done, total)` is called
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
                                           const std::function<void(std::uint64_t, std::uint64_t)>& progress = {},
                                           CameraFraming framing = CameraFraming::WaistUp);

}  // namespace signstim::signer
