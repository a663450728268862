// Posing the signer: wrists land on their targets, fingers follow the hand model, bring-your-
// own skeletons are mapped or refused with the list of missing bones.
#include "signer/avatar_builder.hpp"
#include "signer/signer_pose.hpp"
#include "common/error.hpp"
#include "tests/signer/avatar_variants.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>

using namespace signstim;

namespace {
const render::Scene& avatar() {
    static const render::Scene scene = signer::buildDefaultAvatar();
    return scene;
}
}  // namespace

TEST(SignerPose, WristsLandOnTheirTargetsAndFingersFollowTheHandModel) {
    const render::Scene& s = avatar();
    const signer::SignerRig rig(s);
    signer::SignerPosture posture;
    posture.rightHand.fingers[0].bend = 0.6f;
    posture.rightHand.thumb.bendDeg = 60.0f;
    posture.rightWrist = rig.presentingTarget(hand::Side::Right);
    posture.leftWrist = hand::ArmTarget{{120, -50, 280}, glm::quat(1, 0, 0, 0)};
    signer::PoseReport report;
    const render::Pose pose = rig.pose(posture, &report);
    std::vector<glm::mat4> world;
    render::computeWorldTransforms(s, pose, world);
    const glm::vec3 chest = glm::vec3(world[s.findNode("chest")][3]);
    for (hand::Side side : {hand::Side::Right, hand::Side::Left}) {
        const hand::ArmTarget target = side == hand::Side::Right ? *posture.rightWrist : *posture.leftWrist;
        const hand::ArmPose& arm = side == hand::Side::Right ? report.right : report.left;
        const glm::mat4& palm = world[s.findNode(side == hand::Side::Right ? "rightHand" : "leftHand")];
        const glm::vec3 wristMm = (glm::vec3(palm[3]) - chest) * 1000.0f;
        EXPECT_LT(glm::length(wristMm - arm.wristMm), 0.5f);
        if (arm.reachable) {
            EXPECT_LT(glm::length(wristMm - target.wristMm), 0.5f);
        }
        const glm::quat palmRotation = glm::normalize(glm::quat_cast(glm::mat3(palm)));
        EXPECT_LT(hand::rotationAngleDeg(palmRotation, arm.hand), 0.1f);
    }
    // Fingertips: the hand model's tips, carried by the palm transform.
    const hand::HandModel model = hand::buildHandModel();
    const hand::HandPose hp = hand::forwardKinematics(model, posture.rightHand, hand::Side::Right);
    const glm::mat4& palm = world[s.findNode("rightHand")];
    const glm::mat4& distal = world[s.findNode("rightIndexDistal")];
    const glm::vec3 tipFromBones = glm::vec3(distal * glm::vec4(0, 0, hand::boneLengthMm(model, hand::Body::IndexDistal) * 0.001f, 1));
    const glm::vec3 tipFromModel = glm::vec3(palm * glm::vec4(hp.tips[1] * 0.001f, 1));
    EXPECT_LT(glm::length(tipFromBones - tipFromModel) * 1000.0f, 0.05f);
}

TEST(SignerPose, GazeTurnsHeadAndEyesTowardThePoint) {
    const render::Scene& s = avatar();
    const signer::SignerRig rig(s);
    signer::SignerPosture posture;
    posture.gazeMm = glm::vec3(400, 100, 500);  // to the signer's left
    signer::PoseReport report;
    const render::Pose pose = rig.pose(posture, &report);
    std::vector<glm::mat4> world;
    render::computeWorldTransforms(s, pose, world);
    const glm::mat4& eye = world[s.findNode("leftEye")];
    const glm::vec3 chest = glm::vec3(world[s.findNode("chest")][3]);
    const glm::vec3 look = glm::normalize(glm::vec3(eye[2]));
    const glm::vec3 toTarget = glm::normalize(*posture.gazeMm * 0.001f + chest - glm::vec3(eye[3]));
    EXPECT_GT(glm::dot(look, toTarget), 0.995f);
    EXPECT_GT(report.gaze.headYawDeg, 10.0f);
}

TEST(SignerPose, SigningSpaceIsTheMirrorOfTheBodyFrame) {
    EXPECT_EQ(signer::bodyFromSigningSpace(glm::vec3(100, 20, 300)), glm::vec3(-100, 20, 300));
    // A rotation about the vertical axis turns the other way in the mirrored frame.
    const glm::quat yaw = glm::angleAxis(0.5f, glm::vec3(0, 1, 0));
    EXPECT_LT(hand::rotationAngleDeg(signer::bodyFromSigningSpace(yaw), glm::angleAxis(-0.5f, glm::vec3(0, 1, 0))), 1e-3f);
}

TEST(SignerPose, HandFrameFromSigningSpaceKeepsPalmAndFingerDirections) {
    // Verb data give a palm frame by its palm (x) and finger (z) directions in signing-space
    // coordinates, with y = z × x computed there. The body-frame palm frame must point the
    // palm and fingers the same physical ways (x -> -x) and be a proper rotation.
    const glm::vec3 fingers = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
    const glm::vec3 palm = glm::normalize(glm::cross(glm::vec3(0.0f, 0.0f, 1.0f), fingers));
    const glm::quat signing = glm::quat_cast(glm::mat3(palm, glm::cross(fingers, palm), fingers));
    const glm::mat3 body = glm::mat3_cast(signer::handFrameFromSigningSpace(signing));
    const auto mirror = [](glm::vec3 v) { return glm::vec3(-v.x, v.y, v.z); };
    EXPECT_LT(glm::distance(body[0], mirror(palm)), 1e-5f);
    EXPECT_LT(glm::distance(body[2], mirror(fingers)), 1e-5f);
    EXPECT_NEAR(glm::determinant(body), 1.0f, 1e-5f);
}

TEST(SignerPose, IncompleteSkeletonIsRefusedListingEveryMissingBone) {
    render::Scene s = avatar();
    s.sourceName = "my_avatar.glb";
    s.nodes[s.findNode("leftIndexDistal")].name = "L_index_3";
    s.nodes[s.findNode("rightLowerArm")].name = "forearm.R";
    try {
        signer::SignerRig rig(s);
        FAIL() << "accepted an incomplete skeleton";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("my_avatar.glb"), std::string::npos) << what;
        EXPECT_NE(what.find("leftIndexDistal"), std::string::npos) << what;
        EXPECT_NE(what.find("rightLowerArm"), std::string::npos) << what;
        EXPECT_NE(what.find("2 required"), std::string::npos) << what;
    }
}

TEST(SignerPose, MappingFileNamesTheUsersBones) {
    render::Scene s = avatar();
    s.nodes[s.findNode("leftIndexDistal")].name = "L_index_3";
    s.nodes[s.findNode("rightLowerArm")].name = "forearm.R";
    const std::string path = std::string(SIGNSTIM_BINARY_DIR) + "/avatar_test_mapping.json";
    {
        std::ofstream out(path);
        out << R"({"bones": {"leftIndexDistal": "L_index_3", "rightLowerArm": "forearm.R"}})";
    }
    const signer::BoneMapping mapping = signer::loadBoneMapping(path);
    const signer::SignerRig mapped(s, mapping);
    const signer::SignerRig original(avatar());
    signer::SignerPosture posture;
    posture.rightWrist = original.presentingTarget(hand::Side::Right);
    const render::Pose a = mapped.pose(posture), b = original.pose(posture);
    for (std::size_t i = 0; i < a.local.size(); ++i)
        EXPECT_GT(std::fabs(glm::dot(a.local[i].rotation, b.local[i].rotation)), 1.0f - 1e-6f);
    {
        std::ofstream out(path);
        out << "{\"bones\": {\"leftIndexDistal\": 3}}";
    }
    EXPECT_THROW(signer::loadBoneMapping(path), InputError);
    // The shared JSON reader: the line of the mistake, duplicate keys refused.
    {
        std::ofstream out(path);
        out << "{\"bones\": {\n  \"leftIndexDistal\": \"a\",\n  \"rightLowerArm\": 3\n}}\n";
    }
    try {
        signer::loadBoneMapping(path);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.line(), 3) << e.what();
    }
    {
        std::ofstream out(path);
        out << "{\"bones\": {\n  \"leftIndexDistal\": \"a\",\n  \"leftIndexDistal\": \"b\"\n}}\n";
    }
    EXPECT_THROW(signer::loadBoneMapping(path), InputError);
    std::remove(path.c_str());
}

TEST(SignerPose, RetargetingThroughTheRestPoseIgnoresTheUsersBoneAxes) {
    // Rotate one bone's rest frame (and compensate its children) as another tool would: the
    // posed world positions of every bone must not change.
    render::Scene s = avatar();
    const int lower = s.findNode("rightLowerArm");
    const glm::quat extra = glm::angleAxis(0.9f, glm::normalize(glm::vec3(0.2f, 1.0f, -0.4f)));
    s.nodes[lower].rest.rotation = s.nodes[lower].rest.rotation * extra;
    for (int child : s.nodes[lower].children) {
        s.nodes[child].rest.translation = glm::inverse(extra) * s.nodes[child].rest.translation;
        s.nodes[child].rest.rotation = glm::inverse(extra) * s.nodes[child].rest.rotation;
    }
    const signer::SignerRig changed(s), original(avatar());
    signer::SignerPosture posture;
    posture.rightWrist = original.presentingTarget(hand::Side::Right);
    std::vector<glm::mat4> wa, wb;
    render::computeWorldTransforms(s, changed.pose(posture), wa);
    render::computeWorldTransforms(avatar(), original.pose(posture), wb);
    for (std::size_t i = 0; i < wa.size(); ++i)
        EXPECT_LT(glm::length(glm::vec3(wa[i][3]) - glm::vec3(wb[i][3])), 1e-4f) << s.nodes[i].name;
}

namespace {

// The required bones and the forearm twist bones.
const std::vector<std::string>& comparedBones() {
    static const std::vector<std::string> bones = [] {
        std::vector<std::string> b = signer::requiredSignerBones();
        for (const char* twist : {"leftForearmTwistMid", "leftForearmTwistWrist", "rightForearmTwistMid", "rightForearmTwistWrist"})
            b.emplace_back(twist);
        return b;
    }();
    return bones;
}

// World transforms of comparedBones(), in that order.
std::vector<glm::mat4> posedJoints(const render::Scene& s, const signer::SignerRig& rig, const signer::SignerPosture& posture) {
    std::vector<glm::mat4> world;
    render::computeWorldTransforms(s, rig.pose(posture), world);
    std::vector<glm::mat4> joints;
    for (const std::string& bone : comparedBones()) joints.push_back(world[s.findNode(bone)]);
    return joints;
}

}  // namespace

TEST(SignerPose, AnyRestPoseIsMeasuredFromTheSkeleton) {
    // The default signer re-exported in an A-pose (arms 40° down), with the right palm turned
    // down and the fingers curled and splayed in the rest pose: posed, every joint must land
    // where the default signer's does, turned the same way.
    render::Scene s = avatar();
    test::useAnotherRestPose(s);
    const signer::SignerRig changed(s), original(avatar());
    for (int variant = 0; variant < 2; ++variant) {
        signer::SignerPosture posture;
        if (variant == 1) {
            posture.rightWrist = original.presentingTarget(hand::Side::Right);
            posture.leftWrist = hand::ArmTarget{{120, -50, 280}, glm::quat(1, 0, 0, 0)};
            posture.rightHand.fingers[0].bend = 0.6f;
            posture.leftHand.thumb.bendDeg = 60.0f;
        }
        const std::vector<glm::mat4> a = posedJoints(s, changed, posture), b = posedJoints(avatar(), original, posture);
        for (std::size_t i = 0; i < a.size(); ++i) {
            const std::string& bone = comparedBones()[i];
            // 0.2 mm: the arm solver's swivel search settles within a hair on the two rigs' arm models, equal
            // only to float rounding.
            EXPECT_LT(glm::length(glm::vec3(a[i][3]) - glm::vec3(b[i][3])) * 1000.0f, 0.2f) << bone << " variant " << variant;
            const glm::quat qa = glm::quat_cast(glm::mat3(a[i])), qb = glm::quat_cast(glm::mat3(b[i]));
            EXPECT_LT(hand::rotationAngleDeg(qa, qb), 0.1f) << bone << " variant " << variant;
        }
    }
}

TEST(SignerPose, AnAvatarFacingAnotherWayIsTurnedToFaceForward) {
    std::vector<glm::mat4> expected;
    render::computeWorldTransforms(avatar(), render::restPose(avatar()), expected);
    for (float degrees : {180.0f, 90.0f, -35.0f}) {
        render::Scene s = avatar();
        test::turnRoots(s, glm::angleAxis(glm::radians(degrees), glm::vec3(0, 1, 0)));
        const float turned = signer::faceAvatarForward(s);
        EXPECT_NEAR(std::remainder(turned + degrees, 360.0f), 0.0f, 1e-3f) << degrees << " turned by " << turned;
        std::vector<glm::mat4> world;
        render::computeWorldTransforms(s, render::restPose(s), world);
        for (std::size_t i = 0; i < world.size(); ++i)
            ASSERT_LT(glm::length(glm::vec3(world[i][3]) - glm::vec3(expected[i][3])), 1e-5f) << s.nodes[i].name;
    }
    render::Scene forward = avatar();
    EXPECT_EQ(signer::faceAvatarForward(forward), 0.0f) << "the default signer already faces +Z";
}

TEST(SignerPose, AnAvatarNotStandingUprightIsRefused) {
    for (const glm::vec3& axis : {glm::vec3(0, 0, 1), glm::vec3(1, 0, 0)}) {  // on its side; on its back
        render::Scene s = avatar();
        s.sourceName = "lying.glb";
        test::turnRoots(s, glm::angleAxis(glm::radians(90.0f), axis));
        try {
            signer::faceAvatarForward(s);
            ADD_FAILURE() << "accepted an avatar turned about " << axis.x << "," << axis.y << "," << axis.z;
        } catch (const InputError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find("lying.glb"), std::string::npos) << message;
            EXPECT_NE(message.find("+Y"), std::string::npos) << message;
            if (axis.z > 0.5f) {  // on its side: the shoulders are judged, and named
                EXPECT_NE(message.find("leftUpperArm = node 'leftUpperArm'"), std::string::npos) << message;
                EXPECT_NE(message.find("90° from level"), std::string::npos) << message;
            } else {  // on its back: the head and hips are judged, and named
                EXPECT_NE(message.find("head (node 'head')"), std::string::npos) << message;
                EXPECT_NE(message.find("90° from vertical"), std::string::npos) << message;
            }
        }
    }
}

TEST(SignerPose, TheLastBoneOfADigitAimsOnlyAtALeafThatContinuesIt) {
    // A curled middle-finger tip with a VRM-style "_end" leaf is measured; a ring-finger tip with
    // a sideways attachment (say a ring) is not turned by it.
    render::Scene s = avatar();
    std::vector<glm::mat4> world;
    render::computeWorldTransforms(s, render::restPose(s), world);
    const auto addChild = [&](const std::string& parent, const std::string& name, const glm::vec3& localOffset) {
        render::Node leaf;
        leaf.name = name;
        leaf.parent = s.findNode(parent);
        leaf.rest.translation = localOffset;
        s.nodes.push_back(leaf);
        s.nodes[leaf.parent].children.push_back(static_cast<int>(s.nodes.size()) - 1);
    };
    const float tipM = 0.02f;
    addChild("rightMiddleDistal", "rightMiddleDistal_end", {0.0f, 0.0f, tipM});  // hand bones run along +z
    addChild("rightRingDistal", "ring", {0.0f, 0.012f, 0.001f});
    test::swingRest(s, "rightMiddleDistal", "rightMiddleDistal_end", glm::vec3(0, 1, 0), 35.0f);
    const signer::SignerRig changed(s), original(avatar());
    signer::SignerPosture posture;
    posture.rightWrist = original.presentingTarget(hand::Side::Right);
    posture.rightHand.fingers[1].hook = 0.5f;
    const std::vector<glm::mat4> a = posedJoints(s, changed, posture), b = posedJoints(avatar(), original, posture);
    for (std::size_t i = 0; i < a.size(); ++i) {
        const glm::quat qa = glm::quat_cast(glm::mat3(a[i])), qb = glm::quat_cast(glm::mat3(b[i]));
        EXPECT_LT(hand::rotationAngleDeg(qa, qb), 0.1f) << comparedBones()[i];
    }
}

TEST(SignerPose, ABoneOfNoLengthIsRefusedNamingIt) {
    render::Scene s = avatar();
    s.sourceName = "flat.glb";
    s.nodes[s.findNode("rightIndexIntermediate")].rest.translation = glm::vec3(0.0f);
    try {
        const signer::SignerRig rig(s);
        ADD_FAILURE() << "accepted a skeleton with a bone of no length";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("flat.glb"), std::string::npos) << message;
        EXPECT_NE(message.find("rightIndexProximal"), std::string::npos) << message;
        EXPECT_NE(message.find("rightIndexIntermediate"), std::string::npos) << message;
    }
}

// Largest rotation difference (degrees) between the posed comparedBones() of two rigs.
float largestTurnDeg(const render::Scene& a, const signer::SignerRig& rigA, const render::Scene& b,
                     const signer::SignerRig& rigB, const signer::SignerPosture& posture, std::string* worst) {
    const std::vector<glm::mat4> wa = posedJoints(a, rigA, posture), wb = posedJoints(b, rigB, posture);
    float largest = 0.0f;
    for (std::size_t i = 0; i < wa.size(); ++i) {
        const float d = hand::rotationAngleDeg(glm::quat_cast(glm::mat3(wa[i])), glm::quat_cast(glm::mat3(wb[i])));
        if (d > largest) {
            largest = d;
            *worst = comparedBones()[i];
        }
    }
    return largest;
}

TEST(SignerPose, ThePalmsRestRollIsMeasuredOnBothSidesAtAnyAngle) {
    const signer::SignerRig original(avatar());
    signer::SignerPosture posture;
    posture.rightWrist = original.presentingTarget(hand::Side::Right);
    posture.leftWrist = original.presentingTarget(hand::Side::Left);
    for (float tilt : {0.0f, 40.0f}) {
        for (float roll : {-150.0f, -90.0f, -45.0f, -15.0f, 15.0f, 45.0f, 90.0f, 150.0f}) {
            render::Scene s = avatar();
            test::swingRest(s, "leftUpperArm", "leftLowerArm", glm::vec3(0, 0, 1), -tilt);
            test::swingRest(s, "rightUpperArm", "rightLowerArm", glm::vec3(0, 0, 1), tilt);
            test::rollPalmInRest(s, "left", roll);
            test::rollPalmInRest(s, "right", roll);
            const signer::SignerRig changed(s);
            std::string worst;
            EXPECT_LT(largestTurnDeg(s, changed, avatar(), original, posture, &worst), 0.1f)
                << "tilt " << tilt << " roll " << roll << ": " << worst;
        }
    }
}

TEST(SignerPose, WithoutTwistBonesTheLowerArmTakesHalfThePalmsRoll) {
    // An avatar without forearm twist bones (most VRM avatars): hide them by name.
    for (float roll : {-120.0f, 90.0f}) {
        render::Scene s = avatar();
        for (const char* twist : {"rightForearmTwistMid", "rightForearmTwistWrist", "leftForearmTwistMid", "leftForearmTwistWrist"})
            s.nodes[s.findNode(twist)].name = std::string("unmapped_") + twist;
        render::Scene unrolled = s;
        test::rollPalmInRest(s, "right", roll, false);
        const signer::SignerRig rolledRig(s), unrolledRig(unrolled);
        signer::SignerPosture posture;
        posture.rightWrist = unrolledRig.presentingTarget(hand::Side::Right);
        std::vector<glm::mat4> a, b;
        render::computeWorldTransforms(s, rolledRig.pose(posture), a);
        render::computeWorldTransforms(unrolled, unrolledRig.pose(posture), b);
        const int lower = s.findNode("rightLowerArm"), palm = s.findNode("rightHand");
        // The lower arm's skin (modelled half rolled) is turned back by half the roll; the hand lands
        // exactly where it does on the unrolled avatar.
        EXPECT_NEAR(hand::rotationAngleDeg(glm::quat_cast(glm::mat3(a[lower])), glm::quat_cast(glm::mat3(b[lower]))),
                    0.5f * std::abs(roll), 0.1f) << roll;
        EXPECT_LT(hand::rotationAngleDeg(glm::quat_cast(glm::mat3(a[palm])), glm::quat_cast(glm::mat3(b[palm]))), 0.1f) << roll;
    }
}

