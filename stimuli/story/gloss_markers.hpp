#pragma once
// The vocabulary of non-manual markers in gloss (issue 23 §4, docs/nonmanuals.md): how each is
// written inside '[', its canonical name (NonManualSpan::marker), what it takes in parentheses
// and which markers may not overlap. What each marker does to the face, head and torso is in
// stimuli/story/nonmanuals.hpp.
#include "stimuli/story/gloss.hpp"

#include <string_view>
#include <variant>
#include <vector>

namespace signstim::stimuli {

// Markers of one class share articulators and cannot overlap (one nested in another of its
// class is refused): a clause is one of y/n, wh, topic, conditional, rhetorical question
// (brows); negation and affirmation move the head; one mouth shape at a time; one role shift
// at a time. Events (blink, nod) may stand anywhere.
enum class MarkerClass { Clause, Head, Mouth, RoleShift, Event };

enum class MarkerArgument { None, Character, Word };

struct MarkerDefinition {
    std::string_view written;  // "y/n": as the gloss writes it (any case)
    std::string_view name;     // "yn-question"
    MarkerClass markerClass = MarkerClass::Clause;
    MarkerArgument argument = MarkerArgument::None;  // required when not None
    std::string_view meaning;  // "yes/no question", for messages
};

// Every marker, in the order docs/nonmanuals.md lists them.
const std::vector<MarkerDefinition>& markerDefinitions();
// The marker written so (case-insensitive; "yn" for "y/n"), or nullptr.
const MarkerDefinition* findMarker(std::string_view written);
// The marker of a canonical name, or nullptr.
const MarkerDefinition* findMarkerByName(std::string_view name);
std::string_view toString(MarkerClass markerClass);

// [D] An intensity scales every value of the marker: 1 is the marker as documented, below
// it fainter, up to 1.5 stronger (face weights are clipped at 1).
inline constexpr double kMinimumMarkerIntensity = 0.1;
inline constexpr double kMaximumMarkerIntensity = 1.5;
// [D] A mouthed word is at most this long (the longest English words a signer mouths).
inline constexpr std::size_t kMaximumMouthedLetters = 32;

// Parses a marker's head, the text between '[' and the first space or ']' ("neg(0.5)",
// "rs(JOE)"), at `offset` (0-based, of the '[') in the sentence. Sets name, written,
// intensity, argument and column.
std::variant<GlossMarker, GlossError> parseMarkerHead(std::string_view head, std::size_t offset);

}  // namespace signstim::stimuli
