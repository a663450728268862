#pragma once
// The timeline: a story (stimuli/story/story.hpp) in one stimulus version as plain values — per hand,
// keyframes of where the hand is, how it is turned and its handshape (resolved hand controls);
// gaze targets; and the spans of what is being signed. It is the seam between what is signed
// (stimuli/) and how the body moves (the signer, which samples it frame by frame and solves
// arms, hands and gaze). How a story becomes a timeline: stimuli/story/timeline_builder.hpp.
//
// Rules (docs/stories.md, "Timing"):
//  - The signer starts and ends at rest; between sentences the last sign is held (a boundary
//    hold) and the next sentence starts from there (TimelineOptions: the legacy preset rests).
//  - Between two items the hands move in a Fitts-like time that grows with the distance and
//    with the precision of what comes next; they stop only where the movement reverses, holds
//    or starts/ends at rest, and flow through other keys (sampleTrack).
//  - A verb occupies a slot of the same length in every version: a transition in (the same in
//    every version), the verb — each version's path slowed where it would be faster than human
//    — padded with a hold to the longest of the versions, a transition out to the next item's
//    first keyframe. Everything outside the verb slots is therefore identical in the four
//    versions, frame for frame (tested), which lets a study render those frames once. A HOLD
//    right after a verb, a boundary hold or the return to rest belongs to the verb's slot (the
//    hands hold or leave the verb's own end pose, which differs by version).
//  - Gaze: toward a referent while pointing at it, toward the object during a verb (the same
//    in every version), toward the viewer otherwise.
#include "hand/hand_model.hpp"
#include "stimuli/verbs/verbs.hpp"

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace signstim::stimuli {

struct TimelineKey {
    double timeSeconds = 0.0;
    bool rest = false;            // the hand at the signer's resting place, relaxed (the rest unused)
    HandPose pose;                // signing space (stimuli/verbs/signing_space.hpp)
    hand::HandControls controls;  // the handshape, resolved from the library when the key is made
    std::string handshape;        // its name in the library: for the JSON and messages only
    // The hand passes through this key without stopping (coarticulation, sampleTrack): set by
    // the builder where the movement continues on both sides within one stretch.
    bool passThrough = false;
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
    int letters = 0;      // fingerspelled letters (fingerspelling and fingerspelled names)
};

// Non-manual channels (issue 23): the face, head, torso and shoulders as curves of time, the
// same in every version of a story (non-manuals are not the experimental variable). A channel
// is named by what it moves:
//  - the face: ARKit-52 blendshape names ("browInnerUp", "browDownLeft", "eyeBlinkLeft",
//    "eyeWideRight", "jawOpen", "mouthFunnel", "mouthPucker", "cheekPuff", ...), weight 0..1;
//  - the head: "head.nod" (pitch, radians, + chin down), "head.shake" (yaw, radians, + toward
//    the signer's left), "head.tilt" (roll, radians, + toward the signer's left shoulder),
//    "head.jut" (mm forward, − back);
//  - the torso: "torso.lean" (pitch, radians, + forward), "torso.turn" (yaw, radians, + toward
//    the signer's left), "torso.shift" (mm toward the signer's left);
//  - the shoulders: "shoulders.raise" (0..1, both), "shoulder.raiseLeft", "shoulder.raiseRight".
// A channel a body cannot show is ignored by it (docs/nonmanuals.md: the name map).
struct NonManualKey {
    double timeSeconds = 0.0;
    double value = 0.0;
};
struct NonManualTrack {
    std::string channel;
    std::vector<NonManualKey> keys;  // times increase; before the first and after the last: 0
};
// What was marked, for `story --json`, annotation tiers and messages: a span over signs
// ("yn-question", "wh-question", "negation", "topic", "role-shift", "mouth:MM", "mouthing", ...)
// or an event ("blink", "nod"), with its time including the ramps.
struct NonManualSpan {
    std::string marker;
    double startSeconds = 0.0, endSeconds = 0.0;
    int sentence = -1;
    double intensity = 1.0;
    std::string text;  // the mouthed word, the role-shift character; empty otherwise
};

struct Timeline {
    std::string story;         // the story's file, for messages
    std::string version;       // "point", ...
    double durationSeconds = 0.0;
    std::vector<TimelineKey> right, left;  // times increase; first at 0, last at durationSeconds
    std::vector<GazeKey> gaze;             // times increase
    std::vector<TimelineSpan> spans;       // in time order; verbs' spans are their slots
    double pauseSeconds = 0.0;             // held still: HOLD items, boundary holds, rests between sentences
    std::vector<NonManualTrack> nonManuals;   // by channel, at most one track per channel
    std::vector<NonManualSpan> nonManualSpans;  // in time order
};

// Minimum-jerk position profile s(u) = 10u³ − 15u⁴ + 6u⁵ for u in [0, 1] (clamped).
double minimumJerk(double u);
// The quintic Hermite ease with zero acceleration at both ends and slopes v0, v1 (du/du at
// u = 0 and 1; minimumJerk when both are 0). Monotone with a peak slope ≤ 1.875 for slopes in
// [0, 1.875].
double hermiteEase(double u, double v0, double v1);

// A hand at time t: the two keys around it and the eased blend (0 at `from`, 1 at `to`).
// Between keys the blend eases by minimum jerk where the hand stops at both keys; at a key
// marked passThrough it keeps the Catmull-Rom velocity of its neighbours (projected on each
// side's straight path), so the hand flows through (hermiteEase). A pure function of the track
// and t.
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

// A non-manual channel's value at t: eased between keys by minimum jerk (every key a turning
// point or a plateau), 0 before the first key and after the last. A pure function of the track
// and t.
double sampleNonManual(const NonManualTrack& track, double timeSeconds);
// The track of a channel, or nullptr.
const NonManualTrack* findNonManual(const Timeline& timeline, const std::string& channel);

// The timeline as JSON (`signstim story FILE --version V --json`).
std::string formatTimelineJson(const Timeline& timeline);

}  // namespace signstim::stimuli
