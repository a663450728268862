#pragma once
// espeak-ng behind mouthing (stimuli/story/mouthing.hpp): internal to mouthing.cpp and its tests.
#include <string>
#include <vector>

namespace signstim::stimuli::mouthing_detail {

// A phoneme of espeak-ng's translation: its name ("m", "A:", "oU") and its stress (2 primary,
// 1 secondary, 0 none; on vowels).
struct SpokenPhoneme {
    std::string name;
    int stress = 0;
};

// Loads espeak-ng (once per process; see loadMouthingSynthesizer).
void loadSynthesizer(const std::string& espeakDataPath);
// The phonemes of `text` (ASCII letters, apostrophes and spaces) in American English, as
// espeak-ng translates it. Thread-safe; loads espeak-ng if needed.
std::vector<SpokenPhoneme> sayWord(const std::string& text);

}  // namespace signstim::stimuli::mouthing_detail
