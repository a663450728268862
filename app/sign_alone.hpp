#pragma once
// One lexicon sign signed alone (issue 22 §4), as `signstim sign GLOSS` shows and checks it:
// its clip in citation form between rests, and its hands as the signer's arms pose them, for
// the checks on the posed hands (stimuli/story/sign_notation_check.hpp, PosedHands). Shared by
// `signstim sign` and the signer's test that every sign realizes its code on the posed hands.
#include "signer/signer.hpp"
#include "signer/timeline_clip.hpp"
#include "stimuli/story/sign_notation_check.hpp"
#include "stimuli/story/story_world.hpp"

namespace signstim::app {

// [D] A sign is shown between short rests, in citation form (rate 1, not shortened for a
// story: TimelineOptions::signScale 1).
inline constexpr double kSignRestSeconds = 0.3;

// The sign alone in citation form, between rests, as the signer signs it (point version).
signer::TimelineClip signAlone(const stimuli::StoryWorld& world, const signer::Signer& signer, const stimuli::LexiconSign& sign);

// The clip's time of `seconds` into the sign's own keys: the timeline builder may lengthen a
// stretch between two keys (the wrist's speed limit, TimelineOptions::peakSpeedMmPerSecond) or
// shorten a repetition's, so each stretch between the sign's keys maps onto its own stretch of
// the clip (the same easing between the same keys); uniformly when the keys do not pair up.
double clipSeconds(const signer::TimelineClip& clip, const stimuli::LexiconSign& sign, double seconds);

// The hands of `clip` (signAlone of `sign`) as the signer's arms pose them (issue 22: the
// checks judge the hand a viewer sees, not the pose the notation asks), `seconds` into the
// sign's own keys. Keeps references to its arguments.
stimuli::PosedHands posedHands(const signer::Signer& signer, const signer::TimelineClip& clip, const stimuli::LexiconSign& sign);

}  // namespace signstim::app
