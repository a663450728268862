#pragma once
// How much input signstim accepts: every reader refuses more, at once and before the expensive
// work, as an InputError naming the file (exit 2), so a hostile or broken file costs
// milliseconds and memory in proportion to the limit, never a crash or a full machine.
// docs/errors.md ("Limits") lists them with the reason for each; change both together.
#include <cstddef>

namespace signstim::limits {

inline constexpr std::size_t kMebibyte = 1024 * 1024;

// Bytes of one JSON data file (scenes/, lexicons, studies, models, manifests). The largest the
// project ships is under 1 MiB; a study plan of 1,000 participants is a few MiB.
inline constexpr std::size_t kJsonFileBytes = 64 * kMebibyte;
// Bytes of one story file (gloss in JSON): a story of kStorySentences sentences of kSentenceSigns
// signs and its questions is well under 1 MiB.
inline constexpr std::size_t kStoryFileBytes = 4 * kMebibyte;
// Bytes of one CSV results file (one participant's trials: tens of rows in practice).
inline constexpr std::size_t kCsvFileBytes = 64 * kMebibyte;
// Bytes of any other text file read whole (sensor samples, corpus, study copies).
inline constexpr std::size_t kTextFileBytes = 256 * kMebibyte;

// White space in a row in a JSON file: nlohmann's parser keeps the white space before a token
// and quotes it, 8 bytes for each, in a syntax error's message (200 MB of it took 2.5 GB and
// a minute); a written file has lines of at most a few hundred spaces of indentation.
inline constexpr std::size_t kJsonWhitespaceRun = 64 * 1024;

// Nesting of arrays and objects in a JSON file: the deepest signstim writes or reads is 6
// (a study plan); 64 leaves room for tools that wrap files, and keeps the parser's state small.
inline constexpr std::size_t kJsonDepth = 64;

// Sentences in one story: each is checked in four versions (~0.2 s each); 1,000 sentences is
// over an hour of signing, far beyond a comprehension study's stories of 5 to 20 sentences.
inline constexpr std::size_t kStorySentences = 1000;
// Signs (gloss items) in one sentence: ASL sentences of studies have 3 to 15 signs.
inline constexpr std::size_t kSentenceSigns = 64;
// Letters of one fingerspelled word (fs-...): the longest English words used as names are
// under 20 letters.
inline constexpr std::size_t kFingerspelledLetters = 40;
// Rows of one CSV results file (one participant): a study of 100 stories and 1,000 rated
// sentences has 1,100; the limit leaves 90 times that.
inline constexpr std::size_t kResultRows = 100000;

}  // namespace signstim::limits
