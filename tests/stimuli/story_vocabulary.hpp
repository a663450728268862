#pragma once
// What the story tests read stories with (stimuli/story/story.hpp): the verb library of the
// repository's scenes/verbs.json, loaded once per test binary, and the signs a test names as its
// lexicon.
#include "stimuli/story/story.hpp"
#include "stimuli/verbs/verbs.hpp"

#include <string>
#include <utility>
#include <vector>

namespace signstim::test {

inline const stimuli::VerbLibrary& sceneVerbs() {
    static const stimuli::VerbLibrary library =
        stimuli::loadVerbLibrary(std::string(SIGNSTIM_SOURCE_DIR) + "/scenes/verbs.json");
    return library;
}

// The scene's verbs and `signs`; every letter can be fingerspelled.
inline stimuli::StoryVocabulary storyVocabulary(std::vector<std::string> signs) {
    stimuli::StoryVocabulary vocabulary;
    vocabulary.verbs = &sceneVerbs();
    vocabulary.signs = std::move(signs);
    return vocabulary;
}

}  // namespace signstim::test
