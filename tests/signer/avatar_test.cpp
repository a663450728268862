// The default signer: VRM skeleton, hand bones = the McDonald hand, smooth skin weights, and
// no cracks, stretching or candy-wrapper collapse when skinned at extreme poses.
#include "signer/avatar_builder.hpp"
#include "signer/signer_pose.hpp"
#include "hand/hand_model.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

using namespace signstim;

namespace {

const render::Scene& avatar() {
    static const render::Scene scene = signer::buildDefaultAvatar();
    return scene;
}

std::vector<glm::vec3> skinnedPositions(const render::Scene& scene, const render::Pose& pose,
                                        const render::Primitive& prim) {
    std::vector<glm::mat4> world, joints;
    render::computeWorldTransforms(scene, pose, world);
    render::computeJointMatrices(scene, 0, world, joints);
    std::vector<glm::vec3> out;
    out.reserve(prim.vertices.size());
    for (const render::Vertex& v : prim.vertices) {
        glm::mat4 m(0.0f);
        for (int k = 0; k < 4; ++k) m += v.weights[k] * joints[v.joints[k]];
        out.push_back(glm::vec3(m * glm::vec4(v.position, 1.0f)));
    }
    return out;
}

std::set<std::pair<std::uint32_t, std::uint32_t>> edges(const render::Primitive& prim) {
    std::set<std::pair<std::uint32_t, std::uint32_t>> e;
    for (std::size_t t = 0; t + 2 < prim.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            std::uint32_t a = prim.indices[t + k], b = prim.indices[t + (k + 1) % 3];
            e.insert({std::min(a, b), std::max(a, b)});
        }
    return e;
}

hand::HandControls fist() {
    hand::HandControls c;
    for (auto& f : c.fingers) { f.bend = 1.0f; f.hook = 1.0f; }
    c.thumb = {100.0f, 35.0f, 60.0f, 80.0f};
    return c;
}

}  // namespace

TEST(Avatar, SkeletonHasEveryVrmBoneInTheHumanoidHierarchy) {
    const render::Scene& s = avatar();
    for (const std::string& name : signer::requiredAvatarBones()) EXPECT_GE(s.findNode(name), 0) << name;
    const auto parentName = [&](const char* child) { return s.nodes[s.nodes[s.findNode(child)].parent].name; };
    EXPECT_EQ(parentName("rightHand"), "rightLowerArm");
    EXPECT_EQ(parentName("rightLowerArm"), "rightUpperArm");
    EXPECT_EQ(parentName("leftUpperArm"), "leftShoulder");
    EXPECT_EQ(parentName("head"), "neck");
    EXPECT_EQ(parentName("leftIndexDistal"), "leftIndexIntermediate");
    EXPECT_EQ(parentName("rightThumbMetacarpal"), "rightHand");
    ASSERT_EQ(s.skins.size(), 1u);
    EXPECT_EQ(s.materials.size(), 9u);  // skin, top, eye white, iris, hair, lips, nail, pupil, mouth
    // The posing code accepts it as it is.
    EXPECT_NO_THROW(signer::SignerRig rig(s));
}

TEST(Avatar, HandBonesAreTheHandModelsBodiesAtItsDimensions) {
    const render::Scene& s = avatar();
    const hand::HandModel model = hand::buildHandModel();
    std::vector<glm::mat4> world;
    render::computeWorldTransforms(s, render::restPose(s), world);
    for (hand::Side side : {hand::Side::Right, hand::Side::Left}) {
        const auto rest = hand::restLocalTransforms(model, side);
        const auto info = hand::handBones(side);
        for (int b = 1; b < hand::kBodyCount; ++b) {
            const render::Node& n = s.nodes[s.findNode(info[b].name)];
            EXPECT_LT(glm::length(n.rest.translation - rest[b].position * 0.001f), 1e-6f) << info[b].name;
            EXPECT_GT(std::fabs(glm::dot(n.rest.rotation, rest[b].rotation)), 1.0f - 1e-6f) << info[b].name;
        }
        // The hand bone's frame is the palm frame of the T-pose: +z along the arm, +x down.
        const glm::mat4& palm = world[s.findNode(info[0].name)];
        const float out = side == hand::Side::Right ? -1.0f : 1.0f;
        EXPECT_GT(glm::dot(glm::normalize(glm::vec3(palm[2])), glm::vec3(out, 0, 0)), 0.9999f);
        EXPECT_GT(glm::dot(glm::normalize(glm::vec3(palm[0])), glm::vec3(0, -1, 0)), 0.9999f);
    }
}

TEST(Avatar, SkinWeightsSumToOneAndChangeSmoothlyAcrossEdges) {
    const render::Scene& s = avatar();
    const auto jointCount = static_cast<unsigned>(s.skins[0].joints.size());
    std::size_t vertices = 0;
    float worstStep = 0.0f;
    for (const render::Primitive& p : s.meshes[0].primitives) {
        ASSERT_TRUE(p.skinned);
        for (const render::Vertex& v : p.vertices) {
            EXPECT_NEAR(v.weights.x + v.weights.y + v.weights.z + v.weights.w, 1.0f, 1e-5f);
            for (int k = 0; k < 4; ++k) {
                EXPECT_GE(v.weights[k], 0.0f);
                EXPECT_LT(v.joints[k], jointCount);
            }
        }
        vertices += p.vertices.size();
        for (auto [a, b] : edges(p)) {
            std::map<unsigned, float> diff;
            for (int k = 0; k < 4; ++k) {
                diff[p.vertices[a].joints[k]] += p.vertices[a].weights[k];
                diff[p.vertices[b].joints[k]] -= p.vertices[b].weights[k];
            }
            float l1 = 0.0f;
            for (auto [j, d] : diff) l1 += std::fabs(d);
            worstStep = std::max(worstStep, l1);
        }
    }
    EXPECT_GT(vertices, 5000u);
    // A rigid seam between two bones would be a step of 2.
    EXPECT_LT(worstStep, 0.8f);
}

TEST(Avatar, NoEdgeStretchesOrCollapsesAtExtremePoses) {
    const render::Scene& s = avatar();
    const signer::SignerRig rig(s);
    // Elbows at their flexion limit, wrists flexed to the limit, fists; then hands overhead.
    std::vector<signer::SignerPosture> postures(3);
    for (auto& p : postures) { p.rightHand = fist(); p.leftHand = fist(); }
    postures[0].rightWrist = hand::ArmTarget{rig.arm(hand::Side::Right).shoulderMm + glm::vec3(60, -60, 150),
                                             glm::quat(1, 0, 0, 0)};
    postures[1].rightWrist = hand::ArmTarget{{-150, 450, 200}, glm::quat(1, 0, 0, 0)};
    postures[1].leftWrist = hand::ArmTarget{{250, -100, 400}, glm::quat(0.7071f, 0.7071f, 0, 0)};
    for (const signer::SignerPosture& posture : postures) {
        signer::PoseReport report;
        const render::Pose pose = rig.pose(posture, &report);
        for (const render::Primitive& p : s.meshes[0].primitives) {
            const std::vector<glm::vec3> posed = skinnedPositions(s, pose, p);
            for (auto [a, b] : edges(p)) {
                const float rest = glm::length(p.vertices[a].position - p.vertices[b].position);
                const float now = glm::length(posed[a] - posed[b]);
                if (rest < 1e-5f) continue;
                EXPECT_LT(now / rest, 3.5f) << "edge " << a << "-" << b << " of material " << p.material
                                            << " at " << p.vertices[a].position.x << "," << p.vertices[a].position.y
                                            << "," << p.vertices[a].position.z << " bones "
                                            << s.nodes[p.vertices[a].joints[0]].name << "/"
                                            << s.nodes[p.vertices[b].joints[0]].name;
                if (now / rest >= 3.5f) return;
            }
        }
    }
}

TEST(Avatar, ForearmTwistDoesNotCandyWrap) {
    // Full pronation and full supination about the forearm axis (T-pose, so the twist is
    // pure): the sleeve keeps its girth all along the forearm.
    const render::Scene& s = avatar();
    const int lower = s.findNode("rightLowerArm"), handNode = s.findNode("rightHand");
    const int mid = s.findNode("rightForearmTwistMid"), wrist = s.findNode("rightForearmTwistWrist");
    std::vector<glm::mat4> restWorld;
    render::computeWorldTransforms(s, render::restPose(s), restWorld);
    const glm::vec3 er = restWorld[lower][3], wr = restWorld[handNode][3];
    const glm::vec3 axis = glm::normalize(wr - er);  // in the lower arm's frame too (identity rest)
    for (float degrees : {-85.0f, 90.0f}) {
        render::Pose pose = render::restPose(s);
        const float radians = degrees * 3.14159265f / 180.0f;
        pose.local[mid].rotation = glm::angleAxis(0.5f * radians, axis);
        pose.local[wrist].rotation = glm::angleAxis(radians, axis);
        pose.local[handNode].rotation = glm::angleAxis(radians, axis) * s.nodes[handNode].rest.rotation;
        float worst = 10.0f;
        int counted = 0;
        for (const render::Primitive& p : s.meshes[0].primitives) {
            if (p.material != 1) continue;  // the sleeve
            const std::vector<glm::vec3> posed = skinnedPositions(s, pose, p);
            for (std::size_t i = 0; i < posed.size(); ++i) {
                const glm::vec3 r = p.vertices[i].position - er;
                const float along = glm::dot(r, axis) / glm::length(wr - er);
                const float r0 = glm::length(r - glm::dot(r, axis) * axis);
                if (along < 0.15f || along > 0.95f || r0 > 0.06f) continue;  // forearm sleeve only
                const glm::vec3 q = posed[i] - er;
                const float r1 = glm::length(q - glm::dot(q, axis) * axis);
                worst = std::min(worst, r1 / r0);
                ++counted;
            }
        }
        EXPECT_GT(counted, 100);
        EXPECT_GT(worst, 0.9f) << "twist " << degrees;
        // Without the helper bones (all the twist at the wrist, linear weights) the middle of
        // the forearm would shrink to cos(45°) ≈ 0.71 — the candy wrapper this guards against.
    }
}

TEST(Avatar, FingerVolumeHoldsAtFullFlexion) {
    // A fist: every finger and thumb vertex keeps a good part of its rest distance from its
    // dominant bone (a collapsed knuckle would fold onto the bone axis).
    const render::Scene& s = avatar();
    const signer::SignerRig rig(s);
    signer::SignerPosture posture;
    posture.rightHand = fist();
    posture.rightWrist = rig.presentingTarget(hand::Side::Right);
    const render::Pose pose = rig.pose(posture);
    std::vector<glm::mat4> world, restWorld;
    render::computeWorldTransforms(s, pose, world);
    render::computeWorldTransforms(s, render::restPose(s), restWorld);
    const hand::HandModel model = hand::buildHandModel();
    const auto info = hand::handBones(hand::Side::Right);
    struct Segment { int node; float length; };
    std::map<unsigned, float> boneLength;  // finger joints -> bone length (m)
    for (int b = 1; b < hand::kBodyCount; ++b)
        boneLength[static_cast<unsigned>(s.findNode(info[b].name))] =
            hand::boneLengthMm(model, static_cast<hand::Body>(b)) * 0.001f;
    // Distance from the vertex to its dominant bone's axis segment.
    const auto distance = [&](const std::vector<glm::mat4>& w, unsigned node, glm::vec3 p) {
        const glm::vec3 a = w[node][3];
        const glm::vec3 b = a + glm::normalize(glm::vec3(w[node][2])) * boneLength[node];
        const float t = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0f, 1.0f);
        return glm::length(p - (a + t * (b - a)));
    };
    const render::Primitive& skin = s.meshes[0].primitives[0];
    ASSERT_EQ(skin.material, 0);
    const std::vector<glm::vec3> posed = skinnedPositions(s, pose, skin);
    float worst = 10.0f;
    int counted = 0;
    for (std::size_t i = 0; i < posed.size(); ++i) {
        const render::Vertex& v = skin.vertices[i];
        if (!boneLength.count(v.joints[0]) || v.weights[0] < 0.5f) continue;
        const float r0 = distance(restWorld, v.joints[0], v.position);
        if (r0 < 0.003f) continue;  // caps near the axis
        worst = std::min(worst, distance(world, v.joints[0], posed[i]) / r0);
        ++counted;
    }
    EXPECT_GT(counted, 500);
    // Linear blend skinning squeezes the palmar side of a knuckle bent 90° or more (like the
    // skin crease of a real fist) to ~30 % of its rest thickness; a collapse goes to ~0.
    EXPECT_GT(worst, 0.25f);
}

TEST(Avatar, EveryDigitHasANailOnTheBackOfItsDistalBoneSkinnedRigidlyToIt) {
    // Nails make the back of a finger read as the back in a front view. Each lies on the
    // dorsal side (-x of the bone frame: +x is palmar) of its distal phalanx, moves with it
    // only, and the skin tone differs palm to back (texture coordinate u: back 0.25, palm 0.75).
    const render::Scene& s = avatar();
    const render::Primitive* nails = nullptr;
    for (const render::Primitive& p : s.meshes[0].primitives)
        if (p.material >= 0 && s.materials[static_cast<std::size_t>(p.material)].name == "nail") nails = &p;
    ASSERT_NE(nails, nullptr);
    std::vector<glm::mat4> world;
    render::computeWorldTransforms(s, render::restPose(s), world);
    std::map<unsigned, int> perBone;
    for (const render::Vertex& v : nails->vertices) {
        ASSERT_FLOAT_EQ(v.weights[0], 1.0f);
        ++perBone[v.joints[0]];
        const glm::mat4& bone = world[v.joints[0]];
        const glm::vec3 local = glm::vec3(glm::inverse(bone) * glm::vec4(v.position, 1.0f)) * 1000.0f;  // mm
        EXPECT_LT(local.x, -3.0f) << s.nodes[v.joints[0]].name;  // dorsal, not inside the finger's axis
        EXPECT_GT(local.z, 0.0f) << s.nodes[v.joints[0]].name;   // beyond the DIP/IP joint
    }
    ASSERT_EQ(perBone.size(), 10u);
    for (hand::Side side : {hand::Side::Right, hand::Side::Left})
        for (hand::Body distal : {hand::Body::ThumbDistal, hand::Body::IndexDistal, hand::Body::MiddleDistal,
                                  hand::Body::RingDistal, hand::Body::LittleDistal}) {
            const int node = s.findNode(std::string(hand::boneName(side, distal)));
            EXPECT_GT(perBone[static_cast<unsigned>(node)], 50) << hand::boneName(side, distal);
        }
    // Palm and back tones: the palm's centre is palm-toned, the back of the hand back-toned.
    const render::Primitive& skin = s.meshes[0].primitives[0];
    ASSERT_EQ(s.materials[0].baseColorTexture, 0);
    const int rightHand = s.findNode("rightHand");
    int palmar = 0, dorsal = 0;
    for (const render::Vertex& v : skin.vertices) {
        if (v.joints[0] != static_cast<unsigned>(rightHand) || v.weights[0] < 0.99f) continue;
        const glm::vec3 n = glm::vec3(glm::inverse(world[rightHand]) * glm::vec4(v.normal, 0.0f));
        if (n.x > 0.9f) { EXPECT_NEAR(v.uv.x, 0.75f, 1e-6f); ++palmar; }
        if (n.x < -0.9f) { EXPECT_NEAR(v.uv.x, 0.25f, 1e-6f); ++dorsal; }
    }
    EXPECT_GT(palmar, 10);
    EXPECT_GT(dorsal, 10);
}
