#include "signer/timeline_clip.hpp"

#include "signer/hand_capsules.hpp"
#include "signer/signer.hpp"
#include "signer/signer_pose.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>

namespace signstim::signer {
namespace {

// [D] The most a detour's bump adds to the wrist's speed at its peak (see routeTransition).
constexpr double kDetourPeakSpeedMmPerSecond = 1200.0;
// SPEC §6.2: peak wrist speed of natural signing.
constexpr double kWristPeakSpeedMmPerSecond = 2500.0;

// [D] A glance at a referent: 1.2 m out along its direction, 12° below eye level.
constexpr double kGazeDistanceMm = 1200.0;
constexpr double kGazeDropDegrees = 12.0;
// The default signer's eyes in the body frame (hand/gaze.hpp, GazeModel::eyesMm).
constexpr double kEyeHeightMm = 420.0;

struct Resolved {
    hand::ArmTarget target;
    hand::HandControls controls;
};

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

// The steepest slope of a bump's shape, |d bump / du| at its maximum (sampled; 1e-3 of u).
double steepestSlope(int shape) {
    double steepest = 0.0;
    for (int i = 0; i < 1000; ++i) {
        const double u = i / 1000.0;
        steepest = std::max(steepest, std::abs(static_cast<double>(bump(shape, u + 1e-3)) - bump(shape, u)) / 1e-3);
    }
    return steepest;
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

// How close the hands come to each other and to the body where the arms put them.
struct Gaps {
    float hands = 0.0f, rightBody = 0.0f, leftBody = 0.0f;
    Approach handsApproach;
};

Gaps measure(const SignerRig& rig, const SignerPosture& posture, const PoseReport& arms) {
    const SignerCapsules capsules = signerCapsules(rig, posture, arms);
    Gaps g;
    g.handsApproach = closestApproach(capsules.right, capsules.left);
    g.hands = g.handsApproach.gapMm;
    g.rightBody = closestApproach(capsules.right, bodyCapsules()).gapMm;
    g.leftBody = closestApproach(capsules.left, bodyCapsules()).gapMm;
    return g;
}

}  // namespace

glm::vec3 gazePointForReferent(const glm::dvec3& p) {
    const double horizontal = std::hypot(p.x, p.z);
    const glm::dvec3 direction = horizontal > 1e-6 ? glm::dvec3(p.x / horizontal, 0.0, p.z / horizontal) : glm::dvec3(0, 0, 1);
    const double drop = std::tan(kGazeDropDegrees * 3.14159265358979323846 / 180.0) * kGazeDistanceMm;
    const glm::dvec3 point = glm::dvec3(0.0, kEyeHeightMm - drop, 0.0) + kGazeDistanceMm * direction;
    return bodyFromSigningSpace(glm::vec3(point));
}

NonManualPosture nonManualAt(const stimuli::Timeline& timeline, double seconds) {
    NonManualPosture posture;
    for (const stimuli::NonManualTrack& track : timeline.nonManuals) {
        const double value = stimuli::sampleNonManual(track, seconds);
        // A face channel at 0 is left out, so a neutral instant poses exactly as without tracks.
        if (value == 0.0) continue;
        setNonManualChannel(posture, track.channel, value);
    }
    return posture;
}

glm::vec3 gazePointForViewer() { return glm::vec3(0.0f, static_cast<float>(kEyeHeightMm), 2000.0f); }

glm::vec3 gazePoint(const stimuli::GazeKey& key) {
    return key.targetMm ? gazePointForReferent(*key.targetMm) : gazePointForViewer();
}

TimelineClip::TimelineClip(const SignerRig& rig, stimuli::Timeline timeline) : rig_(&rig), timeline_(std::move(timeline)) {
    // Transitions: neighbouring keys that no item's own keys hold (both hands have keys at
    // every transition's ends; the right track lists them). Each is routed on its own: the
    // arms at any instant depend on the wrist targets alone.
    const auto insideItem = [&](double start, double end) {
        for (const stimuli::TimelineSpan& span : timeline_.spans)
            if (span.keysStartSeconds <= start && end <= span.keysEndSeconds) return true;
        return false;
    };
    // The elbows at the keys, by the solver's rule of the target alone: every instant between
    // two keys looks for its elbow near their blend.
    for (const hand::Side side : {hand::Side::Right, hand::Side::Left}) {
        const bool right = side == hand::Side::Right;
        for (const stimuli::TimelineKey& key : right ? timeline_.right : timeline_.left) {
            const hand::ArmTarget target = key.rest ? rig_->restingTarget(side) : armTargetFromSigningSpace(key.pose);
            (right ? rightElbows_ : leftElbows_).push_back(hand::solveArm(rig_->arm(side), target).elbowDirection);
        }
    }
    // The head's turns, one after another (a minimum-jerk turn of angle A over T peaks at
    // 1.875·A/T).
    const std::vector<stimuli::GazeKey>& gaze = timeline_.gaze;
    const auto headFor = [&](const stimuli::GazeKey& key) {
        const hand::GazePose g = hand::solveGaze(rig_->gaze(), gazePoint(key));
        return glm::vec2(g.headYawDeg, g.headPitchDeg);
    };
    if (!gaze.empty()) {
        headStartDeg_ = headFor(gaze.front());
        glm::vec2 head = headStartDeg_;
        double free = gaze.front().timeSeconds;
        for (std::size_t k = 1; k < gaze.size(); ++k) {
            const glm::vec2 target = headFor(gaze[k]);
            const double angle = glm::length(target - head);
            if (angle < 1e-3) continue;
            const double start = std::max(gaze[k - 1].timeSeconds, free);
            const double duration =
                std::max(gaze[k].timeSeconds - gaze[k - 1].timeSeconds, 1.875 * angle / kHeadPeakDegPerSecond);
            headMoves_.push_back({start, duration, head, target});
            head = target;
            free = start + duration;
        }
    }
    const std::vector<stimuli::TimelineKey>& keys = timeline_.right;
    for (std::size_t k = 0; k + 1 < keys.size(); ++k) {
        const double start = keys[k].timeSeconds, end = keys[k + 1].timeSeconds;
        if (end <= start || insideItem(start, end)) continue;
        Detour detour = routeTransition(start, end);
        if (!detour.bumps.empty()) detours_.push_back(std::move(detour));
    }
}

PoseReport TimelineClip::arms(const SignerPosture& posture) const {
    PoseReport report;
    report.right = rig_->solveArm(hand::Side::Right, posture);
    report.left = rig_->solveArm(hand::Side::Left, posture);
    return report;
}

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
    Detour detour;
    detour.startSeconds = startSeconds;
    detour.endSeconds = endSeconds;
    const SignerPosture from = straightPostureAt(startSeconds), to = straightPostureAt(endSeconds);
    const bool rightMoves = !sameTarget(from.rightWrist, to.rightWrist) || !sameControls(from.rightHand, to.rightHand);
    const bool leftMoves = !sameTarget(from.leftWrist, to.leftWrist) || !sameControls(from.leftHand, to.leftHand);
    if (!rightMoves && !leftMoves) return detour;

    // The frames inside the transition, and its end: a grid from the transition's start, so
    // that the same transition is routed alike wherever it falls in a timeline (the timeline
    // builder's pacer, transitionPacer, routes it on its own to time it).
    std::vector<double> times;
    for (int f = 1; startSeconds + f / kRoutingFramesPerSecond < endSeconds; ++f)
        times.push_back(startSeconds + f / kRoutingFramesPerSecond);
    times.push_back(endSeconds);
    std::vector<SignerPosture> straight;
    for (double t : times) straight.push_back(straightPostureAt(t));
    const auto offsetAt = [&](const std::vector<Bump>& bumps, std::size_t j, bool right) {
        glm::vec3 offset(0.0f);
        const double u = (times[j] - startSeconds) / (endSeconds - startSeconds);
        for (const Bump& b : bumps) offset += bump(b.shape, u) * (right ? b.rightMm : b.leftMm);
        return offset;
    };
    // The hands along the transition with `bumps`: every frame's gaps, or (bounded) the
    // largest shortfall, given up on as soon as it exceeds `bound`.
    float handsNeeded = 0.0f, rightBodyNeeded = 0.0f, leftBodyNeeded = 0.0f;
    // The wrists' peak speed along the transition with `bumps`, on the routing grid.
    const auto peakSpeed = [&](const std::vector<Bump>& bumps) {
        double peak = 0.0, before = startSeconds;
        glm::vec3 right = from.rightWrist->wristMm, left = from.leftWrist->wristMm;
        for (std::size_t j = 0; j < times.size(); ++j) {
            const glm::vec3 r = straight[j].rightWrist->wristMm + offsetAt(bumps, j, true);
            const glm::vec3 l = straight[j].leftWrist->wristMm + offsetAt(bumps, j, false);
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
    double speedAllowed = std::max(kWristPeakSpeedMmPerSecond, peakSpeed({}));
    const auto follow = [&](const std::vector<Bump>& bumps, std::vector<Gaps>* gaps, float bound) {
        if (!bumps.empty() && peakSpeed(bumps) > speedAllowed) return std::numeric_limits<float>::infinity();
        float worst = 0.0f;
        for (std::size_t j = 0; j < times.size(); ++j) {
            SignerPosture p = straight[j];
            p.rightWrist->wristMm += offsetAt(bumps, j, true);
            p.leftWrist->wristMm += offsetAt(bumps, j, false);
            const Gaps g = measure(*rig_, p, arms(p));
            if (gaps) gaps->push_back(g);
            worst = std::max({worst, handsNeeded - g.hands, rightBodyNeeded - g.rightBody, leftBodyNeeded - g.leftBody});
            if (worst > bound) break;
        }
        return worst;
    };
    std::vector<Gaps> straightGaps;
    follow({}, &straightGaps, std::numeric_limits<float>::infinity());
    // Never closer than the clearance, or than the ends are (an item there touches).
    const Gaps first = measure(*rig_, from, arms(from));
    const Gaps& last = straightGaps.back();
    handsNeeded = std::min({kTransitionClearanceMm, first.hands, last.hands});
    // A hand that does not move in the transition (resting) is not asked to clear the body.
    constexpr float kNotAsked = -std::numeric_limits<float>::infinity();
    rightBodyNeeded = rightMoves ? std::min({kTransitionClearanceMm, first.rightBody, last.rightBody}) : kNotAsked;
    leftBodyNeeded = leftMoves ? std::min({kTransitionClearanceMm, first.leftBody, last.leftBody}) : kNotAsked;
    float shortfall = follow({}, nullptr, std::numeric_limits<float>::infinity());
    if (shortfall <= kShortfallToleranceMm) return detour;

    // Ways aside, per millimetre: (right hand, left hand). A hand that does not move in the
    // transition stays where it is.
    const Gaps& closest = *std::min_element(straightGaps.begin(), straightGaps.end(),
                                            [](const Gaps& a, const Gaps& b) { return a.hands < b.hands; });
    glm::vec3 apart = closest.handsApproach.onFirst - closest.handsApproach.onSecond;
    apart = glm::length(apart) > 1e-3f ? glm::normalize(apart) : glm::vec3(-1.0f, 0.0f, 0.0f);
    const glm::vec3 rightward(-1.0f, 0.0f, 0.0f), up(0.0f, 1.0f, 0.0f), forward(0.0f, 0.0f, 1.0f);
    const std::array<std::pair<glm::vec3, glm::vec3>, 5> ways{{{apart, -apart},
                                                              {rightward, -rightward},
                                                              {up, -up},
                                                              {-up, up},
                                                              {forward, forward}}};
    const auto withBump = [&](int shape, const std::pair<glm::vec3, glm::vec3>& way, float size) {
        std::vector<Bump> trial = detour.bumps;
        trial.push_back({shape, rightMoves ? size * way.first : glm::vec3(0.0f), leftMoves ? size * way.second : glm::vec3(0.0f)});
        return trial;
    };
    // A bump adds its own speed to the wrist's: size times the shape's steepest slope over the
    // transition's length. [D] At most kDetourPeakSpeedMmPerSecond, so that a detour in a short
    // transition (0.1-0.2 s at the natural pace) does not take the wrist past SPEC §6.2's
    // 2.5 m/s; a bigger one is not tried.
    const auto largestBump = [&](int shape) {
        return static_cast<float>(kDetourPeakSpeedMmPerSecond * (endSeconds - startSeconds) / steepestSlope(shape));
    };
    const float straightShortfall = shortfall;
    std::optional<std::pair<std::vector<Bump>, float>> withinSpeed;  // the first pass's detour
    for (int pass = 0; pass < 2; ++pass) {
        if (pass == 1) {
            if (shortfall <= kShortfallToleranceMm) break;
            withinSpeed = std::make_pair(detour.bumps, shortfall);
            detour.bumps.clear();
            shortfall = straightShortfall;
            speedAllowed = std::numeric_limits<double>::infinity();
        }
        while (static_cast<int>(detour.bumps.size()) < kMostBumps && shortfall > kShortfallToleranceMm) {
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
                    const float result = follow(trial, nullptr, best);
                    if (result < best) {
                        best = result;
                        chosen = trial.back();
                    }
                }
            if (!chosen) break;
            detour.bumps.push_back(*chosen);
            shortfall = best;
        }
    }
    if (withinSpeed && withinSpeed->second <= shortfall) detour.bumps = withinSpeed->first;
    return detour;
}

SignerPosture TimelineClip::postureAt(double seconds) const {
    SignerPosture posture = straightPostureAt(seconds);
    for (const Detour& detour : detours_) {
        if (seconds <= detour.startSeconds || seconds >= detour.endSeconds) continue;
        const double u = (seconds - detour.startSeconds) / (detour.endSeconds - detour.startSeconds);
        for (const Bump& b : detour.bumps) {
            posture.rightWrist->wristMm += bump(b.shape, u) * b.rightMm;
            posture.leftWrist->wristMm += bump(b.shape, u) * b.leftMm;
        }
        break;
    }
    return posture;
}

SignerPosture TimelineClip::straightPostureAt(double seconds) const {
    SignerPosture posture;
    for (const hand::Side side : {hand::Side::Right, hand::Side::Left}) {
        const auto& track = side == hand::Side::Right ? timeline_.right : timeline_.left;
        const stimuli::TimelineSample sample = stimuli::sampleTrack(track, seconds);
        auto resolve = [&](const stimuli::TimelineKey& key) {
            if (key.rest) return Resolved{rig_->restingTarget(side), relaxedHand()};
            return Resolved{armTargetFromSigningSpace(key.pose), key.controls};
        };
        const Resolved from = resolve(*sample.from), to = resolve(*sample.to);
        const float blend = static_cast<float>(sample.blend);
        const hand::ArmTarget target = blendTargets(from.target, to.target, blend);
        const hand::HandControls controls = hand::interpolate(from.controls, to.controls, blend);
        const std::vector<glm::vec3>& elbows = side == hand::Side::Right ? rightElbows_ : leftElbows_;
        const glm::vec3 elbow = blendElbowHints(elbows[static_cast<std::size_t>(sample.from - track.data())],
                                                elbows[static_cast<std::size_t>(sample.to - track.data())], blend);
        if (side == hand::Side::Right) {
            posture.rightWrist = target;
            posture.rightHand = controls;
            posture.rightElbowHint = elbow;
        } else {
            posture.leftWrist = target;
            posture.leftHand = controls;
            posture.leftElbowHint = elbow;
        }
    }
    posture.nonManual = nonManualAt(timeline_, seconds);
    const stimuli::GazeSample gaze = stimuli::sampleGaze(timeline_.gaze, seconds);
    if (gaze.from) {
        const glm::vec3 a = gazePoint(*gaze.from), b = gazePoint(*gaze.to);
        posture.gazeMm = a + static_cast<float>(gaze.blend) * (b - a);
        posture.headDeg = headAt(seconds);
    }
    return posture;
}

glm::vec2 TimelineClip::headAt(double seconds) const {
    glm::vec2 head = headStartDeg_;
    for (const HeadMove& move : headMoves_) {
        if (seconds <= move.startSeconds) break;
        const double u = (seconds - move.startSeconds) / move.durationSeconds;
        head = move.fromDeg + static_cast<float>(stimuli::minimumJerk(u)) * (move.toDeg - move.fromDeg);
    }
    return head;
}

double pacedTransitionSeconds(const SignerRig& rig, const stimuli::TransitionQuery& query) {
    // [D] The drawn wrists are sampled every 1/240 s (the speed between neighbouring samples:
    // finer than any output's frames, so the peak is not missed between them).
    constexpr double kSamplesPerSecond = 240.0;
    // [D] Once a length that keeps the limit is found, the shortest one is sought between it
    // and the last too fast, halving the gap this many times (to ~1 % of the step).
    constexpr int kBisections = 4;
    if (!(query.seconds > 0.0) || !(query.peakSpeedMmPerSecond > 0.0)) return query.seconds;
    // The transition's drawn wrists' peak speed when it lasts `seconds`.
    const auto peakAt = [&](double seconds) {
        stimuli::Timeline timeline;
        for (std::size_t h = 0; h < 2; ++h) {
            std::vector<stimuli::TimelineKey>& track = h == 0 ? timeline.right : timeline.left;
            track = {query.from[h], query.to[h]};
            track[0].timeSeconds = 0.0;
            track[1].timeSeconds = seconds;
            track[0].passThrough = track[1].passThrough = false;
        }
        timeline.durationSeconds = seconds;
        // Inside an item the clip routes nothing (TimelineClip routes only between items).
        if (query.insideItem)
            timeline.spans.push_back({stimuli::SpanKind::Verb, 0.0, seconds, "", 0, 0, 0.0, seconds, {}, 0});
        const TimelineClip clip(rig, std::move(timeline));
        const auto samples = static_cast<int>(std::ceil(seconds * kSamplesPerSecond));
        double peak = 0.0;
        glm::vec3 right(0.0f), left(0.0f);
        for (int i = 0; i <= samples; ++i) {
            const SignerPosture posture = clip.postureAt(seconds * i / samples);
            const glm::vec3 r = rig.solveArm(hand::Side::Right, posture).wristMm;
            const glm::vec3 l = rig.solveArm(hand::Side::Left, posture).wristMm;
            if (i > 0) peak = std::max(peak, std::max(glm::distance(r, right), glm::distance(l, left)) * samples / seconds);
            right = r;
            left = l;
        }
        return peak;
    };
    double tooFast = 0.0, seconds = query.seconds;
    for (int step = 0;; ++step) {
        const double peak = peakAt(seconds);
        if (peak <= query.peakSpeedMmPerSecond) break;
        if (step + 1 >= kPacerSteps) return seconds;  // the longest tried (the check reports what is left)
        tooFast = seconds;
        seconds *= std::max(1.05, peak / query.peakSpeedMmPerSecond);
    }
    if (tooFast > 0.0)
        for (int i = 0; i < kBisections; ++i) {
            const double middle = 0.5 * (tooFast + seconds);
            (peakAt(middle) <= query.peakSpeedMmPerSecond ? seconds : tooFast) = middle;
        }
    return seconds;
}

namespace {

// `keepAlive` owns what `rig` belongs to (or nothing).
stimuli::TransitionPacer pacerOf(const SignerRig* rig, std::shared_ptr<const void> keepAlive) {
    struct Memory {
        std::mutex mutex;
        std::map<std::string, double> seconds;
    };
    auto memory = std::make_shared<Memory>();
    return [rig, keepAlive, memory](const stimuli::TransitionQuery& query) {
        // The query's exact bits (the controls follow from the handshape's name).
        std::string key;
        const auto add = [&key](const void* bytes, std::size_t size) { key.append(static_cast<const char*>(bytes), size); };
        add(&query.seconds, sizeof query.seconds);
        add(&query.peakSpeedMmPerSecond, sizeof query.peakSpeedMmPerSecond);
        key += query.insideItem ? 'i' : 't';
        for (const auto* ends : {&query.from, &query.to})
            for (const stimuli::TimelineKey& k : *ends) {
                const double values[] = {k.rest ? 1.0 : 0.0, k.pose.positionMm.x, k.pose.positionMm.y, k.pose.positionMm.z,
                                         k.pose.orientation.w, k.pose.orientation.x, k.pose.orientation.y,
                                         k.pose.orientation.z};
                add(values, sizeof values);
                key += k.handshape;
                key += '\0';
            }
        {
            const std::lock_guard<std::mutex> lock(memory->mutex);
            if (const auto found = memory->seconds.find(key); found != memory->seconds.end()) return found->second;
        }
        const double seconds = pacedTransitionSeconds(*rig, query);
        const std::lock_guard<std::mutex> lock(memory->mutex);
        memory->seconds.emplace(key, seconds);
        return seconds;
    };
}

}  // namespace

stimuli::TransitionPacer transitionPacer(std::shared_ptr<const Signer> signer) {
    const SignerRig* rig = &signer->rig();
    return pacerOf(rig, std::move(signer));
}

stimuli::TransitionPacer transitionPacer(const SignerRig& rig) { return pacerOf(&rig, nullptr); }

}  // namespace signstim::signer
