#pragma once
// Stories (SPEC §4.1, docs/stories.md): a title, 2-6 characters placed on the signing arc,
// sentences in gloss (stimuli/story/gloss.hpp), multiple-choice comprehension questions with their
// answer keys, and notes for the experimenter — read from a JSON file and validated against
// the story's own characters, the verb library and the lexicon's sign names. Every problem
// is an InputError naming the file, the line, the column (inside a sentence) and the field.
//
// The verb's subject and object (SPEC §3.2) come from the sentence by one rule, written down
// in docs/stories.md: the subject is the nearest character named or pointed to before the
// verb, the object the first one named or pointed to after it; ASK(JOHN,MARY) or TELL(MARY)
// says so explicitly where the rule cannot read the sentence.
#include "stimuli/json_source.hpp"
#include "stimuli/story/timing.hpp"
#include "stimuli/verbs/verbs.hpp"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace signstim::stimuli {

struct StoryCharacter {
    std::string gloss;       // "JOHN": how the sentences name the character
    double position = 0.0;   // arc position, SPEC §3.1
    // A lexicon sign used as the name; empty: fingerspelled. A character whose gloss is a
    // sign (TEACHER, COACH) is signed with it, and within the story that gloss means the
    // character.
    std::string nameSign;
    std::string spelled;     // the letters fingerspelled (default: the gloss)
    bool spelledGiven = false;  // "spelled" written in the file: the letters are meant
    std::string description; // "a student", for the experimenter
    int line = 0;
};

enum class StoryItemKind { Sign, Name, Pointing, Fingerspelling, Verb, Hold };

// One item of a sentence with what it means in this story.
struct StoryItem {
    StoryItemKind kind = StoryItemKind::Sign;
    std::string gloss;                 // Sign: the lexicon gloss; Verb: the verb; Name: the character's gloss
    std::string letters;               // Fingerspelling, and a Name that is fingerspelled
    int character = -1;                // Name, Pointing (when at a character): index into characters
    double position = 0.0;             // Pointing: the arc position pointed at
    int subject = -1, object = -1;     // Verb: character indices (subject -1 for object-only verbs)
    std::optional<double> holdSeconds; // Hold: explicit duration, else the timing default
    bool placesCharacter = false;      // Pointing right after a Name: introduces the character there
    int line = 0, column = 0;          // where it is written
};

// A non-manual marker of a sentence (gloss_markers.hpp; docs/nonmanuals.md) with what it means
// in this story.
struct StoryMarker {
    std::string marker;        // canonical: "yn-question", "negation", "mouth:MM", "blink", ...
    int firstItem = 0, lastItem = -1;  // items covered; an event: lastItem < firstItem, before item firstItem
    double intensity = 1.0;
    int character = -1;        // role shift: the character turned toward
    std::string word;          // mouthing: the English word
    int line = 0, column = 0;  // where its '[' is written
    bool event() const { return lastItem < firstItem; }
};

struct StorySentence {
    std::string gloss;  // as written
    std::vector<StoryItem> items;
    int line = 0;
    std::vector<StoryMarker> markers{};  // by first item
};

struct StoryQuestion {
    std::string text;
    std::vector<std::string> choices;  // 3-4
    int answer = 0;                    // index into choices (written as a letter, "A".."D")
    int probeSentence = 0;             // 0-based index of the sentence it asks about
    std::string probeVerb;             // the verb it asks about ("ASK")
    int line = 0;
    // Issue 24: the question in ASL gloss ("TOM ASK WHO"), parsed by the story's own gloss
    // parser in the story's context (its characters, placed by the story) as signed text
    // (parseSignedGloss's rules); empty when the file gives none. Rendered as the question clip.
    std::string gloss{};
    StorySentence sentence{};
    std::vector<std::string> fingerspelled{};  // words of `gloss` no sign has: fingerspelled (story --check notes them)
};

struct Story {
    std::string file;
    std::string title;
    std::vector<StoryCharacter> characters;
    std::vector<StorySentence> sentences;
    std::vector<StoryQuestion> questions;
    std::string notes;
    StoryTiming timing;  // the `timing` object (natural when not given)
    // `"nonManuals": false`: no face, head or torso movement from the markers or blinks (a
    // matched set for a study of the face itself; docs/nonmanuals.md). The manual timing,
    // the y/n question's held last sign included, is the same either way.
    bool nonManuals = true;

    int characterIndex(std::string_view gloss) const;  // -1 when none
};

// What a story may say: the verbs, the lexicon's signs, and the letters that can be
// fingerspelled (those with a handshape, and J and Z with their path).
struct StoryVocabulary {
    const VerbLibrary* verbs = nullptr;
    std::vector<std::string> signs;                // lexicon glosses, also for "closest known" hints
    std::function<bool(std::string_view)> isSign;  // nullptr: membership of `signs`
    std::function<bool(char)> canFingerspell;      // nullptr: every letter A-Z
};

// Characters closer than this on the arc cannot be told apart by pointing [D].
inline constexpr double kMinimumCharacterSeparation = 0.2;
// Story file format: {"format": "signstim-story", "version": 1, ...}.
inline constexpr int kStoryFormatVersion = 1;

Story parseStory(const JsonSource& source, const StoryVocabulary& vocabulary);
Story loadStory(const std::filesystem::path& file, const StoryVocabulary& vocabulary);

// Signed text outside a story's sentences (issue 24: comprehension questions, instructions):
// one sentence of gloss, read by the same parser as a story sentence, with three differences:
// a word that is no sign, verb or character is fingerspelled (its letters; listed in
// `fingerspelled` for `story --check`), an indicating verb may lack its subject or object (a
// question asks for one: "WHO ASK ANN"; it is signed uninflected, docs/study.md), and the
// characters of `context` (nullptr: none) count as placed. Errors name `file`, `line`,
// `column` (of the gloss's first character; 0: unknown) and `field`.
StorySentence parseSignedGloss(const std::string& gloss, const Story* context, const StoryVocabulary& vocabulary,
                               const std::string& file, int line, int column, const std::string& field,
                               std::vector<std::string>* fingerspelled = nullptr);

// "A".."D" for 0..3.
std::string choiceLetter(int index);

}  // namespace signstim::stimuli
