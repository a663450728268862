#pragma once
// Issue 21: a verb's hands within the signer's comfortable reach. The point and vector models
// predict loci on the arc of SPEC §3.1 (r = 0.5 m from the chest centre) that a hand crossing
// the body cannot reach: the far side of the arc lies ~690 mm from the opposite shoulder joint,
// the default signer's arm 580 mm long, and the arm locked straight across the chest, up to
// 185 mm short (GIVE vector s=-1.0 o=0.9). A signer reaches toward such a locus with the elbow
// bent, the hand on the line from the shoulder to it. So every keyframe of a performance is
// drawn toward its hand's shoulder joint where it lies beyond the comfortable reach: a pure
// function of the target (the shoulder and the arm's length), the same for the point and vector
// versions, so they still differ only in how they were synthesized.
//
// stimuli/ knows nothing of the body: the reach comes in as a plain value from the signer's
// rig (signer::signerReach), as the transition pacer does (TimelineSources).
#include "stimuli/verbs/verb_synthesis.hpp"

#include <glm/vec3.hpp>

#include <optional>

namespace signstim::stimuli {

// [D] The comfortable reach, as a fraction of the arm's length (shoulder joint to wrist, the
// elbow straight): 0.9, the upper end of the 80–90 % of full reach that ergonomic guidance
// gives for repeated reaches (frequent reaches kept short of full extension: Kroemer &
// Grandjean, Fitting the Task to the Human), so the far loci stay as far apart as a
// comfortable arm allows. (The animator file of EMAIL s=0.9 o=-0.6 reaches to 0.97, the elbow
// bent 29°.)
inline constexpr double kComfortableReachFraction = 0.9;
// [D] Where the drawing-in starts, as a fraction of the arm's length: from here the distance to
// the shoulder is compressed smoothly (slope 1 here, never past the comfortable reach), so
// loci at different depths stay apart and nothing creases where the rule begins.
inline constexpr double kReachKneeFraction = 0.8;

// [D] How much nearer than the folded arm allows (ArmReach::foldedMm) a wrist target is kept
// from its shoulder joint: the elbow short of its last degrees of flexion, against the soft
// tissue (hand/arm_ik.hpp, ArmLimits::elbowFlexion), with a 40 mm band over which the
// pushing-out fades in (as the outer knee's).
inline constexpr double kFoldedMarginMm = 20.0;
inline constexpr double kFoldedBandMm = 40.0;

// One arm in the signing-space frame (stimuli/verbs/signing_space.hpp: +x the signer's right).
struct ArmReach {
    glm::dvec3 shoulderMm{0.0};  // the shoulder joint's centre
    double lengthMm = 0.0;       // shoulder joint to wrist joint, the elbow straight
    double foldedMm = 0.0;       // shoulder joint to wrist joint, the elbow at its flexion limit (0: no limit)
};

// The signer's reach; an arm left empty is not limited (what stimuli/ knows by itself).
struct SignerReach {
    std::optional<ArmReach> right, left;
    double comfortableFraction = kComfortableReachFraction;
    double kneeFraction = kReachKneeFraction;
    const std::optional<ArmReach>& arm(HandSide side) const { return side == HandSide::Right ? right : left; }
};

// `positionMm` (a wrist target) drawn toward the shoulder joint where it lies beyond the knee
// (kneeFraction · length): the distance d becomes knee + (c − knee)·tanh((d − knee)/(c − knee)),
// c the comfortable reach, on the same line from the shoulder; and pushed out from it where it
// lies nearer than the folded arm allows (foldedMm + kFoldedMarginMm, faded in over
// kFoldedBandMm the same way); targets between are returned as they are. Continuous with its
// first derivative, monotonic in d, never past c.
glm::dvec3 withinComfortableReach(const glm::dvec3& positionMm, const ArmReach& arm, double comfortableFraction,
                                  double kneeFraction);

// The point and vector versions (what the models synthesize; the citation form and the animator
// files are returned as they are: authored on a body, reached as written): every keyframe of
// every hand of `performance` within its arm's comfortable reach
// (withinComfortableReach); times, orientations and handshapes kept. The keyed path between
// keyframes is a blend of their positions, so it stays inside the outer reach (a ball is
// convex) — but a straight path can pass nearer the shoulder than the folded arm allows (COPY
// point s=1 o=-0.9: 128 mm from the right shoulder joint on the way from the far left to the
// right side). So where a hand's path does, the hand's keyframes are all moved forward (+z, away
// from the body, the lateral and vertical placement of its loci kept) by the least that clears
// it (1 mm steps), both hands alike where they touch each other (the touch kept); not where a
// hand touches the body (its contact would be lost).
VerbPerformance withinReach(VerbPerformance performance, const SignerReach& reach);

}  // namespace signstim::stimuli
