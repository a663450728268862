#pragma once
// Head and eye gaze toward a 3-D point (e.g. a referent placed in signing space). Body frame
// and units as in hand/arm_ik.hpp: millimetres, +y up, +z forward, +x the signer's left.
#include "hand/hand_model.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

namespace signstim::hand {

struct GazeModel {
    glm::vec3 eyesMm{0.0f, 420.0f, 70.0f};  // midpoint between the eyes, looking ahead
    // [S] Cervical range of motion (yaw ±70–80°, flexion 45–50°, extension 60°) trimmed to
    // comfortable gaze shifts: in natural head-free gaze shifts the head turns no more than
    // ~45° and the eyes stay within ~30–35° of the orbit's centre (Freedman & Sparks 1997;
    // Goossens & Van Opstal 1997), so a glance toward a far referent is eyes and head together.
    AngleRange headYaw{-45.0f, 45.0f};
    AngleRange headPitch{-35.0f, 35.0f};  // + looks up
    AngleRange eyeYaw{-35.0f, 35.0f};
    AngleRange eyePitch{-25.0f, 25.0f};
    // [D] Share of a gaze shift taken by the head (eyes do the rest, head-free gaze shifts
    // are ~40–70 % head), and of the head's rotation taken by the neck.
    float headShare = 0.6f;
    float neckShare = 0.4f;
};

struct GazePose {
    float headYawDeg = 0.0f, headPitchDeg = 0.0f;  // head in the body frame (+yaw to the left)
    float eyeYawDeg = 0.0f, eyePitchDeg = 0.0f;    // eyes in the head
    glm::quat neck{1.0f, 0.0f, 0.0f, 0.0f};        // neck in the body frame
    glm::quat head{1.0f, 0.0f, 0.0f, 0.0f};        // head in the body frame
    glm::quat eyes{1.0f, 0.0f, 0.0f, 0.0f};        // eyes relative to the head
    float errorDeg = 0.0f;   // angle between the achieved gaze and the target direction
    bool reachable = true;   // error below 0.5°
};

// Yaw/pitch toward `targetMm`, split between head (and neck) and eyes, each within its
// limits. A target behind the signer is approached as far as the limits allow and reported.
GazePose solveGaze(const GazeModel& model, const glm::vec3& targetMm);

// The eyes toward `targetMm` with the head held at `headYawDeg`, `headPitchDeg` (clamped to the
// head's limits): the head of a gaze shift still on its way (it lags the eyes), the eyes
// taking the rest within their limits.
GazePose solveGazeWithHead(const GazeModel& model, const glm::vec3& targetMm, float headYawDeg, float headPitchDeg);

}  // namespace signstim::hand
