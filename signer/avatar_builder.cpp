#include "signer/avatar_builder.hpp"

#include "signer/avatar_mesh.hpp"

#include "hand/arm_ik.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <utility>

namespace signstim::signer {
namespace {
using namespace avatar_mesh;

// ---- skeleton --------------------------------------------------------------------------
struct SkeletonBuilder {
    render::Scene& scene;
    int add(const std::string& name, int parent, glm::vec3 translation,
            glm::quat rotation = glm::quat(1.0f, 0.0f, 0.0f, 0.0f)) {
        render::Node node;
        node.name = name;
        node.parent = parent;
        node.rest.translation = translation;
        node.rest.rotation = rotation;
        const int index = static_cast<int>(scene.nodes.size());
        scene.nodes.push_back(node);
        if (parent >= 0) scene.nodes[parent].children.push_back(index);
        else scene.roots.push_back(index);
        return index;
    }
};

std::string sideName(hand::Side side) { return side == hand::Side::Right ? "right" : "left"; }

// Materials (linear RGB). Sign-language video practice: a plain dark top, skin that contrasts
// with it, a plain background and even light (the renderer's defaults).
std::vector<render::Material> avatarMaterials() {
    const auto make = [](const char* name, glm::vec3 color, float roughness) {
        render::Material m;
        m.name = name;
        m.baseColorFactor = glm::vec4(color, 1.0f);
        m.metallicFactor = 0.0f;
        m.roughnessFactor = roughness;
        return m;
    };
    render::Material skin = make("skin", {1.0f, 1.0f, 1.0f}, 0.65f);
    skin.baseColorTexture = 0;  // skinToneTexture(): back (0.56, 0.33, 0.22), palm lighter
    return {skin,
            make("top", {0.018f, 0.020f, 0.028f}, 0.85f),
            make("eyeWhite", {0.78f, 0.77f, 0.74f}, 0.35f),
            make("iris", {0.16f, 0.09f, 0.045f}, 0.3f),  // brown, lighter than the pupil
            make("hair", {0.022f, 0.015f, 0.011f}, 0.75f),
            make("lips", {0.36f, 0.12f, 0.10f}, 0.5f),
            // Paler and pinker than the skin, a little glossy: the back of a finger reads
            // as the back (from the front a curled finger's back otherwise looks like a palm).
            make("nail", {0.72f, 0.47f, 0.42f}, 0.45f),
            make("pupil", {0.022f, 0.015f, 0.011f}, 0.3f),
            // The inside of the mouth seen between parted lips: dark, unlit-looking.
            make("mouth", {0.045f, 0.012f, 0.012f}, 0.9f)};
}

std::uint8_t srgbByte(float linear) {
    const float s = linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
    return static_cast<std::uint8_t>(std::lround(std::clamp(s, 0.0f, 1.0f) * 255.0f));
}

// The skin tones (linear RGB; stored sRGB as glTF base-colour textures are).
void addSkinToneTexture(render::Scene& scene) {
    const glm::vec3 back{0.56f, 0.33f, 0.22f}, palm{0.66f, 0.38f, 0.29f};
    render::ImageData image;
    image.name = "skinTone";
    image.width = 2;
    image.height = 1;
    for (const glm::vec3& c : {back, palm})
        image.rgba.insert(image.rgba.end(), {srgbByte(c.r), srgbByte(c.g), srgbByte(c.b), 255});
    scene.images.push_back(std::move(image));
    render::Texture texture;
    texture.image = 0;
    texture.mipmaps = false;
    texture.wrapS = texture.wrapT = render::Wrap::ClampToEdge;
    scene.textures.push_back(texture);
}

}  // namespace

const std::vector<std::string>& requiredAvatarBones() {
    static const std::vector<std::string> bones = [] {
        std::vector<std::string> b{"hips", "spine", "chest", "neck", "head"};
        for (hand::Side side : {hand::Side::Left, hand::Side::Right}) {
            const std::string s = sideName(side);
            for (const char* part : {"Shoulder", "UpperArm", "LowerArm"}) b.push_back(s + part);
            for (const auto& bone : hand::handBones(side)) b.emplace_back(bone.name);
        }
        return b;
    }();
    return bones;
}

render::Scene buildDefaultAvatar(const AvatarDimensions& d) {
    render::Scene scene;
    scene.sourceName = "signstim default signer";
    SkeletonBuilder sk{scene};
    const int hips = sk.add("hips", -1, d.hipsM);
    const int spine = sk.add("spine", hips, {0.0f, 0.12f, 0.0f});
    const int chest = sk.add("chest", spine, d.chestM - d.hipsM - glm::vec3(0.0f, 0.12f, 0.0f));
    const int neck = sk.add("neck", chest, {0.0f, 0.15f, -0.01f});
    const int head = sk.add("head", neck, {0.0f, 0.09f, 0.01f});
    const glm::vec3 headWorld = d.chestM + glm::vec3(0.0f, 0.24f, 0.0f);
    // The eyeballs' fronts lie at the face's skin (z ≈ 0.098 here) under lids that stand ~3 mm
    // proud of it (avatar_face_mesh.cpp), inside the head's outline in profile (issue 21).
    const glm::vec3 eyeLocal{0.032f, 0.115f, 0.086f};
    const int leftEye = sk.add("leftEye", head, eyeLocal);
    const int rightEye = sk.add("rightEye", head, {-eyeLocal.x, eyeLocal.y, eyeLocal.z});

    const hand::HandModel handModel = hand::buildHandModel(d.hand);
    struct Arm {
        int shoulder, upper, lower, twistMid;
        HandBones hand;
        glm::vec3 shoulderJoint, wrist;
        glm::mat4 handWorld;
    };
    std::array<Arm, 2> arms{};
    for (hand::Side side : {hand::Side::Left, hand::Side::Right}) {
        const float sx = side == hand::Side::Left ? 1.0f : -1.0f;
        const std::string s = sideName(side);
        Arm& arm = arms[side == hand::Side::Left ? 0 : 1];
        arm.shoulder = sk.add(s + "Shoulder", chest, {sx * 0.04f, 0.11f, 0.0f});
        arm.upper = sk.add(s + "UpperArm", arm.shoulder,
                           glm::vec3(sx * d.shoulderOffsetM.x, d.shoulderOffsetM.y, d.shoulderOffsetM.z) -
                               glm::vec3(sx * 0.04f, 0.11f, 0.0f));
        arm.lower = sk.add(s + "LowerArm", arm.upper, {sx * d.upperArmM, 0.0f, 0.0f});
        arm.twistMid = sk.add(s + "ForearmTwistMid", arm.lower, {sx * d.forearmM * 0.5f, 0.0f, 0.0f});
        arm.hand.forearmTwistWrist = sk.add(s + "ForearmTwistWrist", arm.lower, {sx * d.forearmM, 0.0f, 0.0f});
        // The hand bone's frame is the palm frame (SPEC §1.1) in the T-pose: hand::restFrame.
        const glm::quat palmFrame = hand::restFrame(side);
        arm.hand.hand = sk.add(s + "Hand", arm.lower, {sx * d.forearmM, 0.0f, 0.0f}, palmFrame);
        arm.hand.body[0] = arm.hand.hand;
        const auto bonesInfo = hand::handBones(side);
        const auto rest = hand::restLocalTransforms(handModel, side);
        for (int b = 1; b < hand::kBodyCount; ++b) {
            const int parent = arm.hand.body[bonesInfo[b].parent];
            arm.hand.body[b] = sk.add(std::string(bonesInfo[b].name), parent, rest[b].position * kMmToM,
                                      glm::normalize(rest[b].rotation));
        }
        arm.shoulderJoint = d.chestM + glm::vec3(sx * d.shoulderOffsetM.x, d.shoulderOffsetM.y, d.shoulderOffsetM.z);
        arm.wrist = arm.shoulderJoint + glm::vec3(sx * (d.upperArmM + d.forearmM), 0.0f, 0.0f);
        arm.handWorld = glm::translate(glm::mat4(1.0f), arm.wrist) * glm::mat4_cast(palmFrame) *
                        glm::scale(glm::mat4(1.0f), glm::vec3(kMmToM));
    }
    const int boneCount = static_cast<int>(scene.nodes.size());

    // Skin: every node so far is a joint; joint index = node index.
    render::Skin skin;
    skin.name = "signer";
    skin.skeleton = hips;
    {
        render::Pose rest = render::restPose(scene);
        std::vector<glm::mat4> world;
        render::computeWorldTransforms(scene, rest, world);
        for (int i = 0; i < boneCount; ++i) {
            skin.joints.push_back(i);
            skin.inverseBindMatrices.push_back(glm::inverse(world[i]));
        }
    }

    MeshBuilder mesh;
    // Torso (dark top): superellipse sections from the hips to the shoulders.
    {
        struct Section { float y, halfWidth, halfDepth, z; };
        const std::vector<Section> sections{
            {0.86f, 0.165f, 0.105f, 0.0f},  {0.96f, 0.160f, 0.100f, 0.0f},
            {1.06f, 0.148f, 0.092f, 0.0f},  {1.16f, 0.150f, 0.097f, 0.004f},
            {1.24f, 0.160f, 0.105f, 0.008f}, {1.32f, 0.170f, 0.108f, 0.008f},
            {1.38f, 0.182f, 0.100f, 0.002f}, {1.42f, 0.184f, 0.090f, -0.004f},
            {1.455f, 0.170f, 0.075f, -0.008f}, {1.475f, 0.130f, 0.058f, -0.010f},
            {1.487f, 0.080f, 0.045f, -0.010f}};
        std::vector<Ring> rings;
        for (std::size_t i = 0; i + 1 < sections.size(); ++i) {
            for (int k = 0; k < 3; ++k) {
                const float t = static_cast<float>(k) / 3.0f;
                const Section& a = sections[i];
                const Section& b = sections[i + 1];
                Ring r;
                const float y = a.y + (b.y - a.y) * t;
                r.center = {0.0f, y, a.z + (b.z - a.z) * t};
                r.u = {0, 0, 1};
                r.v = {1, 0, 0};
                r.ru = a.halfDepth + (b.halfDepth - a.halfDepth) * t;
                r.rv = a.halfWidth + (b.halfWidth - a.halfWidth) * t;
                r.exponent = 2.6f;
                const Weights body = Weights::blend(
                    Weights::blend(Weights(hips), Weights(spine), smoothstep(0.96f, 1.12f, y)),
                    Weights(chest), smoothstep(1.16f, 1.30f, y));
                r.weights = body;
                // Shoulder tops follow the upper arms a little (rounded deltoid).
                r.adjust = [body, &arms, y](glm::vec3& p, Weights& w, float, float) {
                    const int armIndex = p.x > 0.0f ? 0 : 1;
                    const float reach = smoothstep(0.13f, 0.18f, std::fabs(p.x)) * smoothstep(1.36f, 1.42f, y);
                    w = Weights::blend(body, Weights(arms[armIndex].upper), 0.35f * reach);
                };
                rings.push_back(r);
            }
        }
        Ring top;
        top.center = {0.0f, sections.back().y, sections.back().z};
        top.u = {0, 0, 1};
        top.v = {1, 0, 0};
        top.ru = sections.back().halfDepth;
        top.rv = sections.back().halfWidth;
        top.exponent = 2.6f;
        top.weights = Weights(chest);
        rings.push_back(top);
        mesh.tube(kTop, rings, 32, 0.0f, 0.004f);
    }
    // Neck (skin) from inside the torso into the head.
    {
        std::vector<Ring> rings;
        for (float y = 1.40f; y <= 1.605f; y += 0.015f) {
            Ring r;
            r.center = {0.0f, y, -0.008f + 0.01f * smoothstep(1.45f, 1.58f, y)};
            r.u = {0, 0, 1};
            r.v = {1, 0, 0};
            r.ru = 0.050f - 0.006f * smoothstep(1.45f, 1.6f, y);
            r.rv = 0.054f - 0.006f * smoothstep(1.45f, 1.6f, y);
            r.weights = Weights::blend(Weights::blend(Weights(chest), Weights(neck), smoothstep(1.42f, 1.48f, y)),
                                       Weights(head), smoothstep(1.52f, 1.58f, y));
            rings.push_back(r);
        }
        mesh.tube(kSkin, rings, 20, 0.0f, 0.0f);
    }
    // Head: the hair cap, the eyeballs and the ears here; the face (skin, brows, lids, nose,
    // mouth) is a mesh of its own with the morph targets (avatar_face_mesh.cpp).
    {
        const glm::vec3 c = headWorld + glm::vec3(0.0f, 0.10f, 0.012f);  // skull centre
        const glm::mat3 axesYUp(glm::vec3(1, 0, 0), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
        const glm::mat3 front(glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1));
        // Hair: a cap over the top and back, leaving the forehead and face clear.
        mesh.ellipsoid(kHair, c + glm::vec3(0.0f, 0.022f, -0.016f), {0.083f, 0.098f, 0.100f},
                       axesYUp, Weights(head), 28, 18, [](glm::vec3& local) {
                           if (local.z < 0.0f) local.z *= 0.55f;  // ends above the ears
                       });
        for (int e = 0; e < 2; ++e) {
            const float sx = e == 0 ? 1.0f : -1.0f;
            const int eyeBone = e == 0 ? leftEye : rightEye;
            const glm::vec3 eye = headWorld + glm::vec3(sx * eyeLocal.x, eyeLocal.y, eyeLocal.z);
            const float r = kEyeballRadiusM;
            mesh.ellipsoid(kEyeWhite, eye, glm::vec3(r), front, Weights(eyeBone), 16, 10);
            mesh.ellipsoid(kIris, eye + glm::vec3(0.0f, 0.0f, 0.76f * r), {0.54f * r, 0.54f * r, 0.33f * r},
                           front, Weights(eyeBone), 16, 8);
            // Pupil: dark, in front of the iris, turning with it.
            mesh.ellipsoid(kPupil, eye + glm::vec3(0.0f, 0.0f, 0.97f * r), {0.23f * r, 0.23f * r, 0.14f * r}, front,
                           Weights(eyeBone), 12, 6);
            // Ear.
            mesh.ellipsoid(kSkin, c + glm::vec3(sx * 0.077f, -0.012f, -0.004f), {0.010f, 0.027f, 0.016f},
                           front, Weights(head), 12, 8);
        }
    }
    // Arms: one continuous sleeve per arm from a round shoulder to the wrist cuff; the skin
    // blends across the elbow and spreads the forearm's twist over two helper bones.
    for (const Arm& arm : arms) {
        const float sx = arm.wrist.x > 0.0f ? 1.0f : -1.0f;
        const glm::vec3 axis{sx, 0.0f, 0.0f};
        const glm::vec3 u{0, 1, 0};
        const glm::vec3 v = glm::cross(axis, u);  // u × v = axis
        const float elbowT = d.upperArmM, wristT = d.upperArmM + d.forearmM;
        const auto radiusAt = [&](float t) {
            const float r0 = 0.050f, rElbow = 0.038f, rForearm = 0.040f, rWrist = 0.029f;
            if (t < elbowT) return r0 + (rElbow - r0) * smoothstep(0.0f, elbowT, t);
            const float f = (t - elbowT) / d.forearmM;
            return f < 0.3f ? rElbow + (rForearm - rElbow) * smoothstep(0.0f, 0.3f, f)
                            : rForearm + (rWrist - rForearm) * smoothstep(0.3f, 1.0f, f);
        };
        const auto weightsAt = [&](float t) {
            const float elbowBlend = smoothstep(elbowT - 0.04f, elbowT + 0.04f, t);
            const float f = std::clamp((t - elbowT) / d.forearmM, 0.0f, 1.0f);
            Weights fore = f < 0.5f ? Weights::blend(Weights(arm.lower), Weights(arm.twistMid), f / 0.5f)
                                    : Weights::blend(Weights(arm.twistMid), Weights(arm.hand.forearmTwistWrist),
                                                     (f - 0.5f) / 0.5f);
            return Weights::blend(Weights(arm.upper), fore, elbowBlend);
        };
        std::vector<Ring> rings;
        const float r0 = radiusAt(0.0f);
        for (int k = 4; k >= 1; --k) {  // round shoulder: a hemisphere about the joint
            const float a = 0.5f * kPi * static_cast<float>(k) / 5.0f;
            Ring r;
            r.center = arm.shoulderJoint - axis * (r0 * std::sin(a));
            r.u = u;
            r.v = v;
            r.ru = r.rv = r0 * std::cos(a);
            r.weights = Weights(arm.upper);
            rings.push_back(r);
        }
        const float cuffT = wristT - 0.012f;
        for (float t = 0.0f; t < cuffT; t += 0.012f) {
            Ring r;
            r.center = arm.shoulderJoint + axis * t;
            r.u = u;
            r.v = v;
            const float rad = radiusAt(t);
            r.ru = rad;
            r.rv = rad * (t > elbowT ? 1.0f - 0.12f * smoothstep(elbowT, wristT, t) : 1.0f);
            r.weights = weightsAt(t);
            rings.push_back(r);
        }
        for (float extra : {0.0f, 0.003f}) {  // cuff: a short flat end
            Ring r;
            r.center = arm.shoulderJoint + axis * (cuffT + extra);
            r.u = u;
            r.v = v;
            r.ru = radiusAt(cuffT) + 0.002f - extra;
            r.rv = r.ru * 0.9f;
            r.weights = weightsAt(cuffT);
            rings.push_back(r);
        }
        mesh.tube(kTop, rings, 20, r0 * (1.0f - std::sin(0.4f * kPi)) + 0.001f, 0.0f);
        // Elbow filler: keeps the inside of a sharply bent elbow from looking hollow.
        mesh.ellipsoid(kTop, arm.shoulderJoint + axis * elbowT, glm::vec3(0.034f), glm::mat3(1.0f),
                       Weights(arm.lower), 16, 10);
        buildHand(mesh, handModel, sx > 0.0f ? hand::Side::Left : hand::Side::Right, arm.handWorld, arm.hand);
    }

    render::Mesh body;
    body.name = "signer";
    body.primitives = mesh.finish();
    scene.meshes.push_back(std::move(body));
    scene.meshes.push_back(buildFaceMesh(headWorld, eyeLocal, head));
    scene.materials = avatarMaterials();
    addSkinToneTexture(scene);
    scene.skins.push_back(std::move(skin));
    render::Node meshNode;
    meshNode.name = "signerMesh";
    meshNode.mesh = 0;
    meshNode.skin = 0;
    scene.nodes.push_back(meshNode);
    scene.roots.push_back(static_cast<int>(scene.nodes.size()) - 1);
    render::Node faceNode;
    faceNode.name = "signerFace";
    faceNode.mesh = 1;
    faceNode.skin = 0;
    scene.nodes.push_back(faceNode);
    scene.roots.push_back(static_cast<int>(scene.nodes.size()) - 1);
    return scene;
}

}  // namespace signstim::signer
