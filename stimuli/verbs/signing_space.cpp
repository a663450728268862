#include "stimuli/verbs/signing_space.hpp"

#include "common/error.hpp"
#include "common/number_format.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <numbers>

namespace signstim::stimuli {

void checkArcPosition(double position, const std::string& source, const std::string& field) {
    if (!(position >= -1.0 && position <= 1.0)) {
        throw InputError(source, 0, field,
                         "arc position " + formatNumber(position) +
                             " is outside [-1, 1] (-1 = signer's far left, 0 = straight ahead, "
                             "1 = far right)");
    }
}

double arcAngleRadians(double position) { return 0.5 * std::numbers::pi * position; }

glm::dvec3 arcPoint(double position, const SigningSpace& space) {
    checkArcPosition(position, "<arc position>", "p");
    const double psi = arcAngleRadians(position);
    return space.chestMm + space.arcRadiusMm * glm::dvec3(std::sin(psi), 0.0, std::cos(psi));
}

namespace {

// Where a position lies about the sweep axis: its angle (radians, 0 straight ahead, + toward
// the signer's right), its distance from the axis and its height.
struct AboutAxis {
    double angle, radius, height;
};
AboutAxis aboutAxis(const glm::dvec3& p) {
    const double x = p.x, z = p.z - kVerbSweepAxisZMm;
    return {std::atan2(x, z), std::hypot(x, z), p.y};
}
constexpr double kNearAxisMm = 1.0;

// How much of the way from the chord to the swept path a stretch goes (signing_space.hpp): by
// how far the chord dips toward the axis below the nearer of its ends (seen from above), all
// of it from kVerbSweepFullDipMm on, times how near the body it comes (all of it within
// kVerbSweepNearMm of the axis, none from kVerbSweepFarMm); 0 where either end lies at the axis.
double sweepWeight(const glm::dvec3& a, const glm::dvec3& b, const AboutAxis& from, const AboutAxis& to) {
    if (from.radius < kNearAxisMm || to.radius < kNearAxisMm) return 0.0;
    const glm::dvec2 start(a.x, a.z - kVerbSweepAxisZMm), chord(b.x - a.x, b.z - a.z);
    const double lengthSquared = glm::dot(chord, chord);
    if (!(lengthSquared > 0.0)) return 0.0;
    const double u = -glm::dot(start, chord) / lengthSquared;
    if (u <= 0.0 || u >= 1.0) return 0.0;  // nearest the axis at an end: the chord dips nowhere
    const double nearest = glm::length(start + u * chord);
    const double dip = std::min(from.radius, to.radius) - nearest;
    const double near = (kVerbSweepFarMm - nearest) / (kVerbSweepFarMm - kVerbSweepNearMm);
    return std::clamp(dip / kVerbSweepFullDipMm, 0.0, 1.0) * std::clamp(near, 0.0, 1.0);
}

}  // namespace

glm::dvec3 sweptPathPoint(const glm::dvec3& a, const glm::dvec3& b, double blend) {
    if (blend <= 0.0) return a;
    if (blend >= 1.0) return b;
    const glm::dvec3 straight = a + blend * (b - a);
    const AboutAxis from = aboutAxis(a), to = aboutAxis(b);
    const double weight = sweepWeight(a, b, from, to);
    if (weight <= 0.0) return straight;
    // The angles as atan2 gives them (-π..π, 0 ahead): the path goes round the front of the
    // body, never behind it.
    const double angle = from.angle + blend * (to.angle - from.angle);
    const double radius = from.radius + blend * (to.radius - from.radius);
    const glm::dvec3 swept{radius * std::sin(angle), straight.y, kVerbSweepAxisZMm + radius * std::cos(angle)};
    return straight + weight * (swept - straight);
}

double sweptPathRateMm(const glm::dvec3& a, const glm::dvec3& b) {
    const double chord = glm::length(b - a);
    const AboutAxis from = aboutAxis(a), to = aboutAxis(b);
    const double weight = sweepWeight(a, b, from, to);
    if (weight <= 0.0) return chord;
    const double turn = std::max(from.radius, to.radius) * (to.angle - from.angle);
    const double swept = std::sqrt((to.radius - from.radius) * (to.radius - from.radius) + turn * turn +
                                   (to.height - from.height) * (to.height - from.height));
    // The blend's rate is at most the weighted sum of the chord's and the swept path's.
    return (1.0 - weight) * chord + weight * swept;
}

}  // namespace signstim::stimuli
