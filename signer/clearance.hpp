#pragma once
// How close the signer's hands come to each other and to the body, frame by frame: the check
// behind "no interpenetration of the hands at transitions" (docs/stories.md, "Timing"), on the
// capsules of signer/hand_capsules.hpp.
#include "signer/hand_capsules.hpp"
#include "signer/signer_pose.hpp"
#include "stimuli/story/timeline.hpp"

#include <limits>
#include <string>
#include <vector>

namespace signstim::signer {

class TimelineClip;

struct ClearanceFrame {
    double seconds = 0.0;
    Clearance clearance;
    // The span (index into Timeline::spans) whose own keys hold this frame; -1 in a
    // transition between items (TimelineSpan::keysStartSeconds).
    int span = -1;
};

// Every frame of `clip` at `framesPerSecond`, from 0 to its end inclusive, and the instants
// where each item's own keys start and end (TimelineSpan::keysStartSeconds, keysEndSeconds),
// in time order, posed as renderClips poses them (ClipPoser).
std::vector<ClearanceFrame> clearanceFrames(const SignerRig& rig, const TimelineClip& clip,
                                            double framesPerSecond = 30.0);

// [D] Capsules that overlap by no more than this touch; deeper, they interpenetrate. The
// capsules follow the drawn hand to a millimetre or two; a palm pressed on a palm dents.
inline constexpr float kClearanceToleranceMm = 3.0f;

// [D] Inside a sign that touches on purpose, how deep the touch may go: deeper, the hand is
// seen through the body or the other hand. What the capsules add to the drawn surfaces where
// they meet: up to 3 mm on the torso (a capsule is rounder than the mesh's superellipse
// section, exponent 2.6, beside the sternum), 1 mm on a finger (the mesh is 12% flatter
// palmar-dorsal than its capsule), and a fingertip placed on a surface ("touch": "index-tip"
// puts the tip joint there) sinks its capsule's round end in by part of its 7-9 mm radius
// when the finger meets the surface at a slant; a fingertip pad and clothing give 2-3 mm
// under a press. 10 mm covers the sum; a hand through the body is far deeper (30-100 mm).
inline constexpr float kContactDepthToleranceMm = 10.0f;

// The rules (docs/stories.md, "Timing"), for the hands against each other and each hand
// against the body:
//  - inside an item's own keys they keep clear, unless its citation form touches on purpose
//    (TimelineSpan::contact: hands, body);
//  - in a transition they never come closer than at its ends: where an item there touches,
//    the transition leaves or reaches that contact, and goes no deeper.
//  - inside an item that touches there, the touch goes no deeper than contactDepthMm.
// Keeping clear allows kClearanceToleranceMm of overlap.
struct ClearanceViolation {
    bool hands = true;        // the hands against each other (else a hand against the body)
    bool transition = false;  // in a transition (else inside an item's keys)
    bool contact = false;     // inside an item that touches there: the touch is too deep
    int before = -1, after = -1;  // a transition's items (indices into Timeline::spans), or the item twice
    double seconds = 0.0;     // the deepest frame
    float gapMm = 0.0f;       // its gap
    float allowedMm = 0.0f;   // the least gap the rule allows there
};

// A closest approach over a stretch of frames; span as in ClearanceViolation.
struct ClearanceExtreme {
    float gapMm = std::numeric_limits<float>::infinity();
    double seconds = 0.0;
    int before = -1, after = -1;
};

// The closest approaches of a story in one version. A transition that leaves or reaches a
// contact (its ends closer than kClearanceToleranceMm) is judged by the rule, not counted.
struct ClearanceSummary {
    ClearanceExtreme handsAtTransitions;   // the hands, in transitions
    ClearanceExtreme handsInSigns;         // the hands, inside items that do not touch them together (not at rest)
    ClearanceExtreme handsInContactSigns;  // the hands, inside items that do: how deep they touch
    ClearanceExtreme body;                 // a hand and the body, in transitions and items that do not touch it
    ClearanceExtreme bodyInContactSigns;   // a hand and the body, inside items that touch it: how deep
    std::vector<ClearanceViolation> violations;  // the deepest frame of each offending stretch
};
ClearanceSummary checkClearance(const stimuli::Timeline& timeline, const std::vector<ClearanceFrame>& frames,
                                float toleranceMm = kClearanceToleranceMm,
                                float contactDepthMm = kContactDepthToleranceMm);

// Where in the story: "BOOK (sentence 3)" for an item, "IX -> BOOK (sentence 3)" for a
// transition (spans as in ClearanceViolation).
std::string describeClearancePlace(const stimuli::Timeline& timeline, int before, int after);

}  // namespace signstim::signer
