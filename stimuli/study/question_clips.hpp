#pragma once
// Questions and instructions in ASL (issue 24 §1; docs/study.md, "Questions and instructions in
// ASL"). A story's comprehension question may carry gloss beside its English text; the study
// renders it, with the same signer and the same gloss parser as a story sentence, as a question
// clip, and the study's instructions (gloss and English text per page) as instruction clips.
// What a participant is shown is the study's choice: "asl" (the clip), "english" (the text) or
// "both" (the default: the field's practice for deaf participants is to ask in ASL, Kacorri &
// Huenerfauth 2015, while the English text keeps the item readable for a participant who
// wants to check it and for the experimenter).
//
// Question and instruction clips are units of the study like the stories: "instructions" (every
// instruction page's clip) and "questions-03" (story 3's question clips), with records, input
// hashes, shards, resume, merge and verify as for any unit (stimuli/study/study_folder.hpp).
// They are the same for every version and participant: one clip per question.
#include "stimuli/study/study_listing.hpp"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace signstim::stimuli {

struct JsonSource;

// What the participant is shown of the questions or the instructions.
inline constexpr std::string_view kShowAsl = "asl";
inline constexpr std::string_view kShowEnglish = "english";
inline constexpr std::string_view kShowBoth = "both";
inline constexpr std::string_view kDefaultShow = kShowBoth;
bool showsSigned(std::string_view shown);   // "asl" or "both": clips are rendered and played
bool showsEnglish(std::string_view shown);  // "english" or "both"; also "" (a listing without the choice)
bool isShowChoice(std::string_view text);

// The instruction pages the experiment has, in order: "welcome" (before part 1) and "part2"
// (before part 2).
inline constexpr std::string_view kInstructionPages[] = {"welcome", "part2"};

// One instruction page: its English text and the same in gloss (sentences), as a study file or
// SCENES/studies/instructions.json writes them.
struct StudyInstruction {
    std::string page;                   // "welcome", "part2"
    std::string text;                   // English, plain text (paragraphs split at blank lines)
    std::vector<std::string> gloss;     // one sentence of gloss each
    std::string file;                   // where it is written, for messages
    int line = 0;
    std::string field;                  // "/session/instructions/welcome"
};

// Reads {"welcome": {"text": "...", "gloss": ["...", ...]}, "part2": {...}} at `pointer` of
// `source` (a study file's "session/instructions" object, or the instructions file's root),
// pages not given left out. `extraKeys` are further keys allowed at that level (a study file's
// "show"). Throws InputError naming the file, line and field.
std::vector<StudyInstruction> readInstructionPages(const JsonSource& source, const std::string& pointer,
                                                   std::initializer_list<const char*> extraKeys);
// SCENES/studies/instructions.json (format "signstim-instructions"): the default pages.
std::filesystem::path defaultInstructionsFile(const std::filesystem::path& scenesDir);
std::vector<StudyInstruction> loadInstructionsFile(const std::filesystem::path& file);
// `given` with the pages it lacks taken from `defaults`, in kInstructionPages order.
std::vector<StudyInstruction> withDefaultPages(const std::vector<StudyInstruction>& given,
                                               const std::vector<StudyInstruction>& defaults);

// Names: "story-03_question-2", "instructions-welcome" (clips, without extension), and the
// units "questions-03" and "instructions".
std::string questionClipName(std::size_t storyIndex, std::size_t question);
std::string instructionClipName(const std::string& page);
std::string questionsUnitId(std::size_t storyIndex);
inline constexpr const char* kInstructionsUnitId = "instructions";

// Whether the listing has any question clip / any instruction clip (then it has those units).
bool hasQuestionClips(const ListedStory& story);
bool hasInstructionClips(const StudyListing& listing);

}  // namespace signstim::stimuli
