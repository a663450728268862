// Properties of the McDonald hand (SPEC §1), stated as the paper states them and checked
// over sweeps of the whole control range (and beyond it, where clamping must hold).
#include "hand/hand_model.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

namespace signstim::hand {
namespace {

constexpr float kPi = 3.14159265358979f;
float deg(float rad) { return rad * 180.0f / kPi; }

// Signed rotation angle (degrees) of a unit quaternion that rotates about the given axis only.
float angleAbout(const glm::quat& q, const glm::vec3& axis) {
    const glm::vec3 v(q.x, q.y, q.z);
    return deg(2.0f * std::atan2(glm::dot(v, axis), q.w));
}

std::vector<float> range(float from, float to, int steps) {
    std::vector<float> values;
    for (int i = 0; i <= steps; ++i) values.push_back(from + (to - from) * float(i) / float(steps));
    return values;
}

// A set of controls covering every finger control beyond its range on every finger.
std::vector<HandControls> fingerSweep() {
    std::vector<HandControls> out;
    for (float spread : range(-40.0f, 45.0f, 6)) {
        for (float bend : range(-0.5f, 1.5f, 16)) {
            for (float hook : range(-0.5f, 1.5f, 16)) {
                HandControls c;
                for (int f = 0; f < kFingerCount; ++f) {
                    c.fingers[f] = {spread + 3.0f * f, bend, hook};
                }
                out.push_back(c);
            }
        }
    }
    return out;
}

std::vector<ThumbControls> thumbSweep() {
    std::vector<ThumbControls> out;
    for (float bend : range(-40.0f, 140.0f, 18)) {
        for (float spread : range(0.0f, 100.0f, 20)) {
            for (float mcp : range(-20.0f, 70.0f, 3)) {
                out.push_back({bend, spread, mcp, 1.2f * mcp + 5.0f});
            }
        }
    }
    return out;
}

class HandModelTest : public ::testing::Test {
protected:
    HandModel model = buildHandModel();
};

TEST_F(HandModelTest, PositiveBendFlexesTowardPalm) {
    HandControls c;
    const HandPose rest = forwardKinematics(model, c, Side::Right);
    for (auto& f : c.fingers) f.bend = 0.25f;
    c.thumb.mcpDeg = 30.0f;
    const HandPose bent = forwardKinematics(model, c, Side::Right);
    for (int d = 1; d < kDigitCount; ++d) {
        EXPECT_GT(bent.tips[d].x, rest.tips[d].x + 20.0f) << digitName(Digit(d));
    }
}

TEST_F(HandModelTest, NoJointEverLeavesItsLimit) {
    const HandLimits& lim = model.limits;
    for (const HandControls& controls : fingerSweep()) {
        const JointAngles a = jointAngles(model, controls);
        const HandPose pose = forwardKinematics(model, a, Side::Right);
        const auto local = localTransforms(pose);
        for (int f = 0; f < kFingerCount; ++f) {
            const FingerJointAngles& j = a.fingers[f];
            ASSERT_TRUE(lim.fingerSpread.contains(j.spreadDeg)) << j.spreadDeg;
            ASSERT_TRUE(lim.fingerTwist.contains(j.twistDeg)) << j.twistDeg;
            ASSERT_TRUE(lim.mcp.contains(j.mcpDeg)) << j.mcpDeg;
            ASSERT_TRUE(lim.pip.contains(j.pipDeg)) << j.pipDeg;
            ASSERT_TRUE(lim.dip.contains(j.dipDeg)) << j.dipDeg;
            // The posed bodies themselves (not only the numbers) respect the hinge limits.
            const int first = firstBodyOf(Digit(f + 1));
            const float pip = angleAbout(local[first + 1].rotation, {0, 1, 0});
            const float dip = angleAbout(local[first + 2].rotation, {0, 1, 0});
            ASSERT_TRUE(lim.pip.contains(pip, 0.05f)) << pip;
            ASSERT_TRUE(lim.dip.contains(dip, 0.05f)) << dip;
            ASSERT_NEAR(pip, j.pipDeg, 0.05f);
            ASSERT_NEAR(dip, j.dipDeg, 0.05f);
        }
    }
    for (const ThumbControls& thumb : thumbSweep()) {
        HandControls c;
        c.thumb = thumb;
        const JointAngles a = jointAngles(model, c);
        ASSERT_TRUE(lim.thumbBend.contains(a.thumb.bendDeg));
        ASSERT_TRUE(lim.thumbSpread.contains(a.thumb.spreadDeg));
        ASSERT_TRUE(lim.thumbMcp.contains(a.thumb.mcpDeg));
        ASSERT_TRUE(lim.thumbIp.contains(a.thumb.ipDeg));
        const auto local = localTransforms(forwardKinematics(model, a, Side::Right));
        ASSERT_NEAR(angleAbout(local[int(Body::ThumbProximal)].rotation, {0, 1, 0}), a.thumb.mcpDeg, 0.05f);
        ASSERT_NEAR(angleAbout(local[int(Body::ThumbDistal)].rotation, {0, 1, 0}), a.thumb.ipDeg, 0.05f);
    }
}

TEST_F(HandModelTest, HookKeepsDipAtTwoThirdsOfPip) {
    for (float bend : range(-0.5f, 1.0f, 30)) {
        for (float hook : range(-0.3f, 1.0f, 26)) {
            HandControls c;
            c.fingers[1] = {0.0f, bend, hook};
            const FingerJointAngles j = jointAngles(model, c).fingers[1];
            // Wherever the hook determines the PIP, DIP = 2/3 PIP (SPEC §1.5).
            const float pipFromBend = bend > 0.5f ? (bend - 0.5f) * 2.0f * model.limits.pipBendMaxDeg : -1e9f;
            if (hook * model.limits.pipHookMaxDeg >= pipFromBend) {
                ASSERT_NEAR(j.dipDeg, 2.0f / 3.0f * j.pipDeg, 1e-3f) << bend << " " << hook;
            } else {
                // Bend drives the PIP further than the hook; the DIP never exceeds 2/3 of it.
                ASSERT_LE(j.dipDeg, 2.0f / 3.0f * j.pipDeg + 1e-3f);
            }
        }
    }
    HandControls full;
    full.fingers[0].hook = 1.0f;
    const FingerJointAngles j = jointAngles(model, full).fingers[0];
    EXPECT_FLOAT_EQ(j.pipDeg, 120.0f);
    EXPECT_FLOAT_EQ(j.dipDeg, 80.0f);
}

TEST_F(HandModelTest, FirstHalfOfBendMovesOnlyTheMcp) {
    float previousPip = 0.0f;
    for (float bend : range(0.0f, 1.0f, 40)) {
        HandControls c;
        c.fingers[2].bend = bend;
        const FingerJointAngles j = jointAngles(model, c).fingers[2];
        if (bend <= 0.5f) {
            EXPECT_NEAR(j.mcpDeg, 180.0f * bend, 1e-3f);
            EXPECT_EQ(j.pipDeg, 0.0f);
            EXPECT_EQ(j.dipDeg, 0.0f);
        } else {
            EXPECT_FLOAT_EQ(j.mcpDeg, 90.0f);
            EXPECT_GT(j.pipDeg, previousPip);
            EXPECT_EQ(j.dipDeg, 0.0f);  // bend moves the PIP independently of the DIP
        }
        previousPip = j.pipDeg;
    }
    HandControls fist;
    fist.fingers[2].bend = 1.0f;
    EXPECT_FLOAT_EQ(jointAngles(model, fist).fingers[2].pipDeg, model.limits.pipBendMaxDeg);
}

TEST_F(HandModelTest, PipIsTheMaximumOfBendAndHook) {
    // SPEC §1.6 presets as (bend, hook) -> MCP/PIP/DIP.
    struct Preset { float bend, hook, mcp, pip, dip; };
    const Preset presets[] = {{0, 0, 0, 0, 0},          {0.95f, 0.8f, 90, 99, 64},
                              {0.5f, 0, 90, 0, 0},      {0.05f, 0.75f, 9, 90, 60},
                              {0.2f, 0.35f, 36, 42, 28}, {0.28f, 0.5f, 50, 60, 40},
                              {0.36f, 0.08f, 65, 10, 6}, {0.33f, 0.92f, 59, 110, 73},
                              {0.4f, 0.6f, 72, 72, 48},  {0.35f, 0.7f, 63, 84, 56}};
    for (const Preset& p : presets) {
        HandControls c;
        c.fingers[0] = {0.0f, p.bend, p.hook};
        const FingerJointAngles j = jointAngles(model, c).fingers[0];
        EXPECT_NEAR(j.mcpDeg, p.mcp, 1.0f) << p.bend << "," << p.hook;
        EXPECT_NEAR(j.pipDeg, p.pip, 1.0f) << p.bend << "," << p.hook;
        EXPECT_NEAR(j.dipDeg, p.dip, 1.0f) << p.bend << "," << p.hook;
    }
}

TEST_F(HandModelTest, NegativeBendAndHookHyperextendWithinLimits) {
    HandControls c;
    c.fingers[0] = {0.0f, -1.0f, -1.0f};
    const FingerJointAngles j = jointAngles(model, c).fingers[0];
    EXPECT_FLOAT_EQ(j.mcpDeg, model.limits.mcp.minDeg);
    EXPECT_FLOAT_EQ(j.pipDeg, model.limits.pip.minDeg);
    EXPECT_LT(j.dipDeg, 0.0f);
    EXPECT_GE(j.dipDeg, model.limits.dip.minDeg);
}

TEST_F(HandModelTest, FingerTwistStaysWithinTenDegrees) {
    float maxTwist = 0.0f, minTwist = 0.0f;
    for (float spread : range(-60.0f, 60.0f, 240)) {
        HandControls c;
        c.fingers[3].spreadDeg = spread;
        const FingerJointAngles j = jointAngles(model, c).fingers[3];
        ASSERT_LE(std::abs(j.twistDeg), 10.0f + 1e-4f);
        // Twist grows with spread and has its sign.
        ASSERT_GE(j.twistDeg * j.spreadDeg, 0.0f);
        maxTwist = std::max(maxTwist, j.twistDeg);
        minTwist = std::min(minTwist, j.twistDeg);
    }
    // The correlation uses the whole ±10° band at the spread limits.
    EXPECT_NEAR(maxTwist, 10.0f, 1e-3f);
    EXPECT_NEAR(minTwist, -10.0f, 1e-3f);
}

TEST_F(HandModelTest, ThumbTwistFollowsSpreadAndBend) {
    // The passive twist is a pronation (negative about the thumb's own axis: it turns the pad
    // toward the fingers) that starts at ~60 % of the spread range, spans 45° and is scaled
    // down below θ = 20°.
    const HandLimits& lim = model.limits;
    auto pronation = [&](float bend, float spread) {
        HandControls c;
        c.thumb.bendDeg = bend;
        c.thumb.spreadDeg = spread;
        return lim.thumbTwistRestDeg - jointAngles(model, c).thumb.twistDeg;
    };
    const float sixtyPercent = lim.thumbSpread.minDeg + 0.6f * (lim.thumbSpread.maxDeg - lim.thumbSpread.minDeg);
    for (float bend : range(-25.0f, 120.0f, 29)) {
        for (float spread : range(10.0f, sixtyPercent - 1.0f, 20)) {
            ASSERT_EQ(pronation(bend, spread), 0.0f) << "no twist below ~60 % spread";
        }
        // Monotone in spread above the start.
        float previous = 0.0f;
        for (float spread : range(sixtyPercent, 90.0f, 20)) {
            const float t = pronation(bend, spread);
            ASSERT_GE(t, previous);
            previous = t;
        }
    }
    for (float bend : range(20.0f, 120.0f, 10)) EXPECT_NEAR(pronation(bend, 90.0f), 45.0f, 1e-3f);
    for (float bend : range(0.0f, 19.0f, 19)) EXPECT_LT(pronation(bend, 90.0f), 45.0f * (bend + 1.0f) / 20.0f);
    EXPECT_LT(pronation(10.0f, 90.0f), pronation(25.0f, 90.0f));
}

// Flexion direction of the thumb's MCP (the metacarpal frame's +x) in the palm frame.
glm::vec3 thumbFlexionDirection(const HandModel& model, float bendDeg, float spreadDeg) {
    HandControls c;
    c.thumb.bendDeg = bendDeg;
    c.thumb.spreadDeg = spreadDeg;
    const HandPose pose = forwardKinematics(model, c, Side::Right);
    return pose.bodies[int(Body::ThumbMetacarpal)].rotation * glm::vec3(1.0f, 0.0f, 0.0f);
}

TEST_F(HandModelTest, ThumbSwingCarriesNoSpin) {
    // θ and φ place the metacarpal by the shortest rotation from the palm's z-axis: they do not
    // roll the thumb about its own axis, which only ψ does (docs/hand.md). Below the twist
    // start ψ = ψ₀, so the frame is that swing followed by R_z(ψ₀).
    const HandLimits& lim = model.limits;
    for (float bend : range(-25.0f, 120.0f, 29)) {
        for (float spread : range(10.0f, lim.thumbTwistStartSpreadDeg - 1.0f, 12)) {
            HandControls c;
            c.thumb.bendDeg = bend;
            c.thumb.spreadDeg = spread;
            const glm::quat actual = forwardKinematics(model, c, Side::Right).bodies[int(Body::ThumbMetacarpal)].rotation;
            const float t = glm::radians(bend), p = glm::radians(spread);
            const glm::vec3 direction(std::sin(p) * std::sin(t), std::sin(p) * std::cos(t), std::cos(p));
            // Shortest rotation from +z to the metacarpal direction: by φ about z × direction.
            const glm::vec3 axis = glm::normalize(glm::cross(glm::vec3(0.0f, 0.0f, 1.0f), direction));
            const glm::quat expected = glm::angleAxis(p, axis) *
                                       glm::angleAxis(glm::radians(lim.thumbTwistRestDeg), glm::vec3(0.0f, 0.0f, 1.0f));
            ASSERT_GT(std::abs(glm::dot(actual, expected)), 1.0f - 1e-6f) << bend << " " << spread;
        }
    }
}

TEST_F(HandModelTest, ThumbFlexesAcrossThePalmAtEveryBend) {
    // Bending the thumb's MCP carries it toward the little finger whatever θ is, never straight
    // into the palm (with the SPEC's literal chain, θ = 90° turned the flexion into the palm).
    for (float bend : range(-25.0f, 120.0f, 29)) {
        for (float spread : range(10.0f, model.limits.thumbTwistStartSpreadDeg - 1.0f, 12)) {
            const glm::vec3 flexion = thumbFlexionDirection(model, bend, spread);
            ASSERT_LT(flexion.y, -0.5f) << bend << " " << spread;
            ASSERT_GT(flexion.x, -0.25f) << bend << " " << spread;
        }
    }
    HandModel literal = model;
    literal.limits.thumbSpinFreeSwing = false;
    EXPECT_LT(thumbFlexionDirection(literal, 90.0f, 15.0f).x, -0.9f) << "the literal chain flexes into the palm";
}

TEST_F(HandModelTest, ThumbPronationTurnsThePadTowardTheFingertips) {
    // Opposition: at full spread the passive twist turns the thumb's pad (its flexion side)
    // toward the fingertips of the open hand, compared with the same posture untwisted. (Near
    // θ = 20° the spread thumb points out sideways and the same roll turns its pad toward the
    // back of the hand rather than the fingertips, so the sweep starts at 30°.)
    HandModel untwisted = model;
    untwisted.limits.thumbTwistSpanDeg = 0.0f;
    const HandPose open = forwardKinematics(model, HandControls{}, Side::Right);
    for (float bend : range(30.0f, 120.0f, 9)) {
        HandControls c;
        c.thumb.bendDeg = bend;
        c.thumb.spreadDeg = 90.0f;
        const glm::vec3 mcp = forwardKinematics(model, c, Side::Right).bodies[int(Body::ThumbProximal)].position;
        const glm::vec3 towardFingertips = glm::normalize(open.tips[int(Digit::Middle)] - mcp);
        const float twisted = glm::dot(thumbFlexionDirection(model, bend, 90.0f), towardFingertips);
        const float plain = glm::dot(thumbFlexionDirection(untwisted, bend, 90.0f), towardFingertips);
        EXPECT_GT(twisted, plain + 0.05f) << bend << ": " << twisted << " vs " << plain;
    }
}

TEST_F(HandModelTest, LiteralSpecChainIsAvailable) {
    // thumbSpinFreeSwing = false with thumbTwistSpanDeg = +45 is SPEC §1.4 exactly:
    // R_z(−θ)·R_x(−φ)·R_z(ψ), ψ = −90° + 45°·r·g. Checked where the twist is active.
    HandModel literal = model;
    literal.limits.thumbSpinFreeSwing = false;
    literal.limits.thumbTwistSpanDeg = 45.0f;
    for (float bend : {10.0f, 60.0f, 110.0f}) {
        for (float spread : {40.0f, 74.0f, 90.0f}) {
            HandControls c;
            c.thumb = {bend, spread, 0.0f, 0.0f};
            const float r = std::clamp((spread - 58.0f) / 32.0f, 0.0f, 1.0f), g = std::clamp(bend / 20.0f, 0.0f, 1.0f);
            const float psi = -90.0f + 45.0f * r * g;
            const glm::quat expected = glm::angleAxis(glm::radians(-bend), glm::vec3(0, 0, 1)) *
                                       glm::angleAxis(glm::radians(-spread), glm::vec3(1, 0, 0)) *
                                       glm::angleAxis(glm::radians(psi), glm::vec3(0, 0, 1));
            const glm::quat actual = forwardKinematics(literal, c, Side::Right).bodies[int(Body::ThumbMetacarpal)].rotation;
            EXPECT_GT(std::abs(glm::dot(actual, expected)), 1.0f - 1e-6f) << bend << " " << spread;
        }
    }
}

TEST_F(HandModelTest, ThumbMetacarpalPointsAlongSphericalDirection) {
    for (float bend : range(-25.0f, 120.0f, 10)) {
        for (float spread : range(10.0f, 90.0f, 8)) {
            HandControls c;
            c.thumb.bendDeg = bend;
            c.thumb.spreadDeg = spread;
            const HandPose pose = forwardKinematics(model, c, Side::Right);
            const glm::vec3 dir = glm::normalize(pose.bodies[int(Body::ThumbProximal)].position -
                                                 pose.bodies[int(Body::ThumbMetacarpal)].position);
            const float t = bend * kPi / 180.0f, p = spread * kPi / 180.0f;
            const glm::vec3 expected(std::sin(p) * std::sin(t), std::sin(p) * std::cos(t), std::cos(p));
            ASSERT_NEAR(glm::distance(dir, expected), 0.0f, 1e-5f) << bend << " " << spread;
        }
    }
}

TEST_F(HandModelTest, ConvergenceTwistsMatchTheSpec) {
    // SPEC §1.3: defaults give roughly θ = (−2.2°, 0°, 1.7°, 3.6°).
    EXPECT_NEAR(model.convergenceDeg[0], -2.2f, 0.1f);
    EXPECT_EQ(model.convergenceDeg[1], 0.0f);
    EXPECT_NEAR(model.convergenceDeg[2], 1.7f, 0.1f);
    EXPECT_NEAR(model.convergenceDeg[3], 3.6f, 0.1f);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(glm::distance(model.mcpPositionMm[i], model.mcpPositionMm[i + 1]),
                    model.dimensions.mcpSpacingMm[i], 1e-3f);
    }
    EXPECT_NEAR(model.mcpPositionMm[1].z, 0.446f * 190.0f, 1e-3f);
}

TEST_F(HandModelTest, BentFingersConvergeWithoutOverlap) {
    HandControls rest;
    HandControls bent;
    for (auto& f : bent.fingers) f.bend = 0.5f;  // MCP 90°, PIP and DIP straight
    const HandPose r = forwardKinematics(model, rest, Side::Right);
    const HandPose b = forwardKinematics(model, bent, Side::Right);
    const auto& d = model.dimensions;
    for (int i = 0; i < 3; ++i) {
        const int digit = i + 1;
        const int first = firstBodyOf(Digit(digit)), next = firstBodyOf(Digit(digit + 1));
        const float tipGapBent = glm::distance(b.tips[digit], b.tips[digit + 1]);
        const float tipGapRest = glm::distance(r.tips[digit], r.tips[digit + 1]);
        const float dipWidths = 0.5f * (d.dipWidthMm[i] + d.dipWidthMm[i + 1]);
        const float pipWidths = 0.5f * (d.pipWidthMm[i] + d.pipWidthMm[i + 1]);
        EXPECT_GE(tipGapBent, dipWidths) << "tips overlap between fingers " << digit << "," << digit + 1;
        EXPECT_LT(tipGapBent, tipGapRest) << "bent fingers do not converge";
        EXPECT_GE(glm::distance(b.bodies[first + 1].position, b.bodies[next + 1].position), pipWidths);
        EXPECT_GE(glm::distance(b.bodies[first + 2].position, b.bodies[next + 2].position), dipWidths);
    }
}

TEST_F(HandModelTest, LeftHandIsTheMirrorOfTheRight) {
    const glm::mat3 mirror(1, 0, 0, 0, -1, 0, 0, 0, 1);
    for (const HandControls& c : fingerSweep()) {
        if (c.fingers[0].bend != 0.75f && c.fingers[0].bend != -0.25f) continue;  // a slice keeps it quick
        HandControls controls = c;
        controls.thumb = {60.0f, 70.0f, 20.0f, 30.0f};
        const HandPose right = forwardKinematics(model, controls, Side::Right);
        const HandPose left = forwardKinematics(model, controls, Side::Left);
        EXPECT_EQ(left.side, Side::Left);
        for (int b = 0; b < kBodyCount; ++b) {
            ASSERT_NEAR(glm::distance(left.bodies[b].position, mirror * right.bodies[b].position), 0.0f, 1e-4f);
            const glm::mat3 l = glm::mat3_cast(left.bodies[b].rotation);
            const glm::mat3 r = mirror * glm::mat3_cast(right.bodies[b].rotation) * mirror;
            for (int col = 0; col < 3; ++col) ASSERT_NEAR(glm::distance(l[col], r[col]), 0.0f, 1e-5f);
        }
        for (int digit = 0; digit < kDigitCount; ++digit) {
            ASSERT_NEAR(glm::distance(left.tips[digit], mirror * right.tips[digit]), 0.0f, 1e-4f);
        }
    }
    const HandPose left = forwardKinematics(model, HandControls{}, Side::Left);
    EXPECT_LT(left.tips[0].y, 0.0f) << "the left thumb is on the -y side";
    const RigidTransform t{{1, 2, 3}, glm::normalize(glm::quat(0.9f, 0.1f, -0.3f, 0.2f))};
    const RigidTransform twice = mirrorToLeft(mirrorToLeft(t));
    EXPECT_EQ(twice.position, t.position);
    EXPECT_EQ(twice.rotation, t.rotation);
}

TEST_F(HandModelTest, LocalTransformsRecomposeThePose) {
    HandControls c;
    c.thumb = {80.0f, 50.0f, 25.0f, 30.0f};
    for (int f = 0; f < kFingerCount; ++f) c.fingers[f] = {5.0f * f - 5.0f, 0.3f + 0.1f * f, 0.4f};
    for (Side side : {Side::Right, Side::Left}) {
        const HandPose pose = forwardKinematics(model, c, side);
        const auto local = localTransforms(pose);
        for (int b = 1; b < kBodyCount; ++b) {
            const int parent = boneParent(Body(b));
            const RigidTransform world = compose(pose.bodies[parent], local[b]);
            ASSERT_NEAR(glm::distance(world.position, pose.bodies[b].position), 0.0f, 1e-4f);
            ASSERT_NEAR(std::abs(glm::dot(world.rotation, pose.bodies[b].rotation)), 1.0f, 1e-5f);
            // Phalanges hang at the end of their parent bone.
            if (parent != 0) {
                ASSERT_NEAR(glm::length(local[b].position), boneLengthMm(model, Body(parent)), 1e-3f);
            }
        }
        const auto rest = restLocalTransforms(model, side);
        const auto restAgain = localTransforms(forwardKinematics(model, HandControls{}, side));
        for (int b = 0; b < kBodyCount; ++b) EXPECT_EQ(rest[b].position, restAgain[b].position);
    }
}

TEST_F(HandModelTest, BonesCarryVrmNamesAndParents) {
    const auto right = handBones(Side::Right);
    const auto left = handBones(Side::Left);
    EXPECT_EQ(right[0].name, "rightHand");
    EXPECT_EQ(right[0].parent, -1);
    EXPECT_EQ(right[int(Body::ThumbMetacarpal)].name, "rightThumbMetacarpal");
    EXPECT_EQ(right[int(Body::IndexIntermediate)].name, "rightIndexIntermediate");
    EXPECT_EQ(right[int(Body::IndexIntermediate)].parent, int(Body::IndexProximal));
    EXPECT_EQ(right[int(Body::LittleDistal)].name, "rightLittleDistal");
    EXPECT_EQ(left[int(Body::MiddleProximal)].name, "leftMiddleProximal");
    EXPECT_EQ(left[int(Body::MiddleProximal)].parent, 0);
    for (int b = 1; b < kBodyCount; ++b) EXPECT_LT(right[b].parent, b) << "parents come first";
}

TEST_F(HandModelTest, InterpolationHoldsTheCorrelationsOnEveryFrame) {
    HandControls a;
    HandControls b;
    for (int f = 0; f < kFingerCount; ++f) {
        a.fingers[f] = {-10.0f, 0.1f, 0.9f};
        b.fingers[f] = {20.0f, 0.45f, 0.0f};
    }
    a.thumb = {0.0f, 40.0f, 0.0f, 0.0f};
    b.thumb = {90.0f, 90.0f, 40.0f, 60.0f};
    for (float t : range(0.0f, 1.0f, 20)) {
        const HandControls m = interpolate(a, b, t);
        const JointAngles j = jointAngles(model, m);
        for (const auto& f : j.fingers) {
            ASSERT_NEAR(f.dipDeg, 2.0f / 3.0f * f.pipDeg, 1e-3f);
            ASSERT_NEAR(f.twistDeg, fingerTwistDeg(f.spreadDeg), 1e-4f);
        }
        ASSERT_NEAR(j.thumb.twistDeg, thumbTwistDeg(model.limits, j.thumb.spreadDeg, j.thumb.bendDeg), 1e-4f);
    }
    const JointAngles start = jointAngles(model, interpolate(a, b, 0.0f));
    const JointAngles end = jointAngles(model, interpolate(a, b, 1.0f));
    EXPECT_EQ(start.fingers[0].pipDeg, jointAngles(model, a).fingers[0].pipDeg);
    EXPECT_EQ(end.thumb.twistDeg, jointAngles(model, b).thumb.twistDeg);
}

TEST_F(HandModelTest, SmallerHandScalesEveryPosition) {
    const HandModel small = buildHandModel(scaledHandDimensions(0.9f * 190.0f, 0.9f * 85.0f));
    HandControls c;
    c.thumb = {70.0f, 60.0f, 15.0f, 15.0f};
    for (int f = 0; f < kFingerCount; ++f) c.fingers[f] = {4.0f, 0.3f, 0.5f};
    const HandPose big = forwardKinematics(model, c, Side::Right);
    const HandPose little = forwardKinematics(small, c, Side::Right);
    for (int b = 0; b < kBodyCount; ++b) {
        ASSERT_NEAR(glm::distance(little.bodies[b].position, 0.9f * big.bodies[b].position), 0.0f, 1e-3f);
    }
    EXPECT_THROW(scaledHandDimensions(0.0f, 85.0f), std::invalid_argument);
}

}  // namespace
}  // namespace signstim::hand
