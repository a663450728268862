// Issue 21: a verb's keyframes within the signer's comfortable reach (stimuli/verbs/verb_reach.hpp).
// The arm below is synthetic (a round 600 mm arm at a made-up shoulder), not the default signer.
#include "stimuli/verbs/signing_space.hpp"
#include "stimuli/verbs/verb_reach.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

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


// ---- Out of the torso (clearOfTorso). A synthetic torso: one section from hip to neck, 340 mm
// wide and 210 deep about z = 0 (the default signer's chest is 340 by 216), and a hand as long
// and broad as the default one.
TorsoReach syntheticTorso() {
    TorsoReach torso;
    torso.sections = {{-400.0, 170.0, 105.0, 0.0}, {200.0, 170.0, 105.0, 0.0}};
    torso.hand = {30.0, 190.0, 42.5, 15.0};
    return torso;
}

// The palm frame with the fingers along `fingers` and the palm facing `palm` (signing space).
glm::dquat palmFrame(const glm::dvec3& fingers, const glm::dvec3& palm) {
    const glm::dvec3 z = glm::normalize(fingers);
    const glm::dvec3 x = glm::normalize(palm - glm::dot(palm, z) * z);
    return glm::quat_cast(glm::dmat3(x, glm::cross(z, x), z));
}

// The least gap between the torso's section (the stadium) and the hand, sampled: the segment
// from the heel to the fingertips and the rim of its elliptical section along it.
double handGapMm(const glm::dvec3& wrist, const glm::dquat& orientation, const TorsoReach& torso) {
    const TorsoSection& s = torso.sections.front();
    const double half = s.halfWidthMm - s.halfDepthMm;
    const glm::dvec3 f = orientation * glm::dvec3(0, 0, 1), p = orientation * glm::dvec3(1, 0, 0),
                     w = orientation * glm::dvec3(0, 1, 0);
    double gap = 1e30;
    for (double a = -torso.hand.backMm; a <= torso.hand.lengthMm; a += 5.0)
        for (int k = 0; k < 36; ++k) {
            const double angle = k * 3.14159265358979323846 / 18.0;
            const glm::dvec3 q = wrist + a * f + std::cos(angle) * torso.hand.halfWidthMm * w +
                                 std::sin(angle) * torso.hand.halfThicknessMm * p;
            const double x = std::clamp(q.x, -half, half);
            gap = std::min(gap, std::hypot(q.x - x, q.z - s.zMm) - s.halfDepthMm);
        }
    return gap;
}

TEST(VerbReach, AKeyInsideTheTorsoComesOutWithItsHandAndTheClearance) {
    const TorsoReach torso = syntheticTorso();
    // GIVE vector s=-1 o=-0.8's keys as the model gives them (rounded): the left hand behind the
    // right one, in the torso, reaching across to the right; SEND vector s=-1 o=-0.5's first
    // right key at the chest. Fingers up and forward, palms in; and pointing at the body.
    struct Key {
        glm::dvec3 wrist;
        HandSide side;
        glm::dquat orientation;
    };
    const glm::dquat up = palmFrame({-0.14, 0.92, 0.37}, {0.3, -0.4, 0.9});
    const glm::dquat atBody = palmFrame({0.0, -0.2, -1.0}, {0.0, -1.0, 0.2});
    for (const Key& key : {Key{{204.0, -100.0, -12.0}, HandSide::Left, up}, Key{{34.0, -88.0, 42.0}, HandSide::Left, up},
                           Key{{19.0, 48.0, 147.0}, HandSide::Right, up}, Key{{19.0, 48.0, 147.0}, HandSide::Right, atBody}}) {
        EXPECT_LT(handGapMm(key.wrist, key.orientation, torso), torso.clearanceMm);
        const glm::dvec3 out = clearOfTorso(key.wrist, key.orientation, key.side, torso);
        EXPECT_GE(handGapMm(out, key.orientation, torso), torso.clearanceMm - 0.5) << key.wrist.x << " " << key.wrist.z;
        EXPECT_EQ(out.y, key.wrist.y);  // out along the torso's normal, in the horizontal plane
        EXPECT_GT(out.z, key.wrist.z);  // forward: in front of the body, not behind it
    }
    // The crossing hand beside the far flank comes out forward more than sideways: its arm passes
    // in front of the chest.
    const glm::dvec3 crossing = clearOfTorso({204.0, -100.0, -12.0}, up, HandSide::Left, torso);
    EXPECT_GT(crossing.z - (-12.0), crossing.x - 204.0);
    // The right hand 85 mm beyond the left flank, its forearm across the chest, 45 mm behind its
    // front: clear of the torso itself, but not of the slope its forearm turns back by.
    const glm::dvec3 across = clearOfTorso({-255.0, 0.0, 60.0}, up, HandSide::Right, torso);
    EXPECT_GT(across.z, 60.0 + 10.0);
    // MEET vector s=-1 o=-0.9's left key (rounded), 35 mm behind the chest's mid-plane: out in
    // front, where signing is, not out of the flank; and a target moving through the body's
    // back half moves its key continuously (no step over 10 mm for 1 mm).
    const glm::dvec3 meet = clearOfTorso({-79.0, 0.0, -27.0}, up, HandSide::Left, torso);
    EXPECT_GT(meet.z, 105.0);
    for (double x = -150.0; x < 150.0; x += 1.0)
        for (double z = -100.0; z <= 100.0; z += 10.0)
            EXPECT_LT(glm::distance(clearOfTorso({x, 0.0, z}, up, HandSide::Left, torso),
                                    clearOfTorso({x + 1.0, 0.0, z}, up, HandSide::Left, torso)),
                      10.0)
                << x << " " << z;
    // Its own hand there may hang beside its flank: pushed sideways, out of the flank only.
    const glm::dvec3 own = clearOfTorso({204.0, -100.0, -12.0}, up, HandSide::Right, torso);
    EXPECT_GT(own.x - 204.0, std::abs(own.z - (-12.0)));
}

TEST(VerbReach, AKeyClearOfTheTorsoStaysWhereItIs) {
    const TorsoReach torso = syntheticTorso();
    const glm::dquat up = palmFrame({0.0, 1.0, 0.2}, {-1.0, 0.0, 0.0});
    for (double p = -1.0; p <= 1.0 + 1e-9; p += 0.1)  // the arc's loci, 500 mm from the chest
        for (const HandSide side : {HandSide::Right, HandSide::Left})
            EXPECT_EQ(clearOfTorso(arcPoint(p), up, side, torso), arcPoint(p)) << p;
    // Beside its own flank, 120 mm out: the resting arm's place.
    EXPECT_EQ(clearOfTorso({290.0, -300.0, 0.0}, up, HandSide::Right, torso), glm::dvec3(290.0, -300.0, 0.0));
    // Without a torso, nothing moves.
    EXPECT_EQ(clearOfTorso({0.0, 0.0, 0.0}, up, HandSide::Right, TorsoReach{}), glm::dvec3(0.0));
}

// The pose is a function of the timeline and t, and nearby loci stay nearby: the pushed key
// moves continuously with the target, at most a few times as far as the target moves, from
// the torso's front outward. (Inside the body the push turns faster with the target about the
// stadium's round ends' centres, as 1/r there; still continuous.)
TEST(VerbReach, TheTorsosPushChangesContinuouslyWithTheTarget) {
    const TorsoReach torso = syntheticTorso();
    const glm::dquat orientations[] = {palmFrame({0.0, 1.0, 0.3}, {0.0, 0.0, 1.0}), palmFrame({0.6, 0.0, -0.8}, {0.0, -1.0, 0.0}),
                                       palmFrame({-0.3, -0.5, 0.8}, {0.1, -0.8, -0.5})};
    constexpr double kStepMm = 2.0;
    double worst = 0.0;
    std::string where;
    for (const glm::dquat& q : orientations)
        for (const HandSide side : {HandSide::Right, HandSide::Left})
            for (double z = 100.0; z <= 400.0; z += 25.0)
                for (double x = -450.0; x < 450.0; x += kStepMm) {
                    const glm::dvec3 a = clearOfTorso({x, -50.0, z}, q, side, torso);
                    const glm::dvec3 b = clearOfTorso({x + kStepMm, -50.0, z}, q, side, torso);
                    const glm::dvec3 c = clearOfTorso({x, -50.0, z + kStepMm}, q, side, torso);
                    const double slope = std::max(glm::distance(a, b), glm::distance(a, c)) / kStepMm;
                    if (slope > worst) {
                        worst = slope;
                        where = std::to_string(x) + ", " + std::to_string(z) + (side == HandSide::Right ? " right" : " left");
                    }
                }
    EXPECT_LE(worst, 4.0) << where;
}

TEST(VerbReach, BothHandsOfAPairLeaveTheTorsoTogetherButNotATouchOfTheBodyOrAnAuthoredKey) {
    SignerReach reach;
    reach.torso = syntheticTorso();
    const glm::dquat up = palmFrame({-0.14, 0.92, 0.37}, {0.3, -0.4, 0.9});
    VerbPerformance performance;
    performance.version = VerbVersion::Vector;
    // GIVE vector s=-1 o=-0.8 (rounded): the right hand clear, the left one in the torso.
    HandTrack r{HandSide::Right, {{0.0, HandPose{{391.0, -81.0, 161.0}, up}, "flat-O", 0, ""}, {0.55, HandPose{{183.0, -84.0, 239.0}, up}, "flat-O", 0, ""}}};
    HandTrack l{HandSide::Left, {{0.0, HandPose{{204.0, -100.0, -12.0}, up}, "flat-O", 0, ""}, {0.55, HandPose{{34.0, -88.0, 42.0}, up}, "flat-O", 0, ""}}};
    performance.hands = {r, l};
    const VerbPerformance out = withinReach(performance, reach);
    for (std::size_t k = 0; k < 2; ++k) {
        const glm::dvec3 right = out.hands[0].keyframes[k].pose.positionMm, left = out.hands[1].keyframes[k].pose.positionMm;
        EXPECT_GE(handGapMm(left, up, reach.torso), reach.torso.clearanceMm - 0.5) << k;
        // The pair keeps its shape: both moved by one offset.
        const glm::dvec3 before = performance.hands[1].keyframes[k].pose.positionMm - performance.hands[0].keyframes[k].pose.positionMm;
        EXPECT_LT(glm::distance(left - right, before), 1e-9) << k;
        EXPECT_GT(right.z, performance.hands[0].keyframes[k].pose.positionMm.z + 10.0) << k;
    }
    // A verb that touches the body (TELL from the chin) and the authored versions keep their keys.
    VerbPerformance touching = performance;
    touching.contact.body = true;
    VerbPerformance authored = performance;
    authored.version = VerbVersion::Animator;
    for (const VerbPerformance& p : {touching, authored})
        EXPECT_EQ(withinReach(p, reach).hands[1].keyframes[0].pose.positionMm, glm::dvec3(204.0, -100.0, -12.0));
}

}  // namespace
}  // namespace signstim::stimuli
