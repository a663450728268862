#pragma once
// Non-manual markers become channels (issue 23 §4, SPEC §6.4, docs/nonmanuals.md): what each
// marker of a story's sentences (StoryMarker) does to the face, head and torso, when, and the
// blinks at sentence boundaries and between them. The channels (Timeline::nonManuals) and the
// marked spans (Timeline::nonManualSpans) depend only on the story, the rate and the spans'
// times, which are the same in every version (stimuli/story/timeline.hpp), so the face, head
// and torso are identical in the four versions, inside the verb slots too.
#include "stimuli/story/story.hpp"
#include "stimuli/story/timeline.hpp"

namespace signstim::stimuli {

// Timing at rate 1; every duration is divided by the rate (SPEC §6.4, Wilbur 2009: non-manuals
// shorten with faster signing).
//
// [R: SPEC §6.4; Baker-Shenk 1983, Wilbur 2000/2009: a marker begins slightly before the first
// manual sign of its span and ends with the last; Huenerfauth's group (Kacorri & Huenerfauth)
// animate such onsets as ramps] [D: the figures] The marker reaches its full value as the
// first sign's own movement begins, after a ramp in of kNonManualLeadSeconds (its onset leads
// the manual span by that much), holds it to the last sign's end and ramps out over
// kNonManualRampOutSeconds.
inline constexpr double kNonManualLeadSeconds = 0.2;
inline constexpr double kNonManualRampOutSeconds = 0.2;
// [R: SPEC §6.4, Baker-Shenk & Cokely 1980: the last sign of a yes/no question is held]
// [D: the figure, a boundary hold's length and a little more] The hold added after the last
// sign of a [y/n ...] span (manual: added whether or not non-manuals are shown, so a face
// study's two sets are matched).
inline constexpr double kYesNoHoldSeconds = 0.3;
// [D, Veinberg & Wilbur 1990 describe the negative headshake as a side-to-side rotation over
// the negated span] Headshake: half a cycle every 0.25 s (2 Hz), 0.17 rad (~10°) at the peaks.
inline constexpr double kHeadshakeHalfCycleSeconds = 0.25;
inline constexpr double kHeadshakeRadians = 0.17;
// [D] Affirmation: nods of 0.15 rad (~9°), a nod every 0.4 s; [nod]: one nod of 0.35 s.
inline constexpr double kNodHalfCycleSeconds = 0.2;
inline constexpr double kNodRadians = 0.15;
// [R: Evinger, Manning & Sibony 1991: the lid closes faster than it opens; a blink lasts
// ~0.2-0.3 s] A blink closes in 0.1 s and opens in 0.15 s.
inline constexpr double kBlinkCloseSeconds = 0.1;
inline constexpr double kBlinkOpenSeconds = 0.15;
// [R: Baker & Padden 1978: signers blink at constituent boundaries, sentence ends above all;
// Bentivoglio et al. 1997: ~26 blinks/min in conversation, ~17 at rest] Between the boundary
// blinks (and a topic's or a condition's end), blinks come every 2-6 s (uniform, mean 4 s:
// 15/min besides the boundaries), from a generator seeded by the story's title and sentences
// (common/random.hpp); no natural blink starts closer than kMinimumBlinkGapSeconds to another.
inline constexpr double kBlinkIntervalMinimumSeconds = 2.0;
inline constexpr double kBlinkIntervalMaximumSeconds = 6.0;
inline constexpr double kMinimumBlinkGapSeconds = 1.0;
// [D] The blinks the grammar places (sentence ends, a topic's or a condition's end, [blink])
// may be as close as this to each other (twice a blink's 0.25 s: the eye open again as long as
// it was shut); a natural blink keeps kMinimumBlinkGapSeconds from every other. Looked at
// (issue 23): story 03's topic [t MEETING] ends 0.9 s after the sentence before it ended, and
// with the 1 s rule its blink, the topic's boundary mark (Baker & Padden 1978), was dropped.
inline constexpr double kMinimumBoundaryBlinkGapSeconds = 0.5;
// [D, SPEC §6.2] Role shift: the torso turns 30 % of the way toward the character (at most
// 0.3 rad, ~17°), the head 30 % more (at most 0.35 rad; the gaze-driven head turn does the
// rest), the torso shifts up to 25 mm toward that side.
inline constexpr double kRoleShiftTorsoShare = 0.3;
inline constexpr double kRoleShiftTorsoMaximumRadians = 0.3;
inline constexpr double kRoleShiftHeadShare = 0.3;
inline constexpr double kRoleShiftHeadMaximumRadians = 0.35;
inline constexpr double kRoleShiftShiftMm = 25.0;

// The seconds (at rate 1) the hands hold after item `item` of `sentence`: kYesNoHoldSeconds
// where a [y/n ...] span ends, else 0.
double markerHoldSeconds(const StorySentence& sentence, int item);

// Fills timeline.nonManuals and nonManualSpans from the story's markers and the blinks, and
// turns the gaze toward a role shift's character; needs the timeline's spans and duration.
void addNonManuals(const Story& story, double rate, Timeline& timeline);

// One line for `story --check`: "non-manuals: 2 markers (wh-question 1, negation 1), 14 blinks",
// or that they are off.
std::string describeNonManuals(const Story& story, const Timeline& timeline);

}  // namespace signstim::stimuli
