#include "stimuli/verbs/verb_reach.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace signstim::stimuli {
namespace {

constexpr double kPi = 3.14159265358979323846;

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

// The torso's section at height y: linear between the sections, the end ones beyond them.
TorsoSection sectionAt(const std::vector<TorsoSection>& sections, double y) {
    if (y <= sections.front().yMm) return sections.front();
    if (y >= sections.back().yMm) return sections.back();
    std::size_t i = 1;
    while (sections[i].yMm < y) ++i;
    const TorsoSection& a = sections[i - 1];
    const TorsoSection& b = sections[i];
    const double u = (y - a.yMm) / (b.yMm - a.yMm);
    const auto mix = [u](double p, double q) { return p + (q - p) * u; };
    return {y, mix(a.halfWidthMm, b.halfWidthMm), mix(a.halfDepthMm, b.halfDepthMm), mix(a.zMm, b.zMm)};
}

// Every key of `performance` out of `torso` (clearOfTorso), the hands of a pair by one offset.
void outOfTorso(VerbPerformance& performance, const TorsoReach& torso);

// The largest of `a` and `b` in magnitude where they agree in sign, their sum where not:
// continuous, and `b` where `a` is 0.
double combinedPush(double a, double b) {
    if ((a >= 0.0) == (b >= 0.0)) return std::abs(a) >= std::abs(b) ? a : b;
    return a + b;
}

}  // namespace

glm::dvec3 clearOfTorso(const glm::dvec3& wristMm, const glm::dquat& orientation, HandSide side, const TorsoReach& torso) {
    if (torso.sections.empty()) return wristMm;
    const TorsoSection section = sectionAt(torso.sections, wristMm.y);
    const double radius = section.halfDepthMm;
    const double half = std::max(0.0, section.halfWidthMm - section.halfDepthMm);  // the stadium's straight part
    // The section's frame: u toward the hand's own side (its shoulder's), v forward from the centre.
    const double own = side == HandSide::Right ? 1.0 : -1.0;
    const double u = own * wristMm.x, v = wristMm.z - section.zMm;
    // The obstacle is convex, its outward normals at angles θ (from +u) from 0 (the own side's
    // face) through π/2 (the front) to π/2 + the far side's slope: its signed distance is the
    // largest of u·cos θ + v·sin θ − support(θ) over them, support(θ) = half·|cos θ| + radius,
    // exact outside and inside, and the normal is the θ that gives it.
    const double slope = torso.farSideSlopeDeg * kPi / 180.0;
    double phi = -1e300, theta = 0.0;
    const auto consider = [&](double angle) {
        const double value = u * std::cos(angle) + v * std::sin(angle) - half * std::abs(std::cos(angle)) - radius;
        if (value > phi) {
            phi = value;
            theta = angle;
        }
    };
    consider(0.0);
    consider(kPi / 2.0);
    consider(kPi / 2.0 + slope);
    const double ownEnd = std::atan2(v, u - half);  // the own side's round end, about its centre
    if (ownEnd > 0.0 && ownEnd < kPi / 2.0) consider(ownEnd);
    const double farEnd = std::atan2(v, u + half);  // the far side's, as far as the slope
    if (farEnd > kPi / 2.0 && farEnd < kPi / 2.0 + slope) consider(farEnd);
    // Deep in the body the nearest face jumps (between the front and the own side's face behind
    // the mid-plane, and about the round ends' centres): from half the section's half depth in,
    // the direction turns smoothly to the one from a point 2 half depths behind the centre
    // (mostly forward: MEET vector s=-1 o=-0.9's left key, 35 mm behind the mid-plane, comes out
    // in front, where signing is, not out of the flank), fully at 0.9 of it. Any normal of the
    // outline will do: pushed along it until it is `need` beyond the outline's supporting line
    // there, the hand is at least that far from the whole (convex) obstacle; near and outside
    // the outline it is the nearest face's, so a key already clear stays where it is.
    const double depth = std::clamp((-phi / radius - 0.5) / 0.4, 0.0, 1.0);
    if (depth > 0.0) {
        const double inward = std::clamp(std::atan2(v + 2.0 * radius, u), 0.0, kPi / 2.0 + slope);
        theta += (inward - theta) * depth * depth * (3.0 - 2.0 * depth);
        phi = u * std::cos(theta) + v * std::sin(theta) - half * std::abs(std::cos(theta)) - radius;
    }
    const glm::dvec3 normal(own * std::cos(theta), 0.0, std::sin(theta));
    // The hand's extent toward the body (−normal): the heel-to-fingertip segment's support in
    // that direction, and the palm's elliptical section (half width by half thickness) about it.
    const glm::dvec3 toward = -normal;
    const double fingers = glm::dot(toward, orientation * glm::dvec3(0.0, 0.0, 1.0));
    const double palm = glm::dot(toward, orientation * glm::dvec3(1.0, 0.0, 0.0));
    const double across = glm::dot(toward, orientation * glm::dvec3(0.0, 1.0, 0.0));
    const HandExtent& hand = torso.hand;
    const double extent = std::max(hand.lengthMm * fingers, -hand.backMm * fingers) +
                          std::hypot(hand.halfWidthMm * across, hand.halfThicknessMm * palm);
    const double knee = extent + torso.clearanceMm + torso.bandMm;
    if (phi >= knee || !(torso.bandMm > 0.0)) return wristMm;
    const double pushed = knee - torso.bandMm * std::tanh((knee - phi) / torso.bandMm);
    return wristMm + normal * (pushed - phi);
}

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
    for (std::size_t h = 0; h < performance.hands.size(); ++h)
        for (PerformanceKeyframe& key : performance.hands[h].keyframes) key.pose.positionMm.z += forward[h];
    // Out of the torso (not a verb that touches the body: TELL's chin key stays on the chin),
    // then within reach: the pair's common offset can carry the other hand past the comfortable
    // reach (MEET vector s=-1 o=-0.9: the right hand 583 mm from its shoulder), which draws it
    // back toward the shoulder, away from the torso.
    if (!reach.torso.sections.empty() && !performance.contact.body) outOfTorso(performance, reach.torso);
    for (HandTrack& track : performance.hands)
        if (const std::optional<ArmReach>& arm = reach.arm(track.side))
            for (PerformanceKeyframe& key : track.keyframes)
                key.pose.positionMm =
                    withinComfortableReach(key.pose.positionMm, *arm, reach.comfortableFraction, reach.kneeFraction);
    return performance;
}

namespace {
void outOfTorso(VerbPerformance& performance, const TorsoReach& torso) {
    std::vector<std::vector<glm::dvec3>> push(performance.hands.size());
    for (std::size_t h = 0; h < performance.hands.size(); ++h)
        for (const PerformanceKeyframe& key : performance.hands[h].keyframes)
            push[h].push_back(clearOfTorso(key.pose.positionMm, key.pose.orientation, performance.hands[h].side, torso) -
                              key.pose.positionMm);
    // Both hands keyed together: one offset per key for the pair.
    if (push.size() == 2 && push[0].size() == push[1].size())
        for (std::size_t k = 0; k < push[0].size(); ++k) {
            glm::dvec3 both(0.0);
            for (int c = 0; c < 3; ++c) both[c] = combinedPush(push[0][k][c], push[1][k][c]);
            push[0][k] = push[1][k] = both;
        }
    for (std::size_t h = 0; h < performance.hands.size(); ++h)
        for (std::size_t k = 0; k < push[h].size(); ++k) performance.hands[h].keyframes[k].pose.positionMm += push[h][k];
}
}  // namespace

}  // namespace signstim::stimuli
