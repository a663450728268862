#pragma once
// ELAN annotation files (issue 24 §4; docs/study.md, "ELAN files"): a clip's timelines as an
// EAF 3.0 document (ELAN's format, https://www.mpi.nl/tools/elan/EAFv3.0.xsd) that a lab opens
// in ELAN beside the clip, with what was signed and when — written from the plain values of
// the timeline (stimuli/story/timeline.hpp), so the signer and renderer play no part.
//
// Tiers (each its own linguistic type, all time-alignable, no parents):
//   sentences        one annotation per sentence: its gloss, from its first item's keys to its
//                    last item's (transitions and boundary holds outside)
//   signs            every item written in the gloss (signs, names, IX, fs-, verbs, HOLD):
//                    its label, over its own keys (the transition into it outside)
//   fingerspelling   every fingerspelled letter (fs- words and fingerspelled names): the letter,
//                    from its first key to its last (its hold; J's and Z's strokes included)
//   verb             the verb's slot (timeline.hpp: transition in, the verb, its padding hold
//                    and the transition out) as "ASK (point)": the verb and the version
//   non-manual       the non-manual spans (Timeline::nonManualSpans), "marker" or
//                    "marker: text"; written (empty) when the timeline has none. Spans that
//                    overlap go to "non-manual 2", "non-manual 3", ... (ELAN shows one
//                    annotation at a time per tier).
// A clip of several versions side by side (phase 2): the sentence, sign, letter and
// non-manual tiers once (the versions are the same there frame for frame, timeline.hpp), from
// the first panel's timeline, and one verb tier per panel, "verb A", "verb B", ... with that
// panel's version.
//
// Times are milliseconds on the clip's frame grid: a time t becomes frame round(t · fps), and
// the frame's start round(frame · 1000 / fps) ms; an annotation lasts at least one frame and
// does not overlap the one before it on its tier. Every annotation has its own two time slots,
// numbered in time order. Text is XML-escaped (escapeHtml). DATE is fixed (1970-01-01) so that
// the same inputs give the same bytes.
#include "stimuli/story/timeline.hpp"

#include <string>
#include <vector>

namespace signstim::stimuli {

struct ElanPanel {
    std::string label;  // "" for a clip of one signer; "A", "B", ... for the panels of a side-by-side clip
    const Timeline* timeline = nullptr;  // its version is Timeline::version
};

struct ElanDocumentOptions {
    // The clip, relative to the .eaf ("../clips/story-03_version-point.mp4"): MEDIA_URL and
    // RELATIVE_MEDIA_URL both (ELAN looks beside the .eaf when neither resolves).
    std::string mediaUrl;
    std::string mimeType = "video/mp4";
    double framesPerSecond = 30.0;
    // The sentences' glosses as written (the study's listing); missing ones are made from the
    // items' labels.
    std::vector<std::string> sentenceGlosses;
};

// The EAF 3.0 document of a clip showing `panels` (at least one).
std::string elanDocument(const std::vector<ElanPanel>& panels, const ElanDocumentOptions& options);

// The letters fingerspelled in `span` (a fingerspelling span, or a name spelled letter by
// letter) with the time of each: from the letter's first key to its last, found by walking the
// right hand's keys in the span (a letter is two keys, J three, Z four: the timeline builder's
// fingerspellingSegment). When the keys do not read that way, the span's keys are shared out
// evenly. Letters: the span's label without "fs-" when it has span.letters capitals, else the
// keys' handshapes.
struct SpelledLetter {
    char letter = 'A';
    double startSeconds = 0.0, endSeconds = 0.0;
};
std::vector<SpelledLetter> spelledLetters(const Timeline& timeline, const TimelineSpan& span);

}  // namespace signstim::stimuli
