#pragma once
// The default signer re-exported differently, as another tool would: a node's rest pose
// turned (A-pose arms, palms down, curled fingers), or the whole avatar turned about +Y.
// For the bring-your-own-avatar tests.
#include "renderer/scene.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/trigonometric.hpp>

#include <string>
#include <vector>

namespace signstim::test {

// Rotates node n's rest pose by `worldTurn` (a rotation in world coordinates about the node's
// own joint), keeping its children where they are relative to it: a different rest pose of the
// same skeleton, as another tool would export it.
inline void turnRest(render::Scene& s, const std::string& name, const glm::quat& worldTurn) {
    const int n = s.findNode(name);
    ASSERT_GE(n, 0) << name;
    std::vector<glm::mat4> world;
    render::computeWorldTransforms(s, render::restPose(s), world);
    const glm::quat parentWorld =
        s.nodes[n].parent < 0 ? glm::quat(1, 0, 0, 0) : glm::normalize(glm::quat_cast(glm::mat3(world[s.nodes[n].parent])));
    s.nodes[n].rest.rotation = glm::normalize(glm::inverse(parentWorld) * worldTurn * parentWorld * s.nodes[n].rest.rotation);
}

// Turns the whole avatar: every root node's rest transform, about the world origin.
inline void turnRoots(render::Scene& s, const glm::quat& turn) {
    for (render::Node& n : s.nodes) {
        if (n.parent >= 0) continue;
        n.rest.translation = turn * n.rest.translation;
        n.rest.rotation = glm::normalize(turn * n.rest.rotation);
    }
}


// Swings node `name`'s rest pose by `degrees` about the axis closest to `hint` that is
// perpendicular to the bone (toward `child`): a change of rest pose that joint positions
// show. (A turn about a bone's own axis is not visible in them; SignerRig measures only the
// hand's whole frame, see signer/signer_pose.hpp.)
inline void swingRest(render::Scene& s, const std::string& name, const std::string& child, const glm::vec3& hint,
                      float degrees) {
    std::vector<glm::mat4> world;
    render::computeWorldTransforms(s, render::restPose(s), world);
    const glm::vec3 along = glm::normalize(glm::vec3(world[s.findNode(child)][3]) - glm::vec3(world[s.findNode(name)][3]));
    const glm::vec3 axis = glm::normalize(hint - glm::dot(hint, along) * along);
    turnRest(s, name, glm::angleAxis(glm::radians(degrees), axis));
}

// Turns `side`'s palm in the rest pose by `degrees` about its forearm, as an avatar modelled
// so would be: the hand, and the wrist end of the forearm with it (the twist bones: all of it
// at the wrist, half at the middle, when `twistBones`), the elbow end not.
inline void rollPalmInRest(render::Scene& s, const std::string& side, float degrees, bool twistBones = true) {
    std::vector<glm::mat4> world;
    render::computeWorldTransforms(s, render::restPose(s), world);
    const glm::vec3 forearm = glm::normalize(glm::vec3(world[s.findNode(side + "Hand")][3]) -
                                             glm::vec3(world[s.findNode(side + "LowerArm")][3]));
    turnRest(s, side + "Hand", glm::angleAxis(glm::radians(degrees), forearm));
    if (!twistBones) return;
    turnRest(s, side + "ForearmTwistWrist", glm::angleAxis(glm::radians(degrees), forearm));
    turnRest(s, side + "ForearmTwistMid", glm::angleAxis(glm::radians(0.5f * degrees), forearm));
}

// The default signer with a different rest pose: arms 40° down (A-pose), the right forearm
// swung forward and its hand turned palm down about the forearm, fingers curled and splayed.
// Every turn is one SignerRig can see in the skeleton, so the posed skin must match the
// default signer's.
inline void useAnotherRestPose(render::Scene& s) {
    const glm::vec3 forward(0, 0, 1), up(0, 1, 0);
    swingRest(s, "leftUpperArm", "leftLowerArm", forward, -40.0f);
    swingRest(s, "rightUpperArm", "rightLowerArm", forward, 40.0f);
    swingRest(s, "rightLowerArm", "rightHand", up, 15.0f);
    rollPalmInRest(s, "right", 90.0f);  // palm down
    swingRest(s, "rightIndexProximal", "rightIndexIntermediate", forward, 30.0f);
    swingRest(s, "rightIndexIntermediate", "rightIndexDistal", up, 25.0f);
    swingRest(s, "leftLittleProximal", "leftLittleIntermediate", up, -20.0f);
    swingRest(s, "leftThumbProximal", "leftThumbDistal", up, 35.0f);
}

}  // namespace signstim::test
