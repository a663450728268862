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

}  // namespace signstim::stimuli
