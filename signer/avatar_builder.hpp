#pragma once
// The default signer avatar, generated procedurally (`signstim avatar build`), and the
// skeleton contract every avatar (default or the user's own) must meet.
//
// Skeleton: VRM humanoid bone names. Rest posture: T-pose, facing +Z, +Y up, the signer's left
// toward +X, palms down, fingers straight; glTF units (metres). Body bones and arm bones
// have identity rest rotations; the 16 bones of each hand ARE the McDonald hand's bodies
// (hand/hand_model.hpp) at its dimensions: the hand bone's frame is the palm frame (SPEC
// §1.1) and each finger bone's local transform is the model's rest local transform (mm ->
// m). Two non-VRM helper bones per forearm spread the forearm's pronation along it so the
// skin does not twist like a candy wrapper: `<side>ForearmTwistMid` (half the rotation,
// at mid-forearm) and `<side>ForearmTwistWrist` (all of it, at the wrist).
#include "hand/hand_model.hpp"
#include "renderer/scene.hpp"

#include <string>
#include <vector>

namespace signstim::signer {

struct AvatarDimensions {
    // [S] Drillis & Contini segment ratios, stature 1750 mm; shoulder joint centres 175 mm
    // from the midline. Chest bone = origin of the body frame of hand/arm_ik.hpp.
    float statureM = 1.75f;
    glm::vec3 hipsM{0.0f, 1.00f, 0.0f};
    glm::vec3 chestM{0.0f, 1.30f, 0.0f};
    glm::vec3 shoulderOffsetM{0.175f, 0.13f, 0.0f};  // from the chest, left side (+x)
    float upperArmM = 0.325f;
    float forearmM = 0.255f;
    hand::HandDimensions hand = hand::scaledHandDimensions();
};

// VRM humanoid bones the posing code needs, in parent-before-child order.
const std::vector<std::string>& requiredAvatarBones();

// The default avatar. Deterministic: the same build gives the same scene, bit for bit.
render::Scene buildDefaultAvatar(const AvatarDimensions& dimensions = {});

}  // namespace signstim::signer
