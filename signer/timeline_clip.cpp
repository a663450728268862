#include "signer/timeline_clip.hpp"

#include "signer/signer_pose.hpp"

#include <cmath>

namespace signstim::signer {
namespace {

// [D] A glance at a referent: 1.2 m out along its direction, 12° below eye level.
constexpr double kGazeDistanceMm = 1200.0;
constexpr double kGazeDropDegrees = 12.0;
// The default signer's eyes in the body frame (hand/gaze.hpp, GazeModel::eyesMm).
constexpr double kEyeHeightMm = 420.0;

struct Resolved {
    hand::ArmTarget target;
    hand::HandControls controls;
};

}  // namespace

glm::vec3 gazePointForReferent(const glm::dvec3& p) {
    const double horizontal = std::hypot(p.x, p.z);
    const glm::dvec3 direction = horizontal > 1e-6 ? glm::dvec3(p.x / horizontal, 0.0, p.z / horizontal) : glm::dvec3(0, 0, 1);
    const double drop = std::tan(kGazeDropDegrees * 3.14159265358979323846 / 180.0) * kGazeDistanceMm;
    const glm::dvec3 point = glm::dvec3(0.0, kEyeHeightMm - drop, 0.0) + kGazeDistanceMm * direction;
    return bodyFromSigningSpace(glm::vec3(point));
}

glm::vec3 gazePointForViewer() { return glm::vec3(0.0f, static_cast<float>(kEyeHeightMm), 2000.0f); }

TimelineClip::TimelineClip(const SignerRig& rig, const stimuli::HandshapeLibrary& shapes, stimuli::Timeline timeline)
    : rig_(&rig), shapes_(&shapes), timeline_(std::move(timeline)) {
    for (const auto* track : {&timeline_.right, &timeline_.left})
        for (const stimuli::TimelineKey& key : *track)
            if (!key.rest) shapes.at(key.handshape);
}

bool TimelineClip::solveAfresh(double previousSeconds, double seconds) const {
    for (const stimuli::TimelineSpan& span : timeline_.spans)
        if (span.kind == stimuli::SpanKind::Verb && span.endSeconds >= previousSeconds && span.endSeconds < seconds)
            return true;
    return false;
}

SignerPosture TimelineClip::postureAt(double seconds) const {
    SignerPosture posture;
    for (const hand::Side side : {hand::Side::Right, hand::Side::Left}) {
        const auto& track = side == hand::Side::Right ? timeline_.right : timeline_.left;
        const stimuli::TimelineSample sample = stimuli::sampleTrack(track, seconds);
        auto resolve = [&](const stimuli::TimelineKey& key) {
            if (key.rest) return Resolved{rig_->restingTarget(side), relaxedHand()};
            return Resolved{armTargetFromSigningSpace(key.pose), shapes_->at(key.handshape).controls};
        };
        const Resolved from = resolve(*sample.from), to = resolve(*sample.to);
        const float blend = static_cast<float>(sample.blend);
        const hand::ArmTarget target = blendTargets(from.target, to.target, blend);
        const hand::HandControls controls = hand::interpolate(from.controls, to.controls, blend);
        if (side == hand::Side::Right) {
            posture.rightWrist = target;
            posture.rightHand = controls;
        } else {
            posture.leftWrist = target;
            posture.leftHand = controls;
        }
    }
    const stimuli::GazeSample gaze = stimuli::sampleGaze(timeline_.gaze, seconds);
    if (gaze.from) {
        auto point = [](const stimuli::GazeKey& key) {
            return key.targetMm ? gazePointForReferent(*key.targetMm) : gazePointForViewer();
        };
        const glm::vec3 a = point(*gaze.from), b = point(*gaze.to);
        posture.gazeMm = a + static_cast<float>(gaze.blend) * (b - a);
    }
    return posture;
}

}  // namespace signstim::signer
