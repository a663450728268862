// The timeline builder's story walk (timeline_builder_internal.hpp): items in order, the
// holds at boundaries, spans and gaze, coarticulation; and buildTimeline.
#include "stimuli/story/timeline_builder_internal.hpp"

#include "stimuli/story/nonmanuals.hpp"
#include "stimuli/verbs/signing_space.hpp"

#include <algorithm>
#include <cmath>

namespace signstim::stimuli {
namespace timeline_detail {
namespace {

// [D] Gaze reaches its target a moment after a span begins.
constexpr double kGazeLeadSeconds = 0.12;

}  // namespace

// `boundaryHoldSeconds`: the hold at each sentence boundary (at rate 1), or empty for the
// options' fixed one.
Builder::Builder(const Story& story, VerbVersion version, const TimelineSources& sources, const TimelineOptions& options,
                 double boundaryHoldSeconds)
    : story_(story), version_(version), sources_(sources), options_(options), boundaryHold_(boundaryHoldSeconds) {
    if (!sources_.lexicon || !sources_.shapes || !sources_.verbs)
        throw std::invalid_argument("buildTimeline: lexicon, handshapes and verbs are required");
    if (!(options_.rate > 0.1 - 1e-12 && options_.rate <= 4.0))
        throw std::invalid_argument("buildTimeline: rate outside 0.1 to 4 (the command line checks --rate)");
    if (std::find(sources_.slotVersions.begin(), sources_.slotVersions.end(), version) == sources_.slotVersions.end())
        throw std::invalid_argument("buildTimeline: the version is not among the slot versions");
}

Timeline Builder::build() {
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

// A gaze key at t (the last one is retargeted when t does not advance).
void Builder::gaze(double t, std::optional<glm::dvec3> target) {
    if (!timeline_.gaze.empty() && timeline_.gaze.back().timeSeconds >= t) {
        timeline_.gaze.back().targetMm = target;
        return;
    }
    timeline_.gaze.push_back({t, target});
}

// Appends `segment` after a transition, records its span and the gaze during it.
// `verbTransition`: for a verb, the transition into its slot (the same in every version).
void Builder::place(const Segment& segment, SpanKind kind, const std::string& label, int sentence, int item,
                    std::optional<glm::dvec3> gazeTarget, std::optional<double> verbTransition,
                    int letters) {
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

void Builder::holdAll(double seconds, SpanKind kind, const std::string& label, int sentence, int item) {
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
void Builder::hold(double seconds, const std::string& label, int sentence, int index) {
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
double Builder::itemScale(const std::string& said, bool beforeBoundary) {
    double scale = beforeBoundary ? options_.boundaryLengthening : 1.0;
    if (!said.empty() && !said_.insert(said).second) scale *= options_.repetitionShortening;
    return scale;
}

void Builder::addItem(const StoryItem& item, int sentence, int index, bool beforeBoundary) {
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

// Coarticulation: a key that is neither rest nor at either end of a verb slot, between
// neighbours in the same stretch (all outside the slots, or all inside one), is passed
// through (sampleTrack decides how fast from the geometry: a reversal or a hold still
// stops). Keys at a slot's edge stop, so that nothing outside a slot depends on the
// version's keys inside it.
void Builder::markPassThrough() {
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

MissingAnimatorFiles Builder::missingAnimatorFiles() const {
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

}  // namespace timeline_detail

using timeline_detail::Builder;

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
