#pragma once
// Mouthing of an English word (issue 23 §4): the lip shapes a signer makes while signing a word
// whose English equivalent is mouthed, timed from the word's phonemes.
//
// The seam between the non-manual grammar (which marks a mouthed span in the gloss) and the
// lip shapes: the grammar calls mouthingTracks with the word and the span's time, and merges
// the tracks into Timeline::nonManuals.
#include "stimuli/story/timeline.hpp"

#include <string>
#include <vector>

namespace signstim::stimuli {

// Tracks of the mouth channels (ARKit-52 names: "jawOpen", "mouthFunnel", "mouthPucker",
// "mouthClose", "mouthPressLeft", ...) that mouth `word` over [startSeconds, endSeconds], each
// starting and ending at 0, at most one track per channel, every value within [0, intensity].
// Empty for a word with no letters.
std::vector<NonManualTrack> mouthingTracks(const std::string& word, double startSeconds, double endSeconds,
                                           double intensity);

}  // namespace signstim::stimuli
