#include "signer/timeline_clip.hpp"

#include "signer/hand_capsules.hpp"
#include "signer/settled_pace.hpp"
#include "signer/signer.hpp"
#include "signer/signer_pose.hpp"
#include "stimuli/verbs/signing_space.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace signstim::signer {
namespace {

// [D] A glance at a referent: 1.2 m out along its direction, 12° below eye level.
constexpr double kGazeDistanceMm = 1200.0;
constexpr double kGazeDropDegrees = 12.0;

struct Resolved {
    hand::ArmTarget target;
    hand::HandControls controls;
};

}  // namespace

hand::HandControls claspYielded(const hand::HandControls& controls, float share) {
    if (share <= 0.0f) return controls;
    hand::HandControls straight;
    for (std::size_t f = 0; f < straight.fingers.size(); ++f) straight.fingers[f].spreadDeg = controls.fingers[f].spreadDeg;
    return hand::interpolate(controls, straight, share);
}

glm::vec3 gazePointForReferent(const glm::dvec3& p, double eyeHeightMm) {
    const double horizontal = std::hypot(p.x, p.z);
    const glm::dvec3 direction = horizontal > 1e-6 ? glm::dvec3(p.x / horizontal, 0.0, p.z / horizontal) : glm::dvec3(0, 0, 1);
    const double drop = std::tan(kGazeDropDegrees * 3.14159265358979323846 / 180.0) * kGazeDistanceMm;
    const glm::dvec3 point = glm::dvec3(0.0, eyeHeightMm - drop, 0.0) + kGazeDistanceMm * direction;
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

glm::vec3 gazePointForViewer(double eyeHeightMm) { return glm::vec3(0.0f, static_cast<float>(eyeHeightMm), 2000.0f); }

glm::vec3 gazePoint(const stimuli::GazeKey& key, double eyeHeightMm) {
    return key.targetMm ? gazePointForReferent(*key.targetMm, eyeHeightMm) : gazePointForViewer(eyeHeightMm);
}

TimelineClip::TimelineClip(const SignerRig& rig, stimuli::Timeline timeline, bool trackElbows)
    : rig_(&rig), timeline_(std::move(timeline)) {
    // Transitions: neighbouring keys that no item's own keys hold (both hands have keys at
    // every transition's ends; the right track lists them). Each is routed on its own: the
    // arms at any instant depend on the wrist targets alone.
    const auto insideItem = [&](double start, double end) {
        for (const stimuli::TimelineSpan& span : timeline_.spans)
            if (span.keysStartSeconds <= start && end <= span.keysEndSeconds) return true;
        return false;
    };
    // A verb's keys: the hand goes from one to the next about the torso's axis, as the verb's
    // own clip does (stimuli::sampleHand), so that a path from one side to the other bows in
    // front of the chest instead of cutting through it (issue 21). Transitions and lexical
    // signs keep the straight blend (transitions are routed around the body: routeTransition).
    for (const bool right : {true, false}) {
        const std::vector<stimuli::TimelineKey>& track = right ? timeline_.right : timeline_.left;
        std::vector<bool>& swept = right ? rightSwept_ : leftSwept_;
        swept.assign(track.size(), false);
        for (std::size_t k = 0; k + 1 < track.size(); ++k) {
            if (track[k].rest || track[k + 1].rest) continue;
            for (const stimuli::TimelineSpan& span : timeline_.spans)
                if (span.kind == stimuli::SpanKind::Verb && span.keysStartSeconds <= track[k].timeSeconds &&
                    track[k + 1].timeSeconds <= span.keysEndSeconds)
                    swept[k] = true;
        }
    }
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
        const hand::GazePose g = hand::solveGaze(rig_->gaze(), gazePoint(key, rig_->gaze().eyesMm.y));
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
    // Touches settled before the transitions are routed: a transition leaves and reaches the
    // settled keys.
    rightTouch_.assign(timeline_.right.size(), glm::vec3(0.0f));
    leftTouch_.assign(timeline_.left.size(), glm::vec3(0.0f));
    rightYield_.assign(timeline_.right.size(), 0.0f);
    leftYield_.assign(timeline_.left.size(), 0.0f);
    settleTouches();
    const std::vector<stimuli::TimelineKey>& keys = timeline_.right;
    for (std::size_t k = 0; k + 1 < keys.size(); ++k) {
        const double start = keys[k].timeSeconds, end = keys[k + 1].timeSeconds;
        if (end <= start || insideItem(start, end)) continue;
        Detour detour = routeTransition(start, end);
        if (!detour.bumps.empty()) detours_.push_back(std::move(detour));
    }
    // The elbows' track (signer/elbow_track.hpp): the arm solver's elbows on the postures as
    // drawn (touches settled, detours routed), blended across their jumps; from here on every
    // posture follows it (straightPostureAt). The touches and the detours stay those of the
    // solver's own arms, as the timeline's pacer saw them: settled and routed again on the
    // blended arms, a verb slot's wrists reached 2.68 m/s (MEET point s=-0.5 o=-1; measured
    // 2026-11-26). Outside a blend the arms are the solver's, so those touches hold there.
    if (trackElbows) elbows_ = ElbowTrack(*rig_, timeline_.durationSeconds, [this](double t) { return postureAt(t); });
}

PoseReport TimelineClip::arms(const SignerPosture& posture) const {
    PoseReport report;
    report.right = rig_->solveArm(hand::Side::Right, posture);
    report.left = rig_->solveArm(hand::Side::Left, posture);
    return report;
}

void TimelineClip::settleTouches() {
    // [D] An instant within kSettledMm of kTouchDepthMm is left as it is; the way out is
    // sought in steps of kStepMm up to kMostMm (about a palm's width: a touch that needs more is
    // no touch but a hand through the other, which the sign's data must change), then halved
    // kHalvings times (to 0.25 mm).
    constexpr float kSettledMm = 0.25f, kStepMm = 4.0f, kMostMm = 64.0f;
    constexpr int kHalvings = 4;
    // The stretches that touch with both hands: an item, with the items that follow it without a
    // transition (its HOLD at a sentence's end), settled as one, so that its offsets are one
    // function of t.
    struct Stretch {
        double startSeconds, endSeconds;
        bool clasp;
    };
    std::vector<Stretch> stretches;
    for (const stimuli::TimelineSpan& span : timeline_.spans) {
        if (!span.contact.hands || span.keysEndSeconds <= span.keysStartSeconds) continue;
        if (!stretches.empty() && span.keysStartSeconds <= stretches.back().endSeconds + 1e-9) {
            stretches.back().endSeconds = std::max(stretches.back().endSeconds, span.keysEndSeconds);
            stretches.back().clasp = stretches.back().clasp || span.contact.clasp;
        } else {
            stretches.push_back({span.keysStartSeconds, span.keysEndSeconds, span.contact.clasp});
        }
    }
    const auto keysIn = [](const std::vector<stimuli::TimelineKey>& track, const Stretch& span) {
        std::vector<std::size_t> in;
        for (std::size_t k = 0; k < track.size(); ++k)
            if (track[k].timeSeconds >= span.startSeconds - 1e-9 && track[k].timeSeconds <= span.endSeconds + 1e-9)
                in.push_back(k);
        return in;
    };
    // Whether a hand moves in the item: a held base hand is not the one that comes to the other.
    const auto moves = [](const std::vector<stimuli::TimelineKey>& track, const std::vector<std::size_t>& in) {
        for (const std::size_t k : in) {
            const stimuli::TimelineKey &a = track[in.front()], &b = track[k];
            if (a.rest != b.rest || glm::distance(a.pose.positionMm, b.pose.positionMm) > 0.5 ||
                std::abs(glm::dot(a.pose.orientation, b.pose.orientation)) < 0.99999)
                return true;
        }
        return false;
    };
    for (const Stretch& span : stretches) {
        const std::vector<std::size_t> right = keysIn(timeline_.right, span), left = keysIn(timeline_.left, span);
        const bool rightMoves = moves(timeline_.right, right), leftMoves = moves(timeline_.left, left);
        // The right hand's share of the way out.
        const float rightShare = rightMoves == leftMoves ? 0.5f : rightMoves ? 1.0f : 0.0f;
        // The instants: the item's keys and a grid of the timeline's own time between them.
        TouchSpan settled;
        settled.startSeconds = span.startSeconds;
        settled.endSeconds = span.endSeconds;
        std::vector<double>& times = settled.times;
        times.push_back(span.startSeconds);
        times.push_back(span.endSeconds);
        for (const std::size_t k : right) times.push_back(timeline_.right[k].timeSeconds);
        for (const std::size_t k : left) times.push_back(timeline_.left[k].timeSeconds);
        for (auto f = static_cast<std::uint64_t>(std::floor(span.startSeconds * kTouchFramesPerSecond)) + 1;
             static_cast<double>(f) / kTouchFramesPerSecond < span.endSeconds; ++f)
            times.push_back(static_cast<double>(f) / kTouchFramesPerSecond);
        std::sort(times.begin(), times.end());
        times.erase(std::unique(times.begin(), times.end(), [](double a, double b) { return b - a < 1e-9; }), times.end());
        // The way out: one direction for the whole stretch, so that the offsets grow and shrink
        // along it smoothly. Tried: the line between the closest points at the deepest instant,
        // the wrists' separation there, and the body's six axes.
        std::vector<SignerPosture> straight;
        for (const double t : times) straight.push_back(straightPostureAt(t, false));
        // A clasp: the digits yield first (timeline_clip.hpp), each instant by the least share
        // that brings the touch to kTouchDepthMm (halved kHalvings + 2 times, to 1/64 of
        // kMostClaspYield), or the most where none does; its rate limited as the offsets' are.
        if (span.clasp) {
            const auto yieldedGap = [&](std::size_t i, float share) {
                SignerPosture posture = straight[i];
                posture.rightHand = claspYielded(posture.rightHand, share);
                posture.leftHand = claspYielded(posture.leftHand, share);
                const SignerCapsules capsules = signerCapsules(*rig_, posture, arms(posture));
                return closestApproach(capsules.right, capsules.left).gapMm;
            };
            std::vector<float> need(times.size(), 0.0f);
            for (std::size_t i = 0; i < times.size(); ++i) {
                if (yieldedGap(i, 0.0f) >= -kTouchDepthMm - kSettledMm) continue;
                float low = 0.0f, high = kMostClaspYield;
                if (yieldedGap(i, high) >= -kTouchDepthMm)
                    for (int k = 0; k < kHalvings + 2; ++k)
                        (yieldedGap(i, 0.5f * (low + high)) < -kTouchDepthMm ? low : high) = 0.5f * (low + high);
                need[i] = high;
            }
            const std::vector<RateBounds> rates(times.size() - 1, RateBounds{-kClaspYieldPerSecond, kClaspYieldPerSecond});
            settled.yield = rateLimitedEnvelope(times, need, rates);
            for (std::size_t i = 0; i < times.size(); ++i) {
                settled.yield[i] = std::min(settled.yield[i], kMostClaspYield);
                straight[i].rightHand = claspYielded(straight[i].rightHand, settled.yield[i]);
                straight[i].leftHand = claspYielded(straight[i].leftHand, settled.yield[i]);
            }
            for (const std::size_t k : right) rightYield_[k] = settled.yieldAt(timeline_.right[k].timeSeconds);
            for (const std::size_t k : left) leftYield_[k] = settled.yieldAt(timeline_.left[k].timeSeconds);
        }
        const auto gapWith = [&](std::size_t i, const glm::vec3& direction, float way) {
            SignerPosture posture = straight[i];
            posture.rightWrist->wristMm += rightShare * way * direction;
            posture.leftWrist->wristMm -= (1.0f - rightShare) * way * direction;
            const SignerCapsules capsules = signerCapsules(*rig_, posture, arms(posture));
            return closestApproach(capsules.right, capsules.left).gapMm;
        };
        std::vector<float> gaps;
        std::vector<std::pair<glm::vec3, glm::vec3>> wrists;  // the posed wrists (right, left), unsettled
        std::size_t deepest = 0;
        for (std::size_t i = 0; i < times.size(); ++i) {
            const PoseReport posed = arms(straight[i]);
            wrists.emplace_back(posed.right.wristMm, posed.left.wristMm);
            gaps.push_back(gapWith(i, glm::vec3(0.0f), 0.0f));
            if (gaps[i] < gaps[deepest]) deepest = i;
        }
        if (gaps[deepest] >= -kTouchDepthMm - kSettledMm) {
            if (span.clasp) {  // settled by its digits alone
                settled.right.assign(times.size(), glm::vec3(0.0f));
                settled.left.assign(times.size(), glm::vec3(0.0f));
                touchSpans_.push_back(std::move(settled));
            }
            continue;
        }
        // The way out along `direction` at instant i: the least that brings the touch to
        // kTouchDepthMm (steps of kStepMm, then halved); where no way up to kMostMm does, the
        // step that leaves the touch shallowest (the clearance check reports the rest).
        struct Way {
            float mm = 0.0f, gapMm = 0.0f;
        };
        const auto wayOut = [&](std::size_t i, const glm::vec3& direction) {
            if (gaps[i] >= -kTouchDepthMm - kSettledMm) return Way{0.0f, gaps[i]};
            Way shallowest{0.0f, gaps[i]};
            float inside = 0.0f, outside = kStepMm;
            for (;; outside += kStepMm) {
                if (outside > kMostMm) return shallowest;
                const float gap = gapWith(i, direction, outside);
                if (gap >= -kTouchDepthMm) break;
                if (gap > shallowest.gapMm) shallowest = {outside, gap};
                inside = outside;
            }
            for (int k = 0; k < kHalvings; ++k) {
                const float middle = 0.5f * (inside + outside);
                (gapWith(i, direction, middle) < -kTouchDepthMm ? inside : outside) = middle;
            }
            return Way{outside, -kTouchDepthMm};
        };
        const SignerPosture& at = straight[deepest];
        const SignerCapsules capsules = signerCapsules(*rig_, at, arms(at));
        const Approach closest = closestApproach(capsules.right, capsules.left);
        const std::vector<glm::vec3> directions{closest.onFirst - closest.onSecond,
                                                at.rightWrist->wristMm - at.leftWrist->wristMm,
                                                {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        // Kept: the direction whose deepest remaining touch is shallowest, then the one that
        // moves the hands least at its worst instant, then in all.
        std::vector<float> best;
        float bestDeepest = -std::numeric_limits<float>::infinity(), bestWorst = 0.0f, bestTotal = 0.0f;
        glm::vec3 chosen(0.0f);
        for (glm::vec3 direction : directions) {
            if (glm::length(direction) < 1e-3f) continue;
            direction = glm::normalize(direction);
            std::vector<float> ways;
            float deepestGap = std::numeric_limits<float>::infinity(), worst = 0.0f, total = 0.0f;
            for (std::size_t i = 0; i < times.size(); ++i) {
                const Way w = wayOut(i, direction);
                ways.push_back(w.mm);
                deepestGap = std::min(deepestGap, w.gapMm);
                worst = std::max(worst, w.mm);
                total += w.mm;
            }
            const bool better = deepestGap > bestDeepest + 0.1f ||
                                (deepestGap > bestDeepest - 0.1f &&
                                 (worst < bestWorst - 0.1f || (worst < bestWorst + 0.1f && total < bestTotal)));
            if (best.empty() || better) {
                best = ways;
                bestDeepest = deepestGap;
                bestWorst = worst;
                bestTotal = total;
                chosen = direction;
            }
        }
        if (best.empty()) continue;
        // The way out grows and shrinks no faster than kTouchRateMmPerSecond, and only as fast
        // as the headroom the wrists' own motion leaves under kSettledPeakSpeedMmPerSecond
        // (signer/settled_pace.hpp): each instant moves out as far as any other needs, less
        // what the rates allow between them (never less than an instant's own need).
        std::vector<RateBounds> bounds;
        for (std::size_t i = 0; i + 1 < times.size(); ++i) {
            RateBounds b{-kTouchRateMmPerSecond, kTouchRateMmPerSecond};
            const double dt = times[i + 1] - times[i];
            for (const bool r : {true, false}) {
                const glm::dvec3 velocity = glm::dvec3((r ? wrists[i + 1].first : wrists[i + 1].second) -
                                                       (r ? wrists[i].first : wrists[i].second)) / dt;
                const RateBounds hand = offsetRateBounds(velocity, glm::dvec3(chosen * (r ? rightShare : rightShare - 1.0f)),
                                                         kSettledPeakSpeedMmPerSecond);
                b = {std::max(b.lo, hand.lo), std::min(b.hi, hand.hi)};
            }
            bounds.push_back(b);
        }
        best = rateLimitedEnvelope(times, best, bounds);
        for (std::size_t i = 0; i < times.size(); ++i) {
            settled.right.push_back(rightShare * best[i] * chosen);
            settled.left.push_back(-(1.0f - rightShare) * best[i] * chosen);
        }
        // The item's keys carry the offsets at their instants, for the transitions out of and
        // into it (blended with the keys, straightPostureAt).
        for (const std::size_t k : right) rightTouch_[k] = settled.at(timeline_.right[k].timeSeconds, true);
        for (const std::size_t k : left) leftTouch_[k] = settled.at(timeline_.left[k].timeSeconds, false);
        touchSpans_.push_back(std::move(settled));
    }
    blendTouches();
}

namespace {

// `values` at `seconds`, linear between the instants `times` (held beyond them).
template <typename T>
T linearAt(const std::vector<double>& times, const std::vector<T>& values, double seconds) {
    if (seconds <= times.front()) return values.front();
    for (std::size_t i = 1; i < times.size(); ++i)
        if (seconds <= times[i]) {
            const auto u = static_cast<float>((seconds - times[i - 1]) / (times[i] - times[i - 1]));
            return values[i - 1] + u * (values[i] - values[i - 1]);
        }
    return values.back();
}

}  // namespace

float TimelineClip::TouchSpan::yieldAt(double seconds) const {
    return yield.empty() ? 0.0f : linearAt(times, yield, seconds);
}

glm::vec3 TimelineClip::TouchSpan::at(double seconds, bool rightHand) const {
    return linearAt(times, rightHand ? right : left, seconds);
}

SignerPosture TimelineClip::postureAt(double seconds) const {
    SignerPosture posture = straightPostureAt(seconds);
    for (const Detour& detour : detours_) {
        if (seconds <= detour.startSeconds || seconds >= detour.endSeconds) continue;
        const double u = (seconds - detour.startSeconds) / (detour.endSeconds - detour.startSeconds);
        for (const Bump& b : detour.bumps) {
            posture.rightWrist->wristMm += bumpAt(b.shape, u) * b.rightMm;
            posture.leftWrist->wristMm += bumpAt(b.shape, u) * b.leftMm;
        }
        break;
    }
    return posture;
}

SignerPosture TimelineClip::straightPostureAt(double seconds, bool settled) const {
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
        hand::ArmTarget target = blendTargets(from.target, to.target, blend);
        const std::vector<bool>& swept = side == hand::Side::Right ? rightSwept_ : leftSwept_;
        if (sample.from != sample.to && sample.blend > 0.0 && sample.blend < 1.0 &&
            swept[static_cast<std::size_t>(sample.from - track.data())])
            target.wristMm = bodyFromSigningSpace(
                glm::vec3(stimuli::sweptPathPoint(sample.from->pose.positionMm, sample.to->pose.positionMm, sample.blend)));
        // A settled touch's offsets, blended as the keys are (settleTouches).
        // A settled touch (settleTouches): inside the item, its offsets at t; in a transition,
        // the keys' offsets blended as the keys are.
        const TouchSpan* inside = nullptr;
        for (const TouchSpan& span : touchSpans_)
            if (!inside && seconds >= span.startSeconds && seconds <= span.endSeconds) inside = &span;
        const std::vector<glm::vec3>& touch = side == hand::Side::Right ? rightTouch_ : leftTouch_;
        if (settled && inside) target.wristMm += inside->at(seconds, side == hand::Side::Right);
        else if (settled && !touch.empty()) {
            const glm::vec3 a = touch[static_cast<std::size_t>(sample.from - track.data())];
            const glm::vec3 b = touch[static_cast<std::size_t>(sample.to - track.data())];
            if (a != glm::vec3(0.0f) || b != glm::vec3(0.0f)) target.wristMm += a + blend * (b - a);
        }
        hand::HandControls controls = hand::interpolate(from.controls, to.controls, blend);
        // A settled clasp's yield (settleTouches): inside the item, its share at t; elsewhere the
        // keys' shares blended as the keys are.
        const std::vector<float>& yields = side == hand::Side::Right ? rightYield_ : leftYield_;
        if (inside && !inside->yield.empty()) controls = claspYielded(controls, inside->yieldAt(seconds));
        else if (!yields.empty()) {
            const float a = yields[static_cast<std::size_t>(sample.from - track.data())];
            const float b = yields[static_cast<std::size_t>(sample.to - track.data())];
            if (a > 0.0f || b > 0.0f) controls = claspYielded(controls, a + blend * (b - a));
        }
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
    elbows_.apply(seconds, posture);  // the arms follow the elbows' track (none while it is made)
    posture.nonManual = nonManualAt(timeline_, seconds);
    const stimuli::GazeSample gaze = stimuli::sampleGaze(timeline_.gaze, seconds);
    if (gaze.from) {
        const double eyeHeightMm = rig_->gaze().eyesMm.y;
        const glm::vec3 a = gazePoint(*gaze.from, eyeHeightMm), b = gazePoint(*gaze.to, eyeHeightMm);
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

}  // namespace signstim::signer
