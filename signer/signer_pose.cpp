#include "signer/signer_pose.hpp"
#include "signer/arm_memo.hpp"

#include "signer/avatar_face.hpp"
#include "stimuli/json_source.hpp"

#include "common/error.hpp"
#include "renderer/gltf_loader.hpp"

#include <nlohmann/json.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

namespace signstim::signer {
namespace {

constexpr float kMToMm = 1000.0f;
constexpr float kDeg = 3.14159265358979323846f / 180.0f;

glm::quat frameFromAxes(glm::vec3 x, glm::vec3 z) {
    z = glm::normalize(z);
    x = glm::normalize(x - glm::dot(x, z) * z);
    return glm::normalize(glm::quat_cast(glm::mat3(x, glm::cross(z, x), z)));
}

// The left hand's frame is the mirror of the right's (SPEC §1.1): body mirror x -> -x, and
// the frame's own y -> -y.
glm::quat mirrorHandRotation(const glm::quat& q) {
    const glm::mat3 body(glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1));
    const glm::mat3 frame(glm::vec3(1, 0, 0), glm::vec3(0, -1, 0), glm::vec3(0, 0, 1));
    return glm::normalize(glm::quat_cast(body * glm::mat3_cast(q) * frame));
}

std::string sideName(hand::Side side) { return side == hand::Side::Right ? "right" : "left"; }

// The node of a VRM bone: through `mapping` when it names one, else the VRM name itself.
int findBone(const render::Scene& scene, const BoneMapping& mapping, const std::string& vrm) {
    const auto it = mapping.nodes.find(vrm);
    return scene.findNode(it != mapping.nodes.end() ? it->second : vrm);
}

// Keys a bone map may have: the VRM 1.0 humanoid bones (and VRM 0.x's thumb names), and the
// forearm twist helpers the rig uses when present. Anything else is a typo that would
// otherwise be ignored silently.
bool isKnownBoneName(const std::string& name) {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n{"hips", "spine", "chest", "upperChest", "neck", "head", "leftEye", "rightEye", "jaw"};
        for (const char* side : {"left", "right"}) {
            const std::string s = side;
            for (const char* part : {"UpperLeg", "LowerLeg", "Foot", "Toes", "Shoulder", "UpperArm", "LowerArm",
                                     "ForearmTwistMid", "ForearmTwistWrist", "Hand", "ThumbMetacarpal",
                                     "ThumbProximal", "ThumbIntermediate", "ThumbDistal"})
                n.push_back(s + part);
            for (const char* finger : {"Index", "Middle", "Ring", "Little"})
                for (const char* joint : {"Proximal", "Intermediate", "Distal"}) n.push_back(s + finger + joint);
        }
        return n;
    }();
    return std::find(names.begin(), names.end(), name) != names.end();
}

// The shortest rotation taking direction a onto direction b.
glm::quat swingBetween(glm::vec3 a, glm::vec3 b) {
    a = glm::normalize(a);
    b = glm::normalize(b);
    const float c = glm::dot(a, b);
    if (c < -1.0f + 1e-6f) {  // opposite: half a turn about any perpendicular axis
        glm::vec3 axis = glm::cross(a, glm::vec3(1.0f, 0.0f, 0.0f));
        if (glm::length(axis) < 1e-3f) axis = glm::cross(a, glm::vec3(0.0f, 1.0f, 0.0f));
        return glm::angleAxis(180.0f * kDeg, glm::normalize(axis));
    }
    const glm::vec3 axis = glm::cross(a, b);
    return glm::normalize(glm::quat(1.0f + c, axis.x, axis.y, axis.z));  // half-angle form
}

// A rest pose this close to the canonical one is the canonical one: the default signer is
// built in it and differs only by float rounding, which must not perturb its output.
constexpr float kRestToleranceDeg = 0.05f;

glm::quat rotationOf(const glm::mat4& m) {
    return glm::normalize(glm::quat_cast(glm::mat3(glm::normalize(glm::vec3(m[0])), glm::normalize(glm::vec3(m[1])),
                                                   glm::normalize(glm::vec3(m[2])))));
}

}  // namespace

const std::vector<std::string>& requiredSignerBones() {
    static const std::vector<std::string> bones = [] {
        std::vector<std::string> b{"hips", "spine", "neck", "head"};
        for (hand::Side side : {hand::Side::Left, hand::Side::Right}) {
            const std::string s = sideName(side);
            b.push_back(s + "UpperArm");
            b.push_back(s + "LowerArm");
            for (const auto& bone : hand::handBones(side)) b.emplace_back(bone.name);
        }
        return b;
    }();
    return bones;
}

BoneMapping loadBoneMapping(const std::filesystem::path& file) {
    // The shared JSON reader: not-a-regular-file, parse errors, duplicate keys and a BOM are
    // handled as in every data file, and each mistake names its line.
    const stimuli::JsonSource source = stimuli::readJsonFile(file);
    const nlohmann::json& json = source.root;
    BoneMapping mapping;
    mapping.file = file.string();
    mapping.pointer = json.is_object() && json.contains("bones") ? "/bones" : "";
    const nlohmann::json& object = mapping.pointer.empty() ? json : json["bones"];
    if (!object.is_object())
        throw InputError(mapping.file, source.lineAt(mapping.pointer), mapping.pointer,
                         (mapping.pointer.empty() ? "the top level: " : "") +
                             std::string("expected an object {\"vrmBoneName\": \"nodeName\"}"));
    for (const auto& [vrm, node] : object.items()) {
        const std::string pointer = mapping.pointer + "/" + stimuli::jsonPointerToken(vrm);
        const int line = source.lineAt(pointer);
        if (!isKnownBoneName(vrm))
            throw InputError(mapping.file, line, pointer,
                             "'" + vrm + "' is not a VRM humanoid bone name (e.g. leftUpperArm, rightIndexProximal)");
        if (!node.is_string()) throw InputError(mapping.file, line, pointer, "expected the node name as a string");
        mapping.nodes[vrm] = node.get<std::string>();
        mapping.lines[vrm] = line;
    }
    return mapping;
}

glm::vec3 bodyFromSigningSpace(const glm::vec3& pointMm) { return {-pointMm.x, pointMm.y, pointMm.z}; }

glm::quat bodyFromSigningSpace(const glm::quat& rotation) {
    const glm::mat3 s(glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1));
    return glm::normalize(glm::quat_cast(s * glm::mat3_cast(rotation) * s));
}

glm::quat handFrameFromSigningSpace(const glm::quat& orientation) {
    const glm::mat3 s(glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1));
    const glm::mat3 flipY(glm::vec3(1, 0, 0), glm::vec3(0, -1, 0), glm::vec3(0, 0, 1));
    return glm::normalize(glm::quat_cast(s * glm::mat3_cast(orientation) * flipY));
}

float faceAvatarForward(render::Scene& scene, const BoneMapping& mapping) {
    const int left = findBone(scene, mapping, "leftUpperArm"), right = findBone(scene, mapping, "rightUpperArm");
    if (left < 0 || right < 0) return 0.0f;
    std::vector<glm::mat4> world;
    render::computeWorldTransforms(scene, render::restPose(scene), world);
    const glm::vec3 across = glm::vec3(world[left][3]) - glm::vec3(world[right][3]);  // toward the signer's left
    const float width = glm::length(across);
    const auto degreesOf = [](float sine) { return std::asin(std::clamp(sine, -1.0f, 1.0f)) / kDeg; };
    if (!(width > 1e-6f) || std::abs(across.y) > 0.5f * width) {
        throw InputError(scene.sourceName, 0, "skeleton",
                         "the shoulders (leftUpperArm = node '" + scene.nodes[left].name + "', rightUpperArm = node '" +
                             scene.nodes[right].name + "') are " +
                             (width > 1e-6f ? std::to_string(static_cast<int>(std::lround(degreesOf(across.y / width)))) +
                                                  "° from level"
                                            : std::string("at the same place")) +
                             " in the rest pose: the avatar must stand upright with +Y up (glTF's convention)");
    }
    const int hips = findBone(scene, mapping, "hips"), head = findBone(scene, mapping, "head");
    if (hips >= 0 && head >= 0) {
        const glm::vec3 up = glm::vec3(world[head][3]) - glm::vec3(world[hips][3]);
        if (!(up.y > 0.5f * glm::length(up))) {
            const float length = glm::length(up);
            throw InputError(scene.sourceName, 0, "skeleton",
                             "the head (node '" + scene.nodes[head].name + "') is not above the hips (node '" +
                                 scene.nodes[hips].name + "') in the rest pose" +
                                 (length > 1e-6f ? " (" + std::to_string(static_cast<int>(std::lround(
                                                              90.0f - degreesOf(up.y / length)))) +
                                                       "° from vertical)"
                                                 : std::string()) +
                                 ": the avatar must stand upright with +Y up (glTF's convention)");
        }
    }
    const glm::vec3 forward = glm::cross(across, glm::vec3(0.0f, 1.0f, 0.0f));
    const float yaw = std::atan2(forward.x, forward.z);  // 0 when facing +Z
    if (std::abs(yaw) < 1.0f * kDeg) return 0.0f;
    const glm::quat turn = glm::angleAxis(-yaw, glm::vec3(0.0f, 1.0f, 0.0f));
    for (render::Node& n : scene.nodes) {
        if (n.parent >= 0) continue;
        if (n.restMatrix) {
            n.restMatrix = glm::mat4_cast(turn) * *n.restMatrix;
        } else {
            n.rest.translation = turn * n.rest.translation;
            n.rest.rotation = glm::normalize(turn * n.rest.rotation);
        }
    }
    return -yaw / kDeg;
}

render::Scene loadSignerAvatar(const std::filesystem::path& file, const BoneMapping& mapping, const std::string& flag) {
    if (!std::filesystem::exists(file)) throw InputError(file.string(), 0, flag, "no such file");
    render::Scene scene = render::loadGltf(file);
    scene.sourceName = file.string();
    faceAvatarForward(scene, mapping);
    return scene;
}

SignerRig::SignerRig(const render::Scene& scene, const BoneMapping& mapping, const hand::HandModel& handModel)
    : scene_(&scene), handModel_(handModel), armMemo_(std::make_shared<ArmMemo>()),
      pacerMemo_(std::make_shared<PacerMemo>()) {
    const auto lookup = [&](const std::string& vrm) { return findBone(scene, mapping, vrm); };
    // An entry naming a node the avatar lacks is the bone map's mistake, not the avatar's.
    for (const auto& [vrm, node] : mapping.nodes) {
        if (scene.findNode(node) >= 0) continue;
        const auto line = mapping.lines.find(vrm);
        throw InputError(mapping.file.empty() ? scene.sourceName : mapping.file,
                         line != mapping.lines.end() ? line->second : 0, mapping.pointer + "/" + vrm,
                         "node '" + node + "' is not in " + scene.sourceName +
                             " (the bone map names, for each VRM bone, a node of the avatar)");
    }
    std::vector<std::string> missing;
    for (const std::string& name : requiredSignerBones())
        if (lookup(name) < 0) missing.push_back(name);
    if (!missing.empty()) {
        std::string list;
        for (const auto& m : missing) list += (list.empty() ? "" : ", ") + m;
        throw InputError(scene.sourceName, 0, "skeleton",
                         std::to_string(missing.size()) + " required bone(s) missing: " + list +
                             " (use VRM humanoid bone names, or map them with a bone mapping file)");
    }

    // Canonical rest rotations (see the top of the header and hand/arm_ik.hpp).
    const auto add = [&](const std::string& vrm, glm::quat canonicalRest) {
        const int n = lookup(vrm);
        if (n >= 0) bones_[vrm] = Bone{n, canonicalRest};
    };
    const glm::quat identity(1.0f, 0.0f, 0.0f, 0.0f);
    for (const char* b : {"hips", "spine", "chest", "upperChest", "neck", "head", "leftEye", "rightEye"}) add(b, identity);
    for (hand::Side side : {hand::Side::Right, hand::Side::Left}) {
        const std::string s = sideName(side);
        for (const char* part : {"Shoulder", "UpperArm", "LowerArm", "ForearmTwistMid", "ForearmTwistWrist"})
            add(s + part, identity);
        const hand::HandPose rest = hand::forwardKinematics(handModel_, hand::HandControls{}, side);
        const auto info = hand::handBones(side);
        for (int b = 0; b < hand::kBodyCount; ++b)
            add(std::string(info[b].name), hand::restFrame(side) * rest.bodies[b].rotation);
    }

    const render::Pose restPose = render::restPose(scene);
    std::vector<glm::mat4> world;
    render::computeWorldTransforms(scene, restPose, world);
    restWorldRotation_.resize(world.size());
    for (std::size_t i = 0; i < world.size(); ++i) restWorldRotation_[i] = rotationOf(world[i]);
    measureRestPose(world);
    const auto position = [&](const std::string& vrm) { return glm::vec3(world[node(vrm)][3]); };

    const glm::vec3 leftShoulder = position("leftUpperArm"), rightShoulder = position("rightUpperArm");
    const float shoulderHalfWidth = 0.5f * glm::length(leftShoulder - rightShoulder);
    // The chest sits 130 mm below the shoulder joints in the default signer; scale with the
    // skeleton's shoulder width (175 mm half-width there).
    bodyOriginM_ = 0.5f * (leftShoulder + rightShoulder) - glm::vec3(0.0f, 0.13f * shoulderHalfWidth / 0.175f, 0.0f);
    for (hand::Side side : {hand::Side::Right, hand::Side::Left}) {
        const std::string s = sideName(side);
        hand::ArmModel arm = hand::defaultArmModel(side);
        arm.shoulderMm = (position(s + "UpperArm") - bodyOriginM_) * kMToMm;
        arm.upperArmLengthMm = glm::length(position(s + "LowerArm") - position(s + "UpperArm")) * kMToMm;
        arm.forearmLengthMm = glm::length(position(s + "Hand") - position(s + "LowerArm")) * kMToMm;
        arms_[side == hand::Side::Right ? 0 : 1] = arm;
    }
    {
        const hand::HandPose rest = hand::forwardKinematics(handModel_, hand::HandControls{}, hand::Side::Right);
        const float modelMm = glm::length(rest.bodies[hand::firstBodyOf(hand::Digit::Middle)].position);
        handScale_ = glm::length(position("rightMiddleProximal") - position("rightHand")) * kMToMm / modelMm;
    }
    // Without eye bones: the default signer's eyes relative to its head bone.
    gaze_.eyesMm = (position("head") - bodyOriginM_) * kMToMm + glm::vec3(0.0f, 115.0f, 78.0f);
    if (bones_.count("leftEye") && bones_.count("rightEye"))
        gaze_.eyesMm = (0.5f * (position("leftEye") + position("rightEye")) - bodyOriginM_) * kMToMm;
    // The top of the head, above which a raised hand may take the elbow over the shoulder
    // (hand::ArmModel::elbowRiseWristAboveShoulderMm). [S] Drillis & Contini: the eyes at
    // 0.936·H, the vertex at 1.0·H, 112 mm above them at the default stature of 1750 mm.
    for (hand::ArmModel& arm : arms_) arm.elbowRiseWristAboveShoulderMm = gaze_.eyesMm.y + 112.0f - arm.shoulderMm.y;
    // What the non-manuals move (signer_pose_nonmanual.cpp).
    morphTargets_ = morphTargetNames(scene);
    for (hand::Side side : {hand::Side::Right, hand::Side::Left})
        if (bones_.count(sideName(side) + "Shoulder"))
            shoulderBoneMm_[side == hand::Side::Right ? 0 : 1] = (position(sideName(side) + "Shoulder") - bodyOriginM_) * kMToMm;
    neckLengthMm_ = std::max(10.0f, glm::length(position("head") - position("neck")) * kMToMm);
    torsoLengthMm_ = std::max(50.0f, glm::length(0.5f * (leftShoulder + rightShoulder) - position("spine")) * kMToMm);
}

void SignerRig::measureRestPose(const std::vector<glm::mat4>& restWorld) {
    const glm::quat identity(1.0f, 0.0f, 0.0f, 0.0f);
    const render::Scene& scene = *scene_;
    const auto at = [&](int node) { return glm::vec3(restWorld[node][3]); };
    const auto setCorrection = [&](const std::string& vrm, glm::quat delta) {
        const auto it = bones_.find(vrm);
        if (it == bones_.end()) return;
        if (hand::rotationAngleDeg(delta, identity) < kRestToleranceDeg) delta = identity;
        it->second.restCorrection = delta;
    };
    // The rest-pose direction from bone `from` to bone `to`; a bone of no length cannot be
    // measured and is refused (it would turn everything after it).
    constexpr float kMinBoneM = 1e-4f;  // 0.1 mm
    const auto direction = [&](const std::string& from, const std::string& to) {
        const glm::vec3 d = at(node(to)) - at(node(from));
        if (!(glm::length(d) > kMinBoneM)) {
            throw InputError(scene.sourceName, 0, "skeleton",
                             from + " (node '" + scene.nodes[node(from)].name + "') and " + to + " (node '" +
                                 scene.nodes[node(to)].name + "') are at the same place in the rest pose");
        }
        return d;
    };
    for (hand::Side side : {hand::Side::Right, hand::Side::Left}) {
        const std::string s = sideName(side);
        // Arms: canonically straight out sideways (T-pose); each bone toward the next joint,
        // after its parent's correction.
        const glm::vec3 outward(side == hand::Side::Right ? -1.0f : 1.0f, 0.0f, 0.0f);
        const glm::vec3 upperArm = direction(s + "UpperArm", s + "LowerArm");
        const glm::vec3 forearm = direction(s + "LowerArm", s + "Hand");
        const glm::quat upper = swingBetween(outward, upperArm);
        const glm::quat lower = swingBetween(upper * outward, forearm) * upper;
        setCorrection(s + "UpperArm", upper);

        // Hand: its whole frame, from the middle knuckle (along) and the little-to-index
        // knuckle line (across), so a palm turned down or forward in the rest pose is measured.
        const hand::HandPose rest = hand::forwardKinematics(handModel_, hand::HandControls{}, side);
        const glm::quat frame = hand::restFrame(side);
        const auto knuckle = [&](hand::Digit digit) { return rest.bodies[hand::firstBodyOf(digit)].position; };
        const auto knuckleName = [&](hand::Digit digit) {
            return std::string(hand::boneName(side, static_cast<hand::Body>(hand::firstBodyOf(digit))));
        };
        const glm::vec3 along = direction(s + "Hand", knuckleName(hand::Digit::Middle));
        const glm::vec3 across = direction(knuckleName(hand::Digit::Little), knuckleName(hand::Digit::Index));
        if (glm::length(glm::cross(glm::normalize(along), glm::normalize(across))) < 0.2f) {
            throw InputError(scene.sourceName, 0, "skeleton",
                             s + "Hand: the index and little knuckles lie in line with the wrist and the middle "
                                 "knuckle in the rest pose, so the palm's orientation cannot be measured");
        }
        const glm::quat canonicalHand = frameFromAxes(frame * (knuckle(hand::Digit::Index) - knuckle(hand::Digit::Little)),
                                                      frame * knuckle(hand::Digit::Middle));
        const glm::quat handCorrection = glm::normalize(frameFromAxes(across, along) * glm::inverse(canonicalHand));
        setCorrection(s + "Hand", handCorrection);

        // Forearm roll. What a bone's correction must undo is how its skin was modelled: an
        // avatar modelled with the palm turned (down or forward) has the wrist end of its
        // forearm turned with it and the elbow end not. The roll is the hand's correction
        // beyond the forearm's swing, about the forearm; twist bones take it in proportion
        // (all at the wrist, half at the middle) and the lower arm none; without twist bones the
        // lower arm, carrying the whole forearm, takes half.
        const glm::vec3 axis = glm::normalize(forearm);
        glm::quat beyond = glm::normalize(handCorrection * glm::inverse(lower));
        if (beyond.w < 0.0f) beyond = -beyond;  // the same rotation, its angle within ±180°
        const float roll = 2.0f * std::atan2(glm::dot(glm::vec3(beyond.x, beyond.y, beyond.z), axis), beyond.w);
        const auto rolled = [&](float fraction) { return glm::normalize(glm::angleAxis(fraction * roll, axis) * lower); };
        const bool twistBones = bones_.count(s + "ForearmTwistMid") || bones_.count(s + "ForearmTwistWrist");
        setCorrection(s + "LowerArm", twistBones ? lower : rolled(0.5f));
        setCorrection(s + "ForearmTwistMid", rolled(0.5f));
        setCorrection(s + "ForearmTwistWrist", rolled(1.0f));

        // Digits: each bone toward the next joint. The last bone aims at a leaf that continues
        // it (its only child, such as a VRM "_end" node, at least 1 mm away and within 60° of
        // the direction its parent's correction predicts); otherwise it keeps its parent's.
        const auto info = hand::handBones(side);
        for (int digit = 0; digit < hand::kDigitCount; ++digit) {
            const int first = hand::firstBodyOf(static_cast<hand::Digit>(digit));
            glm::quat parent = handCorrection;
            for (int k = 0; k < 3; ++k) {
                const int body = first + k;
                const std::string name(info[body].name);
                const glm::vec3 canonicalNext = k < 2 ? rest.bodies[body + 1].position : rest.tips[digit];
                const glm::vec3 predicted = parent * (frame * (canonicalNext - rest.bodies[body].position));
                std::optional<glm::vec3> actual;
                if (k < 2) {
                    actual = direction(name, std::string(info[body + 1].name));
                } else if (scene.nodes[node(name)].children.size() == 1) {
                    const glm::vec3 leaf = at(scene.nodes[node(name)].children.front()) - at(node(name));
                    if (glm::length(leaf) > 1e-3f &&
                        glm::dot(glm::normalize(leaf), glm::normalize(predicted)) > std::cos(60.0f * kDeg)) {
                        actual = leaf;
                    }
                }
                const glm::quat correction = actual ? swingBetween(predicted, *actual) * parent : parent;
                setCorrection(name, correction);
                parent = correction;
            }
        }
    }
}

int SignerRig::node(const std::string& vrmName) const {
    const auto it = bones_.find(vrmName);
    return it == bones_.end() ? -1 : it->second.node;
}

hand::ArmTarget SignerRig::restingTarget(hand::Side side) const {
    // Right hand: wrist low in front of the waist, palm facing in and down, fingers forward
    // and across.
    hand::ArmTarget right{{-130.0f, -270.0f, 170.0f},
                          frameFromAxes({0.8f, -0.6f, 0.0f}, {0.45f, -0.1f, 1.0f})};
    if (side == hand::Side::Right) return right;
    return {{-right.wristMm.x, right.wristMm.y, right.wristMm.z}, mirrorHandRotation(right.handRotation)};
}

hand::ArmTarget SignerRig::presentingTarget(hand::Side side) const {
    // Right hand beside the right shoulder, palm toward the viewer, fingers up.
    hand::ArmTarget right{{-170.0f, 60.0f, 300.0f}, frameFromAxes({0.0f, 0.0f, 1.0f}, {0.0f, 1.0f, 0.0f})};
    if (side == hand::Side::Right) return right;
    return {{-right.wristMm.x, right.wristMm.y, right.wristMm.z}, mirrorHandRotation(right.handRotation)};
}

hand::ArmPose SignerRig::solveArm(hand::Side side, const SignerPosture& posture) const {
    const bool right = side == hand::Side::Right;
    const hand::ArmTarget target = (right ? posture.rightWrist : posture.leftWrist).value_or(restingTarget(side));
    hand::ArmSolveOptions options;
    options.previousElbowDirection = right ? posture.rightElbowHint : posture.leftElbowHint;
    options.maxSwivelStepDeg = (right ? posture.followRightElbowHint : posture.followLeftElbowHint) ? 0.0f : kElbowHintWindowDeg;
    return armMemo_->solve(raisedArm(side, posture.nonManual), target, options);
}

glm::vec3 SignerRig::reachedWristMm(hand::Side side, const SignerPosture& posture) const {
    const bool right = side == hand::Side::Right;
    const hand::ArmTarget target = (right ? posture.rightWrist : posture.leftWrist).value_or(restingTarget(side));
    return hand::reachedWristMm(raisedArm(side, posture.nonManual), target);
}

hand::GazePose SignerRig::solveGazeAt(const SignerPosture& posture) const {
    if (!posture.gazeMm) return hand::GazePose{};
    if (posture.headDeg) return hand::solveGazeWithHead(gaze_, *posture.gazeMm, posture.headDeg->x, posture.headDeg->y);
    return hand::solveGaze(gaze_, *posture.gazeMm);
}

render::Pose SignerRig::pose(const SignerPosture& posture, PoseReport* report) const {
    const render::Scene& scene = *scene_;
    PoseReport local;
    PoseReport& out = report ? *report : local;

    std::map<std::string, glm::quat> canonical;  // posed canonical world rotations
    for (hand::Side side : {hand::Side::Right, hand::Side::Left}) {
        const bool right = side == hand::Side::Right;
        const hand::ArmPose arm = solveArm(side, posture);
        (right ? out.right : out.left) = arm;

        const std::string s = sideName(side);
        const glm::quat restInv = glm::inverse(hand::restFrame(side));
        const float twistSign = right ? 1.0f : -1.0f;  // hand = forearm·R_z(sign·supination)·…
        const auto twist = [&](float fraction) {
            return arm.forearm * glm::angleAxis(twistSign * fraction * arm.supinationDeg * kDeg, glm::vec3(0, 0, 1));
        };
        canonical[s + "UpperArm"] = arm.upperArm * restInv;
        canonical[s + "LowerArm"] = arm.forearm * restInv;
        canonical[s + "ForearmTwistMid"] = twist(0.5f) * restInv;
        canonical[s + "ForearmTwistWrist"] = twist(1.0f) * restInv;
        const hand::HandPose handPose =
            hand::forwardKinematics(handModel_, right ? posture.rightHand : posture.leftHand, side);
        const auto info = hand::handBones(side);
        for (int b = 0; b < hand::kBodyCount; ++b)
            canonical[std::string(info[b].name)] = arm.hand * handPose.bodies[b].rotation;
    }
    // Head and neck: the gaze's turn, then the non-manual nod, shake and tilt in the head's own
    // frame (the neck takes half) and the jut (the neck leans, the head keeps its turn). The
    // eyes keep the gaze's target in the body frame: they counter-turn a nod or shake as the
    // vestibulo-ocular reflex does, so a signer shaking the head keeps eye contact.
    const NonManualPosture& nm = posture.nonManual;
    const bool headMoves = nm.headNodRad != 0.0f || nm.headShakeRad != 0.0f || nm.headTiltRad != 0.0f || nm.headJutMm != 0.0f;
    if (posture.gazeMm || headMoves) {
        glm::quat neck(1.0f, 0.0f, 0.0f, 0.0f), head(1.0f, 0.0f, 0.0f, 0.0f);
        if (posture.gazeMm) {
            out.gaze = solveGazeAt(posture);
            neck = out.gaze.neck;
            head = out.gaze.head;
            canonical["leftEye"] = out.gaze.head * out.gaze.eyes;
            canonical["rightEye"] = out.gaze.head * out.gaze.eyes;
        }
        if (headMoves) {
            const glm::quat turn = headNonManualRotation(nm);
            neck = glm::normalize(neck * glm::slerp(glm::quat(1.0f, 0.0f, 0.0f, 0.0f), turn, 0.5f) *
                                  glm::angleAxis(jutLeanRad(nm.headJutMm, neckLengthMm_), glm::vec3(1.0f, 0.0f, 0.0f)));
            head = glm::normalize(head * turn);
        }
        canonical["neck"] = neck;
        canonical["head"] = head;
    }
    for (hand::Side side : {hand::Side::Right, hand::Side::Left})
        if (const auto raise = shoulderRaiseRotation(side, nm)) canonical[sideName(side) + "Shoulder"] = *raise;
    // The torso carries everything above it (arms and hands included: the signing space is
    // the chest's, so contacts with the body and the hands' clearance hold as solved).
    if (const auto torso = torsoRotation(nm, torsoLengthMm_)) {
        for (auto& entry : canonical) entry.second = glm::normalize(*torso * entry.second);
        const bool chest = bones_.count("chest") > 0;
        canonical["spine"] = chest ? glm::slerp(glm::quat(1.0f, 0.0f, 0.0f, 0.0f), *torso, 0.5f) : *torso;
        if (chest) canonical["chest"] = *torso;
    }

    // Desired world rotation per posed node.
    std::vector<std::optional<glm::quat>> desired(scene.nodes.size());
    for (const auto& [name, q] : canonical) {
        const auto it = bones_.find(name);
        if (it == bones_.end()) continue;
        const Bone& bone = it->second;
        desired[bone.node] =
            glm::normalize(q * glm::inverse(bone.restCorrection * bone.canonicalRest) * restWorldRotation_[bone.node]);
    }

    render::Pose pose = render::restPose(scene);
    std::vector<glm::quat> worldRotation(scene.nodes.size(), glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
    std::function<void(int, glm::quat)> visit = [&](int n, glm::quat parentWorld) {
        render::Trs& trs = pose.local[n];
        if (desired[n]) {
            if (pose.useRestMatrix.size() > static_cast<std::size_t>(n) && pose.useRestMatrix[n]) {
                // A node given as a glTF matrix: decompose so its rotation can be driven.
                const glm::mat4 m = *scene.nodes[n].restMatrix;
                trs.translation = glm::vec3(m[3]);
                trs.scale = {glm::length(glm::vec3(m[0])), glm::length(glm::vec3(m[1])), glm::length(glm::vec3(m[2]))};
                pose.useRestMatrix[n] = false;
            }
            trs.rotation = glm::normalize(glm::inverse(parentWorld) * *desired[n]);
            worldRotation[n] = *desired[n];
        } else {
            const glm::quat localRotation =
                scene.nodes[n].restMatrix ? rotationOf(*scene.nodes[n].restMatrix) : trs.rotation;
            worldRotation[n] = glm::normalize(parentWorld * localRotation);
        }
        for (int child : scene.nodes[n].children) visit(child, worldRotation[n]);
    };
    for (std::size_t n = 0; n < scene.nodes.size(); ++n)
        if (scene.nodes[n].parent < 0) visit(static_cast<int>(n), glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
    std::map<std::string, float> face = nm.face;
    if (posture.gazeMm) addLidFollow(out.gaze.eyePitchDeg + nm.headNodRad / kDeg, morphTargets_, face);
    if (!face.empty()) pose.morphByName = mapFaceWeights(face, morphTargets_);
    return pose;
}

}  // namespace signstim::signer
