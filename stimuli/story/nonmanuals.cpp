#include "stimuli/story/nonmanuals.hpp"

#include "common/random.hpp"
#include "stimuli/story/mouthing.hpp"
#include "stimuli/verbs/signing_space.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace signstim::stimuli {
namespace {

struct ChannelValue {
    const char* channel;
    double value;  // at intensity 1: a face weight 0..1, radians or mm (timeline.hpp)
};

// What each marker holds over its span at intensity 1 (SPEC §6.4; docs/nonmanuals.md).
// [R: the articulations: Baker-Shenk 1983 and Baker-Shenk & Cokely 1980 (questions, topics,
// conditionals, rhetorical questions, the mouth morphemes), Liddell 1980 (topic: brows up,
// head back), Veinberg & Wilbur 1990 (negation: headshake, brows down)] [D: the weights and
// angles, chosen to read at 1280x720 without caricature]
const std::vector<ChannelValue>& heldChannels(const std::string& marker) {
    static const std::map<std::string, std::vector<ChannelValue>> table{
        // brows up, eyes wide, head forward
        {"yn-question",
         {{"browInnerUp", 0.8}, {"browOuterUpLeft", 0.8}, {"browOuterUpRight", 0.8}, {"eyeWideLeft", 0.5},
          {"eyeWideRight", 0.5}, {"head.nod", 0.1}, {"head.jut", 15.0}}},
        // brows down and drawn together, eyes narrowed, head tilted and forward
        {"wh-question",
         {{"browDownLeft", 0.8}, {"browDownRight", 0.8}, {"eyeSquintLeft", 0.3}, {"eyeSquintRight", 0.3},
          {"head.tilt", 0.1}, {"head.jut", 10.0}}},
        // brows up, head tilted (no head forward: it is not asked of the viewer)
        {"rhetorical-question",
         {{"browInnerUp", 0.8}, {"browOuterUpLeft", 0.8}, {"browOuterUpRight", 0.8}, {"head.tilt", 0.12}}},
        // brows up, head back (chin up, − nod, − jut)
        {"topic",
         {{"browInnerUp", 0.7}, {"browOuterUpLeft", 0.7}, {"browOuterUpRight", 0.7}, {"eyeWideLeft", 0.25},
          {"eyeWideRight", 0.25}, {"head.nod", -0.1}, {"head.jut", -10.0}}},
        // brows up, head tilted and forward
        {"conditional",
         {{"browInnerUp", 0.7}, {"browOuterUpLeft", 0.7}, {"browOuterUpRight", 0.7}, {"head.tilt", 0.1},
          {"head.jut", 10.0}}},
        // brows down, mouth corners down (the headshake is added separately)
        {"negation", {{"browDownLeft", 0.5}, {"browDownRight", 0.5}, {"mouthFrownLeft", 0.3}, {"mouthFrownRight", 0.3}}},
        {"affirmation", {}},
        // MM: lips pressed together, the lower lip pushed up
        {"mouth:MM", {{"mouthPressLeft", 0.5}, {"mouthPressRight", 0.5}, {"mouthShrugLower", 0.4}, {"mouthClose", 0.2}}},
        // OO: lips pursed, rounded
        {"mouth:OO", {{"mouthPucker", 0.7}, {"mouthFunnel", 0.4}}},
        // CHA: jaw dropped, lips spread open
        {"mouth:CHA", {{"jawOpen", 0.45}, {"mouthStretchLeft", 0.3}, {"mouthStretchRight", 0.3},
                       {"mouthUpperUpLeft", 0.2}, {"mouthUpperUpRight", 0.2}}},
        // TH: the tongue between the lips, jaw a little open
        {"mouth:TH", {{"tongueOut", 0.5}, {"jawOpen", 0.15}}},
        // CS: lips drawn back, teeth together, cheek toward the raised (dominant, right) shoulder
        {"mouth:CS", {{"mouthStretchLeft", 0.6}, {"mouthStretchRight", 0.6}, {"head.tilt", -0.12},
                      {"shoulder.raiseRight", 0.5}}},
        // PUFF: cheeks puffed, lips closed
        {"mouth:PUFF", {{"cheekPuff", 0.8}, {"mouthClose", 0.3}}},
    };
    static const std::vector<ChannelValue> none;
    const auto found = table.find(marker);
    return found == table.end() ? none : found->second;
}

// A face weight (an ARKit blendshape name) rather than an angle or a distance.
bool isWeight(const std::string& channel) { return channel.find('.') == std::string::npos; }

// Contributions per channel, summed at the end.
using Contributions = std::map<std::string, std::vector<std::vector<NonManualKey>>>;

// A plateau of `value` over [start, end], ramping in from `onset` and out to `offset`.
std::vector<NonManualKey> plateau(double onset, double start, double end, double offset, double value) {
    return {{onset, 0.0}, {start, value}, {end, value}, {offset, 0.0}};
}

// The manual time of a sentence's items [first, last]: from the first item's keys to the last's.
struct ManualSpan {
    double start = 0.0, end = 0.0;
    bool found = false;
};
ManualSpan manualSpan(const Timeline& timeline, int sentence, int first, int last) {
    ManualSpan m;
    for (const TimelineSpan& s : timeline.spans) {
        if (s.sentence != sentence || s.item < first || s.item > last) continue;
        m.start = m.found ? std::min(m.start, s.keysStartSeconds) : s.keysStartSeconds;
        m.end = m.found ? std::max(m.end, s.keysEndSeconds) : s.keysEndSeconds;
        m.found = true;
    }
    return m;
}

// When an event written before item `item` happens: in the transition into it, at the
// sentence's start a lead before its first sign, at its end as its last item's keys end.
double eventTime(const Timeline& timeline, int sentence, int item, int items, double lead) {
    const ManualSpan next = manualSpan(timeline, sentence, item, item);
    const ManualSpan before = manualSpan(timeline, sentence, item - 1, item - 1);
    if (item == 0 || !before.found) return std::max(0.0, next.start - lead);
    if (item >= items || !next.found) return before.end;
    return 0.5 * (before.end + next.start);
}

// A blink is physiology, not signing: its length is the same at any rate.
void addBlink(Contributions& c, double t, double intensity) {
    const std::vector<NonManualKey> keys{{t, 0.0}, {t + kBlinkCloseSeconds, intensity},
                                         {t + kBlinkCloseSeconds + kBlinkOpenSeconds, 0.0}};
    c["eyeBlinkLeft"].push_back(keys);
    c["eyeBlinkRight"].push_back(keys);
}

// Oscillation between +amplitude and −amplitude (or 0 and amplitude: `oneSided`) over
// [onset, offset], a turning point every `half` seconds or so, starting and ending at 0; the
// first and last peaks at 60 % (the movement builds up and dies down) [D].
std::vector<NonManualKey> oscillation(double onset, double offset, double half, double amplitude, bool oneSided) {
    const int n = std::max(2, static_cast<int>(std::lround((offset - onset) / half)));
    const double step = (offset - onset) / n;
    std::vector<NonManualKey> keys{{onset, 0.0}};
    for (int k = 0; k < n; ++k) {
        const double envelope = (k == 0 || k == n - 1) ? 0.6 : 1.0;
        const double sign = oneSided ? (k % 2 == 0 ? 1.0 : 0.0) : (k % 2 == 0 ? 1.0 : -1.0);
        keys.push_back({onset + (k + 0.5) * step, amplitude * envelope * sign});
    }
    keys.push_back({offset, 0.0});
    return keys;
}

// Keys whose times strictly increase, within [0, duration] (a later key at the same time wins).
std::vector<NonManualKey> tidy(std::vector<NonManualKey> keys, double duration) {
    std::vector<NonManualKey> out;
    for (NonManualKey k : keys) {
        k.timeSeconds = std::clamp(k.timeSeconds, 0.0, duration);
        if (!out.empty() && k.timeSeconds <= out.back().timeSeconds + 1e-9) {
            out.back().value = k.value;
            continue;
        }
        out.push_back(k);
    }
    return out;
}

// The sum of a channel's contributions, keyed at the union of their times (each a turning
// point or plateau of its own curve), face weights clipped to [0, 1].
NonManualTrack merge(const std::string& channel, const std::vector<std::vector<NonManualKey>>& parts, double duration) {
    std::vector<NonManualTrack> tracks;
    std::vector<double> times;
    for (const auto& part : parts) {
        tracks.push_back({channel, tidy(part, duration)});
        for (const NonManualKey& k : tracks.back().keys) times.push_back(k.timeSeconds);
    }
    std::sort(times.begin(), times.end());
    NonManualTrack merged{channel, {}};
    for (double t : times) {
        if (!merged.keys.empty() && t <= merged.keys.back().timeSeconds + 1e-9) continue;
        double value = 0.0;
        for (const NonManualTrack& track : tracks) value += sampleNonManual(track, t);
        if (isWeight(channel)) value = std::clamp(value, 0.0, 1.0);
        merged.keys.push_back({t, value});
    }
    return merged;
}

// The story's own seed: the same story blinks the same in every version and every run.
std::uint64_t storySeed(const Story& story) {
    std::uint64_t seed = hashString(story.title);
    for (const StorySentence& s : story.sentences) seed = mixSeed(seed, hashString(s.gloss));
    return seed;
}

int sentenceAt(const Timeline& timeline, double t) {
    for (const TimelineSpan& s : timeline.spans)
        if (s.sentence >= 0 && s.startSeconds <= t && t < s.endSeconds) return s.sentence;
    return -1;
}

// Turns the gaze toward `target` over [start, end] where it would be on the viewer, with the
// turn in over [onset, start] and back over [end, offset].
void gazeToward(Timeline& timeline, const glm::dvec3& target, double onset, double start, double end, double offset) {
    std::vector<GazeKey> keys;
    std::optional<glm::dvec3> before, after;
    bool afterFound = false;
    for (const GazeKey& g : timeline.gaze) {
        if (g.timeSeconds <= onset) before = g.targetMm;
        if (g.timeSeconds >= offset && !afterFound) {
            after = g.targetMm;
            afterFound = true;
        }
    }
    for (GazeKey g : timeline.gaze) {
        if (g.timeSeconds > onset && g.timeSeconds < offset) {
            if (g.timeSeconds < start || g.timeSeconds > end) continue;  // the turns replace these
            if (!g.targetMm) g.targetMm = target;
        }
        keys.push_back(g);
    }
    keys.push_back({onset, before});
    keys.push_back({start, target});
    keys.push_back({end, target});
    if (afterFound) keys.push_back({offset, after});
    std::stable_sort(keys.begin(), keys.end(), [](const GazeKey& a, const GazeKey& b) { return a.timeSeconds < b.timeSeconds; });
    timeline.gaze.clear();
    for (const GazeKey& g : keys)
        if (timeline.gaze.empty() || g.timeSeconds > timeline.gaze.back().timeSeconds + 1e-9) timeline.gaze.push_back(g);
}

}  // namespace

double markerHoldSeconds(const StorySentence& sentence, int item) {
    for (const StoryMarker& m : sentence.markers)
        if (m.marker == "yn-question" && m.lastItem == item) return kYesNoHoldSeconds;
    return 0.0;
}

void addNonManuals(const Story& story, double rate, Timeline& timeline) {
    Contributions c;
    const double lead = kNonManualLeadSeconds / rate, rampOut = kNonManualRampOutSeconds / rate;
    const double duration = timeline.durationSeconds;
    std::vector<double> anchors;  // blinks placed by the grammar: boundaries, topic ends, [blink]
    std::vector<NonManualSpan> spans;
    for (std::size_t si = 0; si < story.sentences.size(); ++si) {
        const StorySentence& sentence = story.sentences[si];
        const int s = static_cast<int>(si);
        const int items = static_cast<int>(sentence.items.size());
        for (const StoryMarker& m : sentence.markers) {
            const double k = m.intensity;
            if (m.event()) {
                const double t = eventTime(timeline, s, m.firstItem, items, lead);
                if (m.marker == "blink") {
                    addBlink(c, t, std::min(1.0, k));
                    anchors.push_back(t);
                    spans.push_back({"blink", t, t + kBlinkCloseSeconds + kBlinkOpenSeconds, s, k, ""});
                } else {  // nod: chin down and back up once
                    const double down = 0.4 * 2.0 * kNodHalfCycleSeconds / rate, back = 2.0 * kNodHalfCycleSeconds / rate;
                    c["head.nod"].push_back({{t, 0.0}, {t + down, kNodRadians * k}, {t + back, 0.0}});
                    spans.push_back({"nod", t, t + back, s, k, ""});
                }
                continue;
            }
            const ManualSpan manual = manualSpan(timeline, s, m.firstItem, m.lastItem);
            if (!manual.found) continue;
            const double onset = std::max(0.0, manual.start - lead), offset = std::min(duration, manual.end + rampOut);
            NonManualSpan span{m.marker, onset, offset, s, k, ""};
            for (const ChannelValue& v : heldChannels(m.marker))
                c[v.channel].push_back(plateau(onset, manual.start, manual.end, offset, v.value * k));
            if (m.marker == "negation")
                c["head.shake"].push_back(oscillation(onset, offset, kHeadshakeHalfCycleSeconds / rate, kHeadshakeRadians * k, false));
            if (m.marker == "affirmation")
                c["head.nod"].push_back(oscillation(onset, offset, kNodHalfCycleSeconds / rate, kNodRadians * k, true));
            if (m.marker == "topic" || m.marker == "conditional") anchors.push_back(manual.end);  // Baker & Padden 1978
            if (m.marker == "mouth:PAH") {
                // PAH: lips pressed, then released open at the end of the sign ("pah!").
                const double release = manual.start + 0.6 * (manual.end - manual.start);
                const double open = manual.start + 0.75 * (manual.end - manual.start);
                for (const char* lip : {"mouthPressLeft", "mouthPressRight"})
                    c[lip].push_back(plateau(onset, manual.start, release, open, 0.6 * k));
                c["jawOpen"].push_back(plateau(release, open, manual.end, offset, 0.35 * k));
                c["mouthFunnel"].push_back(plateau(release, open, manual.end, offset, 0.2 * k));
            }
            if (m.marker == "mouthing") {
                span.text = m.word;
                for (NonManualTrack& track : mouthingTracks(m.word, manual.start, manual.end, std::min(1.0, k)))
                    c[track.channel].push_back(std::move(track.keys));
            }
            if (m.marker == "role-shift" && m.character >= 0) {
                const StoryCharacter& who = story.characters[static_cast<std::size_t>(m.character)];
                span.text = who.gloss;
                // + toward the signer's left (timeline.hpp); the arc angle is + toward the right.
                const double yaw = -arcAngleRadians(who.position);
                const double torso = std::clamp(kRoleShiftTorsoShare * yaw, -kRoleShiftTorsoMaximumRadians, kRoleShiftTorsoMaximumRadians);
                const double head = std::clamp(kRoleShiftHeadShare * yaw, -kRoleShiftHeadMaximumRadians, kRoleShiftHeadMaximumRadians);
                c["torso.turn"].push_back(plateau(onset, manual.start, manual.end, offset, torso * k));
                c["head.shake"].push_back(plateau(onset, manual.start, manual.end, offset, head * k));
                c["torso.shift"].push_back(plateau(onset, manual.start, manual.end, offset, -who.position * kRoleShiftShiftMm * k));
                gazeToward(timeline, arcPoint(who.position), onset, manual.start, manual.end, offset);
            }
            spans.push_back(span);
        }
    }
    // Blinks: at every sentence's end (its last keys, after a y/n question's hold), then at a
    // natural rate between the blinks the grammar placed.
    std::vector<double> boundaries;
    double tellingStart = duration;
    for (std::size_t si = 0; si < story.sentences.size(); ++si) {
        const ManualSpan all = manualSpan(timeline, static_cast<int>(si), 0, static_cast<int>(story.sentences[si].items.size()));
        if (!all.found) continue;
        tellingStart = std::min(tellingStart, all.start);
        boundaries.push_back(all.end);
    }
    for (double t : boundaries) anchors.push_back(t);
    std::sort(anchors.begin(), anchors.end());
    std::vector<double> blinks;  // from the grammar, no two too close
    for (double t : anchors)
        if (blinks.empty() || t >= blinks.back() + kMinimumBoundaryBlinkGapSeconds) blinks.push_back(t);
    SplitMix64 random(storySeed(story));
    std::vector<double> natural;
    double from = tellingStart;
    for (std::size_t i = 0; i <= blinks.size(); ++i) {
        const double to = i < blinks.size() ? blinks[i] : (boundaries.empty() ? from : boundaries.back());
        for (double t = from + kBlinkIntervalMinimumSeconds + (kBlinkIntervalMaximumSeconds - kBlinkIntervalMinimumSeconds) * random.uniform();
             t <= to - kMinimumBlinkGapSeconds;
             t += kBlinkIntervalMinimumSeconds + (kBlinkIntervalMaximumSeconds - kBlinkIntervalMinimumSeconds) * random.uniform())
            natural.push_back(t);
        if (i < blinks.size()) from = std::max(from, blinks[i]);
    }
    for (double t : blinks) {
        // The explicit [blink] events are already in.
        const bool written = std::any_of(spans.begin(), spans.end(), [&](const NonManualSpan& s) {
            return s.marker == "blink" && std::abs(s.startSeconds - t) < 1e-9;
        });
        if (written) continue;
        addBlink(c, t, 1.0);
        spans.push_back({"blink", t, t + kBlinkCloseSeconds + kBlinkOpenSeconds, sentenceAt(timeline, t), 1.0, ""});
    }
    for (double t : natural) {
        addBlink(c, t, 1.0);
        spans.push_back({"blink", t, t + kBlinkCloseSeconds + kBlinkOpenSeconds, sentenceAt(timeline, t), 1.0, ""});
    }
    for (const auto& [channel, parts] : c) {
        NonManualTrack track = merge(channel, parts, duration);
        if (track.keys.size() >= 2) timeline.nonManuals.push_back(std::move(track));
    }
    for (NonManualSpan& s : spans) s.endSeconds = std::min(s.endSeconds, duration);
    std::stable_sort(spans.begin(), spans.end(),
                     [](const NonManualSpan& a, const NonManualSpan& b) { return a.startSeconds < b.startSeconds; });
    timeline.nonManualSpans = std::move(spans);
}

std::string describeNonManuals(const Story& story, const Timeline& timeline) {
    if (!story.nonManuals) return "non-manuals: off (\"nonManuals\": false): the face, head and torso do not move";
    std::map<std::string, int> counts;
    int markers = 0;
    for (const StorySentence& s : story.sentences)
        for (const StoryMarker& m : s.markers) {
            ++counts[m.marker];
            ++markers;
        }
    int blinks = 0;
    for (const NonManualSpan& s : timeline.nonManualSpans) blinks += s.marker == "blink";
    std::string list;
    for (const auto& [name, n] : counts) list += (list.empty() ? "" : ", ") + name + " " + std::to_string(n);
    return "non-manuals: " + std::to_string(markers) + " marker" + (markers == 1 ? "" : "s") +
           (list.empty() ? "" : " (" + list + ")") + ", " + std::to_string(blinks) + " blink" + (blinks == 1 ? "" : "s") +
           ", " + std::to_string(timeline.nonManuals.size()) + " channels";
}

}  // namespace signstim::stimuli
