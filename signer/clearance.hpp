#pragma once
// How close the signer's hands come to each other and to the body, frame by frame: the check
// behind "no interpenetration of the hands at transitions" (docs/stories.md, "Timing"), and
// the geometry the story timeline routes its transitions with (signer/timeline_clip.hpp).
//
// Geometry [D]. Each hand is capsules in the body frame of hand/arm_ik.hpp (mm): its 15 digit
// bones as hand::boneCapsules gives them (radii from the finger and thumb widths, SPEC §1.2)
// and 4 palm capsules from the heel of the palm to the finger knuckles, as thick as the palm
// slab at the knuckles (HandDimensions::palm*). They are placed at a wrist and hand frame —
// for a posed frame the arm solution's (PoseReport: what the skeleton is posed with) — and
// scaled to the avatar's hand (SignerRig::handScale), so they follow the drawn hand (tested
// against the posed skeleton). The body is capsules fitted to the default signer's torso,
// neck and head (signer/avatar_builder.cpp): horizontal capsules through the torso's
// cross-sections, a vertical one each for the neck and the head. They stand still: the head
// turns with the gaze about an axis close to its capsule's, and the torso is not posed.
#include "hand/contact.hpp"
#include "signer/signer_pose.hpp"
#include "stimuli/story/timeline.hpp"

#include <limits>
#include <string>
#include <vector>

namespace signstim::signer {

class TimelineClip;

// The default signer's torso, neck and head, body frame (mm).
const std::vector<hand::Capsule>& bodyCapsules();

// One hand's capsules (the `side` hand in `controls`) with its wrist at `wristMm` and its
// palm frame turned by `handRotation` (body frame), into `out`.
void handCapsules(const SignerRig& rig, hand::Side side, const hand::HandControls& controls, const glm::vec3& wristMm,
                  const glm::quat& handRotation, std::vector<hand::Capsule>& out);

// The closest approach of two sets of capsules: the smallest surface gap (mm; negative: they
// interpenetrate that deep) and the two axis points it is measured between.
struct Approach {
    float gapMm = std::numeric_limits<float>::infinity();
    glm::vec3 onFirst{0.0f}, onSecond{0.0f};
};
Approach closestApproach(const std::vector<hand::Capsule>& first, const std::vector<hand::Capsule>& second);

struct SignerCapsules {
    std::vector<hand::Capsule> right, left;  // palm and digits
};
// The hands as posed: the posture's hand controls where the arm solution `report` put the
// wrists and turned the hands.
SignerCapsules signerCapsules(const SignerRig& rig, const SignerPosture& posture, const PoseReport& report);

struct Clearance {
    Approach hands;  // right hand (first) to left hand (second)
    Approach body;   // the hand closest to the body (first) to the body (second)
    hand::Side closestToBody = hand::Side::Right;
};
Clearance clearance(const SignerCapsules& capsules);

struct ClearanceFrame {
    double seconds = 0.0;
    Clearance clearance;
    // The span (index into Timeline::spans) whose own keys hold this frame; -1 in a
    // transition between items (TimelineSpan::keysStartSeconds).
    int span = -1;
};

// Every frame of `clip` at `framesPerSecond`, from 0 to its end inclusive, posed as
// renderClips poses them (ClipPoser: the previous frame's elbows, fresh after a verb slot).
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
