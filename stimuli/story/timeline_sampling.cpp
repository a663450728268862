// Reading a timeline: sampling it (the eases between keys, coarticulation), measuring its
// timing, and writing it as JSON.
#include "stimuli/story/timeline_builder.hpp"

#include "stimuli/verbs/sora.hpp"

#include <algorithm>
#include <cmath>

namespace signstim::stimuli {
namespace {

// Minimum jerk's peak slope; no pass-through slope exceeds it, so no coarticulated stretch
// peaks faster than a stop-to-stop one over the same distance and time.
constexpr double kMostSlope = 1.875;

// The slope (du/du, the stretch's u from 0 to 1) at which the hand passes key k on the stretch
// toward k+1 (`leaving`) or from k−1: the Catmull-Rom velocity (C − A)/(tC − tA) projected on
// the stretch's straight path, softened by cos² of the turn at the key, so a sharp turn slows
// the hand nearly to a stop and a reversal or a hold stops it.
double passSlope(const std::vector<TimelineKey>& track, std::size_t k, bool leaving) {
    if (k == 0 || k + 1 >= track.size() || !track[k].passThrough) return 0.0;
    const TimelineKey &a = track[k - 1], &b = track[k], &c = track[k + 1];
    const glm::dvec3 d1 = b.pose.positionMm - a.pose.positionMm, d2 = c.pose.positionMm - b.pose.positionMm;
    const double l1 = glm::length(d1), l2 = glm::length(d2);
    const double t1 = b.timeSeconds - a.timeSeconds, t2 = c.timeSeconds - b.timeSeconds;
    if (l1 < 1e-6 || l2 < 1e-6 || t1 <= 0.0 || t2 <= 0.0) return 0.0;
    const double cosine = glm::dot(d1, d2) / (l1 * l2);
    if (cosine <= 0.0) return 0.0;
    const glm::dvec3 velocity = (c.pose.positionMm - a.pose.positionMm) / (t1 + t2) * (cosine * cosine);
    const double slope = leaving ? glm::dot(velocity, d2) / (l2 * l2) * t2 : glm::dot(velocity, d1) / (l1 * l1) * t1;
    return std::clamp(slope, 0.0, kMostSlope);
}


// Rounded to 1/scale (scale a power of ten): the division by an exact integer gives the
// double nearest the decimal, so the JSON reads 2.106, not 2.1060000000000003.
double roundTo(double v, double scale) {
    const double r = std::round(v * scale) / scale;
    return r == 0.0 ? 0.0 : r;
}

}  // namespace

TimelineOptions legacyTimelineOptions() {
    TimelineOptions o;
    o.restBetweenSentences = true;
    o.sentencePauseSeconds = 0.3;
    o.pauseShare = 0.0;
    o.boundaryHoldSeconds = 0.0;
    o.boundaryLengthening = 1.0;
    o.repetitionShortening = 1.0;
    o.signScale = 1.0;
    o.fittsTransitions = false;
    o.transitionMinimumSeconds = 0.15;
    o.transitionMaximumSeconds = 0.5;
    o.peakSpeedMmPerSecond = 0.0;
    o.coarticulation = false;
    o.verbTransitionSeconds = 0.3;
    o.pointingSeconds = 0.35;
    o.pointingOriginMm = {175.0, 130.0, 0.0};  // the right shoulder joint of the default signer
    o.pointingReachMm = 330.0;
    o.letterSeconds = 0.2;
    o.letterTransitionSeconds = 0.08;
    return o;
}

double minimumJerk(double u) {
    u = std::clamp(u, 0.0, 1.0);
    return u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
}

double hermiteEase(double u, double v0, double v1) {
    u = std::clamp(u, 0.0, 1.0);
    // Quintic Hermite basis with zero end accelerations: position 1 at u = 1 (minimum jerk),
    // slope v0 at 0 (u − 6u³ + 8u⁴ − 3u⁵) and v1 at 1 (−4u³ + 7u⁴ − 3u⁵).
    const double u2 = u * u, u3 = u2 * u;
    const double start = u + u3 * (-6.0 + u * (8.0 - 3.0 * u));
    const double end = u3 * (-4.0 + u * (7.0 - 3.0 * u));
    return minimumJerk(u) + v0 * start + v1 * end;
}

TimelineSample sampleTrack(const std::vector<TimelineKey>& track, double t) {
    TimelineSample sample;
    if (track.empty()) return sample;
    if (t <= track.front().timeSeconds) return {&track.front(), &track.front(), 0.0};
    if (t >= track.back().timeSeconds) return {&track.back(), &track.back(), 0.0};
    const auto next = std::upper_bound(track.begin(), track.end(), t,
                                       [](double time, const TimelineKey& k) { return time < k.timeSeconds; });
    const std::size_t b = static_cast<std::size_t>(next - track.begin()), a = b - 1;
    const double span = track[b].timeSeconds - track[a].timeSeconds;
    if (span <= 0.0) return {&track[a], &track[b], 1.0};
    const double u = (t - track[a].timeSeconds) / span;
    return {&track[a], &track[b], hermiteEase(u, passSlope(track, a, true), passSlope(track, b, false))};
}

GazeSample sampleGaze(const std::vector<GazeKey>& gaze, double t) {
    GazeSample sample;
    if (gaze.empty()) return sample;
    if (t <= gaze.front().timeSeconds) return {&gaze.front(), &gaze.front(), 0.0};
    if (t >= gaze.back().timeSeconds) return {&gaze.back(), &gaze.back(), 0.0};
    const auto next = std::upper_bound(gaze.begin(), gaze.end(), t,
                                       [](double time, const GazeKey& k) { return time < k.timeSeconds; });
    const GazeKey& b = *next;
    const GazeKey& a = *(next - 1);
    const double span = b.timeSeconds - a.timeSeconds;
    return {&a, &b, span > 0.0 ? minimumJerk((t - a.timeSeconds) / span) : 1.0};
}

double sampleNonManual(const NonManualTrack& track, double t) {
    const auto& keys = track.keys;
    if (keys.empty() || t < keys.front().timeSeconds || t > keys.back().timeSeconds) return 0.0;
    const auto next = std::upper_bound(keys.begin(), keys.end(), t,
                                       [](double time, const NonManualKey& k) { return time < k.timeSeconds; });
    if (next == keys.end()) return keys.back().value;
    const NonManualKey& b = *next;
    const NonManualKey& a = *(next - 1);
    const double span = b.timeSeconds - a.timeSeconds;
    const double u = span > 0.0 ? minimumJerk((t - a.timeSeconds) / span) : 1.0;
    return a.value + (b.value - a.value) * u;
}

const NonManualTrack* findNonManual(const Timeline& timeline, const std::string& channel) {
    for (const NonManualTrack& track : timeline.nonManuals)
        if (track.channel == channel) return &track;
    return nullptr;
}

TimelineMeasures measureTimeline(const Timeline& timeline) {
    TimelineMeasures m;
    m.durationSeconds = timeline.durationSeconds;
    double first = timeline.durationSeconds, last = 0.0;
    for (const auto* track : {&timeline.right, &timeline.left})
        for (const TimelineKey& k : *track)
            if (!k.rest) {
                first = std::min(first, k.timeSeconds);
                last = std::max(last, k.timeSeconds);
            }
    m.tellingSeconds = std::max(0.0, last - first);
    for (const TimelineSpan& span : timeline.spans) {
        switch (span.kind) {
            case SpanKind::Sign:
            case SpanKind::Name:
            case SpanKind::Pointing:
            case SpanKind::Fingerspelling:
            case SpanKind::Verb: ++m.signs; break;
            case SpanKind::Rest:
            case SpanKind::Hold: break;
        }
        if (span.letters > 0) {
            m.letters += span.letters;
            m.fingerspellingSeconds += span.keysEndSeconds - span.keysStartSeconds;
        }
    }
    m.pauseSeconds = timeline.pauseSeconds;
    return m;
}

std::string formatTimelineJson(const Timeline& timeline) {
    using Json = nlohmann::ordered_json;
    auto vec = [](const glm::dvec3& v) { return Json::array({roundTo(v.x, 100.0), roundTo(v.y, 100.0), roundTo(v.z, 100.0)}); };
    auto hand = [&](const std::vector<TimelineKey>& keys) {
        Json out = Json::array();
        for (const TimelineKey& k : keys) {
            Json j;
            j["time"] = roundTo(k.timeSeconds, 1e4);
            if (k.rest) {
                j["rest"] = true;
            } else {
                j["position"] = vec(k.pose.positionMm);
                j["fingers"] = vec(fingersDirection(k.pose.orientation));
                j["palm"] = vec(palmDirection(k.pose.orientation));
                j["handshape"] = k.handshape;
            }
            out.push_back(j);
        }
        return out;
    };
    Json root;
    root["story"] = timeline.story;
    root["version"] = timeline.version;
    root["duration"] = roundTo(timeline.durationSeconds, 1e4);
    Json spans = Json::array();
    for (const TimelineSpan& s : timeline.spans)
        spans.push_back({{"kind", toString(s.kind)}, {"label", s.label}, {"sentence", s.sentence + 1}, {"item", s.item + 1},
                         {"start", roundTo(s.startSeconds, 1e4)}, {"end", roundTo(s.endSeconds, 1e4)}});
    root["spans"] = spans;
    root["right"] = hand(timeline.right);
    root["left"] = hand(timeline.left);
    Json gaze = Json::array();
    for (const GazeKey& g : timeline.gaze) {
        Json j;
        j["time"] = roundTo(g.timeSeconds, 1e4);
        if (g.targetMm) j["target"] = vec(*g.targetMm);
        else j["target"] = "viewer";
        gaze.push_back(j);
    }
    root["gaze"] = gaze;
    // Issue 23 (docs/nonmanuals.md): the non-manual channels as keys [time, value] and the
    // marked spans; the same in every version.
    Json channels = Json::array();
    for (const NonManualTrack& track : timeline.nonManuals) {
        Json keys = Json::array();
        for (const NonManualKey& k : track.keys) keys.push_back(Json::array({roundTo(k.timeSeconds, 1e4), roundTo(k.value, 1e4)}));
        channels.push_back({{"channel", track.channel}, {"keys", keys}});
    }
    Json marked = Json::array();
    for (const NonManualSpan& s : timeline.nonManualSpans) {
        Json j{{"marker", s.marker}, {"sentence", s.sentence + 1}, {"start", roundTo(s.startSeconds, 1e4)},
               {"end", roundTo(s.endSeconds, 1e4)}, {"intensity", roundTo(s.intensity, 1e4)}};
        if (!s.text.empty()) j["text"] = s.text;
        marked.push_back(j);
    }
    root["nonManuals"] = {{"channels", channels}, {"spans", marked}};
    return root.dump(2) + "\n";
}

}  // namespace signstim::stimuli
