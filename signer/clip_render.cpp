#include "signer/clip_render.hpp"

#include "signer/avatar_render.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>

namespace signstim::signer {

std::uint64_t renderClips(render::Renderer& renderer, int sceneHandle, const render::Scene& avatar,
                          const SignerRig& rig, const std::vector<const Clip*>& clips,
                          const std::vector<std::string>& labels, const ClipRenderOptions& options,
                          render::FrameSink& sink,
                          const std::function<void(std::uint64_t, std::uint64_t)>& progress) {
    if (clips.empty()) return 0;
    double duration = 0.0;
    for (const Clip* clip : clips) duration = std::max(duration, clip->durationSeconds());
    const std::uint64_t total = static_cast<std::uint64_t>(std::floor(duration * options.framesPerSecond + 1e-9)) + 1;

    // One fixed camera for every view and frame: waist-up on the rest pose.
    const render::RendererOptions& ro = renderer.options();
    const float aspect = (static_cast<float>(ro.width) / static_cast<float>(options.columns)) /
                         (static_cast<float>(ro.height) / static_cast<float>(options.rows));
    const render::Frame restFrame = postureFrame(avatar, rig, sceneHandle, SignerPosture{}, aspect, nullptr, options.framing);
    const render::Camera camera = restFrame.views.front().camera;

    std::vector<ClipPoser> posers;
    for (const Clip* clip : clips) posers.emplace_back(rig, *clip);
    const std::uint32_t inFlight = std::max(1u, renderer.framesInFlight());
    std::uint64_t submitted = 0, retrieved = 0;
    const auto retrieveOne = [&] {
        render::Image image;
        sink.recycle(image);  // a written frame's buffer: no fresh allocation (and page faults) per frame
        renderer.retrieve(image);
        sink.push(std::move(image));
        ++retrieved;
        if (progress) progress(retrieved, total);
    };
    for (std::uint64_t f = 0; f < total; ++f) {
        const double t = static_cast<double>(f) / options.framesPerSecond;
        render::Frame frame;
        frame.columns = options.columns;
        frame.rows = options.rows;
        for (std::size_t i = 0; i < clips.size(); ++i) {
            render::View view;
            view.scene = sceneHandle;
            view.pose = posers[i].next(t);
            view.camera = camera;
            if (i < labels.size()) view.label = labels[i];
            frame.views.push_back(std::move(view));
        }
        if (submitted - retrieved >= inFlight) retrieveOne();
        renderer.submit(frame);
        ++submitted;
    }
    while (retrieved < submitted) retrieveOne();
    return total;
}

namespace {

bool samePose(const render::Pose& a, const render::Pose& b) {
    // The face too: a frame is shared only when the skeleton and the morph weights agree.
    if (a.local.size() != b.local.size() || a.useRestMatrix != b.useRestMatrix || a.morphByName != b.morphByName ||
        a.morphWeights != b.morphWeights)
        return false;
    for (std::size_t i = 0; i < a.local.size(); ++i) {
        const render::Trs& x = a.local[i];
        const render::Trs& y = b.local[i];
        if (x.translation != y.translation || x.rotation != y.rotation || x.scale != y.scale) return false;
    }
    return true;
}

}  // namespace

SharedRenderStats renderClipsSharingFrames(render::Renderer& renderer, int sceneHandle, const render::Scene& avatar,
                                           const SignerRig& rig, const std::vector<const Clip*>& clips,
                                           double framesPerSecond, const std::vector<render::FrameSink*>& sinks,
                                           const std::function<void(std::uint64_t, std::uint64_t)>& progress,
                                           CameraFraming framing) {
    SharedRenderStats stats;
    if (clips.empty()) return stats;
    if (sinks.size() != clips.size()) throw std::invalid_argument("renderClipsSharingFrames: one sink per clip");
    double duration = 0.0;
    for (const Clip* clip : clips) duration = std::max(duration, clip->durationSeconds());
    const std::uint64_t total = static_cast<std::uint64_t>(std::floor(duration * framesPerSecond + 1e-9)) + 1;
    stats.frames = total;

    const render::RendererOptions& ro = renderer.options();
    const float aspect = static_cast<float>(ro.width) / static_cast<float>(ro.height);
    const render::Camera camera =
        postureFrame(avatar, rig, sceneHandle, SignerPosture{}, aspect, nullptr, framing).views.front().camera;

    std::vector<ClipPoser> posers;
    for (const Clip* clip : clips) posers.emplace_back(rig, *clip);
    const std::uint32_t inFlight = std::max(1u, renderer.framesInFlight());
    // Which sink each submitted image goes to, in submission order: -1 for every sink.
    std::deque<int> targets;
    std::uint64_t framesDone = 0;
    const auto retrieveOne = [&] {
        // Buffers of frames the sinks have written are reused: a fresh multi-hundred-kilobyte
        // allocation per image costs page faults that slow the render thread noticeably.
        render::Image image;
        const int target = targets.front();
        targets.pop_front();
        sinks[target >= 0 ? static_cast<std::size_t>(target) : sinks.size() - 1]->recycle(image);
        renderer.retrieve(image);
        if (target >= 0) {
            sinks[static_cast<std::size_t>(target)]->push(std::move(image));
        } else {
            for (std::size_t i = 0; i + 1 < sinks.size(); ++i) {
                render::Image copy;
                sinks[i]->recycle(copy);
                copy.width = image.width;
                copy.height = image.height;
                copy.format = image.format;
                copy.bytes.assign(image.bytes.begin(), image.bytes.end());
                sinks[i]->push(std::move(copy));
            }
            sinks.back()->push(std::move(image));
        }
        // A frame is done when its last image (the shared one, or the last clip's) is out.
        if (target < 0 || target + 1 == static_cast<int>(sinks.size())) {
            ++framesDone;
            if (progress) progress(framesDone, total);
        }
    };
    const auto submit = [&](render::Pose&& pose, int target) {
        render::Frame frame;
        render::View view;
        view.scene = sceneHandle;
        view.pose = std::move(pose);
        view.camera = camera;
        frame.views.push_back(std::move(view));
        if (targets.size() >= inFlight) retrieveOne();
        renderer.submit(frame);
        targets.push_back(target);
        ++stats.renderedImages;
    };
    std::vector<render::Pose> poses(clips.size());
    for (std::uint64_t f = 0; f < total; ++f) {
        const double t = static_cast<double>(f) / framesPerSecond;
        bool shared = true;
        for (std::size_t i = 0; i < clips.size(); ++i) {
            poses[i] = posers[i].next(t);
            shared = shared && (i == 0 || samePose(poses[i], poses[0]));
        }
        if (shared) {
            ++stats.sharedFrames;
            submit(std::move(poses[0]), -1);
        } else {
            for (std::size_t i = 0; i < clips.size(); ++i) submit(std::move(poses[i]), static_cast<int>(i));
        }
    }
    while (!targets.empty()) retrieveOne();
    return stats;
}

}  // namespace signstim::signer
