#include "signer/verb_render.hpp"

#include "signer/avatar_render.hpp"
#include "common/error.hpp"
#include "renderer/gltf_loader.hpp"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <deque>

namespace signstim::signer {
namespace {

double smoothstep(double u) {
    u = std::clamp(u, 0.0, 1.0);
    return u * u * (3.0 - 2.0 * u);
}

hand::Side toHandSide(stimuli::HandSide side) {
    return side == stimuli::HandSide::Right ? hand::Side::Right : hand::Side::Left;
}

}  // namespace

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

Signer::Signer(const std::filesystem::path& scenesDir, const std::filesystem::path& avatarFile,
               const BoneMapping& mapping)
    : avatar_(loadSignerAvatar(avatarFile.empty() ? defaultAvatarPath(scenesDir) : avatarFile, mapping)),
      rig_(avatar_, mapping),
      shapes_(stimuli::loadHandshapes(scenesDir / "handshapes.json", rig_.handModel())) {}

void StillCapturingSink::push(render::Image&& frame) {
    if (count_++ == keep_) still_ = frame;
    next_.push(std::move(frame));
}

hand::ArmTarget armTargetFromSigningSpace(const stimuli::HandPose& pose) {
    hand::ArmTarget target;
    target.wristMm = bodyFromSigningSpace(glm::vec3(pose.positionMm));
    target.handRotation = handFrameFromSigningSpace(glm::quat(pose.orientation));
    return target;
}

VerbClip::VerbClip(const SignerRig& rig, const stimuli::HandshapeLibrary& shapes,
                   stimuli::VerbPerformance performance, ClipTiming timing)
    : rig_(&rig), shapes_(&shapes), performance_(std::move(performance)), timing_(timing) {
    for (const stimuli::HandTrack& track : performance_.hands)
        for (const stimuli::PerformanceKeyframe& key : track.keyframes) shapes.at(key.handshape);
}

double VerbClip::durationSeconds() const {
    return timing_.leadInSeconds + performance_.durationSeconds + timing_.holdSeconds;
}

SignerPosture VerbClip::postureAt(double seconds) const {
    SignerPosture posture;
    posture.rightHand = posture.leftHand = relaxedHand();
    const double verbTime = seconds - timing_.leadInSeconds;
    // Lead-in: rise from rest with an ease-in-out, reaching the first keyframe as the verb begins.
    const float rise =
        timing_.leadInSeconds > 0.0 ? static_cast<float>(smoothstep(seconds / timing_.leadInSeconds)) : 1.0f;
    for (const stimuli::HandTrack& track : performance_.hands) {
        const hand::Side side = toHandSide(track.side);
        const stimuli::HandSample sample = stimuli::sampleHand(track, std::max(0.0, verbTime));
        hand::HandControls controls =
            hand::interpolate(shapes_->at(sample.handshapeFrom).controls, shapes_->at(sample.handshapeTo).controls,
                              static_cast<float>(sample.handshapeBlend));
        hand::ArmTarget target = armTargetFromSigningSpace(sample.pose);
        if (rise < 1.0f) target = blendTargets(rig_->restingTarget(side), target, rise);
        if (side == hand::Side::Right) {
            posture.rightHand = controls;
            posture.rightWrist = target;
        } else {
            posture.leftHand = controls;
            posture.leftWrist = target;
        }
    }
    return posture;
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
    const render::Frame restFrame = postureFrame(avatar, rig, sceneHandle, SignerPosture{}, aspect);
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
    if (a.local.size() != b.local.size() || a.useRestMatrix != b.useRestMatrix) return false;
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
                                           const std::function<void(std::uint64_t, std::uint64_t)>& progress) {
    SharedRenderStats stats;
    if (clips.empty()) return stats;
    if (sinks.size() != clips.size()) throw std::invalid_argument("renderClipsSharingFrames: one sink per clip");
    double duration = 0.0;
    for (const Clip* clip : clips) duration = std::max(duration, clip->durationSeconds());
    const std::uint64_t total = static_cast<std::uint64_t>(std::floor(duration * framesPerSecond + 1e-9)) + 1;
    stats.frames = total;

    const render::RendererOptions& ro = renderer.options();
    const float aspect = static_cast<float>(ro.width) / static_cast<float>(ro.height);
    const render::Camera camera = postureFrame(avatar, rig, sceneHandle, SignerPosture{}, aspect).views.front().camera;

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
