#pragma once
// From a story to its timeline (stimuli/story/timeline.hpp) in one version: the timing rules
// listed there, with the lexicon's signs, the handshape library and the verbs.
#include "stimuli/story/handshapes.hpp"
#include "stimuli/story/lexicon.hpp"
#include "stimuli/story/story.hpp"
#include "stimuli/story/timeline.hpp"
#include "stimuli/story/timing.hpp"
#include "stimuli/verbs/verb_reach.hpp"
#include "stimuli/verbs/verb_synthesis.hpp"

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace signstim::stimuli {

struct TimelineOptions {
    // The defaults are the natural preset (docs/stories.md, "Timing"; SPEC §6.3);
    // legacyTimelineOptions() gives the timing before issue 21, for comparison studies.
    // [D] Every duration below is multiplied by 1 / rate.
    double rate = 1.0;
    double restSeconds = 0.5;  // at rest before the first and after the last sentence
    // Sentence boundaries. Signers hold the last sign of a sentence a moment and go on from
    // there; they return to rest at the end of a turn (SPEC §6.3, Grosjean & Lane 1977).
    bool restBetweenSentences = false;  // legacy: back to rest between sentences ...
    double sentencePauseSeconds = 0.3;  // ... for this long
    // [R: SPEC §6.3, Huenerfauth 2008-09: pauses ~17 % of the total] The boundary holds are
    // sized so that holds (boundary holds and HOLD items) make up `pauseShare` of the telling
    // (0: every boundary hold is boundaryHoldSeconds), within the minimum and maximum [D: a
    // hold of 150-400 ms reads as a boundary, a longer one as a stop].
    double pauseShare = 0.17;
    double boundaryHoldSeconds = 0.25;
    double boundaryHoldMinimumSeconds = 0.15;
    double boundaryHoldMaximumSeconds = 0.25;
    double holdSeconds = 0.3;  // HOLD without a duration
    // [R: Huenerfauth 2008-09, SPEC §6.3] The last sign before a sentence boundary is ~12 %
    // longer; a sign or fingerspelled word already signed in the story is ~12 % shorter.
    double boundaryLengthening = 1.12;
    double repetitionShortening = 0.88;
    // [D] Citation forms are longer than signs in connected signing (ASL-LEX 2.0's median
    // SignDuration of a citation form is 834 ms; at 2-2.3 signs/s a sign and its transition
    // take ~450 ms, the sign itself ~250-300 ms): the lexicon's keys (citation timing) are
    // scaled by this. 0.4 × the lexicon's mean citation sign (0.62 s since issue 22 took the
    // durations from ASL-LEX 2.0's SignDuration) = 0.25 s, the sign in context that 0.5 gave
    // before it (0.5 × 0.49 s): issue 22 changed the citation forms, not the pace of signing
    // in context. Shorter signs, not faster transitions: signers prefer an avatar's signs a
    // little faster than a human's and its transitions slower (Al-khazraji et al., ASSETS 2021).
    double signScale = 0.4;
    // Transitions between items. Fitts-like (MacKenzie 1992's form of Fitts 1954):
    // T = a + b·log2(1 + D/W), D the hands' largest displacement, W the target's tolerance:
    // smaller where the next item touches the body or the other hand. [D] a = 0.04 s,
    // b = 0.06 s/bit with W = 50 mm give 0.1 s for a 50 mm step, 0.21 s for 300 mm and
    // 0.26 s for 600 mm (where the speed limit below takes over): the 100-250 ms transitions
    // of fluent signing.
    bool fittsTransitions = true;
    double fittsInterceptSeconds = 0.04;
    double fittsSecondsPerBit = 0.06;
    double fittsWidthMm = 50.0;
    double fittsContactWidthMm = 25.0;
    // Legacy: transition time = base + distance / speed.
    double transitionBaseSeconds = 0.12;
    double transitionMmPerSecond = 1400.0;
    double transitionMinimumSeconds = 0.1;
    double transitionMaximumSeconds = 0.6;
    // [D, SPEC §6.2: wrist ≤ 2.5 m/s] No keyed stretch is faster than this at its peak
    // (1.875 × its mean speed under the easing, sampleTrack), the wrist's travel being its
    // target's straight displacement (wristTravelMm): transitions, signs and verb paths are
    // lengthened where they would be, and transitions also where the path the signer's hands
    // actually take (detours around the hands and body, the arm solution) would peak above it
    // (TimelineSources::transitions). 0.05 m/s under SPEC's bound for what 60-120 Hz sampling
    // and a coarticulated end add (measured: `story --check`, tests/signer/motion_limits_test;
    // 2.3 m/s before the transitions were paced by the signer's path). 0: no limit (legacy).
    double peakSpeedMmPerSecond = 2450.0;
    // Hands pass through the keys of a continuing movement (coarticulation; sampleTrack)
    // instead of stopping at every key. Legacy: false.
    bool coarticulation = true;
    // In and out of a verb slot: 0: the Fitts time of the longest of the versions'
    // displacements (the same in every version); legacy: a fixed 0.3 s.
    double verbTransitionSeconds = 0.0;
    double pointingSeconds = 0.1;  // [D] IX held on its referent (a brief stop in connected signing)
    // [R: SPEC §6.3, Reed et al. 1990: 2-6 letters/s, fluent near the top; a new handshape
    // at best every 150-200 ms] 0.12 s held + 0.08 s between: a new handshape every 0.2 s,
    // 5.4-5.8 letters/s over a word. J and Z draw their strokes in proportion to the hold.
    double letterSeconds = 0.12;
    double letterTransitionSeconds = 0.08;
    // Where fingerspelling happens: in front of the right shoulder, below the chin [D].
    glm::dvec3 fingerspellingMm{150.0, 170.0, 230.0};
    // IX: the hand goes this far from the origin toward the referent [D: in connected signing
    // IX is a turn of the forearm in front of the chest toward the locus, not a reach of the
    // arm from the shoulder; the legacy preset reaches 330 mm from the right shoulder joint].
    glm::dvec3 pointingOriginMm{150.0, 50.0, 150.0};
    double pointingReachMm = 150.0;
    // ... but no nearer the chest than this (forward, z) where the hand is in front of it [D:
    // the default signer's chest is ~110 mm deep; the fist needs the rest].
    double pointingMinimumForwardMm = 200.0;
    // Issue 23: non-manual channels from the story's markers and blinks (docs/nonmanuals.md);
    // false, or the story's or study's "nonManuals": false, leaves them out (the manual
    // timing stays the same).
    bool nonManuals = true;
};

// The timing before issue 21: rest between sentences, no boundary or repetition rules,
// citation-length signs, distance/speed transitions, fixed 0.3 s verb transitions, hands
// stopping at every key, 5 letters in 1.4 s.
TimelineOptions legacyTimelineOptions();
// The options a story's or study's `timing` object asks for (stimuli/story/timing.hpp), at `rate`.
TimelineOptions timelineOptionsFor(const StoryTiming& timing, double rate);

// What a viewer sees of the timing (SPEC §6.3; `signstim story --check`). The telling runs
// from the first key of the first sign to the last key of the last one (the rests at the two
// ends and the moves to and from them excluded).
struct TimelineMeasures {
    double durationSeconds = 0.0, tellingSeconds = 0.0;
    int signs = 0;  // lexical signs, names, IX, verbs and fingerspelled words, each once
    int letters = 0;
    double fingerspellingSeconds = 0.0;  // from each word's first letter to its last
    double pauseSeconds = 0.0;           // Timeline::pauseSeconds
    double signsPerSecond() const { return tellingSeconds > 0.0 ? signs / tellingSeconds : 0.0; }
    double lettersPerSecond() const { return fingerspellingSeconds > 0.0 ? letters / fingerspellingSeconds : 0.0; }
    double pauseShare() const { return tellingSeconds > 0.0 ? pauseSeconds / tellingSeconds : 0.0; }
};
TimelineMeasures measureTimeline(const Timeline& timeline);

// Gives a verb instance in the requested version (point/vector need trained models,
// animator its keyframe files): the same call stimuli::synthesizeVerb makes for `verb`.
using VerbProvider = std::function<VerbPerformance(const std::string& verb, VerbVersion version, double subject,
                                                   double object, int line, int column)>;

// A transition between two items, as plain values, for whoever knows the body (issue 21): the
// hands' keys where it starts and where it ends ([0] right, [1] left; a key at rest, or a pose
// with its handshape's controls) and the time the timing gives it.
struct TransitionQuery {
    std::array<TimelineKey, 2> from, to;
    double seconds = 0.0;
    double peakSpeedMmPerSecond = 0.0;  // TimelineOptions::peakSpeedMmPerSecond (> 0)
    // A stretch inside an item (a verb's path between two of its keys), which the signer does
    // not route around the hands and the body: timed on its straight blend, posed.
    bool insideItem = false;
    // Where the transition goes into an item that touches with both hands (SignContact::hands):
    // that item's keys ([0] right, [1] left; from its first, at its own times, controls
    // resolved), so that a pacer can time the transition to where the signer settles the touch
    // (signer/timeline_clip.hpp, settleTouches). Empty otherwise.
    std::array<std::vector<TimelineKey>, 2> intoTouch;
    bool intoClasp = false;  // that item's hands clasp (SignContact::clasp)
};
// How long the transition must last so that the path the hands actually take — around each
// other and the body, which a straight blend of the keys does not know (the signer's
// clearance detours, signer/timeline_clip.hpp) — peaks no faster than the speed limit: at
// least `query.seconds`. A pure function of the query (the same in every version for the same
// ends), so that equal transitions stay equally long.
using TransitionPacer = std::function<double(const TransitionQuery& query)>;

struct TimelineSources {
    const Lexicon* lexicon = nullptr;
    const HandshapeLibrary* shapes = nullptr;
    VerbProvider verbs;
    // Optional: paces transitions by the path the signer's hands take (signer::transitionPacer).
    // Empty: by the straight blend of the keys alone (what the timeline can know by itself).
    TransitionPacer transitions;
    // Optional: the signer's reach (signer::signerReach), within which a verb's keyframes are
    // drawn (stimuli/verbs/verb_reach.hpp, issue 21). Empty: the performance's targets as they are.
    SignerReach reach;
    // The versions whose slots must be equally long: all four for a study. `version` must be
    // one of them.
    std::vector<VerbVersion> slotVersions{VerbVersion::Point, VerbVersion::Vector, VerbVersion::Animator,
                                          VerbVersion::Uninflected};
};

// What buildTimeline throws for the animator version when animator keyframe files are missing:
// every one of them (`files()`), named at once; the location is the first verb that needs one.
class MissingAnimatorFiles : public InputError {
public:
    MissingAnimatorFiles(const std::string& file, int line, int column, const std::string& message,
                         std::vector<std::string> files)
        : InputError(file, line, column, "", message), files_(std::move(files)) {}
    const std::vector<std::string>& files() const { return files_; }

private:
    std::vector<std::string> files_;
};

// Throws InputError naming the story file, line and column for a sign missing from the
// lexicon, a letter without a handshape, or a verb the provider cannot give. A missing
// animator file (the provider's MissingAnimatorFile) is an error only for the animator
// version (MissingAnimatorFiles, naming them all); the other versions size the animator slot
// by the point model.
Timeline buildTimeline(const Story& story, VerbVersion version, const TimelineSources& sources,
                       const TimelineOptions& options = {});

// SPEC §6.2: a verb performance at `rate` (the story's, over the item's boundary scale) and at
// human speed, as a story's verb slot plays it (Builder::addVerb) and `signstim verb --out`
// renders it: its keys' times divided by the rate, then stretched alike throughout until no
// stretch between keys peaks above options.peakSpeedMmPerSecond, on its keys' straight path
// and on the posed wrists' path that sources.transitions knows (empty: the straight path
// alone). First its keyframes are drawn within sources.reach (withinReach: every version
// alike, issue 21). Uses sources.shapes (with sources.transitions), sources.reach and nothing
// else of the sources.
VerbPerformance paceVerbPerformance(VerbPerformance performance, const TimelineSources& sources,
                                    const TimelineOptions& options = {}, double rate = 1.0);


}  // namespace signstim::stimuli
