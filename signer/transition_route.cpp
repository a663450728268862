// A story's transitions routed around the hands and the body (signer/timeline_clip.hpp,
// TimelineClip::routeTransition): the detour's bumps, sought on instants of the transition's
// own time and then judged between them, so that no instant of any output's frames — 15, 24,
// 25, 30, 30000/1001 or 60 a second, wherever they fall — takes a hand into the body or the
// other hand. Apart from timeline_clip.cpp, which plays the detours, as its own concern.
#include "signer/hand_capsules.hpp"
#include "signer/signer_pose.hpp"
#include "signer/timeline_clip.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace signstim::signer {
namespace {

// [D] The most a detour's bump adds to the wrist's speed at its peak (see routeTransition).
constexpr double kDetourPeakSpeedMmPerSecond = 1200.0;
// SPEC §6.2: peak wrist speed of natural signing.
constexpr double kWristPeakSpeedMmPerSecond = 2500.0;

// The shapes a detour's bumps take: u^a·(1−u)^b scaled to 1 at its peak, u = a/(a+b); with
// a, b ≥ 3 its velocity and acceleration vanish at both ends of the transition. Early, middle
// and late peaks, for hands that would meet soon after leaving, halfway, or just before
// arriving (an item that ends or starts in contact).
struct BumpShape {
    int a, b;
};
constexpr std::array<BumpShape, 3> kBumpShapes{{{3, 3}, {3, 6}, {6, 3}}};

float bump(int shape, double u) {
    if (u <= 0.0 || u >= 1.0) return 0.0f;
    const auto [a, b] = kBumpShapes[static_cast<std::size_t>(shape)];
    const double peak = static_cast<double>(a) / (a + b);
    return static_cast<float>(std::pow(u / peak, a) * std::pow((1.0 - u) / (1.0 - peak), b));
}

// The steepest slope of a bump's shape, |d bump / du| at its maximum (sampled; 1e-3 of u),
// found once.
double steepestSlope(int shape) {
    static const std::array<double, kBumpShapes.size()> slopes = [] {
        std::array<double, kBumpShapes.size()> out{};
        for (std::size_t s = 0; s < out.size(); ++s)
            for (int i = 0; i < 1000; ++i) {
                const double u = i / 1000.0;
                const int shape = static_cast<int>(s);
                out[s] = std::max(out[s], std::abs(static_cast<double>(bump(shape, u + 1e-3)) - bump(shape, u)) / 1e-3);
            }
        return out;
    }();
    return slopes[static_cast<std::size_t>(shape)];
}

bool sameTarget(const std::optional<hand::ArmTarget>& a, const std::optional<hand::ArmTarget>& b) {
    return glm::distance(a->wristMm, b->wristMm) < 0.01f && std::abs(glm::dot(a->handRotation, b->handRotation)) > 0.999999f;
}

bool sameControls(const hand::HandControls& a, const hand::HandControls& b) {
    if (a.thumb.bendDeg != b.thumb.bendDeg || a.thumb.spreadDeg != b.thumb.spreadDeg || a.thumb.mcpDeg != b.thumb.mcpDeg ||
        a.thumb.ipDeg != b.thumb.ipDeg)
        return false;
    for (std::size_t f = 0; f < a.fingers.size(); ++f)
        if (a.fingers[f].spreadDeg != b.fingers[f].spreadDeg || a.fingers[f].bend != b.fingers[f].bend ||
            a.fingers[f].hook != b.fingers[f].hook)
            return false;
    return true;
}

// How close the hands come to each other and to the body where the arms put them, and the
// capsules they were measured on (to bound the motion to the next instant).
struct Gaps {
    float hands = 0.0f, rightBody = 0.0f, leftBody = 0.0f;
    Approach handsApproach;
};
struct Sample {
    double seconds = 0.0;
    Gaps gaps;
    SignerCapsules capsules;
};

Gaps gapsOf(const SignerCapsules& capsules) {
    Gaps g;
    g.handsApproach = closestApproach(capsules.right, capsules.left);
    g.hands = g.handsApproach.gapMm;
    g.rightBody = closestApproach(capsules.right, bodyCapsules()).gapMm;
    g.leftBody = closestApproach(capsules.left, bodyCapsules()).gapMm;
    return g;
}

// The farthest any capsule's end of a hand moves from one instant to the next. Every point of
// a capsule's axis is a fixed blend of its ends, so it moves no farther than they do; and a
// set of capsules' gap to another changes by no more than the farthest either set's points
// move (the gap is 1-Lipschitz in them).
float farthestMove(const std::vector<hand::Capsule>& a, const std::vector<hand::Capsule>& b) {
    float farthest = 0.0f;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
        farthest = std::max({farthest, glm::distance(a[i].start, b[i].start), glm::distance(a[i].end, b[i].end)});
    return farthest;
}

// Whether the `side` arm is solved from the same inputs in `a` as in `b` (its target,
// elbow hint and shoulder's raise: SignerRig::solveArm), and its hand has the same shape: then
// its capsules are the same, and a hand that does not move in a transition is solved once.
bool sameArm(const SignerPosture& a, const SignerPosture& b, hand::Side side) {
    const bool right = side == hand::Side::Right;
    const std::optional<hand::ArmTarget>&ta = right ? a.rightWrist : a.leftWrist, &tb = right ? b.rightWrist : b.leftWrist;
    if (!ta || !tb || ta->wristMm != tb->wristMm || ta->handRotation != tb->handRotation) return false;
    if ((right ? a.rightElbowHint : a.leftElbowHint) != (right ? b.rightElbowHint : b.leftElbowHint)) return false;
    if ((right ? a.nonManual.shoulderRaiseRight : a.nonManual.shoulderRaiseLeft) !=
        (right ? b.nonManual.shoulderRaiseRight : b.nonManual.shoulderRaiseLeft))
        return false;
    return sameControls(right ? a.rightHand : a.leftHand, right ? b.rightHand : b.leftHand);
}

}  // namespace

float TimelineClip::bumpAt(int shape, double u) { return bump(shape, u); }

TimelineClip::Detour TimelineClip::routeTransition(double startSeconds, double endSeconds) const {
    // [D] The transition is followed on the grid of kRoutingFramesPerSecond. Bumps
    // are added one at a time, at most three, while they help: each shape and way aside —
    // apart along the line between the hands' closest points, to the sides, up, down,
    // forward — is tried at 40 mm per hand at its peak, then the three most promising at each
    // size from 10 to 160 mm, and the one that leaves the smallest shortfall is kept. A
    // transition they cannot clear keeps the best they found (the clearance check reports it).
    constexpr float kShortfallToleranceMm = 0.5f;
    constexpr int kMostBumps = 3;
    constexpr std::array<float, 5> kSizesMm{10.0f, 20.0f, 40.0f, 80.0f, 160.0f};
    // [D] Between two judged instants the route is judged by a bound (judgeBetween below):
    // the gap at any instant between them is at least the mean of theirs less half the way
    // the hands' capsules travel from one to the other, taken as kPathPerChord times the
    // straight distance (a hand turning 90° in an interval travels π/(2√2) ≈ 1.11 times its
    // chord). Where the bound falls short by more than kBetweenToleranceMm the interval is
    // halved, down to kMostHalvings times (1/960 s on the 30-a-second grid: a wrist at
    // SPEC §6.2's 2.5 m/s moves 2.6 mm), and each instant found short is added to the judged
    // ones and the transition routed again, at most kMostRoutings times. kBetweenToleranceMm
    // plus kShortfallToleranceMm stays within kClearanceToleranceMm (signer/clearance.hpp),
    // what the check allows below a transition's ends.
    constexpr float kBetweenToleranceMm = 2.0f;
    constexpr float kPathPerChord = 1.25f;
    constexpr int kMostHalvings = 5;
    constexpr int kMostRoutings = 4;
    // [D] Where a hand's capsules move faster than kJumpMmPerSecond between two instants a
    // millisecond apart (8 times SPEC §6.2's 2.5 m/s), the pose jumps: the arm solver has
    // switched between two solutions (a hand turned beyond the wrist's range, clamped to one
    // side of it or the other). No bound holds across a jump, and where it falls moves a little
    // with the route, so where an instant found short lies within kJumpWindow halvings' steps
    // of a jump, the instants that many steps on either side of the nearest jump are judged too.
    constexpr float kJumpMmPerSecond = 20000.0f;
    constexpr int kJumpWindow = 3;
    Detour detour;
    detour.startSeconds = startSeconds;
    detour.endSeconds = endSeconds;
    const SignerPosture from = straightPostureAt(startSeconds), to = straightPostureAt(endSeconds);
    const bool rightMoves = !sameTarget(from.rightWrist, to.rightWrist) || !sameControls(from.rightHand, to.rightHand);
    const bool leftMoves = !sameTarget(from.leftWrist, to.leftWrist) || !sameControls(from.leftHand, to.leftHand);
    if (!rightMoves && !leftMoves) return detour;

    // The instants judged inside the transition, and its end: a grid from the transition's
    // start, so that the same transition is routed alike wherever it falls in a timeline (the
    // timeline builder's pacer, transitionPacer, routes it on its own to time it); then the
    // instants between them that the routing found short (in time from the start alone too).
    std::vector<double> times;
    for (int f = 1; startSeconds + f / kRoutingFramesPerSecond < endSeconds; ++f)
        times.push_back(startSeconds + f / kRoutingFramesPerSecond);
    times.push_back(endSeconds);
    std::vector<SignerPosture> straight;
    for (double t : times) straight.push_back(straightPostureAt(t));
    const auto withBumps = [&](const std::vector<Bump>& bumps, SignerPosture posture, double seconds) {
        const double u = (seconds - startSeconds) / (endSeconds - startSeconds);
        for (const Bump& b : bumps) {
            posture.rightWrist->wristMm += bumpAt(b.shape, u) * b.rightMm;
            posture.leftWrist->wristMm += bumpAt(b.shape, u) * b.leftMm;
        }
        return posture;
    };
    // A hand that holds still in the transition is solved at its start alone (sameArm).
    std::optional<Sample> still;
    const auto sampleOf = [&](const SignerPosture& posture, double seconds) {
        Sample s;
        s.seconds = seconds;
        const bool rightStill = still && sameArm(posture, from, hand::Side::Right);
        const bool leftStill = still && sameArm(posture, from, hand::Side::Left);
        if (!rightStill && !leftStill) {
            s.capsules = signerCapsules(*rig_, posture, arms(posture));
            s.gaps = gapsOf(s.capsules);
            return s;
        }
        for (const hand::Side side : {hand::Side::Right, hand::Side::Left}) {
            const bool right = side == hand::Side::Right;
            std::vector<hand::Capsule>& capsules = right ? s.capsules.right : s.capsules.left;
            float& body = right ? s.gaps.rightBody : s.gaps.leftBody;
            if (right ? rightStill : leftStill) {
                capsules = right ? still->capsules.right : still->capsules.left;
                body = right ? still->gaps.rightBody : still->gaps.leftBody;
                continue;
            }
            const hand::ArmPose arm = rig_->solveArm(side, posture);
            handCapsules(*rig_, side, right ? posture.rightHand : posture.leftHand, arm.wristMm, arm.hand, capsules);
            body = closestApproach(capsules, bodyCapsules()).gapMm;
        }
        s.gaps.handsApproach = closestApproach(s.capsules.right, s.capsules.left);
        s.gaps.hands = s.gaps.handsApproach.gapMm;
        return s;
    };
    // Never closer than the clearance, or than the ends are (an item there touches); a hand
    // that does not move in the transition (resting) is not asked to clear the body.
    const Sample first = sampleOf(from, startSeconds), last = sampleOf(to, endSeconds);
    still = first;
    constexpr float kNotAsked = -std::numeric_limits<float>::infinity();
    const float handsNeeded = std::min({kTransitionClearanceMm, first.gaps.hands, last.gaps.hands});
    const float rightBodyNeeded =
        rightMoves ? std::min({kTransitionClearanceMm, first.gaps.rightBody, last.gaps.rightBody}) : kNotAsked;
    const float leftBodyNeeded = leftMoves ? std::min({kTransitionClearanceMm, first.gaps.leftBody, last.gaps.leftBody}) : kNotAsked;
    const auto shortfallOf = [&](const Gaps& g) {
        return std::max({0.0f, handsNeeded - g.hands, rightBodyNeeded - g.rightBody, leftBodyNeeded - g.leftBody});
    };

    // The wrists' peak speed along the transition with `bumps`, on the judged instants.
    const auto peakSpeed = [&](const std::vector<Bump>& bumps) {
        double peak = 0.0, before = startSeconds;
        glm::vec3 right = from.rightWrist->wristMm, left = from.leftWrist->wristMm;
        for (std::size_t j = 0; j < times.size(); ++j) {
            const SignerPosture p = withBumps(bumps, straight[j], times[j]);
            const glm::vec3 r = p.rightWrist->wristMm, l = p.leftWrist->wristMm;
            if (times[j] > before)
                peak = std::max({peak, glm::distance(r, right) / (times[j] - before), glm::distance(l, left) / (times[j] - before)});
            right = r;
            left = l;
            before = times[j];
        }
        return peak;
    };
    // SPEC §6.2: a detour is sought first among those that keep the wrists within the peak
    // speed of natural signing (or the straight path's own, where that is faster: the
    // timing's to pace); only where none of them clears does the clearance win (the hands
    // never pass through each other or the body) and the speed is left to the timing.
    double speedAllowed = 0.0;
    // Issue 21 (both hands inside the frame): a detour is sought first among those that take
    // neither moving wrist more than kDetourDipToleranceMm below the resting wrists' height (or
    // below the lower of its two ends, where that is lower), as the straight blend never goes:
    // the waist-up view shows the resting hands a few pixels above its bottom edge, and a hand
    // pushed down under the other as the arms uncross on the way to rest left the frame (story
    // 02's NEW -> rest; SON, DAUGHTER, BABY alone). Where no such detour clears at the judged
    // instants, the transition is routed as if there were no floor (below, in the routing loop).
    // [D] 20 mm: the dips that left the frame went deeper; 1 mm also turned away story 10's
    // IX -> EMAIL detour, and EMAIL's settled hands sank 0.7-4.3 mm deeper in every version.
    constexpr float kDetourDipToleranceMm = 20.0f;
    bool avoidDips = true;
    const float rightLowest = std::min({rig_->restingTarget(hand::Side::Right).wristMm.y, from.rightWrist->wristMm.y,
                                        to.rightWrist->wristMm.y}) - kDetourDipToleranceMm;
    const float leftLowest = std::min({rig_->restingTarget(hand::Side::Left).wristMm.y, from.leftWrist->wristMm.y,
                                       to.leftWrist->wristMm.y}) - kDetourDipToleranceMm;
    const auto dips = [&](const std::vector<Bump>& bumps) {
        for (std::size_t j = 0; j < times.size(); ++j) {
            const SignerPosture p = withBumps(bumps, straight[j], times[j]);
            if ((rightMoves && p.rightWrist->wristMm.y < rightLowest) || (leftMoves && p.leftWrist->wristMm.y < leftLowest))
                return true;
        }
        return false;
    };
    // The hands along the transition with `bumps`: every judged instant's samples, or
    // (bounded) the largest shortfall, given up on as soon as it exceeds `bound`.
    const auto follow = [&](const std::vector<Bump>& bumps, std::vector<Sample>* samples, float bound) {
        if (!bumps.empty() && peakSpeed(bumps) > speedAllowed) return std::numeric_limits<float>::infinity();
        if (!bumps.empty() && avoidDips && dips(bumps)) return std::numeric_limits<float>::infinity();
        float worst = 0.0f;
        for (std::size_t j = 0; j < times.size(); ++j) {
            Sample s = sampleOf(withBumps(bumps, straight[j], times[j]), times[j]);
            worst = std::max(worst, shortfallOf(s.gaps));
            if (samples) samples->push_back(std::move(s));
            if (worst > bound) break;
        }
        return worst;
    };

    // The route on the judged instants: the bumps, and the samples there.
    struct Route {
        std::vector<Bump> bumps;
        std::vector<Sample> samples;
    };
    const auto route = [&](const std::vector<Bump>& seed) {
        Route straightRoute;
        speedAllowed = std::max(kWristPeakSpeedMmPerSecond, peakSpeed({}));
        float shortfall = follow({}, &straightRoute.samples, std::numeric_limits<float>::infinity());
        if (shortfall <= kShortfallToleranceMm) return straightRoute;
        const std::vector<Sample>& straightSamples = straightRoute.samples;
        std::vector<Bump> bumps;
        std::vector<Sample> samples = straightSamples, trialSamples;

        // Ways aside, per millimetre: (right hand, left hand). A hand that does not move in the
        // transition stays where it is.
        const Sample& closest = *std::min_element(straightSamples.begin(), straightSamples.end(),
                                                  [](const Sample& a, const Sample& b) { return a.gaps.hands < b.gaps.hands; });
        glm::vec3 apart = closest.gaps.handsApproach.onFirst - closest.gaps.handsApproach.onSecond;
        apart = glm::length(apart) > 1e-3f ? glm::normalize(apart) : glm::vec3(-1.0f, 0.0f, 0.0f);
        const glm::vec3 rightward(-1.0f, 0.0f, 0.0f), up(0.0f, 1.0f, 0.0f), forward(0.0f, 0.0f, 1.0f);
        const std::array<std::pair<glm::vec3, glm::vec3>, 5> ways{{{apart, -apart},
                                                                  {rightward, -rightward},
                                                                  {up, -up},
                                                                  {-up, up},
                                                                  {forward, forward}}};
        const auto withBump = [&](int shape, const std::pair<glm::vec3, glm::vec3>& way, float size) {
            std::vector<Bump> trial = bumps;
            trial.push_back({shape, rightMoves ? size * way.first : glm::vec3(0.0f), leftMoves ? size * way.second : glm::vec3(0.0f)});
            return trial;
        };
        // A bump adds its own speed to the wrist's: size times the shape's steepest slope over
        // the transition's length. [D] At most kDetourPeakSpeedMmPerSecond, so that a detour in a
        // short transition (0.1-0.2 s at the natural pace) does not take the wrist past SPEC
        // §6.2's 2.5 m/s; a bigger one is not tried.
        const auto largestBump = [&](int shape) {
            return static_cast<float>(kDetourPeakSpeedMmPerSecond * (endSeconds - startSeconds) / steepestSlope(shape));
        };
        const float straightShortfall = shortfall;
        std::optional<std::pair<Route, float>> withinSpeed;  // the first pass's detour
        // A route found before, on fewer instants, is where the search goes on from, in the pass
        // whose speed it keeps: judged on the instants added since, it falls short only there.
        int firstPass = 0;
        if (!seed.empty()) {
            if (peakSpeed(seed) > speedAllowed) {
                firstPass = 1;
                speedAllowed = std::numeric_limits<double>::infinity();
            }
            std::vector<Sample> seeded;
            const float seededShortfall = follow(seed, &seeded, std::numeric_limits<float>::infinity());
            if (seededShortfall < shortfall) {
                bumps = seed;
                samples = std::move(seeded);
                shortfall = seededShortfall;
            }
        }
        for (int pass = firstPass; pass < 2; ++pass) {
            if (pass == 1 && firstPass == 0) {
                if (shortfall <= kShortfallToleranceMm) break;
                withinSpeed = std::make_pair(Route{bumps, samples}, shortfall);
                bumps.clear();
                samples = straightSamples;
                shortfall = straightShortfall;
                speedAllowed = std::numeric_limits<double>::infinity();
            }
            while (static_cast<int>(bumps.size()) < kMostBumps && shortfall > kShortfallToleranceMm) {
                // Every shape and way at a middle size; then every size of the three most promising.
                struct Trial {
                    float shortfallMm;
                    int shape;
                    std::size_t way;
                };
                std::vector<Trial> trials;
                for (int shape = 0; shape < static_cast<int>(kBumpShapes.size()); ++shape)
                    for (std::size_t w = 0; w < ways.size(); ++w)
                        if ((rightMoves && ways[w].first != glm::vec3(0.0f)) || (leftMoves && ways[w].second != glm::vec3(0.0f)))
                            trials.push_back({follow(withBump(shape, ways[w], kSizesMm[2]), nullptr, shortfall), shape, w});
                std::stable_sort(trials.begin(), trials.end(),
                                 [](const Trial& a, const Trial& b) { return a.shortfallMm < b.shortfallMm; });
                float best = shortfall - 0.25f;  // a bump must help by a quarter millimetre
                std::optional<Bump> chosen;
                for (std::size_t t = 0; t < std::min<std::size_t>(3, trials.size()); ++t)
                    for (float size : kSizesMm) {
                        if (size > largestBump(trials[t].shape)) break;
                        std::vector<Bump> trial = withBump(trials[t].shape, ways[trials[t].way], size);
                        trialSamples.clear();
                        const float result = follow(trial, &trialSamples, best);
                        if (result < best) {  // followed to the end: its samples are the route's
                            best = result;
                            chosen = trial.back();
                            std::swap(samples, trialSamples);
                        }
                    }
                if (!chosen) break;
                bumps.push_back(*chosen);
                shortfall = best;
            }
        }
        if (withinSpeed && withinSpeed->second <= shortfall) return withinSpeed->first;
        return Route{bumps, samples};
    };

    // The route judged between its instants (kBetweenToleranceMm above): its largest shortfall
    // at any instant sampled, and in `shortInstants` the deepest instant of each interval of the
    // judged ones where some instant between them falls short.
    const auto judgeBetween = [&](const Route& routed, std::vector<double>& shortInstants, std::vector<double>& jumps) {
        const std::vector<Bump>& bumps = routed.bumps;
        std::vector<Sample> samples{first};
        samples.insert(samples.end(), routed.samples.begin(), routed.samples.end());
        float worst = 0.0f;
        for (const Sample& s : samples) worst = std::max(worst, shortfallOf(s.gaps));
        // The most the gaps can fall short between two instants: each drops by at most the
        // way the hand's capsules travel toward the nearer of them.
        const auto boundBetween = [&](const Sample& a, const Sample& b) {
            const float right = kPathPerChord * farthestMove(a.capsules.right, b.capsules.right);
            const float left = kPathPerChord * farthestMove(a.capsules.left, b.capsules.left);
            return std::max({handsNeeded - 0.5f * (a.gaps.hands + b.gaps.hands - right - left),
                             rightBodyNeeded - 0.5f * (a.gaps.rightBody + b.gaps.rightBody - right),
                             leftBodyNeeded - 0.5f * (a.gaps.leftBody + b.gaps.leftBody - left)});
        };
        struct Deepest {
            double seconds = 0.0;
            float shortfallMm = kShortfallToleranceMm + kBetweenToleranceMm;
        };
        const auto halve = [&](const auto& self, const Sample& a, const Sample& b, int halvings, Deepest& deepest) -> void {
            if (boundBetween(a, b) <= kShortfallToleranceMm + kBetweenToleranceMm) return;
            if (halvings >= kMostHalvings) {
                const float farthest = std::max(farthestMove(a.capsules.right, b.capsules.right),
                                                farthestMove(a.capsules.left, b.capsules.left));
                if (farthest > kJumpMmPerSecond * (b.seconds - a.seconds)) jumps.push_back(0.5 * (a.seconds + b.seconds));
                return;
            }
            const double seconds = 0.5 * (a.seconds + b.seconds);
            const Sample middle = sampleOf(withBumps(bumps, straightPostureAt(seconds), seconds), seconds);
            const float shortfall = shortfallOf(middle.gaps);
            worst = std::max(worst, shortfall);
            if (shortfall > deepest.shortfallMm) deepest = {seconds, shortfall};
            self(self, a, middle, halvings + 1, deepest);
            self(self, middle, b, halvings + 1, deepest);
        };
        for (std::size_t j = 0; j + 1 < samples.size(); ++j) {
            Deepest deepest;
            halve(halve, samples[j], samples[j + 1], 0, deepest);
            if (deepest.shortfallMm > kShortfallToleranceMm + kBetweenToleranceMm) shortInstants.push_back(deepest.seconds);
        }
        return worst;
    };

    // Routed, judged between its instants, and routed again with the short instants judged
    // too (from the best route so far), while that helps; kept: the route that falls least
    // short anywhere.
    float bestShortfall = std::numeric_limits<float>::infinity();
    for (int routing = 0; routing < kMostRoutings; ++routing) {
        avoidDips = true;
        Route routed = route(detour.bumps);
        float atInstants = 0.0f;
        for (const Sample& s : routed.samples) atInstants = std::max(atInstants, shortfallOf(s.gaps));
        if (atInstants > kShortfallToleranceMm) {
            avoidDips = false;
            routed = route(detour.bumps);
        }
        std::vector<double> shortInstants, jumps;
        const float shortfall = judgeBetween(routed, shortInstants, jumps);
        if (shortfall < bestShortfall) {
            bestShortfall = shortfall;
            detour.bumps = routed.bumps;
        }
        if (shortInstants.empty()) break;
        const double step = 1.0 / (kRoutingFramesPerSecond * (1 << kMostHalvings));
        // The window of the jump nearest each short instant, where one is that near.
        std::vector<double> around, windowed;
        for (const double t : shortInstants) {
            const double* nearest = nullptr;
            for (const double& jump : jumps)
                if (std::abs(t - jump) <= kJumpWindow * step && (!nearest || std::abs(t - jump) < std::abs(t - *nearest)))
                    nearest = &jump;
            if (!nearest || std::find(windowed.begin(), windowed.end(), *nearest) != windowed.end()) continue;
            windowed.push_back(*nearest);
            for (int k = -kJumpWindow; k <= kJumpWindow; ++k)
                if (*nearest + k * step > startSeconds && *nearest + k * step < endSeconds) around.push_back(*nearest + k * step);
        }
        shortInstants.insert(shortInstants.end(), around.begin(), around.end());
        for (const double t : shortInstants) {
            const auto at = std::lower_bound(times.begin(), times.end(), t);
            if (at != times.end() && std::abs(*at - t) < 1e-9) continue;
            straight.insert(straight.begin() + (at - times.begin()), straightPostureAt(t));
            times.insert(at, t);
        }
    }
    return detour;
}

}  // namespace signstim::signer
