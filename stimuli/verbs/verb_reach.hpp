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

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <vector>

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

// ---- The torso: no wrist target (with its hand) inside the body ----
// The models put some keyframes in the body: the vector model chooses a verb's start from the
// right hand's location likelihood alone, whatever the subject and object (SPEC §3.5, the
// paper's model, reproduced as it is), so with both loci on the left GIVE's right hand starts
// at the centre-right and its left hand, placed relative to the right one as the pair is
// turned toward the left loci (−188, −18, −172 mm), lands behind it, in the torso (s=−1
// o=−0.8: (204, −100, −12) and (34, −88, 42)); SEND's, EMAIL's and ASK's vector starts lie at
// the chest. A path between keys can be routed around the torso (signing_space.hpp,
// sweptPathPoint), a key cannot: so every point and vector key is pushed out of the torso,
// along its normal, to the body's surface plus the hand's extent toward it plus a clearance.
//
// The torso, seen from above at a height, is a stadium (a rectangle with round ends: a
// capsule's section). A hand on its own side may hang beside its flank, but an arm reaching
// across the body passes in front of it: the crossing hand may lie behind the front only as
// far as its forearm can slope back around the far flank. So for each hand the obstacle is
// everything behind an outline: the own side's face (straight back from the stadium's widest
// point), its round end, the front, the far side's round end as far as kTorsoFarSideSlopeDeg
// beyond the front, and from there a straight line sloping back at that angle toward the far
// side. That set is convex with a smooth (C¹) outline, so the (signed) distance to it changes
// continuously with the target everywhere, and its outward normal too down to the depth of
// the section's half depth (R); from R/2 in, the push turns smoothly toward the direction
// from a point 2R behind the centre, mostly forward, so a key deep in the body (even behind its
// mid-plane) comes out in front, continuously (the one point where it cannot be is 2R behind
// the torso's centre, where no model puts a hand).

// [D] The clearance kept between the hand and the torso's surface (the clearance check allows
// kClearanceToleranceMm of overlap: signer/clearance.hpp), and the band over which the push
// fades in (as the folded arm's: slope 1 and no push at its outer edge).
inline constexpr double kTorsoClearanceMm = 15.0;
inline constexpr double kTorsoBandMm = 20.0;
// [D] How steeply the obstacle's outline slopes back beyond the far flank (from the frontal
// plane): a forearm crossing the chest turns back around the far flank by about this much, so
// a crossing hand 100 mm beyond the flank may lie ~58 mm behind the chest's front. (90° would
// be the bare stadium, which let GIVE vector's left hand stay beside the right flank with its
// forearm through the chest; 0° a wall in front of everything on the far side, which pushed
// EMAIL's right hand 120 mm beyond the left flank forward.)
inline constexpr double kTorsoFarSideSlopeDeg = 30.0;

// One horizontal section of the torso in the signing-space frame (mm): its height, half width
// (x), half depth (z) and the z of its centre; symmetric about x = 0.
struct TorsoSection {
    double yMm = 0.0, halfWidthMm = 0.0, halfDepthMm = 0.0, zMm = 0.0;
};

// The hand in its palm frame (stimuli/verbs/sora.hpp: fingers +z, palm +x, y across): from
// backMm behind the wrist (the heel of the palm) to lengthMm ahead of it (the fingertips,
// extended), an elliptical section halfWidthMm across and halfThicknessMm each side of the
// palm. Its extent toward the body is its support in that direction: the fingertips where they
// point at it, the heel where the fingers point away, the palm's edge where it is side-on.
struct HandExtent {
    double backMm = 0.0, lengthMm = 0.0, halfWidthMm = 0.0, halfThicknessMm = 0.0;
};

// The torso's sections from the bottom up (empty: not limited) and the hand's extent.
struct TorsoReach {
    std::vector<TorsoSection> sections;
    HandExtent hand;
    double clearanceMm = kTorsoClearanceMm;
    double bandMm = kTorsoBandMm;
    double farSideSlopeDeg = kTorsoFarSideSlopeDeg;
};

// `wristMm` (a wrist target, the `side` hand turned by `orientation`) pushed out of the torso
// along its normal, in the horizontal plane: where the wrist's distance φ from the obstacle
// above (the section at the wrist's height, linearly between sections and as the end ones
// beyond them; negative inside) is less than need + band (need: the hand's extent toward the
// body + clearance), it becomes need + band − band·tanh((need + band − φ)/band), never less than
// need; elsewhere the target is returned as it is. Continuous with its first derivative in φ.
glm::dvec3 clearOfTorso(const glm::dvec3& wristMm, const glm::dquat& orientation, HandSide side, const TorsoReach& torso);

// The signer's reach; an arm left empty is not limited (what stimuli/ knows by itself).
struct SignerReach {
    std::optional<ArmReach> right, left;
    TorsoReach torso;
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
// hand touches the body (its contact would be lost). Between the forward move and the reach,
// every key clear of the torso (clearOfTorso; not in a verb that touches the body; the reach
// after it draws a key only toward its shoulder, away from the torso, or out of the folded
// arm): where both hands are keyed together,
// key by key both move by one offset, each of its components the larger of the two hands'
// pushes where they agree in sign and their sum where not, so the pair keeps its shape (the
// hands moving as one, or touching) and neither is left in the body.
VerbPerformance withinReach(VerbPerformance performance, const SignerReach& reach);

}  // namespace signstim::stimuli
