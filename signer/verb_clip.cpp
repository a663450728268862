#include "signer/verb_clip.hpp"

#include <algorithm>
#include <utility>

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

VerbClip::VerbClip(const SignerRig& rig, const stimuli::HandshapeLibrary& shapes,
                   stimuli::VerbPerformance performance, ClipTiming timing)
    : rig_(&rig), shapes_(&shapes), performance_(std::move(performance)), timing_(timing) {
    for (const stimuli::HandTrack& track : performance_.hands)
        for (const stimuli::PerformanceKeyframe& key : track.keyframes) shapes.at(key.handshape);
    for (const stimuli::HandTrack& track : performance_.hands) {
        const hand::Side side = toHandSide(track.side);
        restElbows_.push_back(hand::solveArm(rig.arm(side), rig.restingTarget(side)).elbowDirection);
        std::vector<glm::vec3> elbows;
        for (const stimuli::PerformanceKeyframe& key : track.keyframes)
            elbows.push_back(hand::solveArm(rig.arm(side), armTargetFromSigningSpace(key.pose)).elbowDirection);
        keyElbows_.push_back(std::move(elbows));
    }
    // The elbows' track (signer/elbow_track.hpp), as a story's (TimelineClip): sampled on the
    // postures without it, then followed by every posture (postureAt).
    elbows_ = ElbowTrack(rig, durationSeconds(), [this](double t) { return postureAt(t); });
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
    for (std::size_t h = 0; h < performance_.hands.size(); ++h) {
        const stimuli::HandTrack& track = performance_.hands[h];
        const hand::Side side = toHandSide(track.side);
        const stimuli::HandSample sample = stimuli::sampleHand(track, std::max(0.0, verbTime));
        // The elbow hint: blended between the keyframes' elbows as sampleHand blends the poses.
        const std::vector<stimuli::PerformanceKeyframe>& keys = track.keyframes;
        const std::vector<glm::vec3>& elbows = keyElbows_[h];
        glm::vec3 elbow = elbows.empty() ? restElbows_[h] : elbows.front();
        if (keys.size() > 1 && verbTime >= keys.back().timeSeconds) {
            elbow = elbows.back();
        } else if (keys.size() > 1 && verbTime > keys.front().timeSeconds) {
            std::size_t i = 1;
            while (keys[i].timeSeconds < verbTime) ++i;
            const double u = (verbTime - keys[i - 1].timeSeconds) / (keys[i].timeSeconds - keys[i - 1].timeSeconds);
            elbow = blendElbowHints(elbows[i - 1], elbows[i], static_cast<float>(smoothstep(u)));
        }
        if (rise < 1.0f) elbow = blendElbowHints(restElbows_[h], elbow, rise);
        hand::HandControls controls =
            hand::interpolate(shapes_->at(sample.handshapeFrom).controls, shapes_->at(sample.handshapeTo).controls,
                              static_cast<float>(sample.handshapeBlend));
        hand::ArmTarget target = armTargetFromSigningSpace(sample.pose);
        if (rise < 1.0f) target = blendTargets(rig_->restingTarget(side), target, rise);
        if (side == hand::Side::Right) {
            posture.rightHand = controls;
            posture.rightWrist = target;
            posture.rightElbowHint = elbow;
        } else {
            posture.leftHand = controls;
            posture.leftWrist = target;
            posture.leftElbowHint = elbow;
        }
    }
    elbows_.apply(seconds, posture);  // the arms follow the elbows' track (none while it is made)
    return posture;
}

}  // namespace signstim::signer
