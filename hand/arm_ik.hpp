#pragma once
// Arm kinematics for the signer: analytic two-bone IK (shoulder–elbow–wrist) with a natural
// elbow swivel, anatomical limits and frame-to-frame continuity.
//
// Body frame (torso-fixed, millimetres, right-handed, the glTF avatar's axes):
//   +y up, +z forward (the way the signer faces), +x the signer's LEFT.
// A glTF avatar that faces +Z therefore uses it with no rotation. (The signing-space frame of
// stimuli/verbs/signing_space.hpp has +x to the signer's right; the app converts, x -> -x.)
//
// Anatomical frames. Every arm segment carries a frame that coincides with the hand model's
// palm frame (SPEC §1.1: +z toward the fingers, +x palmar, +y toward the thumb of a right
// hand; the left hand's frame is the mirror, so its +y points to the little-finger side)
// when the arm is straight, the forearm in neutral rotation (thumb forward when the arm is
// held out sideways, palm down) and the wrist straight:
//   upper arm  z along the bone (shoulder -> elbow), x = the palmar side of the elbow hinge;
//   forearm    z along the bone (elbow -> wrist), same x as the upper arm (the hinge axis is
//              shared), no pronation;
//   hand       the forearm frame · R_z(pronation/supination) · R_y(flexion) · R_x(deviation).
// In the canonical rest posture (T-pose: right arm along -x, left along +x, palms down,
// thumbs forward) every one of these frames is the same rotation; `restFrame(side)` gives it.
// A skeleton whose rest bones are aligned with these frames is posed by
// world(bone) = frame(bone) · restFrame⁻¹ · restWorld(bone).
#include "hand/hand_model.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <optional>

namespace signstim::hand {

// Anatomical limits of one arm, degrees. [S] Clinical ranges of motion (AAOS / Norkin &
// White), trimmed to what signing uses; every limit is a parameter.
struct ArmLimits {
    // Elbow flexion: 0 = straight. [S] Active flexion 0–150° (American Academy of
    // Orthopaedic Surgeons, Joint Motion: Method of Measuring and Recording, 1965; Norkin &
    // White, Measurement of Joint Motion), the last degrees against the soft tissue of a
    // forearm pressed to the upper arm. 145° [D]: tried at 150° (issue 22), the wrist comes
    // 22 mm nearer the shoulder, but the face signs then miss their orientation by more
    // (SISTER 48 -> 53°, SOON 63 -> 70°, DRINK 0 -> 25°) and SISTER's contact by 25 mm more:
    // the shortfall of those signs is the wrist's turn, not the elbow's reach.
    AngleRange elbowFlexion{0.0f, 145.0f};
    // Shoulder: elevation of the upper arm from hanging straight down (0) to overhead (180).
    AngleRange shoulderElevation{0.0f, 170.0f};
    // Plane of elevation: 0 = straight out to the side, +90 = straight forward, above 90 =
    // across the body (horizontal adduction), below 0 = behind (horizontal extension). Only
    // binding when the arm is raised (weighted by sin(elevation)).
    AngleRange shoulderPlane{-40.0f, 135.0f};
    // Forearm rotation from neutral (thumb up when the elbow is bent at the side):
    // + supination (palm up), − pronation (palm down). [S] Kapandji (The Physiology of the
    // Joints vol. 1): pronation 85°, supination 90°. AAOS / Norkin & White give 0–80° each
    // (clinical averages); the lexicon's contact signs were authored with these (issue 21:
    // tightening them sinks some into the body).
    AngleRange supination{-85.0f, 90.0f};
    // Wrist: + flexion (palm toward the forearm), − extension. AAOS: flexion 0–80°,
    // extension 0–70°.
    AngleRange wristFlexion{-70.0f, 80.0f};
    // Wrist: + ulnar deviation (toward the little finger), − radial deviation. [S] radial 0–20°
    // (AAOS); ulnar 35°, within Kapandji's 30–45° (AAOS: 30°, narrower, as for supination).
    AngleRange wristUlnarDeviation{-20.0f, 35.0f};
};

// One arm, built once (model and data apart, like HandModel).
struct ArmModel {
    Side side = Side::Right;
    glm::vec3 shoulderMm{-175.0f, 130.0f, 0.0f};  // joint centre in the body frame
    // [S] Drillis & Contini segment ratios for stature 1750 mm: upper arm 0.186·H, forearm
    // 0.146·H (elbow to wrist joint centres).
    float upperArmLengthMm = 325.0f;
    float forearmLengthMm = 255.0f;
    ArmLimits limits;
    // Natural elbow: the elbow points along this "pole" (body frame, normalised by the
    // solver) projected onto the plane the elbow can move in. [D] Down, a little outward
    // and back: a relaxed signer's elbows hang beside the torso.
    float poleOutward = 0.35f;    // weight of the lateral direction
    float poleBackward = 0.25f;   // weight of -z
    float poleOutwardWhenHigh = 0.8f;  // extra outward as the wrist rises above the shoulder
    // The elbow stays outside the torso [D]: at least this far from the body midline
    // (x = 0) toward its own side, unless it is well in front of the chest.
    float minElbowLateralMm = 110.0f;
    float torsoFrontMm = 140.0f;  // elbows further forward than this may cross the midline
    // Issue 21: the elbow never above the shoulder unless the hand is above the head. The
    // elbow may rise above its shoulder joint only by as much as the wrist is higher than this
    // above the shoulder joint: the top of the head (the rig sets it from the avatar's eyes).
    // 340 mm where no rig sets it: the rig measures 337 mm on the default signer (signer_pose.cpp);
    // [S] Drillis & Contini at 1750 mm give 358 (the vertex 0.182·H above the acromion, which is
    // ~40 mm above the joint centre).
    float elbowRiseWristAboveShoulderMm = 340.0f;
};

// Default arms of the default signer (stature 1750 mm), mirrored about the body midline.
ArmModel defaultArmModel(Side side);

// The anatomical frame of every arm segment in the canonical rest posture (see above).
glm::quat restFrame(Side side);

struct ArmTarget {
    glm::vec3 wristMm{0.0f};                          // wrist joint centre, body frame
    glm::quat handRotation{1.0f, 0.0f, 0.0f, 0.0f};   // hand frame in the body frame
};

struct ArmSolveOptions {
    // Continuity: the previous frame's elbow direction (ArmPose::elbowDirection). When set,
    // the swivel moves at most maxSwivelStepDeg from it, so the elbow never flips between
    // neighbouring frames. maxSwivelStepDeg <= 0: the elbow takes the given direction itself
    // (about the shoulder-wrist axis), no search. Either way the elbow stays at or below
    // its shoulder unless the wrist is above the head (ArmModel::elbowRiseWristAboveShoulderMm,
    // issue 21), the swivel moved to the nearest that does.
    std::optional<glm::vec3> previousElbowDirection;
    float maxSwivelStepDeg = 20.0f;
    // [D] The window yields where the hand's orientation is out of the wrist's reach at the
    // previous elbow: it widens by this many degrees per degree the wrist angles there exceed
    // their limits (up to swivelWindowDeg), so a hint cannot hold the elbow where the palm
    // cannot turn as asked (issue 22: FORGET, REMEMBER). A rule of the target and the hint
    // alone, continuous in both, so a pose stays a pure function of its instant.
    // Off (0) by default: with the elbow track (signer/elbow_track.hpp) blending across the jumps
    // the yield makes, story 07's ASK -> GUS took a hand 10-16 mm into the body (point, vector);
    // at 1 it gave FORGET 66->53 deg, REMEMBER 38->32, WILL 48->39 without the track.
    float hintYieldPerWristDeg = 0.0f;
    // Without a previous elbow: the swivel is sought only within this angle of the natural
    // pole [D]. The rule of the target that picks the elbow (issue 21: a pose is a function of
    // its instant, never of the last frame): the elbow stays on the low, outer side of the
    // shoulder-wrist axis, never swung over it.
    float swivelWindowDeg = 75.0f;
    // Cost weights of the 1-D swivel search [D]: stay near the natural pole, keep the wrist
    // comfortable (far from its limits), respect the shoulder limits, keep the elbow out of
    // the torso.
    float poleWeight = 1.0f;
    float wristComfortWeight = 0.3f;
    float shoulderLimitWeight = 20.0f;
    float torsoWeight = 20.0f;
    // (No cost on the elbow's height: the cap of ArmModel::elbowRiseWristAboveShoulderMm holds
    // every swivel the search tries at or below it, so a cost above it could never act.)
};

struct ArmPose {
    glm::vec3 shoulderMm{0.0f}, elbowMm{0.0f}, wristMm{0.0f};
    // Anatomical frames (see the top of this file) in the body frame.
    glm::quat upperArm{1.0f, 0.0f, 0.0f, 0.0f};
    glm::quat forearm{1.0f, 0.0f, 0.0f, 0.0f};   // without pronation
    glm::quat hand{1.0f, 0.0f, 0.0f, 0.0f};
    // Unit vector from the shoulder–wrist axis to the elbow: feed it back for continuity.
    glm::vec3 elbowDirection{0.0f, -1.0f, 0.0f};
    float swivelDeg = 0.0f;  // about the shoulder→wrist axis, 0 = the natural pole
    float elbowFlexionDeg = 0.0f;
    float shoulderElevationDeg = 0.0f;
    float shoulderPlaneDeg = 0.0f;
    float supinationDeg = 0.0f;
    float wristFlexionDeg = 0.0f;
    float wristUlnarDeviationDeg = 0.0f;
    // How far the result is from the target: wrist position (mm) and hand orientation
    // (degrees). Zero (to rounding) when the target was reachable within the limits.
    float reachErrorMm = 0.0f;
    float orientationErrorDeg = 0.0f;
    bool reachable = true;      // the wrist position was reached (within 0.5 mm)
    bool wristLimited = false;  // the hand orientation had to be clamped to the wrist limits
    bool shoulderLimited = false;  // the best swivel still leaves a shoulder limit
};

// Analytic two-bone IK: the elbow flexion follows from the shoulder–wrist distance (clamped
// to the elbow limits, i.e. unreachable targets are approached along the same direction as
// closely as possible and reported), the elbow swivel from a 1-D search of a smooth cost
// (natural pole + wrist comfort + shoulder limits, windowed around the previous frame's
// elbow when given); pronation and the wrist angles follow from the target orientation and
// are clamped to their limits. Pure function; deterministic.
ArmPose solveArm(const ArmModel& arm, const ArmTarget& target, const ArmSolveOptions& options = {});
// Where solveArm puts the wrist (ArmPose::wristMm, the same bits) without seeking the elbow:
// the target, or the nearest point toward it the elbow's flexion limits allow. It does not
// depend on the swivel, so it costs a fraction of a solve (the transition pacer measures the
// wrists' speed alone).
glm::vec3 reachedWristMm(const ArmModel& arm, const ArmTarget& target);

// Decomposes a hand frame relative to a forearm frame (both in the body frame) into
// anatomical angles (degrees) for `side`: supination, flexion, ulnar deviation.
struct WristAngles {
    float supinationDeg = 0.0f;
    float flexionDeg = 0.0f;
    float ulnarDeviationDeg = 0.0f;
};
WristAngles wristAngles(Side side, const glm::quat& forearm, const glm::quat& hand);
// The inverse: the hand frame for a forearm frame and anatomical wrist angles.
glm::quat handFrame(Side side, const glm::quat& forearm, const WristAngles& angles);

// Angle between two rotations, degrees.
float rotationAngleDeg(const glm::quat& a, const glm::quat& b);

}  // namespace signstim::hand
