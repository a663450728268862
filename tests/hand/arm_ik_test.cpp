// Arm IK: reach accuracy, limits, natural elbow, mirror symmetry, continuity over a sweep.
#include "hand/arm_ik.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace signstim::hand;

namespace {
constexpr float kDeg = 3.14159265358979323846f / 180.0f;

glm::quat axes(const glm::vec3& x, const glm::vec3& z) {
    return glm::normalize(glm::quat_cast(glm::mat3(x, glm::cross(z, x), z)));
}

// Right hand in front of the chest, palm facing left (medial), fingers forward: a neutral
// signing orientation.
glm::quat palmInFingersForward() { return axes({1, 0, 0}, {0, 0, 1}); }

// The mirror of a right-hand target for the left arm (body x -> -x; the left hand's frame is
// the mirror of the right hand's, SPEC §1.1).
glm::quat mirrorRotation(const glm::quat& q) {
    const glm::mat3 m(glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1));
    const glm::mat3 f(glm::vec3(1, 0, 0), glm::vec3(0, -1, 0), glm::vec3(0, 0, 1));
    return glm::normalize(glm::quat_cast(m * glm::mat3_cast(q) * f));
}

void expectWithinLimits(const ArmModel& arm, const ArmPose& p) {
    EXPECT_TRUE(arm.limits.elbowFlexion.contains(p.elbowFlexionDeg, 0.01f)) << p.elbowFlexionDeg;
    EXPECT_TRUE(arm.limits.supination.contains(p.supinationDeg, 0.01f)) << p.supinationDeg;
    EXPECT_TRUE(arm.limits.wristFlexion.contains(p.wristFlexionDeg, 0.01f)) << p.wristFlexionDeg;
    EXPECT_TRUE(arm.limits.wristUlnarDeviation.contains(p.wristUlnarDeviationDeg, 0.01f))
        << p.wristUlnarDeviationDeg;
}
}  // namespace

TEST(ArmIk, ReachableTargetsAreReachedWithExactSegmentLengths) {
    for (Side side : {Side::Right, Side::Left}) {
        const ArmModel arm = defaultArmModel(side);
        const float mirror = side == Side::Right ? 1.0f : -1.0f;
        int count = 0;
        for (float x = -250; x <= 250; x += 50)
            for (float y = -200; y <= 250; y += 50)
                for (float z = 150; z <= 450; z += 50) {
                    const glm::vec3 wrist{mirror * x, y, z};
                    const float reach = glm::length(wrist - arm.shoulderMm);
                    if (reach > 560.0f || reach < 200.0f) continue;  // elbow limits: ~187..580 mm
                    const ArmPose p = solveArm(arm, {wrist, side == Side::Right
                                                                ? palmInFingersForward()
                                                                : mirrorRotation(palmInFingersForward())});
                    ++count;
                    EXPECT_TRUE(p.reachable);
                    EXPECT_LT(p.reachErrorMm, 0.05f);
                    EXPECT_NEAR(glm::length(p.elbowMm - p.shoulderMm), arm.upperArmLengthMm, 0.05f);
                    EXPECT_NEAR(glm::length(p.wristMm - p.elbowMm), arm.forearmLengthMm, 0.05f);
                    // The frames' z axes run along the bones.
                    EXPECT_GT(glm::dot(p.upperArm * glm::vec3(0, 0, 1),
                                       glm::normalize(p.elbowMm - p.shoulderMm)), 0.9999f);
                    EXPECT_GT(glm::dot(p.forearm * glm::vec3(0, 0, 1),
                                       glm::normalize(p.wristMm - p.elbowMm)), 0.9999f);
                    expectWithinLimits(arm, p);
                }
        EXPECT_GT(count, 200);
    }
}

TEST(ArmIk, ComfortableOrientationsAreReachedExactly) {
    const ArmModel arm = defaultArmModel(Side::Right);
    // Palm in / palm down / palm forward (fingers up) / palm up / palm down pointing left.
    const std::vector<glm::quat> targets{
        palmInFingersForward(), axes({0, -1, 0}, {0, 0, 1}), axes({0, 0, 1}, {0, 1, 0}),
        axes({0, 1, 0}, {0, 0, 1}), axes({0, -1, 0}, glm::normalize(glm::vec3(1, 0, 1)))};
    for (const glm::quat& q : targets) {
        // Beside the right shoulder, where fingerspelling happens.
        const ArmPose p = solveArm(arm, {{-200, 100, 300}, q});
        EXPECT_LT(p.orientationErrorDeg, 1.0f);
        EXPECT_LT(rotationAngleDeg(p.hand, q), 1.0f);
        expectWithinLimits(arm, p);
    }
}

TEST(ArmIk, UnreachableTargetIsApproachedAlongItsDirectionAndReported) {
    const ArmModel arm = defaultArmModel(Side::Right);
    const glm::vec3 far{-200, 100, 1500};
    const ArmPose p = solveArm(arm, {far, palmInFingersForward()});
    EXPECT_FALSE(p.reachable);
    const float d = glm::length(far - arm.shoulderMm);
    EXPECT_NEAR(p.reachErrorMm, d - (arm.upperArmLengthMm + arm.forearmLengthMm), 0.1f);
    EXPECT_GT(glm::dot(glm::normalize(p.wristMm - p.shoulderMm), glm::normalize(far - arm.shoulderMm)),
              0.99999f);
    EXPECT_NEAR(p.elbowFlexionDeg, 0.0f, 0.05f);

    // Too close: the elbow stops at its flexion limit.
    const ArmPose close = solveArm(arm, {arm.shoulderMm + glm::vec3(0, -10, 40), palmInFingersForward()});
    EXPECT_FALSE(close.reachable);
    EXPECT_NEAR(close.elbowFlexionDeg, arm.limits.elbowFlexion.maxDeg, 0.05f);
}

TEST(ArmIk, OrientationBeyondTheWristIsClampedAndReported) {
    const ArmModel arm = defaultArmModel(Side::Right);
    // Hand bent straight back toward the shoulder: no swivel makes that possible.
    const glm::vec3 wrist{-150, 0, 350};
    const glm::vec3 back = glm::normalize(arm.shoulderMm - wrist);
    const glm::vec3 x = glm::normalize(glm::cross(back, glm::vec3(0, 1, 0)));
    const ArmPose p = solveArm(arm, {wrist, axes(x, back)});
    EXPECT_TRUE(p.wristLimited);
    EXPECT_GT(p.orientationErrorDeg, 10.0f);
    expectWithinLimits(arm, p);
    EXPECT_LT(p.reachErrorMm, 0.05f);  // position still reached
}

TEST(ArmIk, WristAnglesRoundTrip) {
    for (Side side : {Side::Right, Side::Left}) {
        const glm::quat forearm = glm::angleAxis(0.7f, glm::normalize(glm::vec3(0.3f, -1, 0.2f)));
        for (float sup = -80; sup <= 85; sup += 33)
            for (float flex = -60; flex <= 75; flex += 27)
                for (float dev = -18; dev <= 30; dev += 16) {
                    const WristAngles w{sup, flex, dev};
                    const WristAngles back = wristAngles(side, forearm, handFrame(side, forearm, w));
                    EXPECT_NEAR(back.supinationDeg, sup, 1e-2f);
                    EXPECT_NEAR(back.flexionDeg, flex, 1e-2f);
                    EXPECT_NEAR(back.ulnarDeviationDeg, dev, 1e-2f);
                }
    }
}

TEST(ArmIk, TPoseWithTheElbowBackGivesTheRestFrameEverywhere) {
    for (Side side : {Side::Right, Side::Left}) {
        ArmModel arm = defaultArmModel(side);
        arm.poleOutward = 0.0f;  // pole straight back: the elbow of the canonical T-pose
        arm.poleBackward = 100.0f;
        ArmSolveOptions options;
        options.wristComfortWeight = 0.0f;
        const float out = side == Side::Right ? -1.0f : 1.0f;
        const glm::vec3 wrist =
            arm.shoulderMm + glm::vec3(out * (arm.upperArmLengthMm + arm.forearmLengthMm), 0, 0);
        const ArmPose p = solveArm(arm, {wrist, restFrame(side)}, options);
        EXPECT_LT(rotationAngleDeg(p.upperArm, restFrame(side)), 1.0f);
        EXPECT_LT(rotationAngleDeg(p.forearm, restFrame(side)), 1.0f);
        EXPECT_LT(rotationAngleDeg(p.hand, restFrame(side)), 0.01f);  // the wrist makes up the rest
        EXPECT_NEAR(p.supinationDeg, 0.0f, 1.0f);
    }
}

TEST(ArmIk, NaturalElbowHangsDownAndOutInSigningSpace) {
    const ArmModel arm = defaultArmModel(Side::Right);
    ArmSolveOptions options;
    options.wristComfortWeight = 0.0f;  // the pole rule alone
    for (float x : {-200.0f, -50.0f, 100.0f})
        for (float y : {-100.0f, 0.0f, 50.0f}) {
            const ArmPose p = solveArm(arm, {{x, y, 300}, palmInFingersForward()}, options);
            EXPECT_LT(p.elbowMm.y, p.shoulderMm.y) << x << "," << y;
            // Outside the torso, or in front of it.
            EXPECT_TRUE(p.elbowMm.x < -105.0f || p.elbowMm.z > arm.torsoFrontMm) << p.elbowMm.x;
            EXPECT_LT(p.elbowMm.z, p.wristMm.z);
            EXPECT_FALSE(p.shoulderLimited);
        }
}

TEST(ArmIk, WristComfortTermReducesWristStrain) {
    const ArmModel arm = defaultArmModel(Side::Right);
    ArmSolveOptions poleOnly;
    poleOnly.wristComfortWeight = 0.0f;
    float strainPole = 0.0f, strainComfort = 0.0f;
    for (float x : {-200.0f, -50.0f, 100.0f}) {
        const ArmTarget target{{x, 0, 300}, axes({0, -1, 0}, glm::normalize(glm::vec3(1, 0, 1)))};
        const ArmPose a = solveArm(arm, target, poleOnly);
        const ArmPose b = solveArm(arm, target);
        strainPole += a.orientationErrorDeg + std::fabs(a.wristUlnarDeviationDeg) + std::fabs(a.wristFlexionDeg);
        strainComfort += b.orientationErrorDeg + std::fabs(b.wristUlnarDeviationDeg) + std::fabs(b.wristFlexionDeg);
        EXPECT_TRUE(b.elbowMm.x < -100.0f || b.elbowMm.z > arm.torsoFrontMm)
            << "comfort never pushes the elbow into the torso";
    }
    EXPECT_LT(strainComfort, strainPole);
}

TEST(ArmIk, LeftArmIsTheMirrorOfTheRightArm) {
    const ArmModel right = defaultArmModel(Side::Right), left = defaultArmModel(Side::Left);
    const std::vector<glm::vec3> wrists{{-100, 0, 300}, {50, 150, 250}, {-300, -150, 200}};
    for (const glm::vec3& w : wrists) {
        const glm::quat q = axes(glm::normalize(glm::vec3(0.5f, -1, 0.1f)), glm::vec3(0, 0, 1));
        const ArmPose r = solveArm(right, {w, q});
        const ArmPose l = solveArm(left, {{-w.x, w.y, w.z}, mirrorRotation(q)});
        EXPECT_NEAR(l.elbowMm.x, -r.elbowMm.x, 0.5f);
        EXPECT_NEAR(l.elbowMm.y, r.elbowMm.y, 0.5f);
        EXPECT_NEAR(l.elbowMm.z, r.elbowMm.z, 0.5f);
        EXPECT_LT(rotationAngleDeg(l.hand, mirrorRotation(r.hand)), 0.5f);
        EXPECT_NEAR(l.supinationDeg, r.supinationDeg, 0.5f);
        EXPECT_NEAR(l.wristUlnarDeviationDeg, r.wristUlnarDeviationDeg, 0.5f);
    }
}

TEST(ArmIk, SweptPathHasNoElbowFlipsAndStaysWithinLimits) {
    // The right wrist sweeps the signing arc from the far right to across the body, and back
    // up and over, while the palm turns from down to up: 400 frames.
    const ArmModel arm = defaultArmModel(Side::Right);
    ArmSolveOptions options;
    std::optional<ArmPose> previous;
    float maxElbowStepMm = 0.0f, maxWristStepMm = 0.0f;
    for (int i = 0; i <= 400; ++i) {
        const float t = static_cast<float>(i) / 400.0f;
        const float psi = (-80.0f + 140.0f * t) * kDeg;  // arc angle, toward the left
        const glm::vec3 wrist{-180.0f + 420.0f * std::sin(psi) * 0.8f,
                              -60.0f + 220.0f * std::sin(3.14159f * t), 200.0f + 200.0f * std::cos(psi)};
        const float roll = (-60.0f + 150.0f * t) * kDeg;
        const glm::quat q = glm::angleAxis(roll, glm::vec3(0, 0, 1)) * axes({0, -1, 0}, {0, 0, 1});
        if (previous) options.previousElbowDirection = previous->elbowDirection;
        const ArmPose p = solveArm(arm, {wrist, q}, options);
        expectWithinLimits(arm, p);
        if (previous) {
            maxElbowStepMm = std::max(maxElbowStepMm, glm::length(p.elbowMm - previous->elbowMm));
            maxWristStepMm = std::max(maxWristStepMm, glm::length(p.wristMm - previous->wristMm));
            const float swivelStep = std::acos(std::min(1.0f, glm::dot(p.elbowDirection, previous->elbowDirection)));
            EXPECT_LE(swivelStep / kDeg, options.maxSwivelStepDeg + 5.0f) << "frame " << i;
        }
        previous = p;
    }
    EXPECT_LT(maxWristStepMm, 10.0f);
    // The elbow moves smoothly with the wrist: no flip (a flip moves it by hundreds of mm).
    EXPECT_LT(maxElbowStepMm, 4.0f * maxWristStepMm + 5.0f) << maxElbowStepMm;
}

TEST(ArmIk, ContinuityWindowKeepsTheElbowWhereTheGlobalOptimumJumps) {
    // Without the previous elbow the solver may pick a far swivel; with it, it may not.
    const ArmModel arm = defaultArmModel(Side::Right);
    const ArmTarget target{{-100, 50, 300}, palmInFingersForward()};
    const ArmPose free = solveArm(arm, target);
    ArmSolveOptions options;
    const glm::vec3 forced = -free.elbowDirection;  // pretend the previous frame was opposite
    options.previousElbowDirection = forced;
    const ArmPose held = solveArm(arm, target, options);
    const float step = std::acos(std::min(1.0f, glm::dot(held.elbowDirection, forced))) / kDeg;
    EXPECT_LE(step, options.maxSwivelStepDeg + 0.5f);
    EXPECT_LT(held.reachErrorMm, 0.05f);
}

// reachedWristMm is where solveArm puts the wrist, to the bit (the transition pacer times the
// wrists with it instead of full solves): near, far beyond reach, too close to the shoulder.
TEST(ArmIk, ReachedWristIsTheSolvedWristToTheBit) {
    int count = 0;
    for (Side side : {Side::Right, Side::Left}) {
        const ArmModel arm = defaultArmModel(side);
        for (float x = -700; x <= 700; x += 70)
            for (float y = -600; y <= 600; y += 60)
                for (float z = -100; z <= 700; z += 80) {
                    const ArmTarget target{arm.shoulderMm + glm::vec3(x, y, z) * (x > 0.0f ? 1.0f : 0.2f),
                                           palmInFingersForward()};
                    const glm::vec3 reached = reachedWristMm(arm, target), solved = solveArm(arm, target).wristMm;
                    ASSERT_EQ(reached.x, solved.x);
                    ASSERT_EQ(reached.y, solved.y);
                    ASSERT_EQ(reached.z, solved.z);
                    count += glm::length(target.wristMm - solved) > 0.5f;
                }
    }
    EXPECT_GT(count, 100);  // the clamped reach is among the cases
}

// Issue 21: "elbow never above shoulder height unless the sign's citation form puts the hand
// above the head". Over a grid of wrists from the waist to above the head, and orientations a
// signer asks at the face (fingers left and palm in, as across the forehead; fingers up and palm
// forward, as beside the temple; fingers forward), the elbow stays at or below its shoulder
// joint unless the wrist is higher than elbowRiseWristAboveShoulderMm above it, and then rises
// no more than the wrist does beyond that; where no elbow is that low (the wrist close above
// the shoulder), it is the lowest the arm allows. Without the cap (the rise set out of reach)
// the same grid lifts the elbow, so the test sees the cap work.
TEST(ArmIk, TheElbowStaysAtOrBelowTheShoulderUnlessTheWristIsAboveTheHead) {
    const ArmModel arm = defaultArmModel(Side::Right);
    ArmModel uncapped = arm;
    uncapped.elbowRiseWristAboveShoulderMm = -1e6f;
    const glm::quat orientations[] = {axes({0, 0, -1}, {1, 0, 0}), axes({0, 0, 1}, {0, 1, 0}), palmInFingersForward()};
    const float a = arm.upperArmLengthMm, b = arm.forearmLengthMm;
    int checked = 0, capBinds = 0, overHead = 0;
    for (float y = -100.0f; y <= 540.0f; y += 40.0f)
        for (float x = -360.0f; x <= 40.0f; x += 50.0f)
            for (float z = 100.0f; z <= 400.0f; z += 60.0f)
                for (const glm::quat& q : orientations) {
                    const ArmTarget target{{x, y, z}, q};
                    const ArmPose p = solveArm(arm, target);
                    // The lowest elbow the arm allows for this wrist: the lowest point of the
                    // elbow's circle about the shoulder-wrist axis.
                    const glm::vec3 toWrist = p.wristMm - arm.shoulderMm;
                    const float d = glm::length(toWrist);
                    const glm::vec3 axis = toWrist / d;
                    const float cosAlpha = std::clamp((a * a + d * d - b * b) / (2.0f * a * d), -1.0f, 1.0f);
                    const float lowest = a * cosAlpha * axis.y - a * std::sqrt(1.0f - cosAlpha * cosAlpha) *
                                                                     std::sqrt(std::max(0.0f, 1.0f - axis.y * axis.y));
                    const float wristOverHead =
                        std::max(0.0f, p.wristMm.y - arm.shoulderMm.y - arm.elbowRiseWristAboveShoulderMm);
                    const float allowed = std::max(wristOverHead, lowest);
                    EXPECT_LE(p.elbowMm.y - arm.shoulderMm.y, allowed + 0.5f)
                        << "wrist " << x << " " << y << " " << z << ", lowest elbow " << lowest;
                    expectWithinLimits(arm, p);
                    ++checked;
                    if (wristOverHead > 0.0f) ++overHead;
                    if (solveArm(uncapped, target).elbowMm.y - arm.shoulderMm.y > allowed + 20.0f) ++capBinds;
                }
    EXPECT_GT(checked, 1000);
    EXPECT_GT(overHead, 50);
    EXPECT_GT(capBinds, 50) << "the grid never asks for a high elbow: it does not test the cap";
    std::printf("%d targets, %d with the wrist above the head, %d where the cap lowers the elbow by more than 20 mm\n",
                checked, overHead, capBinds);
}

// The cap is continuous in the wrist's height: as a raised hand passes the top of the head, the
// elbow's allowance grows from zero, with no jump.
TEST(ArmIk, TheElbowsAllowanceGrowsContinuouslyAsTheWristPassesTheTopOfTheHead) {
    const ArmModel arm = defaultArmModel(Side::Right);
    const glm::quat q = axes({0, 0, 1}, {0, 1, 0});  // fingers up, palm forward
    float previous = 0.0f;
    float highest = -1e9f;
    for (int i = 0; i <= 200; ++i) {
        const float y = arm.shoulderMm.y + arm.elbowRiseWristAboveShoulderMm - 60.0f + 1.0f * static_cast<float>(i);
        const ArmPose p = solveArm(arm, {{-260.0f, y, 120.0f}, q});
        const float elbow = p.elbowMm.y - arm.shoulderMm.y;
        if (i > 0) {
            EXPECT_LT(std::fabs(elbow - previous), 5.0f) << "wrist at " << y;
        }
        previous = elbow;
        highest = std::max(highest, elbow);
    }
    EXPECT_GT(highest, 20.0f);  // the hand well above the head takes the elbow up with it
}
