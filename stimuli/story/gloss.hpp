#pragma once
// Gloss: the written form of an ASL sentence in a story file (SPEC §4.1, docs/stories.md):
//
//   JOHN IX(0.9) ASK MARY IX(-0.6)
//
// One sentence is a sequence of items separated by spaces:
//   sign             STUDENT, HOMEWORK, YESTERDAY   a sign of the lexicon
//   name             JOHN                            a character of the story (fingerspelled
//                                                    or its name sign)
//   pointing         IX(0.9)  IX(JOHN)               the index points at an arc position or
//                                                    at a character's position
//   fingerspelling   fs-JOHN  fs-PIZZA               letter by letter
//   verb             ASK  ASK(JOHN,MARY)  TELL(MARY)  an indicating verb; its subject and
//                                                    object come from the sentence, or are
//                                                    given in parentheses (SPEC §3.2)
//   hold             HOLD  HOLD(0.5)                 the hands hold still (seconds)
//
// Non-manual markers (issue 23, docs/nonmanuals.md) bracket the signs they mark, as ASL gloss
// writes a line over them with the marker's name:
//   [y/n HELP]  [wh KEY WHERE]  [neg NOT KNOW]  [t MEETING]  [rs(JOE) [wh KEY WHERE]]
//   [neg(0.5) NOT GO]   an intensity, 0.1 to 1.5 (1: the documented marker)
//   [mouth(pizza) PIZZA]  mouthing of an English word;  [blink] [nod]  single events
// Markers of one kind (gloss_markers.hpp, MarkerClass) do not overlap; a marker closes in its
// sentence.
//
// This file only tokenizes and parses one sentence into items with their columns; what the
// names mean (lexicon, characters, verbs) is checked by the story loader (stimuli/story/story.hpp).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace signstim::stimuli {

// An argument of IX(...) or of a verb: an arc position or a character's gloss name.
struct GlossArgument {
    std::optional<double> position;  // IX(0.9)
    std::string name;                // IX(JOHN)
    int column = 0;                  // 1-based column of the argument within the sentence
};

enum class GlossItemKind { Word, Pointing, Fingerspelling, Hold };

// One item as written. A Word is a sign, a character's name or a verb: which one is decided
// against the story's characters, the verb library and the lexicon.
struct GlossItem {
    GlossItemKind kind = GlossItemKind::Word;
    std::string text;                     // as written: "ASK(JOHN,MARY)", "IX(0.9)"
    std::string word;                     // Word: "ASK"; Fingerspelling: the letters "JOHN"
    std::vector<GlossArgument> arguments; // Word with "(...)", Pointing: exactly one
    bool hasArgumentList = false;         // "ASK()" is an error, "ASK" is not
    std::optional<double> holdSeconds;    // Hold with an explicit duration
    int column = 0;                       // 1-based column of the item's first character
};

// A non-manual marker as written (gloss_markers.hpp has the vocabulary).
struct GlossMarker {
    std::string name;                 // canonical: "yn-question", "negation", "mouth:MM", "blink", ...
    std::string written;              // as written: "y/n", "neg(0.5)"
    std::optional<double> intensity;  // (0.5)
    std::string argument;             // rs(JOE): "JOE"; mouth(pizza): "pizza"
    int argumentColumn = 0;
    // The items it covers, by index; an event has lastItem == firstItem - 1 and happens
    // before item firstItem (after the last item when firstItem == items.size()).
    int firstItem = 0, lastItem = -1;
    int column = 0;  // 1-based column of its '['
    bool event() const { return lastItem < firstItem; }
};

// A parse error at a column of the sentence (1-based), with what to change.
struct GlossError {
    int column = 0;
    std::string message;
};

// Parses one sentence. Returns the items, or the first error.
struct GlossParse {
    std::vector<GlossItem> items;
    std::vector<GlossMarker> markers;  // by first item, then column
    std::optional<GlossError> error;
};
GlossParse parseGloss(std::string_view sentence);

// The names of `candidates` closest to `name` by edit distance (at most `count`, each within
// a distance of about a third of the name's length), for "did you mean" messages.
std::vector<std::string> closestNames(std::string_view name, const std::vector<std::string>& candidates,
                                      std::size_t count = 3);

}  // namespace signstim::stimuli
