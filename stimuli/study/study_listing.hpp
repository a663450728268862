#pragma once
// A composed study as plain values: every clip with its file names, every participant's
// trials in order with the questions and panel mappings. It is what the exports
// (stimuli/study/study_exports.hpp: conditions CSV, jsPsych JSON, overview CSV, question and
// response sheets) and the review page (stimuli/study/review_page.hpp) are written from, so those
// writers know nothing of rendering, design rules or story parsing: the study runner
// (app/study_*) fills a listing from the study file, the design (stimuli/study/study_design.hpp)
// and the clips it rendered.
//
// Paths are relative to the study's output folder, with '/' separators
// ("clips/story-03_version-point.mp4"), so every export is valid wherever the folder is moved.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace signstim::stimuli {

// One rendered clip (MP4), with its poster frame and optional PNG frame folder.
struct ListedClip {
    std::string video;         // "clips/story-03_version-point.mp4"
    std::string poster;        // "posters/story-03_version-point.png"
    std::string frames;        // "frames/story-03_version-point" or empty when not written
    // Eye-tracking regions and ELAN annotations (docs/study.md): "regions/story-03_version-point.csv",
    // "elan/story-03_version-point.eaf", or empty when the study does not write them.
    std::string regions;
    std::string annotation;
    double durationSeconds = 0.0;  // frames / fps
    std::uint64_t frameCount = 0;
};

struct ListedQuestion {
    std::string text;
    std::vector<std::string> choices;  // 3-4
    int answer = 0;                    // 0-based index into choices
    std::string probeVerb;             // "ASK": the verb the question asks about
    int probeSentence = 0;             // 0-based sentence index within the story
    // Issue 24: the question in gloss and its signed clip (stimuli/study/question_clips.hpp);
    // empty when the story gives no gloss or the study shows the questions in English only.
    std::string gloss{};
    ListedClip clip{};
};

// Issue 24: an instruction page of the experiment ("welcome", "part2"), its English text, its
// gloss and the signed clip (empty when the study shows instructions in English only).
struct ListedInstruction {
    std::string page;
    std::string text;
    std::vector<std::string> gloss;
    ListedClip clip;
};

struct ListedStory {
    std::string id;       // "story-03" (1-based, zero-padded, the order of the study file)
    std::string title;
    std::string file;     // the story file as the study file names it
    std::vector<std::string> sentences;  // gloss, as written
    std::vector<ListedQuestion> questions;
    std::vector<ListedClip> clips;       // one per study version, in the study's version order
};

struct ListedSentence {            // a phase-2 sentence
    std::string id;                // "likert-05"
    std::string gloss;             // "JOHN IX(0.9) ASK MARY IX(-0.6)"
    std::string verb;              // "ASK"
    std::vector<std::size_t> panelVersion;  // panelVersion[k]: version index shown in panel k (A, B, ...)
    std::string panelCode;         // "VPAU": the versions' letters in panel order
    ListedClip clip;               // the side-by-side video
};

struct ListedPhase1Trial {
    std::size_t trial = 0;    // 1-based position in the participant's phase 1
    std::size_t story = 0;    // index into StudyListing::stories
    std::size_t version = 0;  // index into StudyListing::versions
};

struct ListedPhase2Trial {
    std::size_t trial = 0;     // 1-based position in the participant's phase 2
    std::size_t sentence = 0;  // index into StudyListing::sentences (its panels are fixed per sentence)
};

struct ListedParticipant {
    std::string id;        // "P01" (1-based, zero-padded to the width of the count)
    std::size_t group = 0; // 0-based phase-1 group
    std::vector<ListedPhase1Trial> phase1;  // in presentation order
    std::vector<ListedPhase2Trial> phase2;  // in presentation order
};

struct StudyListing {
    std::string title;
    std::string studyFile;         // as given on the command line
    std::string toolVersion;       // "0.4.0"
    std::uint64_t seed = 0;
    std::string designHash;        // hex SHA-256 of the design (SPEC §5)
    std::vector<std::string> versions;       // "point", "vector", "animator", "uninflected" (study order)
    std::vector<std::string> versionLetters; // "P", "V", "A", "U"
    int likertMinimum = 1, likertMaximum = 10;  // phase-2 rating scale
    std::vector<ListedStory> stories;
    // groupVersion[story][group]: the version index phase-1 group `group` (0-based) sees of
    // `story` — the design's Latin square (study_design.hpp phase1Version), one row per story,
    // one entry per group. It is the design, not who was recruited: the overview CSV is written
    // from it, so it is complete even when a group has no participant yet.
    std::vector<std::vector<std::size_t>> groupVersion;
    std::vector<ListedSentence> sentences;
    std::vector<ListedParticipant> participants;
    // What the jsPsych experiment asks (study file "session", docs/experiment.md): the phase-2
    // question ({verb}, {minimum}, {maximum} filled in by experiment.js) and the background
    // questions asked before part 1, by id ("hearing", "aslAge", "aslSchool", "dailyUse").
    std::string ratingPrompt;
    std::vector<std::string> background;
    // Issue 24: what the participant is shown of the questions and the instructions: "asl",
    // "english" or "both" (question_clips.hpp); a listing written before the choice existed
    // reads as "english" (no clips). The instruction pages (welcome, part 2).
    std::string questionsShown = "english";
    std::string instructionsShown = "english";
    std::vector<ListedInstruction> instructions;
    // Render settings, for the page and the sheets: "1280x720", 30 fps, MSAA 4.
    std::string size;
    std::string fps;
    std::uint32_t msaa = 4;
    // Animator keyframe files marked "draft" that the clips use (file names in SCENES/animator/;
    // a study uses them only with --allow-draft-animator). In the manifest and on the review page.
    std::vector<std::string> draftAnimator;
};

// How many panels each phase-2 clip has: every version, unless a version is left out of phase 2
// (a human-video version in phase 1 only, stimuli/study/human_versions.hpp).
inline std::size_t likertPanelCount(const StudyListing& listing) {
    return listing.sentences.empty() ? listing.versions.size() : listing.sentences.front().panelVersion.size();
}

}  // namespace signstim::stimuli
