#pragma once
// What the motion tests measure on a clip (issue 21): the signer posed at instants of a clip, as
// a function of the clip and the time alone (ClipPoser), with the figures a signer's body
// allows — elbow height, elbow swivel rate, wrist angles, wrist speed, head and eyes.
#include "signer/clip.hpp"
#include "signer/signer_pose.hpp"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace signstim::motion {

// A maximum and where it was found.
struct Peak {
    double value = -1e30;
    std::string where;
    void take(double v, const std::string& place) {
        if (v > value) {
            value = v;
            where = place;
        }
    }
};

struct MotionPeaks {
    Peak elbowAboveShoulderMm;       // elbow height above its shoulder joint, less how far the wrist is above the head
    Peak elbowSwingDegPerFrame;      // change of the upper arm's direction between 60 fps frames
    Peak elbowTurnDegPerFrame;       // turn of the elbow's direction from the shoulder-wrist axis, per 60 fps frame
    Peak swivelStepDegPerFrame;      // turn of the elbow about the shoulder-wrist axis (the axis's own motion apart), per 60 fps frame
    Peak hintStepDegPerFrame;        // turn of the elbow hint (the keys' elbows blended), per 60 fps frame
    Peak wristFlexionDeg, wristExtensionDeg, ulnarDeviationDeg, radialDeviationDeg, supinationDeg, pronationDeg;
    Peak wristSpeedMmPerSecond;      // the drawn wrist (the arm solution's)
    Peak reachShortMm;               // how far the drawn wrist falls short of its target (ArmPose::reachErrorMm)
    Peak headYawDeg, eyeYawDeg, eyePitchDeg, headSpeedDegPerSecond;

    void print(const char* title) const {
        std::printf("%s\n", title);
        const auto line = [](const char* name, const Peak& p) { std::printf("  %-28s %9.2f  at %s\n", name, p.value, p.where.c_str()); };
        line("elbow above shoulder (mm)", elbowAboveShoulderMm);
        line("elbow swing (deg/frame@60)", elbowSwingDegPerFrame);
        line("elbow turn (deg/frame@60)", elbowTurnDegPerFrame);
        line("swivel (deg/frame@60)", swivelStepDegPerFrame);
        line("hint step (deg/frame@60)", hintStepDegPerFrame);
        line("wrist flexion (deg)", wristFlexionDeg);
        line("wrist extension (deg)", wristExtensionDeg);
        line("ulnar deviation (deg)", ulnarDeviationDeg);
        line("radial deviation (deg)", radialDeviationDeg);
        line("supination (deg)", supinationDeg);
        line("pronation (deg)", pronationDeg);
        line("wrist speed (mm/s)", wristSpeedMmPerSecond);
        line("wrist short of target (mm)", reachShortMm);
        line("head yaw (deg)", headYawDeg);
        line("eye-in-orbit yaw (deg)", eyeYawDeg);
        line("eye-in-orbit pitch (deg)", eyePitchDeg);
        line("head speed (deg/s)", headSpeedDegPerSecond);
    }
};

inline double angleDeg(const glm::vec3& a, const glm::vec3& b) {
    const double c = std::clamp(static_cast<double>(glm::dot(glm::normalize(a), glm::normalize(b))), -1.0, 1.0);
    return std::acos(c) * 180.0 / 3.14159265358979323846;
}

// Issue 21: "elbow never above shoulder height unless the sign's citation form puts the hand
// above the head". How far the elbow is above its shoulder joint, less how far the wrist is above
// the top of the head (hand::ArmModel::elbowRiseWristAboveShoulderMm), so a hand raised over the
// head may take the elbow up with it; > 0 breaks the rule.
inline double elbowAboveShoulderMm(const hand::ArmModel& arm, const hand::ArmPose& a) {
    const double overHead = std::max(0.0, static_cast<double>(a.wristMm.y - a.shoulderMm.y) - arm.elbowRiseWristAboveShoulderMm);
    return a.elbowMm.y - a.shoulderMm.y - overHead;
}

// Every instant f / fps of `clip` from 0 to its end, arms and gaze as the renderer poses them
// (SignerRig::solveArm, the gaze of the posture); `name` labels the peaks.
inline void measureClip(const signer::SignerRig& rig, const signer::Clip& clip, const std::string& name, double fps,
                        MotionPeaks& peaks) {
    const auto total = static_cast<std::uint64_t>(std::floor(clip.durationSeconds() * fps + 1e-9)) + 1;
    signer::PoseReport previous;
    signer::SignerPosture previousPosture;
    bool hasPrevious = false;
    for (std::uint64_t f = 0; f < total; ++f) {
        const double t = static_cast<double>(f) / fps;
        const signer::SignerPosture posture = clip.postureAt(t);
        signer::PoseReport r;
        r.right = rig.solveArm(hand::Side::Right, posture);
        r.left = rig.solveArm(hand::Side::Left, posture);
        r.gaze = rig.solveGazeAt(posture);
        char at[64];
        std::snprintf(at, sizeof at, " t=%.3f s", t);
        for (const bool right : {true, false}) {
            const hand::ArmPose& a = right ? r.right : r.left;
            const std::string where = name + (right ? " right" : " left") + at;
            peaks.elbowAboveShoulderMm.take(elbowAboveShoulderMm(rig.arm(right ? hand::Side::Right : hand::Side::Left), a),
                                            where);
            peaks.wristFlexionDeg.take(a.wristFlexionDeg, where);
            peaks.wristExtensionDeg.take(-a.wristFlexionDeg, where);
            peaks.ulnarDeviationDeg.take(a.wristUlnarDeviationDeg, where);
            peaks.radialDeviationDeg.take(-a.wristUlnarDeviationDeg, where);
            peaks.supinationDeg.take(a.supinationDeg, where);
            peaks.pronationDeg.take(-a.supinationDeg, where);
            peaks.reachShortMm.take(a.reachErrorMm, where);
            if (hasPrevious) {
                const hand::ArmPose& p = right ? previous.right : previous.left;
                peaks.elbowSwingDegPerFrame.take(angleDeg(a.elbowMm - a.shoulderMm, p.elbowMm - p.shoulderMm) * fps / 60.0, where);
                const auto& hint = right ? posture.rightElbowHint : posture.leftElbowHint;
                const auto& hintBefore = right ? previousPosture.rightElbowHint : previousPosture.leftElbowHint;
                const double hintStep = hint && hintBefore ? angleDeg(*hint, *hintBefore) : 0.0;
                peaks.hintStepDegPerFrame.take(hintStep * fps / 60.0, where);
                peaks.elbowTurnDegPerFrame.take(angleDeg(a.elbowDirection, p.elbowDirection) * fps / 60.0, where);
                // The swivel's step: the previous elbow direction carried to this frame's axis
                // (its component across the axis), then the angle about the axis to this one.
                const glm::vec3 axis = glm::normalize(a.wristMm - a.shoulderMm);
                const glm::vec3 carried = p.elbowDirection - glm::dot(p.elbowDirection, axis) * axis;
                const glm::vec3 across = a.elbowDirection - glm::dot(a.elbowDirection, axis) * axis;
                if (glm::length(carried) > 1e-3f && glm::length(across) > 1e-3f)
                    peaks.swivelStepDegPerFrame.take(angleDeg(carried, across) * fps / 60.0, where);
                peaks.wristSpeedMmPerSecond.take(glm::distance(a.wristMm, p.wristMm) * fps, where);
            }
        }
        const std::string where = name + at;
        peaks.headYawDeg.take(std::fabs(r.gaze.headYawDeg), where);
        peaks.eyeYawDeg.take(std::fabs(r.gaze.eyeYawDeg), where);
        peaks.eyePitchDeg.take(std::fabs(r.gaze.eyePitchDeg), where);
        if (hasPrevious) {
            const float d = std::min(1.0f, std::fabs(glm::dot(r.gaze.head, previous.gaze.head)));
            peaks.headSpeedDegPerSecond.take(2.0 * std::acos(static_cast<double>(d)) * 180.0 / 3.14159265358979323846 * fps, where);
        }
        previous = r;
        previousPosture = posture;
        hasPrevious = true;
    }
}

}  // namespace signstim::motion
