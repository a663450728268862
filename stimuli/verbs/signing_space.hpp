#pragma once
// The signing space of SPEC §3.1: entities are placed on a semicircular arc at chest height
// around the signer, addressed by an arc position p in [-1, 1].
//
// Frame (torso-fixed, used by every verb file, the corpus CSV and the verb models):
//   origin  the centre of the signer's chest (sternum, at chest height),
//   +x      the signer's right,
//   +y      up,
//   +z      forward, away from the signer (toward the viewer),
//   units   millimetres.
// Physically this frame is left-handed (the signer's right × up points backward, not
// forward): it is the mirror image of the avatar's right-handed body frame (+x the signer's
// left). Coordinates are used as written; orientations are built from palm and finger
// directions with y = z × x computed in these coordinates, and the app converts them to
// the body frame keeping the palm and finger directions (signer/signer_pose.hpp,
// handFrameFromSigningSpace).
#include <glm/vec3.hpp>
#include <string>

namespace signstim::stimuli {

struct SigningSpace {
    // SPEC §3.1 [D]: r ≈ 0.5 m from the chest centre.
    double arcRadiusMm = 500.0;
    // The arc's centre in the frame above: the chest centre itself.
    glm::dvec3 chestMm{0.0, 0.0, 0.0};
};

// Throws InputError(source, 0, field, ...) unless -1 <= p <= 1 (SPEC §3.1: an error, not a
// clamp). NaN is rejected too.
void checkArcPosition(double position, const std::string& source, const std::string& field);

// Angle from straight ahead, radians: ψ = 90°·p, positive toward the signer's right.
double arcAngleRadians(double position);

// The 3-D point of an arc position: chest + r·(right·sin ψ + forward·cos ψ).
// Throws InputError for positions outside [-1, 1].
glm::dvec3 arcPoint(double position, const SigningSpace& space = {});

// ---- A verb's path between two of its keyframes (issue 21: the hands never pass through the
// body) ----
// The models turn a verb's keyframes about a vertical axis behind the chest (the reference
// performer's torso pivot, scenes/corpus/reference_performer.json "torsoPivotMm"), and a
// signer's hand going from a locus on one side to one on the other sweeps around the chest as
// they do, at arm's length. The straight chord between two such keyframes cuts in toward the
// torso by the arc's sagitta: from the far left to the far right, through the chest (SEND point
// s=-1 o=1, 75 mm into it). So where a verb's chord dips toward this axis — comes nearer it,
// seen from above, than the nearer of its two keys — and comes near the body, the hand goes
// from key to key about the axis instead: its angle about it, its distance from it and its
// height each change evenly with the blend (a helix segment), so it comes no nearer the axis
// than its keys. Elsewhere the chord is kept: a move out from the body or in toward it, a
// short move near one side, and a sweep that passes well clear of the chest (a hand going
// through the other's C in EMAIL, 366 mm from the axis, keeps its way through it). Between,
// the path goes part of the way from the chord to the swept path, so it changes smoothly with
// the keys: by the dip over kVerbSweepFullDipMm, times how far inside kVerbSweepFarMm the chord
// comes, over the band down to kVerbSweepNearMm.
// [D] The axis: x = 0, z = kVerbSweepAxisZMm, as the reference performer's pivot (the default
// signer's torso section is about 330 mm wide and 210 mm deep, centred on z = 0: every point
// of it lies within 225 mm of the axis, so a path between keys at least that far out stays out
// of it). [D] kVerbSweepFullDipMm: a chord that dips 10 mm sweeps fully, so no path near the
// body comes more than about 2.5 mm nearer the axis than its nearer key (the most, at a 5 mm
// dip). [D] kVerbSweepNearMm, kVerbSweepFarMm: a wrist 310 mm from the axis leaves ~85 mm
// between it and the torso for the hand's palm and curled fingers; the chords that took a hand
// into the body came 176-301 mm near it (ASK point s=1 o=-1, TELL point o=1), none beyond.
inline constexpr double kVerbSweepAxisZMm = -100.0;
inline constexpr double kVerbSweepFullDipMm = 10.0;
inline constexpr double kVerbSweepNearMm = 310.0;
inline constexpr double kVerbSweepFarMm = 350.0;

// The point a `blend` (0..1) of the way from `a` to `b` (signing space, mm) on the verb's path
// above: exactly `a` at 0 and `b` at 1; the straight blend where the chord does not dip, stays
// clear of the body, or either end lies within 1 mm of the axis. A pure function of its arguments.
glm::dvec3 sweptPathPoint(const glm::dvec3& a, const glm::dvec3& b, double blend);

// At least the most the path's position changes per unit of blend anywhere on it (mm): for
// the speed limit, the path's peak speed being at most this times the ease's peak slope over
// the stretch's time. The chord's length where it is kept; the swept path's bound
// sqrt(Δr² + (r_max·Δθ)² + Δy²) where it sweeps; their weighted sum between.
double sweptPathRateMm(const glm::dvec3& a, const glm::dvec3& b);

}  // namespace signstim::stimuli
