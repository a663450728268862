#pragma once
// A study file (docs/study.md; scenes/studies/default.json): which stories, which versions,
// how many participants, the seed, the phase-2 sentences and the render settings. Read and
// checked here (errors name the file, line and field); the stories themselves are read by
// stimuli/story/story.hpp, the schedules come from stimuli/study/study_design.hpp, and planStudy() turns
// all of it into the listing the exports and the review page are written from.
#include "stimuli/study/human_versions.hpp"
#include "stimuli/study/question_clips.hpp"
#include "stimuli/study/study_design.hpp"
#include "stimuli/study/study_listing.hpp"
#include "stimuli/story/timing.hpp"
#include "stimuli/verbs/verb_synthesis.hpp"

#include <array>
#include <cstdint>
#include <string_view>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace signstim::stimuli {

struct Story;
struct JsonSource;

inline constexpr int kStudyFormatVersion = 1;

// Huenerfauth, Lu & Kacorri 2015 §4: "Participants answered 1-to-10 Likert-scale questions
// about the quality of the verb in each of the ... versions of the sentence".
inline constexpr std::string_view kDefaultRatingPrompt =
    "How would you rate the quality of the verb {verb} in each panel?";
// The background questions experiment.js knows (docs/experiment.md): hearing status, age of
// ASL acquisition, schooling in ASL, daily use (what Kacorri & Huenerfauth 2015 advise
// reporting of participants; the paper's §4 reports exactly these).
inline constexpr std::array<std::string_view, 4> kBackgroundQuestions = {"hearing", "aslAge", "aslSchool", "dailyUse"};

// How clips are rendered: the study's "render" (full quality) or "quick" settings.
struct StudyRenderSettings {
    std::uint32_t width = 1280, height = 720;  // even (H.264 yuv420p)
    std::string fps = "30";                    // as written: "30", "30000/1001" (checked by the renderer's parser)
    int fpsLine = 0;                           // where it is written, for that check's message
    std::uint32_t msaa = 4;                    // 1 or 4 (lavapipe supports these)
    double rate = 1.0;                         // signing rate (stimuli/story/timeline.hpp)
    // The timing model (stimuli/story/timing.hpp); when given, it replaces every story's own.
    StoryTiming timing;
    // `"nonManuals": false`: no face, head or torso movement in any story (issue 23; a
    // matched set for a study of the face itself, docs/study.md). A story's own false holds too.
    bool nonManuals = true;
    std::string text() const;                  // "1280x720, 30 fps, MSAA 4, rate 1[, timing legacy]"
};

struct StudyFile {
    std::string file;   // as given
    std::string title;
    std::uint64_t seed = 1;
    std::size_t participants = 24;
    std::vector<VerbVersion> versions;  // the animated versions compared, in the study's order
    // Versions whose clips a lab supplies (stimuli/study/human_versions.hpp), after the animated
    // ones in the version order; designSpec() counts them in the phases they are shown in.
    std::vector<HumanVersion> humanVersions;
    struct StoryEntry {
        std::filesystem::path path;  // resolved against the study file's folder
        std::string written;         // as the study file writes it
        int line = 0;
    };
    std::vector<StoryEntry> stories;  // phase 1
    // Phase 2: sentences of a story file (without questions) rendered side by side; `path` empty:
    // no phase 2. `sentences`: 0-based indices into that story's sentences (all of them when the
    // study file lists none).
    StoryEntry phase2Story;
    std::vector<int> phase2Sentences;
    int phase2Line = 0;
    int likertMinimum = 1, likertMaximum = 10;  // SPEC §4.3: a 1-to-10 scale
    StudyRenderSettings render;                 // full quality
    StudyRenderSettings quick{320, 240, "15", 0, 1, 1.0, {}};  // timing: the render's unless given
    bool pngFrames = false;                     // also write each clip's PNG frames
    // "outputs": {"regions", "elan"}: each clip's eye-tracking regions (CSV) and ELAN annotation
    // file (.eaf) beside it (docs/study.md); on unless switched off.
    bool regions = true;
    bool elan = true;
    StoryOrder order = StoryOrder::Random;      // "order": phase 1's story order (study_design.hpp)
    // "session": what the jsPsych experiment asks (docs/experiment.md). ratingPrompt: the
    // phase-2 question ({verb}, {minimum}, {maximum} filled in); background: the background
    // questions asked before part 1, by id (kBackgroundQuestions), in the study's order.
    std::string ratingPrompt = std::string(kDefaultRatingPrompt);
    std::vector<std::string> background = {kBackgroundQuestions.begin(), kBackgroundQuestions.end()};
    // Issue 24 (question_clips.hpp): "session": {"questions": "asl"|"english"|"both",
    // "instructions": {"show": ..., "welcome": {...}, "part2": {...}}}. The pages the study file
    // gives; the runner adds the others from SCENES/studies/instructions.json.
    std::string questionsShown = "both";
    std::string instructionsShown = "both";
    std::vector<StudyInstruction> instructions;
    int sessionLine = 0;
    std::string experiment;                     // outputs.experiment: "jspsych" (docs/experiment.md), "none", or "" (not said)
    int participantsLine = 0, storiesLine = 0, versionsLine = 0;

    StudyDesignSpec designSpec() const;
};

StudyFile parseStudyFile(const JsonSource& source);
// Throws InputError naming the file, line and field (exit 2) for anything wrong, including a
// design that cannot be built (designProblem) with what would work.
StudyFile loadStudyFile(const std::filesystem::path& file);

// The default study: SCENES/studies/default.json.
std::filesystem::path defaultStudyFile(const std::filesystem::path& scenesDir);

// Names (SPEC §5): "story-03", "likert-05", "P07", version letters "P", "V", "A", "U".
std::string storyId(std::size_t storyIndex);
std::string likertId(std::size_t sentenceIndex);
std::string participantId(std::size_t participant, std::size_t participantCount);
std::string versionLetter(VerbVersion version);
// "story-03_version-point" and "likert-05_panels-VPAU" (without extension).
std::string storyClipName(std::size_t storyIndex, VerbVersion version);
std::string likertClipName(std::size_t sentenceIndex, const std::string& panelCode);

// Everything but the rendered clips' frame counts and durations (the runner fills those):
// stories with their questions and clip paths, phase-2 sentences with their panel
// arrangements, every participant's schedule. `phase2` is the phase-2 story (nullptr: none).
// The design hash is the SHA-256 of the design as text (designText).
StudyListing planStudy(const StudyFile& study, const std::vector<Story>& stories, const Story* phase2,
                       const std::string& toolVersion, bool pngFrames);

// The design as canonical text: seed, versions, stories (what they say: title, glosses and
// questions; not where their files are), sentences with their panels, every
// participant's group and trials in order. Its SHA-256 is StudyListing::designHash.
std::string designText(const StudyListing& listing);

// The listing as JSON and back (the study folder's plan, read by `study merge` and `study
// verify` without the study file). listingFromJson throws InputError naming `file` when a
// field is missing or of the wrong type.
nlohmann::json listingToJson(const StudyListing& listing);
StudyListing listingFromJson(const nlohmann::json& json, const std::string& file);

}  // namespace signstim::stimuli
