#include "stimuli/story/timeline_builder.hpp"

#include "stimuli/story/nonmanuals.hpp"
#include "stimuli/verbs/signing_space.hpp"
#include "stimuli/verbs/sora.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

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
// The peak speed of a minimum-jerk stretch over its mean speed (max of 30u²(1−u)²); no
// coarticulated stretch peaks higher (hermiteEase's slopes are bounded by it).
constexpr double kPeakToMean = 1.875;

// A stretch of keys, times relative to its start (the first key of a used hand at 0).
struct Segment {
    std::array<std::vector<TimelineKey>, 2> hands;  // empty: the hand rests throughout
    double durationSeconds = 0.0;
    SignContact contact;
};

struct HandState {
    bool rest = true;
    HandPose pose;
    std::string handshape;
};

glm::dquat orientationOf(const glm::dvec3& fingers, const glm::dvec3& palm) { return orientationFromFingersPalm(fingers, palm); }

TimelineKey key(double t, const HandPose& pose, const std::string& shape) {
    TimelineKey k;
    k.timeSeconds = t;
    k.pose = pose;
    k.handshape = shape;
    return k;
}

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
    // `boundaryHoldSeconds`: the hold at each sentence boundary (at rate 1), or empty for the
    // options' fixed one.
    Builder(const Story& story, VerbVersion version, const TimelineSources& sources, const TimelineOptions& options,
            double boundaryHoldSeconds)
        : story_(story), version_(version), sources_(sources), options_(options), boundaryHold_(boundaryHoldSeconds) {
        if (!sources_.lexicon || !sources_.shapes || !sources_.verbs)
            throw std::invalid_argument("buildTimeline: lexicon, handshapes and verbs are required");
        if (!(options_.rate > 0.1 - 1e-12 && options_.rate <= 4.0))
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
            // The last item before the boundary that is signed (a HOLD only holds it).
            std::size_t lastSigned = sentence.items.size();
            for (std::size_t i = 0; i < sentence.items.size(); ++i)
                if (sentence.items[i].kind != StoryItemKind::Hold) lastSigned = i;
            double lastSignEnd = now_;  // where the last signed item's keys end
            for (std::size_t i = 0; i < sentence.items.size(); ++i) {
                addItem(sentence.items[i], static_cast<int>(s), static_cast<int>(i), i == lastSigned);
                if (i == lastSigned) lastSignEnd = now_;
                // SPEC §6.4: a y/n question's last sign held, as part of the item (nonmanuals.hpp).
                if (const double held = markerHoldSeconds(sentence, static_cast<int>(i)); held > 0.0)
                    hold(held / options_.rate, timeline_.spans.back().label, static_cast<int>(s), static_cast<int>(i));
            }
            const bool last = s + 1 == story_.sentences.size();
            if (last || options_.restBetweenSentences) {
                // Back to rest at the end (and, legacy, between sentences).
                Segment rest;
                rest.durationSeconds = last ? options_.restSeconds : options_.sentencePauseSeconds;
                rest.hands[kRight].push_back(restKey(0.0));
                rest.hands[kRight].push_back(restKey(rest.durationSeconds));
                rest.hands[kLeft] = rest.hands[kRight];
                if (!last) timeline_.pauseSeconds += rest.durationSeconds;
                place(rest, SpanKind::Rest, "rest", static_cast<int>(s), -1, std::nullopt);
            } else if (boundaryHold_ > 0.0) {
                // SPEC §6.3: the last sign held at the boundary; the next sentence goes on from it.
                // Labelled with the sign it holds: the hold is that sign prolonged (what it
                // touches, it keeps touching). A sentence that already ends in a hold (a y/n
                // question's held last sign, SPEC §6.4; a HOLD) has its boundary hold in it:
                // the holds do not add up, the boundary hold only tops it up to its length
                // (until issue 21's pace work they were added: story-01's question held 0.55 s).
                const std::string held = timeline_.spans.empty() ? "HOLD" : timeline_.spans.back().label;
                const double topUp = boundaryHold_ / options_.rate - (now_ - lastSignEnd);
                if (topUp > 1e-9) hold(topUp, held, static_cast<int>(s), -1);
            }
        }
        timeline_.durationSeconds = now_;
        if (version_ == VerbVersion::Animator && !missingAnimator_.empty()) throw missingAnimatorFiles();
        markPassThrough();
        // The keys carry their handshapes' controls, so the signer needs no library of its own.
        for (int h : {kRight, kLeft})
            for (TimelineKey& k : track(h))
                if (!k.rest) k.controls = sources_.shapes->at(k.handshape).controls;
        // Issue 23: face, head and torso from markers and blinks (the same in every version).
        if (options_.nonManuals && story_.nonManuals) addNonManuals(story_, options_.rate, timeline_);
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

    // How far a hand goes from `from` to `next`: its Fitts amplitude and its wrist's travel.
    struct Travel {
        double amplitudeMm = 0.0, wristMm = 0.0, legacyMm = 0.0;
        void take(const Travel& o) {
            amplitudeMm = std::max(amplitudeMm, o.amplitudeMm);
            wristMm = std::max(wristMm, o.wristMm);
            legacyMm = std::max(legacyMm, o.legacyMm);
        }
    };
    static Travel distanceMm(int h, const HandState& from, const TimelineKey& next) {
        const glm::dvec3 a = from.rest ? kNominalRestMm[h] : from.pose.positionMm;
        const glm::dvec3 b = next.rest ? kNominalRestMm[h] : next.pose.positionMm;
        if (from.rest || next.rest) return {glm::length(b - a), glm::length(b - a), glm::length(b - a)};
        return {amplitudeMm(from.pose, next.pose), wristTravelMm(from.pose, next.pose), legacyTravelMm(from.pose, next.pose)};
    }

    // The largest travel of a hand from `from` (each of the states) to the segment's start.
    static Travel displacementMm(const std::vector<std::array<HandState, 2>>& from, const Segment& segment) {
        Travel travel;
        for (const auto& state : from)
            for (int h : {kRight, kLeft}) {
                const TimelineKey first = segment.hands[h].empty() ? restKey(0.0) : segment.hands[h].front();
                travel.take(distanceMm(h, state[h], first));
            }
        return travel;
    }

    // How long a transition over `distance` takes toward an item touching (or not).
    double transitionSeconds(const Travel& travel, const SignContact& next) const {
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
    void limitSpeed(Segment& segment, bool eachStretch = false, bool posedPath = false) const {
        if (options_.peakSpeedMmPerSecond <= 0.0) return;
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
                const double distance = wristTravelMm(keys[k].pose, keys[k + 1].pose);
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
    TimelineKey queryKey(bool rest, const HandPose& pose, const std::string& handshape) const {
        if (rest) return restKey(0.0);
        TimelineKey k = key(0.0, pose, handshape);
        k.controls = sources_.shapes->at(handshape).controls;
        return k;
    }

    // SPEC §6.2: the transition from each of `from` to the start of each of `to` lasts long
    // enough for the path the hands take around each other and the body (the sources' pacer,
    // where there is one): at least `seconds`, the most any pair needs.
    double paced(double seconds, const std::vector<std::array<HandState, 2>>& from,
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

    // Appends `segment` after a transition, records its span and the gaze during it.
    // `verbTransition`: for a verb, the transition into its slot (the same in every version).
    void place(const Segment& segment, SpanKind kind, const std::string& label, int sentence, int item,
               std::optional<glm::dvec3> gazeTarget, std::optional<double> verbTransition = std::nullopt,
               int letters = 0) {
        const bool isVerb = verbTransition.has_value();
        double transition = 0.0;
        if (isVerb) {
            transition = *verbTransition;
        } else if (verbSlotOpen_) {
            // Out of a verb slot: from the farthest of the versions' end poses, so that the
            // slot ends at the same time in every version.
            transition = options_.verbTransitionSeconds > 0.0
                             ? options_.verbTransitionSeconds
                             : paced(transitionSeconds(displacementMm(slotEnds_, segment), segment.contact), slotEnds_,
                                     {&segment});
        } else {
            transition = paced(transitionSeconds(displacementMm({state_}, segment), segment.contact), {state_}, {&segment});
        }
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
            state_[h].handshape = last.handshape;
        }
        const double end = start + segment.durationSeconds;
        const bool continuesSlot = verbSlotOpen_ && kind == SpanKind::Rest && !isVerb;
        TimelineSpan span{kind, now_, end, label, sentence, item, start, end, segment.contact, letters};
        if (isVerb) {
            span.kind = SpanKind::Verb;
            timeline_.spans.push_back(span);
        } else if (verbSlotOpen_) {
            // The slot runs to this item's first key (the transition out is inside it); the
            // return to rest that follows a verb stays inside it (the hands leave the verb's
            // end pose).
            timeline_.spans.back().endSeconds = continuesSlot ? end : start;
            span.startSeconds = start;
            if (!continuesSlot) timeline_.spans.push_back(span);
        } else {
            timeline_.spans.push_back(span);
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
        timeline_.spans.push_back({kind, now_, now_ + seconds, label, sentence, item, now_, now_ + seconds, {}, 0});
        gaze(now_ + seconds, timeline_.gaze.empty() ? std::nullopt : timeline_.gaze.back().targetMm);
        now_ += seconds;
    }

    // The hands keep where they are for `seconds` (a HOLD, or a boundary hold): no transition.
    void hold(double seconds, const std::string& label, int sentence, int index) {
        timeline_.pauseSeconds += seconds;
        for (int h : {kRight, kLeft}) {
            TimelineKey k = track(h).back();
            if (k.rest) {
                track(h).push_back(restKey(now_ + seconds));
                continue;
            }
            k.timeSeconds = now_;
            k.passThrough = false;
            if (track(h).back().timeSeconds < now_) track(h).push_back(k);
            k.timeSeconds = now_ + seconds;
            track(h).push_back(k);
        }
        if (verbSlotOpen_) {
            // The hands hold the verb's end pose: part of the verb's own keys.
            timeline_.spans.back().endSeconds = now_ + seconds;
            timeline_.spans.back().keysEndSeconds = now_ + seconds;
        } else {
            // The hands hold the previous item's last pose, and whatever it touches.
            const SignContact held = timeline_.spans.empty() ? SignContact{} : timeline_.spans.back().contact;
            timeline_.spans.push_back({SpanKind::Hold, now_, now_ + seconds, label, sentence, index, now_, now_ + seconds, held, 0});
        }
        gaze(now_ + seconds, timeline_.gaze.back().targetMm);
        now_ += seconds;
    }

    // [R: Huenerfauth 2008-09] How much longer (before a boundary) or shorter (said before) an
    // item is: its keys' times are multiplied by this.
    double itemScale(const std::string& said, bool beforeBoundary) {
        double scale = beforeBoundary ? options_.boundaryLengthening : 1.0;
        if (!said.empty() && !said_.insert(said).second) scale *= options_.repetitionShortening;
        return scale;
    }

    void addItem(const StoryItem& item, int sentence, int index, bool beforeBoundary) {
        switch (item.kind) {
            case StoryItemKind::Sign: {
                const double scale = itemScale(item.gloss, beforeBoundary);
                return place(signSegment(item.gloss, item, scale), SpanKind::Sign, item.gloss, sentence, index, std::nullopt);
            }
            case StoryItemKind::Name: {
                const StoryCharacter& c = story_.characters[static_cast<std::size_t>(item.character)];
                const double scale = itemScale(c.nameSign.empty() ? "" : "name:" + c.gloss, beforeBoundary);
                if (!c.nameSign.empty())
                    return place(signSegment(c.nameSign, item, scale), SpanKind::Name, c.gloss, sentence, index, std::nullopt);
                return place(fingerspellingSegment(item.letters, item, scale), SpanKind::Name, c.gloss, sentence, index,
                             std::nullopt, std::nullopt, static_cast<int>(item.letters.size()));
            }
            case StoryItemKind::Fingerspelling: {
                // Letters keep their pace when the word comes again (Reed et al.'s handshape rate
                // bounds them): only the boundary lengthens them.
                const double scale = itemScale("", beforeBoundary);
                return place(fingerspellingSegment(item.letters, item, scale), SpanKind::Fingerspelling, "fs-" + item.letters,
                             sentence, index, std::nullopt, std::nullopt, static_cast<int>(item.letters.size()));
            }
            case StoryItemKind::Pointing: {
                // IX is not a repeated word: each points anew.
                const double scale = itemScale("", beforeBoundary);
                return place(pointingSegment(item.position, scale), SpanKind::Pointing, "IX", sentence, index,
                             arcPoint(item.position));
            }
            case StoryItemKind::Hold: return hold(item.holdSeconds.value_or(options_.holdSeconds), "HOLD", sentence, index);
            case StoryItemKind::Verb: return addVerb(item, sentence, index, beforeBoundary);
        }
    }

    Segment signSegment(const std::string& gloss, const StoryItem& item, double scale) const {
        const LexiconSign* sign = sources_.lexicon->find(gloss);
        if (!sign)
            throw InputError(story_.file, item.line, item.column, "",
                             "the lexicon (" + sources_.lexicon->file + ") has no sign " + gloss);
        Segment segment;
        segment.contact = sign->contact;
        const double rate = options_.rate / (options_.signScale * scale);
        for (std::size_t h = 0; h < sign->hands.size(); ++h) {
            const int slot = sign->hands[h] == HandSide::Right ? kRight : kLeft;
            segment.hands[slot] = expandPasses(sign->keyframes[h], sign->passes, rate);
            segment.durationSeconds = std::max(segment.durationSeconds, segment.hands[slot].back().timeSeconds);
        }
        limitSpeed(segment, true);
        return segment;
    }

    Segment pointingSegment(double position, double scale) const {
        const glm::dvec3 target = arcPoint(position);
        glm::dvec3 direction = glm::normalize(target - options_.pointingOriginMm);
        glm::dvec3 hand = options_.pointingOriginMm + options_.pointingReachMm * direction;
        // Toward a referent on the left the reach crosses the chest: the hand stays in front
        // of it there and points from where it is.
        if (hand.x < kRightShoulderMm.x && hand.z < options_.pointingMinimumForwardMm) {
            hand.z = options_.pointingMinimumForwardMm;
            direction = glm::normalize(target - hand);
        }
        // Index along the pointing direction, palm turned down (toward -y), as IX is signed.
        const glm::dquat orientation = orientationOf(direction, glm::dvec3(0.0, -1.0, 0.0));
        const HandPose pose = poseAt(hand, orientation);
        Segment segment;
        segment.durationSeconds = options_.pointingSeconds * scale / options_.rate;
        segment.hands[kRight] = {key(0.0, pose, "1"), key(segment.durationSeconds, pose, "1")};
        return segment;
    }

    Segment fingerspellingSegment(const std::string& letters, const StoryItem& item, double scale) const {
        Segment segment;
        const double hold = options_.letterSeconds * scale / options_.rate;
        const double between = options_.letterTransitionSeconds * scale / options_.rate;
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
            // J and Z: their strokes take time in proportion to a letter's hold, so they
            // quicken with the rest of the word.
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
                // SPEC §6.2: the diagonal stroke no faster than the wrist may move.
                double stroke = hold * 0.5;
                if (options_.peakSpeedMmPerSecond > 0.0)
                    stroke = std::max(stroke, kPeakToMean * glm::length(corners[2] - corners[1]) / options_.peakSpeedMmPerSecond);
                for (int c = 0; c < 4; ++c) keys.push_back(key(t + c * stroke, poseAt(at + corners[c], upright), "1"));
                t += 3 * stroke;
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

    void addVerb(const StoryItem& item, int sentence, int index, bool beforeBoundary) {
        const double subject = item.subject >= 0 ? story_.characters[static_cast<std::size_t>(item.subject)].position : 0.0;
        // A question's verb may lack its object ("TOM ASK WHO", issue 24): signed uninflected,
        // toward the centre of the arc.
        const double object = item.object >= 0 ? story_.characters[static_cast<std::size_t>(item.object)].position : 0.0;
        const double rate = options_.rate / itemScale("", beforeBoundary);
        // Every version's path at its own timing, slowed where it would be faster than human;
        // the slot is as long as the longest, the transitions in and out as long as the
        // farthest version needs.
        double longest = 0.0;
        Segment mine;
        std::vector<std::array<HandState, 2>> ends;
        Travel farthestIn;
        std::vector<Segment> versions;  // each version's performance (for its first keys)
        for (VerbVersion v : sources_.slotVersions) {
            VerbPerformance p;
            try {
                p = sources_.verbs(item.gloss, v, subject, object, item.line, item.column);
            } catch (const MissingAnimatorFile& e) {
                // Point, vector and uninflected never need animator files: the missing animator
                // slot is as long as the point model's performance (what `signstim animator
                // draft` writes). The animator version names every missing file at the end.
                missingAnimator_.push_back(e);
                p = sources_.verbs(item.gloss, VerbVersion::Point, subject, object, item.line, item.column);
            }
            Segment segment;
            segment.durationSeconds = p.durationSeconds / rate;
            segment.contact = p.contact;
            for (const HandTrack& trackOfHand : p.hands) {
                const int h = trackOfHand.side == HandSide::Right ? kRight : kLeft;
                for (const PerformanceKeyframe& k : trackOfHand.keyframes)
                    segment.hands[h].push_back(key(k.timeSeconds / rate, k.pose, k.handshape));
            }
            limitSpeed(segment, false, true);
            longest = std::max(longest, segment.durationSeconds);
            farthestIn.take(displacementMm({state_}, segment));
            std::array<HandState, 2> end{};
            for (int h : {kRight, kLeft})
                if (!segment.hands[h].empty())
                    end[h] = HandState{false, segment.hands[h].back().pose, segment.hands[h].back().handshape};
            ends.push_back(end);
            if (v == version_) mine = segment;
            versions.push_back(std::move(segment));
        }
        mine.durationSeconds = longest;
        for (auto& keys : mine.hands) {
            // Padded with a hold to the slot's length, so every version's slot is as long.
            if (!keys.empty() && keys.back().timeSeconds < longest) {
                TimelineKey pad = keys.back();
                pad.timeSeconds = longest;
                keys.push_back(pad);
            }
        }
        std::vector<const Segment*> starts;
        for (const Segment& segment : versions) starts.push_back(&segment);
        const double in = options_.verbTransitionSeconds > 0.0
                              ? options_.verbTransitionSeconds
                              : paced(transitionSeconds(farthestIn, mine.contact), {state_}, starts);
        place(mine, SpanKind::Verb, item.gloss, sentence, index, arcPoint(object), in);
        slotEnds_ = std::move(ends);
    }

    // Coarticulation: a key that is neither rest nor at either end of a verb slot, between
    // neighbours in the same stretch (all outside the slots, or all inside one), is passed
    // through (sampleTrack decides how fast from the geometry: a reversal or a hold still
    // stops). Keys at a slot's edge stop, so that nothing outside a slot depends on the
    // version's keys inside it.
    void markPassThrough() {
        if (!options_.coarticulation) return;
        std::vector<std::pair<double, double>> slots;
        for (const TimelineSpan& span : timeline_.spans)
            if (span.kind == SpanKind::Verb) slots.emplace_back(span.startSeconds, span.endSeconds);
        const auto region = [&](double t) {
            for (std::size_t i = 0; i < slots.size(); ++i)
                if (slots[i].first < t && t < slots[i].second) return static_cast<int>(i);
            return -1;
        };
        // A sign that touches (the body, the other hand) starts and ends at its touch: the hand
        // stops there rather than flowing through the surface (BOSS -> NICE: the shoulder tap's
        // last key passed through sank 1.2 mm deeper than the touch).
        std::vector<double> touchEdges;
        for (const TimelineSpan& span : timeline_.spans)
            if (span.contact.body || span.contact.hands) {
                touchEdges.push_back(span.keysStartSeconds);
                touchEdges.push_back(span.keysEndSeconds);
            }
        const auto atTouchEdge = [&](double t) {
            for (double e : touchEdges)
                if (std::abs(e - t) < 1e-9) return true;
            return false;
        };
        for (int h : {kRight, kLeft}) {
            std::vector<TimelineKey>& keys = track(h);
            for (std::size_t k = 1; k + 1 < keys.size(); ++k) {
                const TimelineKey &a = keys[k - 1], &b = keys[k], &c = keys[k + 1];
                if (a.rest || b.rest || c.rest) continue;
                if (atTouchEdge(b.timeSeconds)) continue;
                if (!(a.timeSeconds < b.timeSeconds && b.timeSeconds < c.timeSeconds)) continue;
                const int r = region(b.timeSeconds);
                if (region(a.timeSeconds) != r || region(c.timeSeconds) != r) continue;
                keys[k].passThrough = true;
            }
        }
    }

    MissingAnimatorFiles missingAnimatorFiles() const {
        std::vector<std::string> files;
        for (const MissingAnimatorFile& e : missingAnimator_)
            if (std::find(files.begin(), files.end(), e.animatorFile()) == files.end()) files.push_back(e.animatorFile());
        std::string list;
        for (const std::string& f : files) list += "\n  " + f;
        const MissingAnimatorFile& first = missingAnimator_.front();
        return MissingAnimatorFiles(first.file(), first.line(), first.column(),
                                    "the animator version needs " + std::to_string(files.size()) + " keyframe file" +
                                        (files.size() == 1 ? "" : "s") + " that do" + (files.size() == 1 ? "es" : "") +
                                        " not exist (the other versions do not need them):" + list +
                                        "\n  write starting files with `signstim animator draft " + story_.file +
                                        "` (docs/verbs.md)",
                                    files);
    }

    const Story& story_;
    VerbVersion version_;
    std::vector<MissingAnimatorFile> missingAnimator_;
    const TimelineSources& sources_;
    const TimelineOptions& options_;
    double boundaryHold_ = 0.0;
    Timeline timeline_;
    std::array<HandState, 2> state_{};
    std::vector<std::array<HandState, 2>> slotEnds_;  // each version's end of the open verb slot
    std::set<std::string> said_;                       // signs and words signed so far
    double now_ = 0.0;
    bool verbSlotOpen_ = false;
};

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

Timeline buildTimeline(const Story& story, VerbVersion version, const TimelineSources& sources,
                       const TimelineOptions& options) {
    const std::size_t boundaries = story.sentences.empty() ? 0 : story.sentences.size() - 1;
    if (options.restBetweenSentences || boundaries == 0 || options.pauseShare <= 0.0)
        return Builder(story, version, sources, options, options.restBetweenSentences ? 0.0 : options.boundaryHoldSeconds)
            .build();
    // [R: Huenerfauth 2008-09] Holds make up `pauseShare` of the telling: told once without
    // boundary holds, the holds h solve (holds + n·h) / (telling + n·h) = share, each within
    // the minimum and maximum. The telling is the same in every version (equal slots), so
    // the holds are too.
    const TimelineMeasures bare = measureTimeline(Builder(story, version, sources, options, 0.0).build());
    const double share = options.pauseShare;
    const double n = static_cast<double>(boundaries);
    const double h = (share * bare.tellingSeconds - bare.pauseSeconds) / (n * (1.0 - share)) * options.rate;
    return Builder(story, version, sources, options,
                   std::clamp(h, options.boundaryHoldMinimumSeconds, options.boundaryHoldMaximumSeconds))
        .build();
}

}  // namespace signstim::stimuli
