#pragma once
// Hand orientation in Simultaneous Orthogonal Rotation Angles (SORA, SPEC §3.6; Stančin &
// Tomažič 2011): Φ = (φx, φy, φz) in radians, three simultaneous rotations about the frame
// axes, which equals one rotation about Φ/|Φ| by |Φ| — the rotation vector.
//
// An orientation here rotates the hand's palm frame (hand/: +z toward the fingers, +x out of
// the palmar surface, +y completing a right-handed frame) into the signing-space frame of
// stimuli/verbs/signing_space.hpp. Quaternions are glm::dquat (w, x, y, z), unit length.
//
// Recorded data use roll, pitch, yaw in degrees with R = Rz(yaw)·Ry(pitch)·Rx(roll) (the
// same composition as the sensors of SPEC §2.1): roll about x first, then pitch about y,
// then yaw about z, all about the fixed signing-space axes.
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace signstim::stimuli {

using Sora = glm::dvec3;

struct AxisAngle {
    glm::dvec3 axis{1.0, 0.0, 0.0};  // unit
    double angleRadians = 0.0;       // in [0, π] when produced by soraToAxisAngle
};

glm::dquat soraToQuaternion(const Sora& phi);
// q and -q give the same Φ (q_w >= 0 is chosen, SPEC §3.6); |Φ| ∈ [0, π].
Sora quaternionToSora(const glm::dquat& q);
glm::dmat3 soraToMatrix(const Sora& phi);  // Rodrigues
Sora matrixToSora(const glm::dmat3& rotation);
AxisAngle soraToAxisAngle(const Sora& phi);
Sora axisAngleToSora(const AxisAngle& axisAngle);

// Robust for every rotation, including angles near π (Shepperd's method).
glm::dquat matrixToQuaternion(const glm::dmat3& rotation);

glm::dquat rollPitchYawDegreesToQuaternion(double rollDeg, double pitchDeg, double yawDeg);
// Inverse of the above; pitch ∈ [-90°, 90°]. At pitch = ±90° roll and yaw are not unique;
// the returned triple still reproduces the rotation.
glm::dvec3 quaternionToRollPitchYawDegrees(const glm::dquat& q);

// The orientation whose fingers point along `fingers` and whose palm faces `palm` (palm is
// made orthogonal to fingers). Throws std::invalid_argument when they are (nearly) parallel
// or zero.
glm::dquat orientationFromFingersPalm(const glm::dvec3& fingers, const glm::dvec3& palm);
glm::dvec3 fingersDirection(const glm::dquat& orientation);  // palm frame +z
glm::dvec3 palmDirection(const glm::dquat& orientation);     // palm frame +x

// Shortest-path spherical interpolation, t ∈ [0, 1].
glm::dquat slerpShortest(const glm::dquat& from, const glm::dquat& to, double t);
// Angle of the rotation from a to b, radians in [0, π]: 2·acos|⟨a, b⟩| (SPEC §3.8).
double rotationAngleBetween(const glm::dquat& a, const glm::dquat& b);
// Average rotation (Markley et al. 2007: principal eigenvector of Σ q qᵀ), w >= 0.
// Throws std::invalid_argument for an empty list.
glm::dquat meanRotation(const std::vector<glm::dquat>& rotations);

}  // namespace signstim::stimuli
