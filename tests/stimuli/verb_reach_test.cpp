// Issue 21: a verb's keyframes within the signer's comfortable reach (stimuli/verbs/verb_reach.hpp).
// The arm below is synthetic (a round 600 mm arm at a made-up shoulder), not the default signer.
#include "stimuli/verbs/signing_space.hpp"
#include "stimuli/verbs/verb_reach.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>

namespace signstim::stimuli {
namespace {

const ArmReach kArm{{180.0, 130.0, 0.0}, 600.0};  // synthetic

TEST(VerbReach, TargetsInsideTheKneeAreKeptAsTheyAre) {
    const glm::dvec3 near = kArm.shoulderMm + glm::dvec3(-100.0, -200.0, 300.0);  // 374 mm < 0.8 · 600
    const glm::dvec3 drawn = withinComfortableReach(near, kArm, kComfortableReachFraction, kReachKneeFraction);
    EXPECT_EQ(drawn, near);
}

TEST(VerbReach, FarTargetsAreDrawnTowardTheShoulderAndNeverPastTheComfortableReach) {
    for (double p = -1.0; p <= 1.0 + 1e-9; p += 0.1) {
        // The arc of SPEC §3.1, 1.5 and 2 times as far: the right hand's far loci.
        for (double scale : {1.0, 1.5, 2.0}) {
            const glm::dvec3 target = arcPoint(p) * scale;
            const glm::dvec3 drawn = withinComfortableReach(target, kArm, kComfortableReachFraction, kReachKneeFraction);
            const double before = glm::distance(target, kArm.shoulderMm);
            const double after = glm::distance(drawn, kArm.shoulderMm);
            EXPECT_LE(after, kComfortableReachFraction * kArm.lengthMm + 1e-9) << p << " x" << scale;
            EXPECT_LE(after, before + 1e-9);
            // On the line from the shoulder to the target: the hand reaches toward the locus.
            EXPECT_GT(glm::dot(glm::normalize(drawn - kArm.shoulderMm), glm::normalize(target - kArm.shoulderMm)),
                      1.0 - 1e-12);
        }
    }
}

TEST(VerbReach, DrawnDistanceGrowsWithTheTargetsDistanceAndIsContinuousAtTheKnee) {
    const glm::dvec3 direction = glm::normalize(glm::dvec3(-1.0, 0.0, 0.4));
    const double knee = kReachKneeFraction * kArm.lengthMm;
    double previous = -1.0;
    for (double d = knee - 50.0; d <= 2.0 * kArm.lengthMm; d += 1.0) {
        const double after = glm::distance(
            withinComfortableReach(kArm.shoulderMm + d * direction, kArm, kComfortableReachFraction, kReachKneeFraction),
            kArm.shoulderMm);
        if (previous >= 0.0) {
            EXPECT_GT(after, previous) << d;               // loci at different depths stay apart
            EXPECT_LE(after - previous, 1.0 + 1e-9) << d;  // slope at most 1: no jump at the knee
        }
        previous = after;
    }
}

TEST(VerbReach, EveryKeyframeOfEveryHandIsWithinItsArmsReachAndNothingElseChanges) {
    VerbPerformance performance;
    performance.version = VerbVersion::Point;
    for (HandSide side : {HandSide::Right, HandSide::Left}) {
        HandTrack track;
        track.side = side;
        track.keyframes.push_back({0.0, HandPose{arcPoint(-1.0), {1.0, 0.0, 0.0, 0.0}}, "B", 0, ""});
        track.keyframes.push_back({0.5, HandPose{arcPoint(1.0), {0.0, 1.0, 0.0, 0.0}}, "5", 0, ""});
        performance.hands.push_back(track);
    }
    SignerReach reach;
    reach.right = kArm;
    ArmReach left = kArm;
    left.shoulderMm.x = -left.shoulderMm.x;
    reach.left = left;
    const VerbPerformance drawn = withinReach(performance, reach);
    ASSERT_EQ(drawn.hands.size(), 2u);
    for (std::size_t h = 0; h < 2; ++h) {
        const ArmReach& arm = *reach.arm(drawn.hands[h].side);
        for (std::size_t k = 0; k < 2; ++k) {
            const PerformanceKeyframe& a = performance.hands[h].keyframes[k];
            const PerformanceKeyframe& b = drawn.hands[h].keyframes[k];
            EXPECT_LE(glm::distance(b.pose.positionMm, arm.shoulderMm), kComfortableReachFraction * arm.lengthMm + 1e-9);
            EXPECT_EQ(a.timeSeconds, b.timeSeconds);
            EXPECT_EQ(a.handshape, b.handshape);
            EXPECT_EQ(a.pose.orientation, b.pose.orientation);
        }
    }
    // Each hand is drawn toward its own shoulder: the far left locus is across the body for the
    // right hand (drawn in) and on the left hand's own side (nearer, drawn less or not at all).
    const double rightMoved = glm::distance(drawn.hands[0].keyframes[0].pose.positionMm, arcPoint(-1.0));
    const double leftMoved = glm::distance(drawn.hands[1].keyframes[0].pose.positionMm, arcPoint(-1.0));
    EXPECT_GT(rightMoved, leftMoved);
    // Without a reach the performance is as it was.
    EXPECT_EQ(withinReach(performance, SignerReach{}).hands[0].keyframes[0].pose.positionMm, arcPoint(-1.0));
}

// COPY point s=1 o=-0.9 as the point model gives it (rounded): from the far left to the right
// side, its straight path 128 mm from the right shoulder joint of the default signer, nearer
// than the folded arm's 187 mm. The arm here is the default signer's, written out (synthetic).
TEST(VerbReach, APathNearerTheShoulderThanTheFoldedArmAllowsIsMovedForwardWithBothTouchingHands) {
    const ArmReach right{{175.0, 130.0, 0.0}, 580.0, 187.0};
    const ArmReach left{{-175.0, 130.0, 0.0}, 580.0, 187.0};
    SignerReach reach;
    reach.right = right;
    reach.left = left;
    VerbPerformance performance;
    performance.version = VerbVersion::Vector;
    performance.contact.hands = true;
    HandTrack r{HandSide::Right, {{0.0, HandPose{{-338.0, 25.0, 217.0}, {}}, "B", 0, ""}, {0.55, HandPose{{333.0, 4.0, -8.0}, {}}, "B", 0, ""}}};
    HandTrack l{HandSide::Left, {{0.0, HandPose{{-314.0, -37.0, 102.0}, {}}, "B", 0, ""}, {0.55, HandPose{{-313.0, -39.0, 112.0}, {}}, "B", 0, ""}}};
    performance.hands = {r, l};
    const VerbPerformance drawn = withinReach(performance, reach);
    const glm::dvec3 a = drawn.hands[0].keyframes[0].pose.positionMm, b = drawn.hands[0].keyframes[1].pose.positionMm;
    double nearest = 1e30;
    for (double u = 0.0; u <= 1.0; u += 0.001) nearest = std::min(nearest, glm::distance(a + u * (b - a), right.shoulderMm));
    EXPECT_GE(nearest, right.foldedMm + kFoldedMarginMm - 1.0);
    EXPECT_LE(glm::distance(a, right.shoulderMm), kComfortableReachFraction * right.lengthMm + 1e-9);
    // The left hand moved forward as far as the right one where the path needed it: the touch kept.
    const double rightForward = b.z - (-8.0);
    EXPECT_GT(rightForward, 10.0);
    EXPECT_NEAR(drawn.hands[1].keyframes[1].pose.positionMm.z - 112.0, rightForward, 1.0);
}

}  // namespace
}  // namespace signstim::stimuli
