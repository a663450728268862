#pragma once
// The timeline: a story (stimuli/story/story.hpp) in one stimulus version as plain values — per hand,
// keyframes of where the hand is, how it is turned and its handshape; gaze targets; and the
// spans of what is being signed. It is the seam between what is signed (stimuli/) and how the
// body moves (the signer, which samples it frame by frame and solves arms, hands and gaze).
//
// Rules (docs/stories.md, "Timing"):
//  - The signer starts and ends at rest; each sentence ends with the hands back at rest.
//  - Between two items the hands move with a minimum-jerk profile (zero velocity and
//    acceleration at both ends) in a time that grows with the distance (SPEC [D]).
//  - A verb occupies a slot of the same length in every version: a fixed transition in, the
//    verb padded with a hold to the longest of the versions' durations, a fixed transition out
//    to the next item's first keyframe. Everything outside the verb slots is therefore
//    identical in the four versions, frame for frame (tested), which lets a study render those
//    frames once. A HOLD right after a verb, or the sentence's return to rest, belongs to the
//    verb's slot (the hands hold or leave the verb's own end pose, which differs by version).
//  - Gaze: toward a referent while pointing at it, toward the object during a verb (the same
//    in every version), toward the viewer otherwise.
#include "stimuli/story/handshapes.hpp"
#include "stimuli/story/lexicon.hpp"
#include "stimuli/story/story.hpp"
#include "stimuli/verbs/verb_synthesis.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace signstim::stimuli {

struct TimelineKey {
    double timeSeconds = 0.0;
    bool rest = false;      // the hand at the signer's resting place, relaxed (pose/handshape unused)
    HandPose pose;          // signing space (stimuli/verbs/signing_space.hpp)
    std::string handshape;  // a name of the handshape library
};

struct GazeKey {
    double timeSeconds = 0.0;
    std::optional<glm::dvec3> targetMm;  // signing space; empty: the viewer (straight ahead)
};

enum class SpanKind { Rest, Sign, Name, Pointing, Fingerspelling, Verb, Hold };
std::string toString(SpanKind kind);

struct TimelineSpan {
    SpanKind kind = SpanKind::Sign;
    double startSeconds = 0.0, endSeconds = 0.0;
    std::string label;        // "ASK", "IX(0.9)", "fs-JOHN"
    int sentence = -1;        // 0-based; -1 for the rest at the start and the end
    int item = -1;            // 0-based within the sentence
    // The item's own keys (a verb's: its keys and the hold that pads it to the slot's length,
    // and a HOLD that follows it): the transition into the item ends at keysStartSeconds, the
    // one out of it starts at keysEndSeconds. A frame outside every span's keys is in a
    // transition (or at rest after a verb, inside its slot).
    double keysStartSeconds = 0.0, keysEndSeconds = 0.0;
    SignContact contact;  // what the sign or verb touches on purpose (the lexicon's, verbs.json's)
};

struct Timeline {
    std::string story;         // the story's file, for messages
    std::string version;       // "point", ...
    double durationSeconds = 0.0;
    std::vector<TimelineKey> right, left;  // times increase; first at 0, last at durationSeconds
    std::vector<GazeKey> gaze;             // times increase
    std::vector<TimelineSpan> spans;       // in time order; verbs' spans are their slots
};

struct TimelineOptions {
    // [D] Citation timing of the lexicon and verb files is multiplied by 1 / rate: 1 signs at
    // citation speed (~2 signs/s with transitions, near natural storytelling, which runs at
    // roughly 2-2.5 signs/s).
    double rate = 1.0;
    double restSeconds = 0.5;           // at rest before the first and after the last sentence
    double sentencePauseSeconds = 0.3;  // at rest between sentences
    double holdSeconds = 0.3;           // HOLD without a duration
    // [D] Transition time = base + distance / speed, within [minimum, maximum]: quick
    // transitions of a fluent signer take 0.15-0.3 s.
    double transitionBaseSeconds = 0.12;
    double transitionMmPerSecond = 1400.0;
    double transitionMinimumSeconds = 0.15;
    double transitionMaximumSeconds = 0.5;
    double verbTransitionSeconds = 0.3;  // in and out of a verb slot, the same in every version
    double pointingSeconds = 0.35;       // IX held on its referent
    double letterSeconds = 0.2;          // each fingerspelled letter held
    double letterTransitionSeconds = 0.08;
    // Where fingerspelling happens: in front of the right shoulder, below the chin [D].
    glm::dvec3 fingerspellingMm{150.0, 170.0, 230.0};
    // How far the index of IX reaches toward the referent, from the right shoulder [D].
    double pointingReachMm = 330.0;
    // ... but no nearer the chest than this (forward, z) where the hand is in front of it [D:
    // the default signer's chest is ~110 mm deep; the fist needs the rest].
    double pointingMinimumForwardMm = 200.0;
};

// Gives a verb instance in the requested version (point/vector need trained models,
// animator its keyframe files): the same call stimuli::synthesizeVerb makes for `verb`.
using VerbProvider = std::function<VerbPerformance(const std::string& verb, VerbVersion version, double subject,
                                                   double object, int line, int column)>;

struct TimelineSources {
    const Lexicon* lexicon = nullptr;
    const HandshapeLibrary* shapes = nullptr;
    VerbProvider verbs;
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

// Minimum-jerk position profile s(u) = 10u³ − 15u⁴ + 6u⁵ for u in [0, 1] (clamped).
double minimumJerk(double u);

// A hand at time t: the two keys around it and the eased blend (0 at `from`, 1 at `to`).
struct TimelineSample {
    const TimelineKey* from = nullptr;
    const TimelineKey* to = nullptr;
    double blend = 0.0;
};
TimelineSample sampleTrack(const std::vector<TimelineKey>& track, double timeSeconds);

// Gaze target at t: the two keys around it and the eased blend.
struct GazeSample {
    const GazeKey* from = nullptr;
    const GazeKey* to = nullptr;
    double blend = 0.0;
};
GazeSample sampleGaze(const std::vector<GazeKey>& gaze, double timeSeconds);

// The timeline as JSON (`signstim story FILE --version V --json`).
std::string formatTimelineJson(const Timeline& timeline);

}  // namespace signstim::stimuli
