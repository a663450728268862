#include "stimuli/verbs/verb_reach.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace signstim::stimuli {
namespace {

// [D] The most a hand's keyframes are moved forward to clear the folded arm's reach.
constexpr double kMostForwardMm = 200.0;

double nearestApproachMm(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& point) {
    const glm::dvec3 ab = b - a;
    const double lengthSquared = glm::dot(ab, ab);
    const double u = lengthSquared > 0.0 ? std::clamp(glm::dot(point - a, ab) / lengthSquared, 0.0, 1.0) : 0.0;
    return glm::distance(a + u * ab, point);
}

// The nearest the keyed path of `track`, moved forward by `forwardMm` and drawn within the reach,
// comes to the shoulder joint, less what the folded arm needs (negative: too near).
double clearanceMm(const HandTrack& track, const ArmReach& arm, const SignerReach& reach, double forwardMm) {
    double nearest = 1e30;
    glm::dvec3 previous{0.0};
    for (std::size_t k = 0; k < track.keyframes.size(); ++k) {
        const glm::dvec3 p = withinComfortableReach(track.keyframes[k].pose.positionMm + glm::dvec3(0.0, 0.0, forwardMm), arm,
                                                    reach.comfortableFraction, reach.kneeFraction);
        if (k > 0) nearest = std::min(nearest, nearestApproachMm(previous, p, arm.shoulderMm));
        previous = p;
    }
    return nearest - (arm.foldedMm + kFoldedMarginMm);
}

}  // namespace

glm::dvec3 withinComfortableReach(const glm::dvec3& positionMm, const ArmReach& arm, double comfortableFraction,
                                  double kneeFraction) {
    const glm::dvec3 offset = positionMm - arm.shoulderMm;
    const double distance = glm::length(offset);
    if (!(arm.lengthMm > 0.0)) return positionMm;
    const double knee = kneeFraction * arm.lengthMm;
    const double band = (comfortableFraction - kneeFraction) * arm.lengthMm;
    if (distance > knee && band > 0.0) {
        const double drawn = knee + band * std::tanh((distance - knee) / band);
        return arm.shoulderMm + offset * (drawn / distance);
    }
    const double innerKnee = arm.foldedMm + kFoldedMarginMm + kFoldedBandMm;
    if (arm.foldedMm > 0.0 && distance < innerKnee) {
        const double pushed = innerKnee - kFoldedBandMm * std::tanh((innerKnee - distance) / kFoldedBandMm);
        // At the joint itself no direction is given: out in front (+z).
        const glm::dvec3 direction = distance > 1e-9 ? offset / distance : glm::dvec3(0.0, 0.0, 1.0);
        return arm.shoulderMm + direction * pushed;
    }
    return positionMm;
}

VerbPerformance withinReach(VerbPerformance performance, const SignerReach& reach) {
    // The authored versions (the citation form, an animator's keyframes) were made on a body and
    // are reached as they are (the verb grid: never short at their keys, once three animator keys
    // inside the folded arm were moved out in the files themselves); drawing them in too shortened story-03's
    // uninflected transition into EMAIL to 2.61 m/s.
    if (performance.version != VerbVersion::Point && performance.version != VerbVersion::Vector) return performance;
    // How far forward each hand's path must move to clear its folded arm; touching hands alike.
    // Not a verb that touches the body, nor only its keys away from the touch: for TELL toward a
    // far-right object (the chin key kept; the straight path passed 145 mm from the right
    // shoulder joint at o=1.0) the locus would go 181 mm forward and turn from 95° to 74° right
    // of straight ahead, o=0.9 from 88° to 73°, o=0.8 from 80° to 72° — all where o=0.7 points,
    // the verb no longer at its object. There the route between the keys bows around the
    // shoulder instead (signing_space.hpp, sweptPathPoint), and the keys stay.
    std::vector<double> forward(performance.hands.size(), 0.0);
    if (!performance.contact.body)
        for (std::size_t h = 0; h < performance.hands.size(); ++h) {
            const std::optional<ArmReach>& arm = reach.arm(performance.hands[h].side);
            if (!arm || !(arm->foldedMm > 0.0)) continue;
            // The least shift that clears; where none up to kMostForwardMm does, the one that comes nearest.
            double best = -1e30;
            for (double mm = 0.0; mm <= kMostForwardMm; mm += 1.0) {
                const double clearance = clearanceMm(performance.hands[h], *arm, reach, mm);
                if (clearance > best) {
                    best = clearance;
                    forward[h] = mm;
                }
                if (clearance >= 0.0) break;
            }
        }
    if (performance.contact.hands && !forward.empty()) {
        const double most = *std::max_element(forward.begin(), forward.end());
        std::fill(forward.begin(), forward.end(), most);
    }
    for (std::size_t h = 0; h < performance.hands.size(); ++h) {
        HandTrack& track = performance.hands[h];
        const std::optional<ArmReach>& arm = reach.arm(track.side);
        if (!arm) continue;
        for (PerformanceKeyframe& key : track.keyframes)
            key.pose.positionMm = withinComfortableReach(key.pose.positionMm + glm::dvec3(0.0, 0.0, forward[h]), *arm,
                                                         reach.comfortableFraction, reach.kneeFraction);
    }
    return performance;
}

}  // namespace signstim::stimuli
