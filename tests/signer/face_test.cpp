// The body side of the non-manuals (issue 23 §2, §3): the default signer's face targets, the
// timeline's channels reaching the pose at any time t, head/torso/shoulder channels on the
// skeleton, and the VRM expression name map on a small avatar this test builds.
#include "signer/avatar_builder.hpp"
#include "signer/avatar_face.hpp"
#include "signer/clip.hpp"
#include "signer/signer_pose.hpp"
#include "signer/timeline_clip.hpp"
#include "renderer/gltf_loader.hpp"
#include "stimuli/json_source.hpp"
#include "stimuli/story/handshapes.hpp"
#include "stimuli/story/lexicon.hpp"
#include "stimuli/story/story.hpp"
#include "stimuli/story/timeline_builder.hpp"
#include "stimuli/verbs/verbs.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>

using namespace signstim;

namespace {

const render::Scene& avatar() {
    static const render::Scene scene = signer::buildDefaultAvatar();
    return scene;
}

const signer::SignerRig& rig() {
    static const signer::SignerRig r(avatar());
    return r;
}

const render::Mesh& faceMesh(const render::Scene& scene) {
    for (const render::Mesh& mesh : scene.meshes)
        if (mesh.targetCount() > 0) return mesh;
    throw std::runtime_error("no mesh with morph targets");
}

// A timeline of a signer at rest for 2 s with the given non-manual tracks (synthetic data).
stimuli::Timeline restingTimeline(std::vector<stimuli::NonManualTrack> tracks) {
    stimuli::Timeline t;
    t.story = "synthetic";
    t.durationSeconds = 2.0;
    for (auto* track : {&t.right, &t.left}) {
        stimuli::TimelineKey a, b;
        a.rest = b.rest = true;
        b.timeSeconds = 2.0;
        *track = {a, b};
    }
    t.nonManuals = std::move(tracks);
    return t;
}

std::vector<glm::mat4> worldOf(const render::Pose& pose) {
    std::vector<glm::mat4> world;
    render::computeWorldTransforms(avatar(), pose, world);
    return world;
}

glm::vec3 positionOf(const std::vector<glm::mat4>& world, const char* node) {
    return glm::vec3(world[static_cast<std::size_t>(avatar().findNode(node))][3]);
}
glm::vec3 axisOf(const std::vector<glm::mat4>& world, const char* node, int column) {
    return glm::normalize(glm::vec3(world[static_cast<std::size_t>(avatar().findNode(node))][column]));
}

float angleBetween(glm::vec3 a, glm::vec3 b) { return std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f)); }

}  // namespace

TEST(FaceTargets, DefaultSignerHasEveryArkitShapeOnItsFaceAndEachMovesIt) {
    const render::Mesh& face = faceMesh(avatar());
    for (const char* name : {"browInnerUp", "browDownLeft", "browDownRight", "browOuterUpLeft", "browOuterUpRight",
                             "eyeBlinkLeft", "eyeBlinkRight", "eyeSquintLeft", "eyeSquintRight", "eyeWideLeft",
                             "eyeWideRight", "cheekSquintLeft", "cheekSquintRight", "cheekPuff", "noseSneerLeft",
                             "noseSneerRight", "jawOpen", "mouthClose", "mouthFunnel", "mouthPucker",
                             "mouthStretchLeft", "mouthStretchRight", "mouthPressLeft", "mouthPressRight",
                             "mouthSmileLeft", "mouthSmileRight", "mouthFrownLeft", "mouthFrownRight",
                             "mouthUpperUpLeft", "mouthUpperUpRight", "mouthRollLower", "tongueOut",
                             "eyeLookUpLeft", "eyeLookUpRight", "eyeLookDownLeft", "eyeLookDownRight",
                             "mouthShrugLower", "mouthShrugUpper", "mouthRollUpper", "mouthLowerDownLeft",
                             "mouthLowerDownRight", "mouthDimpleLeft", "mouthDimpleRight", "mouthLeft", "mouthRight"}) {
        const auto it = std::find(face.targetNames.begin(), face.targetNames.end(), name);
        ASSERT_NE(it, face.targetNames.end()) << name;
        const auto k = static_cast<std::size_t>(it - face.targetNames.begin());
        float largest = 0.0f, leftX = 0.0f, rightX = 0.0f, sideways = 0.0f;
        for (const render::Primitive& p : face.primitives)
            for (std::size_t v = 0; v < p.vertices.size(); ++v) {
                const float d = glm::length(p.targets[k].position[v]);
                largest = std::max(largest, d);
                (p.vertices[v].position.x > 0.0f ? leftX : rightX) += d;
                sideways += p.targets[k].position[v].x;
            }
        // Each shape moves something visibly (a millimetre or more) ...
        EXPECT_GT(largest, 0.001f) << name;
        const std::string n = name;
        // ... mouthLeft/Right pull the whole mouth toward that side (+x: the face's own left) ...
        if (n == "mouthLeft" || n == "mouthRight") {
            EXPECT_GT(n == "mouthLeft" ? sideways : -sideways, 0.0f) << name;
            continue;
        }
        // ... and another sided one moves its own side (ARKit's Left: the face's own left, +x) most.
        if (n.size() > 4 && n.compare(n.size() - 4, 4, "Left") == 0) {
            EXPECT_GT(leftX, 3.0f * rightX) << name;
        }
        if (n.size() > 5 && n.compare(n.size() - 5, 5, "Right") == 0) {
            EXPECT_GT(rightX, 3.0f * leftX) << name;
        }
    }
}

TEST(FaceTargets, EveryFaceChannelOfEveryMarkerIsAShapeOfTheDefaultSigner) {
    // Looked at (issue 23, "Tests and looking"): [mm ...] wrote mouthShrugLower, which the face
    // lacked, so MM showed without its pushed-up lower lip. Every face weight a marker, a blink
    // or a mouthed word writes must be a target of the default signer, or it silently shows
    // nothing. A story with every marker (synthetic).
    const std::filesystem::path scenes = std::filesystem::path(SIGNSTIM_SOURCE_DIR) / "scenes";
    const stimuli::HandshapeLibrary shapes = stimuli::loadHandshapes(scenes / "handshapes.json", rig().handModel());
    const stimuli::Lexicon lexicon = stimuli::loadLexicon(scenes / "lexicon", shapes, rig().handModel());
    const stimuli::VerbLibrary verbs = stimuli::loadVerbLibrary(scenes / "verbs.json");
    stimuli::StoryVocabulary vocabulary;
    vocabulary.verbs = &verbs;
    vocabulary.signs = lexicon.glosses();
    const std::string text = R"J({"format": "signstim-story", "version": 1, "title": "Every marker (synthetic)",
  "characters": [{"gloss": "JOHN", "position": 0.9}, {"gloss": "MARY", "position": -0.6}],
  "sentences": ["JOHN IX(0.9) [mm HELP] [oo KNOW] [cha HELP] [th KNOW]",
                "MARY IX(-0.6) [pah HELP] [cs KNOW] [puff HELP] [nod] [blink]",
                "[t HELP] [y/n KNOW]", "[cond HELP] [wh KNOW]", "[rhq HELP] [neg NOT KNOW]",
                "[rs(MARY) [aff HELP]] [mouth(book) BOOK]"]})J";
    const stimuli::Story story = stimuli::parseStory(stimuli::parseJsonText(text, "every-marker.json"), vocabulary);
    stimuli::TimelineSources sources;
    sources.lexicon = &lexicon;
    sources.shapes = &shapes;
    sources.verbs = [](const std::string& verb, stimuli::VerbVersion, double, double, int, int) -> stimuli::VerbPerformance {
        throw std::logic_error("the story has no verb, yet " + verb + " was asked for");
    };
    const stimuli::Timeline timeline = stimuli::buildTimeline(story, stimuli::VerbVersion::Point, sources);
    const std::vector<std::string>& targets = signer::faceTargetNames();
    std::size_t weights = 0;
    for (const stimuli::NonManualTrack& track : timeline.nonManuals) {
        if (track.channel.find('.') != std::string::npos) continue;  // head, torso, shoulders: bones
        ++weights;
        EXPECT_NE(std::find(targets.begin(), targets.end(), track.channel), targets.end()) << track.channel;
    }
    EXPECT_GT(weights, 20u);  // the markers' face channels were there to check
}

TEST(FaceTargets, CommittedSignerKeepsEveryTargetThroughItsSparseStorage) {
    // scenes/avatar/signer.glb stores the face's targets sparse (renderer/gltf_writer.cpp):
    // loaded back, every displacement is the builder's, bit for bit.
    const render::Scene loaded = render::loadGltf(std::string(SIGNSTIM_SOURCE_DIR) + "/scenes/avatar/signer.glb");
    const render::Mesh& built = faceMesh(avatar());
    const render::Mesh& read = faceMesh(loaded);
    ASSERT_EQ(read.targetNames, built.targetNames);
    ASSERT_EQ(read.primitives.size(), built.primitives.size());
    for (std::size_t p = 0; p < built.primitives.size(); ++p)
        for (std::size_t k = 0; k < built.targetNames.size(); ++k) {
            EXPECT_EQ(read.primitives[p].targets[k].position, built.primitives[p].targets[k].position) << built.targetNames[k];
            const auto& n = built.primitives[p].targets[k].normal;
            if (!n.empty()) {
                EXPECT_EQ(read.primitives[p].targets[k].normal, n) << built.targetNames[k];
            }
        }
}

TEST(FaceTargets, BlinkBringsTheUpperLidsEdgeDownToTheLowerLids) {
    // The upper lid at full blink reaches below the eye's centre (the lower lid's edge is
    // ~29° below it), so the cornea is covered.
    const render::Mesh& face = faceMesh(avatar());
    const auto k = static_cast<std::size_t>(
        std::find(face.targetNames.begin(), face.targetNames.end(), "eyeBlinkLeft") - face.targetNames.begin());
    float largestDrop = 0.0f;
    for (const render::Primitive& p : face.primitives)
        for (std::size_t v = 0; v < p.vertices.size(); ++v) largestDrop = std::max(largestDrop, -p.targets[k].position[v].y);
    EXPECT_GT(largestDrop, 0.012f);  // the lid's edge: from ~7 mm above the eye's centre to ~7 mm below
}

TEST(NonManualTimeline, ChannelsReachThePoseAtTimeTIndependentOfFrameRate) {
    stimuli::NonManualTrack brows{"browInnerUp", {{0.2, 0.0}, {0.5, 1.0}, {1.0, 1.0}, {1.3, 0.0}}};
    stimuli::NonManualTrack nod{"head.nod", {{0.3, 0.0}, {0.6, 0.25}, {0.9, 0.0}}};
    stimuli::NonManualTrack jaw{"jawOpen", {{0.1, 0.0}, {0.4, 0.6}, {0.7, 0.0}}};
    const signer::TimelineClip clip(rig(), restingTimeline({brows, nod, jaw}));
    const signer::ClipPoser poser(rig(), clip);
    // The same instant reached at 30 and 25 frames/s, and at an instant no frame rate hits.
    const render::Pose at30 = poser.next(12.0 / 30.0), at25 = poser.next(10.0 / 25.0);
    EXPECT_EQ(at30.morphByName, at25.morphByName);
    for (std::size_t i = 0; i < at30.local.size(); ++i) EXPECT_EQ(at30.local[i].rotation, at25.local[i].rotation);
    for (const double t : {0.4, 0.55, 0.61803, 0.75}) {
        const render::Pose pose = poser.next(t);
        for (const auto* track : {&brows, &jaw}) {
            const double expected = stimuli::sampleNonManual(*track, t);
            const auto it = pose.morphByName.find(track->channel);
            if (expected == 0.0) {
                EXPECT_TRUE(it == pose.morphByName.end() || it->second == 0.0f) << track->channel << " at " << t;
            } else {
                ASSERT_NE(it, pose.morphByName.end()) << track->channel << " at " << t;
                EXPECT_NEAR(it->second, expected, 1e-6) << track->channel << " at " << t;
            }
        }
        // The nod turns the head's forward axis down by the channel's angle (no gaze here).
        const std::vector<glm::mat4> world = worldOf(pose), rest = worldOf(render::restPose(avatar()));
        const glm::vec3 forward = axisOf(world, "head", 2);
        EXPECT_NEAR(angleBetween(forward, axisOf(rest, "head", 2)), stimuli::sampleNonManual(nod, t), 1e-4) << t;
        if (stimuli::sampleNonManual(nod, t) > 0.01) {
            EXPECT_LT(forward.y, 0.0f) << "+ nod: chin down, at " << t;
        }
    }
    // Before every key and after: the neutral face and head, exactly the rest pose's head.
    const render::Pose before = poser.next(0.05);
    EXPECT_TRUE(before.morphByName.empty());
}

TEST(NonManualPose, HeadShakeAndTiltTurnTheHeadTheSeamsWay) {
    signer::SignerPosture posture;
    posture.nonManual.headShakeRad = 0.3f;
    std::vector<glm::mat4> world = worldOf(rig().pose(posture));
    EXPECT_GT(axisOf(world, "head", 2).x, 0.2f);  // + shake: toward the signer's left (+x)
    posture.nonManual = {};
    posture.nonManual.headTiltRad = 0.3f;
    world = worldOf(rig().pose(posture));
    EXPECT_GT(axisOf(world, "head", 1).x, 0.2f);  // + tilt: the crown toward the left shoulder
    posture.nonManual = {};
    posture.nonManual.headJutMm = 20.0f;
    const std::vector<glm::mat4> rest = worldOf(rig().pose(signer::SignerPosture{}));
    world = worldOf(rig().pose(posture));
    EXPECT_NEAR(positionOf(world, "head").z - positionOf(rest, "head").z, 0.020f, 0.002f);  // forward 20 mm
    EXPECT_NEAR(angleBetween(axisOf(world, "head", 2), axisOf(rest, "head", 2)), 0.0f, 1e-4f);  // face level
}

TEST(NonManualPose, TorsoTurnCarriesTheHandsWithTheChest) {
    // Role shift: the signing space is the chest's, so a hand keeps its place relative to the
    // chest while the torso turns.
    signer::SignerPosture posture;
    posture.rightWrist = rig().presentingTarget(hand::Side::Right);
    const std::vector<glm::mat4> straight = worldOf(rig().pose(posture));
    posture.nonManual.torsoTurnRad = 0.35f;
    posture.nonManual.torsoLeanRad = 0.1f;
    const std::vector<glm::mat4> turned = worldOf(rig().pose(posture));
    const auto inChest = [](const std::vector<glm::mat4>& world, const char* node) {
        return glm::vec3(glm::inverse(world[static_cast<std::size_t>(avatar().findNode("chest"))]) *
                         glm::vec4(positionOf(world, node), 1.0f));
    };
    EXPECT_LT(glm::distance(inChest(straight, "rightHand"), inChest(turned, "rightHand")), 1e-4f);
    EXPECT_GT(glm::distance(positionOf(straight, "rightHand"), positionOf(turned, "rightHand")), 0.05f);
    // The chest faces toward the signer's left (+x) by the turn.
    EXPECT_NEAR(std::atan2(axisOf(turned, "chest", 2).x, axisOf(turned, "chest", 2).z), 0.35f, 0.02f);
}

TEST(NonManualPose, ShoulderRaiseLiftsTheShoulderAndKeepsTheHandOnTarget) {
    signer::SignerPosture posture;
    posture.leftWrist = rig().presentingTarget(hand::Side::Left);
    const std::vector<glm::mat4> level = worldOf(rig().pose(posture));
    ASSERT_TRUE(signer::setNonManualChannel(posture.nonManual, "shoulder.raiseLeft", 1.0));
    const std::vector<glm::mat4> raised = worldOf(rig().pose(posture));
    EXPECT_GT(positionOf(raised, "leftUpperArm").y - positionOf(level, "leftUpperArm").y, 0.02f);
    EXPECT_NEAR(positionOf(raised, "rightUpperArm").y, positionOf(level, "rightUpperArm").y, 1e-6f);
    EXPECT_LT(glm::distance(positionOf(raised, "leftHand"), positionOf(level, "leftHand")), 0.001f);
}

TEST(NonManualPose, UnknownBodyChannelIsRefusedAndFaceWeightsAreClamped) {
    signer::NonManualPosture p;
    EXPECT_FALSE(signer::setNonManualChannel(p, "head.wobble", 1.0));
    EXPECT_TRUE(signer::setNonManualChannel(p, "jawOpen", 1.7));
    EXPECT_EQ(p.face.at("jawOpen"), 1.0f);
    EXPECT_TRUE(signer::setNonManualChannel(p, "shoulders.raise", 0.5));
    EXPECT_EQ(p.shoulderRaiseLeft, 0.5f);
    EXPECT_EQ(p.shoulderRaiseRight, 0.5f);
}

// A small avatar with VRM-named expressions instead of ARKit shapes: the default signer with
// its face targets renamed (synthetic).
render::Scene vrmAvatar(const std::map<std::string, std::string>& renames) {
    render::Scene scene = signer::buildDefaultAvatar();
    for (render::Mesh& mesh : scene.meshes)
        for (std::size_t k = 0; k < mesh.targetNames.size(); ++k) {
            const auto it = renames.find(mesh.targetNames[k]);
            mesh.targetNames[k] = it != renames.end() ? it->second : "unused" + std::to_string(k);
        }
    return scene;
}

TEST(VrmFaceMap, DrivesTheVrm0PresetsOfAnAvatarWithoutArkitNames) {
    const render::Scene scene = vrmAvatar({{"eyeBlinkLeft", "Blink_L"}, {"eyeBlinkRight", "Blink_R"},
                                           {"jawOpen", "A"}, {"mouthPucker", "U"}, {"browDownLeft", "Angry"}});
    const signer::SignerRig vrmRig(scene);
    signer::SignerPosture posture;
    posture.nonManual.face = {{"eyeBlinkLeft", 1.0f}, {"jawOpen", 0.5f}, {"mouthPucker", 0.8f},
                              {"browDownLeft", 1.0f}, {"browDownRight", 0.5f}, {"cheekPuff", 1.0f}};
    const render::Pose pose = vrmRig.pose(posture);
    const std::map<std::string, float, std::less<>> expected{{"Blink_L", 1.0f}, {"A", 0.5f}, {"U", 0.8f}, {"Angry", 0.7f}};
    EXPECT_EQ(pose.morphByName, expected);  // angry: the larger of 0.7×1 and 0.7×0.5; no puff to show
    // The renderer's weights of the face mesh follow: the renamed targets carry them.
    const int faceNode = scene.findNode("signerFace");
    const std::vector<float> weights = render::resolveMorphWeights(scene, pose, faceNode);
    const render::Mesh& face = faceMesh(scene);
    for (std::size_t k = 0; k < face.targetNames.size(); ++k) {
        const auto it = expected.find(face.targetNames[k]);
        EXPECT_EQ(weights[k], it != expected.end() ? it->second : 0.0f) << face.targetNames[k];
    }
}

TEST(VrmFaceMap, PrefersVrm1ExpressionsAndFallsBackToBothEyesBlink) {
    const std::set<std::string> vrm1{"blinkLeft", "blink", "aa", "ou", "oh", "surprised", "happy"};
    const auto w = signer::mapFaceWeights({{"eyeBlinkLeft", 0.9f}, {"mouthFunnel", 0.4f}, {"browInnerUp", 1.0f},
                                           {"eyeWideLeft", 1.0f}, {"mouthSmileRight", 0.5f}},
                                          vrm1);
    const std::map<std::string, float, std::less<>> expected{
        {"blinkLeft", 0.9f}, {"oh", 0.4f}, {"surprised", 0.6f}, {"happy", 0.3f}};
    ASSERT_EQ(w.size(), expected.size());
    for (const auto& [name, weight] : expected) EXPECT_NEAR(w.at(name), weight, 1e-6f) << name;
    // Only a both-eyes blink: a blink of either eye closes both.
    const auto both = signer::mapFaceWeights({{"eyeBlinkRight", 1.0f}}, {"blink"});
    EXPECT_EQ(both.at("blink"), 1.0f);
    // ARKit names the avatar has win over the map.
    const auto own = signer::mapFaceWeights({{"jawOpen", 0.3f}}, {"jawOpen", "aa"});
    EXPECT_EQ(own.size(), 1u);
    EXPECT_EQ(own.at("jawOpen"), 0.3f);
}
