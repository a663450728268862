#include "stimuli/story/timeline_builder.hpp"

#include "stimuli/verbs/signing_space.hpp"
#include "stimuli/verbs/sora.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace signstim::stimuli {
namespace {

// Only for transition times: where a resting hand roughly is (the signer knows exactly).
const std::array<glm::dvec3, 2> kNominalRestMm{glm::dvec3(170.0, -330.0, 120.0), glm::dvec3(-170.0, -330.0, 120.0)};
// The right shoulder joint in signing space (the default signer: 175 mm out, 130 mm up).
constexpr glm::dvec3 kRightShoulderMm{175.0, 130.0, 0.0};
// [D] The second of a doubled letter slides this far toward the signer's right.
constexpr double kDoubledLetterSlideMm = 35.0;
// [D] Gaze reaches its target a moment after a span begins.
constexpr double kGazeLeadSeconds = 0.12;

constexpr int kRight = 0, kLeft = 1;

// A stretch of keys, times relative to its start (the first key of a used hand at 0).
struct Segment {
    std::array<std::vector<TimelineKey>, 2> hands;  // empty: the hand rests throughout
    double durationSeconds = 0.0;
    SignContact contact;
};

struct HandState {
    bool rest = true;
    HandPose pose;
};

glm::dquat orientationOf(const glm::dvec3& fingers, const glm::dvec3& palm) { return orientationFromFingersPalm(fingers, palm); }

TimelineKey key(double t, const HandPose& pose, const std::string& shape) {
    TimelineKey k;
    k.timeSeconds = t;
    k.pose = pose;
    k.handshape = shape;
    return k;
}

HandPose poseAt(const glm::dvec3& position, const glm::dquat& orientation) {
    HandPose pose;
    pose.positionMm = position;
    pose.orientation = orientation;
    return pose;
}

// Keyframes [hand][k] played forth and back `passes` times (as verbs do), scaled by 1/rate.
std::vector<TimelineKey> expandPasses(const std::vector<VerbKeyframe>& keys, int passes, double rate) {
    std::vector<TimelineKey> out;
    const double path = keys.back().timeSeconds;
    for (int pass = 0; pass < passes; ++pass) {
        const bool backward = pass % 2 == 1;
        for (std::size_t j = (pass == 0 ? 0 : 1); j < keys.size(); ++j) {
            const std::size_t k = backward ? keys.size() - 1 - j : j;
            const double local = backward ? path - keys[k].timeSeconds : keys[k].timeSeconds;
            out.push_back(key((pass * path + local) / rate, keys[k].pose, keys[k].handshape));
        }
    }
    return out;
}

class Builder {
public:
    Builder(const Story& story, VerbVersion version, const TimelineSources& sources, const TimelineOptions& options)
        : story_(story), version_(version), sources_(sources), options_(options) {
        if (!sources_.lexicon || !sources_.shapes || !sources_.verbs)
            throw std::invalid_argument("buildTimeline: lexicon, handshapes and verbs are required");
        if (!(options_.rate > 0.1 && options_.rate <= 4.0))
            throw std::invalid_argument("buildTimeline: rate outside 0.1 to 4 (the command line checks --rate)");
        if (std::find(sources_.slotVersions.begin(), sources_.slotVersions.end(), version) == sources_.slotVersions.end())
            throw std::invalid_argument("buildTimeline: the version is not among the slot versions");
    }

    Timeline build() {
        timeline_.story = story_.file;
        timeline_.version = toString(version_);
        for (int h : {kRight, kLeft}) track(h).push_back(restKey(0.0));
        gaze(0.0, std::nullopt);
        holdAll(options_.restSeconds, SpanKind::Rest, "rest", -1, -1);
        for (std::size_t s = 0; s < story_.sentences.size(); ++s) {
            const StorySentence& sentence = story_.sentences[s];
            for (std::size_t i = 0; i < sentence.items.size(); ++i) addItem(sentence.items[i], static_cast<int>(s), static_cast<int>(i));
            // Back to rest between sentences (and at the end).
            const bool last = s + 1 == story_.sentences.size();
            Segment rest;
            rest.durationSeconds = last ? options_.restSeconds : options_.sentencePauseSeconds;
            rest.hands[kRight].push_back(restKey(0.0));
            rest.hands[kRight].push_back(restKey(rest.durationSeconds));
            rest.hands[kLeft] = rest.hands[kRight];
            place(rest, SpanKind::Rest, "rest", static_cast<int>(s), -1, std::nullopt);
        }
        timeline_.durationSeconds = now_;
        // The keys carry their handshapes' controls, so the signer needs no library of its own.
        for (int h : {kRight, kLeft})
            for (TimelineKey& k : track(h))
                if (!k.rest) k.controls = sources_.shapes->at(k.handshape).controls;
        return std::move(timeline_);
    }

private:
    std::vector<TimelineKey>& track(int h) { return h == kRight ? timeline_.right : timeline_.left; }

    static TimelineKey restKey(double t) {
        TimelineKey k;
        k.timeSeconds = t;
        k.rest = true;
        return k;
    }

    // A gaze key at t (the last one is retargeted when t does not advance).
    void gaze(double t, std::optional<glm::dvec3> target) {
        if (!timeline_.gaze.empty() && timeline_.gaze.back().timeSeconds >= t) {
            timeline_.gaze.back().targetMm = target;
            return;
        }
        timeline_.gaze.push_back({t, target});
    }

    double distanceMm(int h, const TimelineKey& next) const {
        const glm::dvec3 from = state_[h].rest ? kNominalRestMm[h] : state_[h].pose.positionMm;
        const glm::dvec3 to = next.rest ? kNominalRestMm[h] : next.pose.positionMm;
        return glm::length(to - from);
    }

    double transitionFor(const Segment& segment) const {
        double distance = 0.0;
        for (int h : {kRight, kLeft}) {
            const TimelineKey first = segment.hands[h].empty() ? restKey(0.0) : segment.hands[h].front();
            distance = std::max(distance, distanceMm(h, first));
        }
        return std::clamp(options_.transitionBaseSeconds + distance / options_.transitionMmPerSecond,
                          options_.transitionMinimumSeconds, options_.transitionMaximumSeconds);
    }

    // Appends `segment` after a transition (distance-based, or the fixed verb transition when
    // the slot of a verb is open), records its span and the gaze during it.
    void place(const Segment& segment, SpanKind kind, const std::string& label, int sentence, int item,
               std::optional<glm::dvec3> gazeTarget, bool isVerb = false) {
        const bool fixedTransition = isVerb || verbSlotOpen_;
        const double transition = fixedTransition ? options_.verbTransitionSeconds : transitionFor(segment);
        const double start = now_ + transition;
        for (int h : {kRight, kLeft}) {
            if (segment.hands[h].empty()) {
                track(h).push_back(restKey(start));
                track(h).push_back(restKey(start + segment.durationSeconds));
                state_[h].rest = true;
                continue;
            }
            for (TimelineKey k : segment.hands[h]) {
                k.timeSeconds += start;
                track(h).push_back(k);
            }
            const TimelineKey& last = segment.hands[h].back();
            state_[h].rest = last.rest;
            state_[h].pose = last.pose;
        }
        const double end = start + segment.durationSeconds;
        const bool continuesSlot = verbSlotOpen_ && (kind == SpanKind::Hold || kind == SpanKind::Rest) && !isVerb;
        if (isVerb) {
            timeline_.spans.push_back({SpanKind::Verb, now_, end, label, sentence, item, start, end, segment.contact});
        } else if (verbSlotOpen_) {
            // The slot runs to this item's first key (the fixed transition out is inside it);
            // a HOLD or the return to rest that follows a verb stays inside it (the hands hold
            // or leave the verb's end pose).
            timeline_.spans.back().endSeconds = continuesSlot ? end : start;
            if (!continuesSlot) timeline_.spans.push_back({kind, start, end, label, sentence, item, start, end, segment.contact});
        } else {
            timeline_.spans.push_back({kind, now_, end, label, sentence, item, start, end, segment.contact});
        }
        if (continuesSlot) {
            gaze(end, timeline_.gaze.back().targetMm);  // still on the verb's object
        } else {
            const double spanStart = isVerb ? now_ : start;
            gaze(std::min(spanStart + kGazeLeadSeconds, end), gazeTarget);
            gaze(end, gazeTarget);
        }
        verbSlotOpen_ = isVerb || continuesSlot;
        if (kind == SpanKind::Rest) verbSlotOpen_ = false;
        now_ = end;
    }

    void holdAll(double seconds, SpanKind kind, const std::string& label, int sentence, int item) {
        for (int h : {kRight, kLeft}) {
            TimelineKey k = track(h).back();
            k.timeSeconds = now_ + seconds;
            track(h).push_back(k);
        }
        timeline_.spans.push_back({kind, now_, now_ + seconds, label, sentence, item, now_, now_ + seconds, {}});
        gaze(now_ + seconds, timeline_.gaze.empty() ? std::nullopt : timeline_.gaze.back().targetMm);
        now_ += seconds;
    }

    void addItem(const StoryItem& item, int sentence, int index) {
        switch (item.kind) {
            case StoryItemKind::Sign: return place(signSegment(item.gloss, item), SpanKind::Sign, item.gloss, sentence, index, std::nullopt);
            case StoryItemKind::Name: {
                const StoryCharacter& c = story_.characters[static_cast<std::size_t>(item.character)];
                if (!c.nameSign.empty())
                    return place(signSegment(c.nameSign, item), SpanKind::Name, c.gloss, sentence, index, std::nullopt);
                return place(fingerspellingSegment(item.letters, item), SpanKind::Name, c.gloss, sentence, index, std::nullopt);
            }
            case StoryItemKind::Fingerspelling:
                return place(fingerspellingSegment(item.letters, item), SpanKind::Fingerspelling, "fs-" + item.letters,
                             sentence, index, std::nullopt);
            case StoryItemKind::Pointing:
                return place(pointingSegment(item.position), SpanKind::Pointing, "IX", sentence, index, arcPoint(item.position));
            case StoryItemKind::Hold: {
                const double seconds = item.holdSeconds.value_or(options_.holdSeconds);
                Segment hold;
                hold.durationSeconds = seconds;
                for (int h : {kRight, kLeft}) {
                    TimelineKey k = track(h).back();
                    k.timeSeconds = 0.0;
                    hold.hands[h] = {k, k};
                    hold.hands[h][1].timeSeconds = seconds;
                    if (k.rest) hold.hands[h].clear();
                }
                // A hold keeps the hands where they are: no transition.
                const bool slot = verbSlotOpen_;
                for (int h : {kRight, kLeft})
                    for (TimelineKey k : hold.hands[h]) {
                        k.timeSeconds += now_;
                        track(h).push_back(k);
                    }
                for (int h : {kRight, kLeft})
                    if (hold.hands[h].empty()) track(h).push_back(restKey(now_ + seconds));
                if (slot) {
                    // The hands hold the verb's end pose: part of the verb's own keys.
                    timeline_.spans.back().endSeconds = now_ + seconds;
                    timeline_.spans.back().keysEndSeconds = now_ + seconds;
                } else {
                    // The hands hold the previous item's last pose, and whatever it touches.
                    const SignContact held = timeline_.spans.empty() ? SignContact{} : timeline_.spans.back().contact;
                    timeline_.spans.push_back({SpanKind::Hold, now_, now_ + seconds, "HOLD", sentence, index, now_,
                                               now_ + seconds, held});
                }
                gaze(now_ + seconds, timeline_.gaze.back().targetMm);
                now_ += seconds;
                return;
            }
            case StoryItemKind::Verb: return addVerb(item, sentence, index);
        }
    }

    Segment signSegment(const std::string& gloss, const StoryItem& item) const {
        const LexiconSign* sign = sources_.lexicon->find(gloss);
        if (!sign)
            throw InputError(story_.file, item.line, item.column, "",
                             "the lexicon (" + sources_.lexicon->file + ") has no sign " + gloss);
        Segment segment;
        segment.contact = sign->contact;
        for (std::size_t h = 0; h < sign->hands.size(); ++h) {
            const int slot = sign->hands[h] == HandSide::Right ? kRight : kLeft;
            segment.hands[slot] = expandPasses(sign->keyframes[h], sign->passes, options_.rate);
            segment.durationSeconds = std::max(segment.durationSeconds, segment.hands[slot].back().timeSeconds);
        }
        return segment;
    }

    Segment pointingSegment(double position) const {
        const glm::dvec3 target = arcPoint(position);
        glm::dvec3 direction = glm::normalize(target - kRightShoulderMm);
        glm::dvec3 hand = kRightShoulderMm + options_.pointingReachMm * direction;
        // Toward a referent on the left the reach from the right shoulder crosses the chest:
        // the hand stays in front of it there and points from where it is.
        if (hand.x < kRightShoulderMm.x && hand.z < options_.pointingMinimumForwardMm) {
            hand.z = options_.pointingMinimumForwardMm;
            direction = glm::normalize(target - hand);
        }
        // Index along the pointing direction, palm turned down (toward -y), as IX is signed.
        const glm::dquat orientation = orientationOf(direction, glm::dvec3(0.0, -1.0, 0.0));
        const HandPose pose = poseAt(hand, orientation);
        Segment segment;
        segment.durationSeconds = options_.pointingSeconds / options_.rate;
        segment.hands[kRight] = {key(0.0, pose, "1"), key(segment.durationSeconds, pose, "1")};
        return segment;
    }

    Segment fingerspellingSegment(const std::string& letters, const StoryItem& item) const {
        Segment segment;
        const double hold = options_.letterSeconds / options_.rate;
        const double between = options_.letterTransitionSeconds / options_.rate;
        const glm::dquat upright = orientationOf({0.0, 1.0, 0.0}, {0.0, 0.0, 1.0});      // palm to the viewer
        const glm::dquat sideways = orientationOf({-1.0, 0.0, 0.0}, {0.0, 0.0, -1.0});   // G, H: index across
        const glm::dquat downward = orientationOf({0.0, -0.8, 0.6}, {-0.6, -0.3, -0.4}); // P, Q: pointing down
        double t = 0.0;
        std::vector<TimelineKey>& keys = segment.hands[kRight];
        for (std::size_t i = 0; i < letters.size(); ++i) {
            const char letter = letters[i];
            const bool doubled = i > 0 && letters[i - 1] == letter;
            glm::dvec3 at = options_.fingerspellingMm;
            if (doubled) at.x += kDoubledLetterSlideMm;
            const glm::dquat orientation = (letter == 'G' || letter == 'H') ? sideways
                                           : (letter == 'P' || letter == 'Q') ? downward
                                                                              : upright;
            if (i > 0) t += between;
            if (letter == 'J') {
                // J: the I hand draws a hook down and toward the signer's left, turning the palm in.
                requireShape("I", item);
                keys.push_back(key(t, poseAt(at, upright), "I"));
                keys.push_back(key(t + hold * 0.6, poseAt(at + glm::dvec3(0, -40, 0), upright), "I"));
                keys.push_back(key(t + hold * 1.4, poseAt(at + glm::dvec3(-30, -55, -10), orientationOf({0, 1, 0}, {-1, 0, 0})), "I"));
                t += hold * 1.4;
            } else if (letter == 'Z') {
                // Z: the index traces a Z from the signer's own point of view.
                requireShape("1", item);
                const double w = 30.0;
                const glm::dvec3 corners[] = {{-w, w, 0}, {w, w, 0}, {-w, -w, 0}, {w, -w, 0}};
                for (int c = 0; c < 4; ++c) keys.push_back(key(t + c * hold * 0.5, poseAt(at + corners[c], upright), "1"));
                t += 3 * hold * 0.5;
            } else {
                const std::string shape(1, letter);
                requireShape(shape, item);
                keys.push_back(key(t, poseAt(at, orientation), shape));
                keys.push_back(key(t + hold, poseAt(at, orientation), shape));
                t += hold;
            }
        }
        segment.durationSeconds = t;
        return segment;
    }

    void requireShape(const std::string& shape, const StoryItem& item) const {
        if (!sources_.shapes->find(shape))
            throw InputError(story_.file, item.line, item.column, "",
                             "no handshape " + shape + " in " + sources_.shapes->file + " for fingerspelling");
    }

    void addVerb(const StoryItem& item, int sentence, int index) {
        const double subject = item.subject >= 0 ? story_.characters[static_cast<std::size_t>(item.subject)].position : 0.0;
        const double object = story_.characters[static_cast<std::size_t>(item.object)].position;
        double longest = 0.0;
        VerbPerformance mine;
        for (VerbVersion v : sources_.slotVersions) {
            VerbPerformance p = sources_.verbs(item.gloss, v, subject, object, item.line, item.column);
            longest = std::max(longest, p.durationSeconds / options_.rate);
            if (v == version_) mine = std::move(p);
        }
        Segment segment;
        segment.durationSeconds = longest;
        segment.contact = mine.contact;
        for (const HandTrack& trackOfHand : mine.hands) {
            const int h = trackOfHand.side == HandSide::Right ? kRight : kLeft;
            for (const PerformanceKeyframe& k : trackOfHand.keyframes)
                segment.hands[h].push_back(key(k.timeSeconds / options_.rate, k.pose, k.handshape));
            // Padded with a hold to the slot's length, so every version's slot is as long.
            if (segment.hands[h].back().timeSeconds < longest) {
                TimelineKey pad = segment.hands[h].back();
                pad.timeSeconds = longest;
                segment.hands[h].push_back(pad);
            }
        }
        place(segment, SpanKind::Verb, item.gloss, sentence, index, arcPoint(object), true);
    }

    const Story& story_;
    VerbVersion version_;
    const TimelineSources& sources_;
    const TimelineOptions& options_;
    Timeline timeline_;
    std::array<HandState, 2> state_{};
    double now_ = 0.0;
    bool verbSlotOpen_ = false;
};

// Rounded to 1/scale (scale a power of ten): the division by an exact integer gives the
// double nearest the decimal, so the JSON reads 2.106, not 2.1060000000000003.
double roundTo(double v, double scale) {
    const double r = std::round(v * scale) / scale;
    return r == 0.0 ? 0.0 : r;
}

}  // namespace

std::string toString(SpanKind kind) {
    switch (kind) {
        case SpanKind::Rest: return "rest";
        case SpanKind::Sign: return "sign";
        case SpanKind::Name: return "name";
        case SpanKind::Pointing: return "pointing";
        case SpanKind::Fingerspelling: return "fingerspelling";
        case SpanKind::Verb: return "verb";
        case SpanKind::Hold: return "hold";
    }
    return "?";
}

double minimumJerk(double u) {
    u = std::clamp(u, 0.0, 1.0);
    return u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
}

Timeline buildTimeline(const Story& story, VerbVersion version, const TimelineSources& sources,
                       const TimelineOptions& options) {
    return Builder(story, version, sources, options).build();
}

TimelineSample sampleTrack(const std::vector<TimelineKey>& track, double t) {
    TimelineSample sample;
    if (track.empty()) return sample;
    if (t <= track.front().timeSeconds) return {&track.front(), &track.front(), 0.0};
    if (t >= track.back().timeSeconds) return {&track.back(), &track.back(), 0.0};
    const auto next = std::upper_bound(track.begin(), track.end(), t,
                                       [](double time, const TimelineKey& k) { return time < k.timeSeconds; });
    const TimelineKey& b = *next;
    const TimelineKey& a = *(next - 1);
    const double span = b.timeSeconds - a.timeSeconds;
    return {&a, &b, span > 0.0 ? minimumJerk((t - a.timeSeconds) / span) : 1.0};
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
    return root.dump(2) + "\n";
}

}  // namespace signstim::stimuli
