#pragma once
// Posing a signer avatar for one frame: hand shapes (McDonald hand controls), wrist targets
// (arm IK) and an optional gaze point -> a render::Pose for the avatar's Scene.
//
// Works for the default avatar (signer/avatar_builder.hpp) and for any glTF whose skeleton uses
// VRM humanoid bone names (or a mapping file), +Y up. Rotations are retargeted through the
// rest pose: world(bone) = canonical(bone) · (Δ(bone) · canonicalRest(bone))⁻¹ · restWorld(bone),
// so the user's own bone axes do not matter. canonicalRest is the bone's frame in the
// canonical rest pose (T-pose facing +Z, palms down-forward as the default signer, fingers
// straight); Δ turns it onto the avatar's own rest pose, measured from the skeleton: A-pose
// arms, palms down or forward, curled or splayed fingers are all taken as they are. Arm and
// digit bones are measured by their direction to the next joint (the last bone of a digit
// by a leaf node continuing it, if it has one), the hand by its whole frame; the forearm's
// roll follows the hand's (signer/signer_pose.cpp, measureRestPose). Not measured: the upper
// arm's or a digit's roll about its own axis — the thumb's included. A bone of no length is refused.
// The arm lengths and shoulder positions are read from the skeleton. An avatar facing another way (VRM 0.x faces
// -Z) is turned to face +Z first by faceAvatarForward().
//
// Frames. Wrist targets and gaze points are given in the body frame of hand/arm_ik.hpp
// (mm, +x the signer's LEFT, +y up, +z forward, origin at the chest). Verb data lives in the
// signing-space frame of stimuli/verbs/signing_space.hpp (+x the signer's RIGHT); convert with
// bodyFromSigningSpace(). The origin (the chest) is 130 mm below the midpoint of the
// shoulder joints, as in the default avatar.
#include "hand/arm_ik.hpp"
#include "hand/gaze.hpp"
#include "hand/hand_model.hpp"
#include "renderer/scene.hpp"

#include <glm/vec2.hpp>

#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace signstim::signer {

// VRM humanoid bone name -> node name in the user's glTF, and where each entry was written, so
// that a wrong entry is reported in the bone-map file rather than blamed on the avatar.
struct BoneMapping {
    std::map<std::string, std::string> nodes;  // VRM name -> node name
    std::string file;                          // the bone-map file; empty when built in code
    std::string pointer;                       // JSON pointer of the object: "/bones" or ""
    std::map<std::string, int> lines;          // VRM name -> line of its entry in `file`
};
// JSON object {"leftUpperArm": "mixamorig:LeftArm", ...} (optionally under "bones"); every
// key a VRM humanoid bone name (or a forearm twist helper, see requiredSignerBones). Throws
// InputError naming the file, line and field (a JSON pointer: "/bones/leftUpperArm").
BoneMapping loadBoneMapping(const std::filesystem::path& file);

// Bones the posing needs (VRM names); eyes, shoulders and the forearm twist helpers are used
// when present.
const std::vector<std::string>& requiredSignerBones();

// Signing space (SPEC §3.1, +x = the signer's right) -> body frame (+x = the signer's left).
// The frames differ by the mirror x -> -x; a rotation R becomes S·R·S (S = diag(-1, 1, 1)),
// which is a proper rotation again.
glm::vec3 bodyFromSigningSpace(const glm::vec3& pointMm);
glm::quat bodyFromSigningSpace(const glm::quat& rotation);

// The orientation of a hand's palm frame written in signing-space coordinates (the verb
// files, corpus and models: columns palmar x, y = z × x computed in those coordinates,
// fingers z) -> the palm frame in the body frame. The signing-space frame is physically
// left-handed (right, up, forward) while the body frame is right-handed, so the cross
// product that made y points the other way in the body frame: the result keeps the palm
// (x) and finger (z) directions and recomputes y: S·R·diag(1, −1, 1). (Conjugation S·R·S,
// right for a rotation *operator* such as `pose --right-rotation`, would turn the palm to
// face the opposite way.)
glm::quat handFrameFromSigningSpace(const glm::quat& orientation);

// Turns the avatar about +Y so that it faces +Z (the default signer's and every camera's
// assumption), judged from its rest skeleton: forward = (left shoulder − right shoulder) × up.
// Applied to the root nodes; does nothing when it already faces +Z within 1°, or when the
// shoulder bones are missing (SignerRig then reports them). Returns the turn in degrees.
// Throws InputError naming the scene when the shoulders are not level or the head is not
// above the hips (not standing with +Y up).
float faceAvatarForward(render::Scene& scene, const BoneMapping& mapping = {});

// Loads a signer avatar (.glb/.gltf) for SignerRig: the file must exist (InputError naming it
// and `flag` otherwise), its scene is named after the file, and it is turned to face +Z.
render::Scene loadSignerAvatar(const std::filesystem::path& file, const BoneMapping& mapping = {},
                               const std::string& flag = "--avatar");

// The non-manual channels of one instant (issue 23; names and units of the seam,
// stimuli/story/timeline.hpp). Zero everywhere is the neutral face and body.
struct NonManualPosture {
    // Face: ARKit-52 blendshape name -> weight 0..1. Shown on the avatar's own shapes of that
    // name, else through the VRM expression map (signer/avatar_face.hpp); ignored otherwise.
    std::map<std::string, float> face;
    // Head (radians; jut mm): composed after the gaze's head turn, in the head's own frame.
    float headNodRad = 0.0f;    // + chin down
    float headShakeRad = 0.0f;  // + toward the signer's left
    float headTiltRad = 0.0f;   // + toward the signer's left shoulder
    float headJutMm = 0.0f;     // + forward (the neck leans, the head stays level)
    // Torso (radians; shift mm): the spine and chest turn, and everything they carry — arms,
    // hands, neck and head — with them: the signing space is the chest's (role shift).
    float torsoLeanRad = 0.0f;   // + forward
    float torsoTurnRad = 0.0f;   // + toward the signer's left
    float torsoShiftMm = 0.0f;   // + toward the signer's left (the chest, by a sideways bend)
    // Shoulders 0..1 (1 = kShoulderRaiseMaxDeg of the shoulder bone); the hands stay on target.
    float shoulderRaiseLeft = 0.0f, shoulderRaiseRight = 0.0f;
    bool neutral() const;
};
// Sets the seam's channel `channel` ("browInnerUp", "head.nod", "torso.turn",
// "shoulders.raise", "shoulder.raiseLeft", ...) to `value` in the seam's units; a face
// weight is clamped to [0, 1]. Returns false for a "head."/"torso."/"shoulder" name it does
// not know (a face name is taken as given: a channel an avatar lacks is ignored when posing).
bool setNonManualChannel(NonManualPosture& posture, const std::string& channel, double value);

// The rotations the non-manuals give (body frame), empty when they are zero
// (signer_pose_nonmanual.cpp).
glm::quat headNonManualRotation(const NonManualPosture& nonManual);
float jutLeanRad(float jutMm, float neckLengthMm);
std::optional<glm::quat> shoulderRaiseRotation(hand::Side side, const NonManualPosture& nonManual);
std::optional<glm::quat> torsoRotation(const NonManualPosture& nonManual, float torsoLengthMm);

// The upper lids follow the eyes' vertical turn: down by as much as the eyes look down
// (adding to eyeBlinkLeft/Right), up a little as they look up (eyeWideLeft/Right), on an
// avatar with those ARKit shapes. `eyeUpDeg`: the eyes' pitch in the head, + up.
void addLidFollow(float eyeUpDeg, const std::set<std::string>& targets, std::map<std::string, float>& face);

// [D] A shrug's elevation of the shoulder girdle at full weight: ~12° of the clavicle, about
// 30 mm at the shoulder joint (within the ~30–40° of clavicular elevation a shrug can reach).
inline constexpr float kShoulderRaiseMaxDeg = 12.0f;

struct SignerPosture {
    hand::HandControls rightHand, leftHand;
    // Body frame. Absent: the hand rests in front of the waist (restingTarget()).
    std::optional<hand::ArmTarget> rightWrist, leftWrist;
    std::optional<glm::vec3> gazeMm;  // body frame; absent: straight ahead
    // The head's yaw and pitch (degrees, hand::GazePose) while it follows the eyes toward
    // gazeMm at its own pace; absent: where hand::solveGaze puts it for gazeMm.
    std::optional<glm::vec2> headDeg;
    // Where each elbow should be (hand::ArmPose::elbowDirection, body frame), blended from the
    // elbows the clip's keys give: the arm solver looks for the swivel within
    // kElbowHintWindowDeg of it (or takes it, follow*ElbowHint). Absent: the solver's rule of
    // the target alone.
    std::optional<glm::vec3> rightElbowHint, leftElbowHint;
    // The elbows at the hints themselves, no search (a clip's elbow track, signer/elbow_track.hpp).
    bool followRightElbowHint = false, followLeftElbowHint = false;
    NonManualPosture nonManual;  // face, head, torso and shoulders
};

// [D] How far from a posture's elbow hint the arm solver may swing the elbow (unless it follows it).
inline constexpr float kElbowHintWindowDeg = 20.0f;

struct PoseReport {
    hand::ArmPose right, left;
    hand::GazePose gaze;
};

class ArmMemo;    // signer/arm_memo.hpp
class PacerMemo;  // signer/arm_memo.hpp

class SignerRig {
public:
    // Finds every required bone (VRM names, or `mapping` VRM -> node name). Throws InputError
    // naming the bone-map file, line and entry when an entry names a node the scene lacks;
    // else naming the scene and listing all missing bones.
    explicit SignerRig(const render::Scene& scene, const BoneMapping& mapping = {},
                       const hand::HandModel& handModel = hand::buildHandModel());

    const hand::ArmModel& arm(hand::Side side) const { return arms_[side == hand::Side::Right ? 0 : 1]; }
    const hand::GazeModel& gaze() const { return gaze_; }
    const hand::HandModel& handModel() const { return handModel_; }

    // A body-frame point (mm) in world coordinates (metres).
    glm::vec3 worldFromBodyMm(const glm::vec3& bodyMm) const { return bodyOriginM_ + bodyMm * 0.001f; }
    // The avatar's hand size relative to the hand model's: rest distance from the right wrist
    // to the middle knuckle over the model's (1 for the default signer).
    float handScale() const { return handScale_; }

    // The avatar node of a VRM humanoid bone ("head", "rightHand"), -1 when the avatar has none
    // (screen regions, signer/screen_regions.hpp, find the parts of the mesh by it).
    int boneNode(const std::string& vrmName) const { return node(vrmName); }
    // Where an unused hand rests: in front of the waist, palm in.
    hand::ArmTarget restingTarget(hand::Side side) const;
    // A comfortable default for a hand being shown: beside the shoulder, palm toward the
    // viewer, fingers up (where fingerspelling happens).
    hand::ArmTarget presentingTarget(hand::Side side) const;

    // The pose for one frame: a function of the posture alone (no previous frame; the elbows
    // follow hand::solveArm's rule of the target). `report` receives reach/limit information.
    render::Pose pose(const SignerPosture& posture, PoseReport* report = nullptr) const;
    // One arm's solution as pose() finds it (ArmPose of PoseReport), without posing the
    // skeleton: cheap enough to look ahead along a clip.
    hand::ArmPose solveArm(hand::Side side, const SignerPosture& posture) const;
    // Where solveArm puts the wrist (its wristMm, the same bits) without seeking the elbow
    // (hand::reachedWristMm): for what needs the wrists alone, as the transition pacer.
    glm::vec3 reachedWristMm(hand::Side side, const SignerPosture& posture) const;
    // What the transition pacers of this rig (and its copies) found (signer/transition_pacer.cpp).
    PacerMemo& pacerMemo() const { return *pacerMemo_; }
    // The head and eyes as pose() turns them (straight ahead without a gaze point).
    hand::GazePose solveGazeAt(const SignerPosture& posture) const;

private:
    struct Bone {
        int node = -1;
        glm::quat canonicalRest{1.0f, 0.0f, 0.0f, 0.0f};
        glm::quat restCorrection{1.0f, 0.0f, 0.0f, 0.0f};  // Δ: canonical rest -> this avatar's rest
    };
    void measureRestPose(const std::vector<glm::mat4>& restWorld);
    int node(const std::string& vrmName) const;

    const render::Scene* scene_;
    hand::HandModel handModel_;
    std::map<std::string, Bone> bones_;      // VRM name -> node, for the bones present
    std::vector<glm::quat> restWorldRotation_;
    std::array<hand::ArmModel, 2> arms_;     // right, left
    hand::GazeModel gaze_;
    glm::vec3 bodyOriginM_{0.0f};            // chest, world metres
    float handScale_ = 1.0f;
    std::set<std::string> morphTargets_;     // every morph target name of the avatar
    std::array<std::optional<glm::vec3>, 2> shoulderBoneMm_;  // right, left shoulder bones, body frame
    float neckLengthMm_ = 90.0f;             // neck bone to head bone
    float torsoLengthMm_ = 300.0f;           // spine bone to the shoulder joints' midpoint
    // The solutions solveArm gave (shared by copies of the rig: its key holds every input).
    std::shared_ptr<ArmMemo> armMemo_;
    std::shared_ptr<PacerMemo> pacerMemo_;
    // The arm model with the shoulder joint where the raised shoulder bone carries it.
    hand::ArmModel raisedArm(hand::Side side, const NonManualPosture& nonManual) const;
};

}  // namespace signstim::signer
