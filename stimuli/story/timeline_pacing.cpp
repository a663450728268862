// The timeline builder's pacing (timeline_builder_internal.hpp): how long a transition takes
// (Fitts, the speed limit, the signer's pacer) and how a segment is slowed to the limit.
#include "stimuli/story/timeline_builder_internal.hpp"
#include "stimuli/verbs/signing_space.hpp"

#include <algorithm>
#include <cmath>

namespace signstim::stimuli::timeline_detail {
namespace {

// Only for transition times: where a resting hand roughly is (the signer knows exactly).
// [D] 88 mm lower, farther out and farther back than the default signer's resting wrist
// (signer/signer_pose.cpp, SignerRig::restingTarget: (130, -270, 170) in signing space), so
// moves to and from rest are timed a little long. Kept (issue 21's pace work): at the signer's
// own rest those moves are up to 0.06 s shorter and the signer's routing no longer clears the
// hands in them (KEY -> WHERE -3.3 mm, MEET -> IX -18 mm) nor its pacer a settled MEET's left
// hand (2.85 m/s): the margin is the routing's until the pacer and the routing see it.
const std::array<glm::dvec3, 2> kNominalRestMm{glm::dvec3(170.0, -330.0, 120.0), glm::dvec3(-170.0, -330.0, 120.0)};

// A movement's amplitude for its Fitts time: how far a point of the hand ~40 mm from the wrist
// goes [D: a turn of the hand is part of what the movement must bring to its target]. That
// point moves by the wrist's displacement plus the chord its lever sweeps as the hand turns;
// over the lever's directions the two add in quadrature on average (root mean square), so the
// amplitude is sqrt(D² + c²), not the worst case D + c (which until issue 21's pace work
// counted every turn as if it pointed along the movement, and the arc rather than the chord).
double amplitudeMm(const HandPose& a, const HandPose& b) {
    constexpr double kHandLeverMm = 40.0;
    const double sinHalf = std::sqrt(std::max(0.0, 1.0 - std::pow(std::min(1.0, std::abs(glm::dot(a.orientation, b.orientation))), 2)));
    const double chord = kHandLeverMm * 2.0 * sinHalf;
    return std::hypot(glm::length(b.positionMm - a.positionMm), chord);
}

// The legacy preset's transition distance (the timing before issue 21, kept as it was): the
// displacement plus the 40 mm lever times the angle the hand turns.
double legacyTravelMm(const HandPose& a, const HandPose& b) {
    constexpr double kHandLeverMm = 40.0;
    const double cosHalf = std::min(1.0, std::abs(glm::dot(a.orientation, b.orientation)));
    return glm::length(b.positionMm - a.positionMm) + kHandLeverMm * 2.0 * std::acos(cosHalf);
}

// How far the wrist travels between two hand poses, for the speed limit (SPEC §6.2 bounds the
// wrist): a pose's position is the wrist joint's target (signer/clip.hpp,
// armTargetFromSigningSpace) and the signer blends it along the straight line between keys,
// so the wrist travels the positions' distance whatever the hand's turn. (Until issue 21's
// pace work the turn was added as a 40 mm lever here too: turning keys were paced as if the
// wrist swung, ~10-30 % slower than the wrist needs.)
double wristTravelMm(const HandPose& a, const HandPose& b) { return glm::length(b.positionMm - a.positionMm); }

}  // namespace

Builder::Travel Builder::distanceMm(int h, const HandState& from, const TimelineKey& next) {
    const glm::dvec3 a = from.rest ? kNominalRestMm[h] : from.pose.positionMm;
    const glm::dvec3 b = next.rest ? kNominalRestMm[h] : next.pose.positionMm;
    if (from.rest || next.rest) return {glm::length(b - a), glm::length(b - a), glm::length(b - a)};
    return {amplitudeMm(from.pose, next.pose), wristTravelMm(from.pose, next.pose), legacyTravelMm(from.pose, next.pose)};
}

// The largest travel of a hand from `from` (each of the states) to the segment's start.
Builder::Travel Builder::displacementMm(const std::vector<std::array<HandState, 2>>& from, const Segment& segment) {
    Travel travel;
    for (const auto& state : from)
        for (int h : {kRight, kLeft}) {
            const TimelineKey first = segment.hands[h].empty() ? restKey(0.0) : segment.hands[h].front();
            travel.take(distanceMm(h, state[h], first));
        }
    return travel;
}

// How long a transition over `distance` takes toward an item touching (or not).
double Builder::transitionSeconds(const Travel& travel, const SignContact& next) const {
    const double distance = travel.amplitudeMm;
    if (!options_.fittsTransitions)
        return std::clamp(options_.transitionBaseSeconds + travel.legacyMm / options_.transitionMmPerSecond,
                          options_.transitionMinimumSeconds, options_.transitionMaximumSeconds);
    // MacKenzie 1992 (Fitts 1954): T = a + b·log2(1 + D/W); W smaller for a touching target.
    const double width = next.hands || next.body ? options_.fittsContactWidthMm : options_.fittsWidthMm;
    const double fitts = (options_.fittsInterceptSeconds + options_.fittsSecondsPerBit * std::log2(1.0 + distance / width)) /
                         options_.rate;
    double t = std::clamp(fitts, options_.transitionMinimumSeconds / options_.rate,
                          options_.transitionMaximumSeconds / options_.rate);
    // SPEC §6.2: never faster than human, whatever the rate (1.875: minimum jerk's peak/mean).
    if (options_.peakSpeedMmPerSecond > 0.0) t = std::max(t, kPeakToMean * travel.wristMm / options_.peakSpeedMmPerSecond);
    return t;
}

// Stretches a segment's keys in time so that no keyed stretch peaks above the speed limit.
// `eachStretch` (a lexical sign): only the stretches too fast are slowed, each by what it
// needs (a compound's long move, HOME to WORK, no longer slows its taps); a verb's
// performance, whose tempo is the version's own, is stretched alike throughout. Both hands
// keep together: each interval between neighbouring key times of either hand gets the most
// that a keyed stretch spanning it needs.
// `posedPath` (a verb's performance): each interval between key times where both hands are
// keyed (or one rests) is also timed by the sources' pacer, on the posed wrists' path (a
// verb's straight path can pass inside the folded arm's reach, where the arm solution
// pushes the wrist around: SEND from -1 to 1 peaked at 3.4 m/s with its keys at 2.45).
void Builder::limitSpeed(Segment& segment, bool eachStretch, bool posedPath) const {
    limitSegmentSpeed(segment, eachStretch, posedPath, sources_, options_);
}

void limitSegmentSpeed(Segment& segment, bool eachStretch, bool posedPath, const TimelineSources& sources_,
                       const TimelineOptions& options_) {
    if (options_.peakSpeedMmPerSecond <= 0.0) return;
    const auto restKey = [](double t) {
        TimelineKey k;
        k.timeSeconds = t;
        k.rest = true;
        return k;
    };
    const auto queryKey = [&sources_](bool rest, const HandPose& pose, const std::string& handshape) {
        return resolvedQueryKey(sources_, rest, pose, handshape);
    };
    std::vector<double> times;
    for (const auto& keys : segment.hands)
        for (const TimelineKey& k : keys) times.push_back(k.timeSeconds);
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    if (times.size() < 2) return;
    std::vector<double> factor(times.size() - 1, 1.0);
    for (const auto& keys : segment.hands)
        for (std::size_t k = 0; k + 1 < keys.size(); ++k) {
            const double dt = keys[k + 1].timeSeconds - keys[k].timeSeconds;
            if (keys[k].rest || keys[k + 1].rest) continue;
            // A verb's path sweeps about the torso's axis (the signer draws it so: signing_space.hpp).
            const double distance = posedPath ? sweptPathRateMm(keys[k].pose.positionMm, keys[k + 1].pose.positionMm)
                                              : wristTravelMm(keys[k].pose, keys[k + 1].pose);
            if (distance <= 0.0) continue;
            const double needed = dt > 0.0 ? kPeakToMean * distance / options_.peakSpeedMmPerSecond / dt : 1e9;
            for (std::size_t i = 0; i + 1 < times.size(); ++i)
                if (times[i] >= keys[k].timeSeconds && times[i + 1] <= keys[k + 1].timeSeconds)
                    factor[i] = std::max(factor[i], needed);
        }
    if (posedPath && sources_.transitions) {
        // Both hands' keys at `t`, or nothing where a signing hand has none there.
        const auto keysAt = [&](double t, std::array<TimelineKey, 2>& out) {
            for (int h : {kRight, kLeft}) {
                const std::vector<TimelineKey>& keys = segment.hands[h];
                if (keys.empty()) {
                    out[static_cast<std::size_t>(h)] = restKey(0.0);
                    continue;
                }
                const auto found = std::find_if(keys.begin(), keys.end(),
                                                [t](const TimelineKey& k) { return std::abs(k.timeSeconds - t) < 1e-12; });
                if (found == keys.end()) return false;
                out[static_cast<std::size_t>(h)] = queryKey(found->rest, found->pose, found->handshape);
            }
            return true;
        };
        for (std::size_t i = 0; i + 1 < times.size(); ++i) {
            TransitionQuery q;
            q.seconds = times[i + 1] - times[i];
            q.peakSpeedMmPerSecond = options_.peakSpeedMmPerSecond;
            q.insideItem = true;
            if (q.seconds <= 0.0 || !keysAt(times[i], q.from) || !keysAt(times[i + 1], q.to)) continue;
            factor[i] = std::max(factor[i], sources_.transitions(q) / q.seconds);
        }
    }
    const double most = *std::max_element(factor.begin(), factor.end());
    if (most <= 1.0 || most >= 1e9) return;
    if (!eachStretch) std::fill(factor.begin(), factor.end(), most);
    // Time warped piecewise linearly through the key times (past the ends as the end stretch).
    std::vector<double> warped(times.size(), times.front() * factor.front());
    for (std::size_t i = 0; i + 1 < times.size(); ++i) warped[i + 1] = warped[i] + (times[i + 1] - times[i]) * factor[i];
    const auto warp = [&](double t) {
        if (t >= times.back()) return warped.back() + (t - times.back()) * factor.back();
        const auto i = static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), t) - times.begin());
        return i == 0 ? t * factor.front() : warped[i - 1] + (t - times[i - 1]) * factor[i - 1];
    };
    for (auto& keys : segment.hands)
        for (TimelineKey& k : keys) k.timeSeconds = warp(k.timeSeconds);
    segment.durationSeconds = warp(segment.durationSeconds);
}

// A key of the transition query: at rest, or the pose with its handshape's controls.
TimelineKey Builder::queryKey(bool rest, const HandPose& pose, const std::string& handshape) const {
    return resolvedQueryKey(sources_, rest, pose, handshape);
}

TimelineKey resolvedQueryKey(const TimelineSources& sources, bool rest, const HandPose& pose, const std::string& handshape) {
    TimelineKey k;
    k.rest = rest;
    if (rest) return k;
    k = key(0.0, pose, handshape);
    k.controls = sources.shapes->at(handshape).controls;
    return k;
}

// SPEC §6.2: the transition from each of `from` to the start of each of `to` lasts long
// enough for the path the hands take around each other and the body (the sources' pacer,
// where there is one): at least `seconds`, the most any pair needs.
double Builder::paced(double seconds, const std::vector<std::array<HandState, 2>>& from,
                      const std::vector<const Segment*>& to) const {
    if (!sources_.transitions || options_.peakSpeedMmPerSecond <= 0.0) return seconds;
    double needed = seconds;
    for (const auto& state : from)
        for (const Segment* segment : to) {
            TransitionQuery q;
            q.seconds = seconds;
            q.peakSpeedMmPerSecond = options_.peakSpeedMmPerSecond;
            for (int h : {kRight, kLeft}) {
                q.from[static_cast<std::size_t>(h)] = queryKey(state[h].rest, state[h].pose, state[h].handshape);
                const std::vector<TimelineKey>& keys = segment->hands[h];
                q.to[static_cast<std::size_t>(h)] =
                    keys.empty() ? restKey(0.0) : queryKey(keys.front().rest, keys.front().pose, keys.front().handshape);
                q.intoClasp = segment->contact.hands && segment->contact.clasp;
                if (segment->contact.hands)
                    for (const TimelineKey& k : keys) {
                        TimelineKey resolved = queryKey(k.rest, k.pose, k.handshape);
                        resolved.timeSeconds = k.timeSeconds - keys.front().timeSeconds;
                        resolved.passThrough = k.passThrough;
                        q.intoTouch[static_cast<std::size_t>(h)].push_back(resolved);
                    }
            }
            needed = std::max(needed, sources_.transitions(q));
        }
    return needed;
}

}  // namespace signstim::stimuli::timeline_detail

namespace signstim::stimuli {

VerbPerformance paceVerbPerformance(VerbPerformance performance, const TimelineSources& sources,
                                    const TimelineOptions& options, double rate) {
    using namespace timeline_detail;
    // Issue 21: where the performance's targets meet the signer, within its comfortable reach.
    performance = withinReach(std::move(performance), sources.reach);
    Segment segment;
    segment.durationSeconds = performance.durationSeconds / rate;
    segment.contact = performance.contact;
    for (const HandTrack& track : performance.hands) {
        const int h = track.side == HandSide::Right ? kRight : kLeft;
        for (const PerformanceKeyframe& k : track.keyframes) segment.hands[h].push_back(key(k.timeSeconds / rate, k.pose, k.handshape));
    }
    // A verb's performance, whose tempo is the version's own, is stretched alike throughout,
    // on its keys' straight path and on the posed wrists' (Builder::limitSpeed).
    limitSegmentSpeed(segment, false, true, sources, options);
    performance.durationSeconds = segment.durationSeconds;
    for (HandTrack& track : performance.hands) {
        const std::vector<TimelineKey>& keys = segment.hands[track.side == HandSide::Right ? kRight : kLeft];
        for (std::size_t i = 0; i < track.keyframes.size() && i < keys.size(); ++i) track.keyframes[i].timeSeconds = keys[i].timeSeconds;
    }
    return performance;
}

}  // namespace signstim::stimuli
