#pragma once
// Everything a story is checked against and built from — handshapes, verbs, trained models,
// lexicon — loaded once and shared by `signstim story` and `signstim study`.
#include "hand/hand_model.hpp"
#include "stimuli/story/handshapes.hpp"
#include "stimuli/story/lexicon.hpp"
#include "stimuli/story/story.hpp"
#include "stimuli/story/timeline_builder.hpp"
#include "stimuli/verbs/verb_models.hpp"
#include "stimuli/verbs/verbs.hpp"

#include <filesystem>
#include <string>

namespace signstim::stimuli {

struct StoryWorld {
    std::filesystem::path scenes;
    std::filesystem::path lexiconPath;  // a file or a folder of .json files
    hand::HandModel handModel = hand::buildHandModel();
    stimuli::HandshapeLibrary shapes;
    stimuli::VerbLibrary verbs;
    stimuli::TrainedVerbModels models;
    stimuli::Lexicon lexicon;

    // `scenesDir` empty: resolveScenesDir's default; `lexicon` empty: SCENES/lexicon/.
    StoryWorld(const std::string& scenesDir, const std::string& lexicon);
    StoryWorld(const StoryWorld&) = delete;
    StoryWorld& operator=(const StoryWorld&) = delete;

    stimuli::StoryVocabulary vocabulary() const;
    stimuli::Story loadStory(const std::filesystem::path& file) const;
    // The verb provider names `story`'s file, line and column when a verb cannot be given
    // (a missing animator file, most often). `story` must outlive the result.
    stimuli::TimelineSources sources(const stimuli::Story& story) const;
};

}  // namespace signstim::stimuli
