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
#include <vector>

namespace signstim::stimuli {

struct StoryWorld {
    std::filesystem::path scenes;
    std::filesystem::path lexiconPath;     // the default lexicon: SCENES/lexicon/
    std::filesystem::path labLexiconPath;  // a lab's own on top of it (--lexicon; a file or folder), or empty
    hand::HandModel handModel = hand::buildHandModel();
    stimuli::HandshapeLibrary shapes;
    stimuli::VerbLibrary verbs;
    stimuli::TrainedVerbModels models;
    stimuli::Lexicon lexicon;
    // Whether an animator file marked "draft" may be used: yes for a story (a preview); a
    // study sets it from --allow-draft-animator. Refused: InputError naming the file's /draft.
    bool allowDraftAnimator = true;
    // Given to every timeline's sources (TimelineSources::transitions): the signer's pacing of
    // transitions by their detours (app/ sets signer::transitionPacer; empty: none).
    stimuli::TransitionPacer transitionPacer;
    // Given to every timeline's sources (TimelineSources::reach): the signer's comfortable reach,
    // within which verbs are signed (app/ sets signer::signerReach; empty: none).
    stimuli::SignerReach reach;

    // `scenesDir` empty: resolveScenesDir's default. `lexicon`: a lab's own lexicon that adds to
    // SCENES/lexicon/ and overrides its signs of the same gloss (empty: the default alone).
    StoryWorld(const std::string& scenesDir, const std::string& lexicon);
    StoryWorld(const StoryWorld&) = delete;
    StoryWorld& operator=(const StoryWorld&) = delete;

    stimuli::StoryVocabulary vocabulary() const;
    stimuli::Story loadStory(const std::filesystem::path& file) const;
    // The verb provider names `story`'s file, line and column when a verb cannot be given
    // (a missing animator file, most often). `story` must outlive the result.
    stimuli::TimelineSources sources(const stimuli::Story& story) const;

    // For --check: one line per sign or location of the default lexicon the lab's lexicon
    // overrides ("lexicon: lab.json:12: sign TEACHER overrides scenes/lexicon/notation-lexb-b.json:161").
    std::vector<std::string> lexiconOverrideNotes() const;
    // For --check: one line per character fingerspelled because no sign has its gloss and the
    // story does not say the letters on purpose ("spelled").
    std::vector<std::string> fingerspellingNotes(const stimuli::Story& story) const;
    // The animator files `story`'s verbs use that are marked "draft" (in story order, each once).
    std::vector<std::string> draftAnimatorFiles(const stimuli::Story& story) const;
    // For --check: one line per animator file `story` uses that is not marked "draft" but holds
    // exactly the point model's keyframes (a draft copied in without its mark).
    std::vector<std::string> copiedDraftNotes(const stimuli::Story& story) const;
};

}  // namespace signstim::stimuli
