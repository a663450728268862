#pragma once
// Mouthing of an English word (issue 23 §4): the lip shapes a signer makes while signing a word
// whose English equivalent is mouthed, timed from the word's phonemes.
//
// The seam between the non-manual grammar (which marks a mouthed span in the gloss) and the
// lip shapes: the grammar calls mouthingTracks with the word and the span's time, and merges
// the tracks into Timeline::nonManuals.
//
// How (docs/mouthing.md): espeak-ng (Debian's libespeak-ng, American English voice) translates
// the word into its phonemes with their stress; each is given a nominal duration (of espeak-ng's
// own magnitudes) and the word is stretched to the span. Each phoneme is shown as one
// of the 15 MPEG-4 / Oculus visemes (two for a diphthong), each viseme is a set of ARKit-52
// mouth weights, neighbouring visemes blend by the Cohen & Massaro (1993) dominance model, and
// the lips meet fully at p, b, m. espeak-ng is loaded once per process, behind a mutex (it is
// not reentrant); it prints nothing and the same word always gives the same tracks.
#include "stimuli/story/timeline.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace signstim::stimuli {

// Letters in one mouthed word (or words: "thank you"): mouthing is of single words or short
// phrases; longer input is refused (InputError) before espeak-ng is asked.
inline constexpr std::size_t kMouthedLetters = 40;

// Tracks of the mouth channels (ARKit-52 names: "jawOpen", "mouthFunnel", "mouthPucker",
// "mouthClose", "mouthPressLeft", ...) that mouth `word` over [startSeconds, endSeconds], each
// starting and ending at 0, at most one track per channel, every value within [0, intensity].
// Empty for a word with no letters.
//  - Only the ASCII letters and the apostrophe of `word` are said (case does not matter); any
//    other character separates words ("mother-in-law" is three words, "C3PO" is "c po").
//  - The spoken phonemes fill the span: the first starts at startSeconds, the last ends at
//    endSeconds (stretched or compressed to the sign); the keys of each track are at the
//    visemes' centres, plus 0 at startSeconds and endSeconds. Channels that stay 0 have no track.
//  - mouthClose follows ARKit's meaning (the lips meet with the jaw open: used with jawOpen), so
//    at p, b and m it equals jawOpen there: the lips are closed.
// Throws std::invalid_argument for a span that is not finite or not increasing or an intensity
// outside [0, 1] (the caller's mistake), InputError for more than kMouthedLetters letters, and
// EnvironmentError (exit 3) when espeak-ng's data is missing (install espeak-ng-data:
// scripts/setup.sh).
std::vector<NonManualTrack> mouthingTracks(const std::string& word, double startSeconds, double endSeconds,
                                           double intensity);

// One viseme of a mouthed word: espeak-ng's phoneme name ("m", "A:", "oU"), the viseme it is
// shown as (Oculus name: "PP", "aa", "oh", "ou", ...; "-" for h and the glottal stop, which take
// their neighbours' shape) and when, in nominal milliseconds from the start of the word (at
// about espeak-ng's default rate; mouthingTracks stretches them to the span). A diphthong is two
// entries with the same phoneme (its first and second half).
struct MouthingViseme {
    std::string phoneme;
    std::string viseme;
    double startMs = 0.0, endMs = 0.0;
};
// The visemes of `word` in order (what mouthingTracks times); empty for a word with no letters.
// Same rules and errors as mouthingTracks.
std::vector<MouthingViseme> mouthingVisemes(const std::string& word);

// Loads espeak-ng now (else the first mouthing does), from espeak-ng's own data search (empty:
// $ESPEAK_DATA_PATH, ~/espeak-ng-data, then Debian's /usr/lib/<arch>/espeak-ng-data) or from
// `espeakDataPath` (a folder holding espeak-ng-data, or that folder itself). Throws
// EnvironmentError naming the folder and the file that is missing, and how to install it; a
// process loads espeak-ng once, so a later call naming another folder than the loaded one
// throws std::logic_error (once its own data is found).
void loadMouthingSynthesizer(const std::string& espeakDataPath = {});

}  // namespace signstim::stimuli
