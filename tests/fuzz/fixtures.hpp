#pragma once
// What the parsers need besides the bytes (the hand model, the project's handshapes, verbs,
// lexicon, a study listing), built once from this checkout's scenes/ and shared by the
// targets; and the checks every target applies to a refusal.
#include "analysis/results_file.hpp"
#include "hand/hand_model.hpp"
#include "stimuli/story/handshapes.hpp"
#include "stimuli/story/lexicon.hpp"
#include "stimuli/story/story.hpp"
#include "stimuli/study/study_listing.hpp"
#include "stimuli/verbs/verbs.hpp"

#include <functional>
#include <string>
#include <string_view>

namespace signstim::fuzz {

const hand::HandModel& handModel();
const stimuli::HandshapeLibrary& handshapes();
const stimuli::VerbLibrary& verbs();
const stimuli::Lexicon& lexicon();
const stimuli::StoryVocabulary& storyVocabulary();
const stimuli::StudyListing& studyListing();  // tests/app/data/tiny-study.json's

// Runs `parse`; an InputError (a user's mistake, refused as it must be) ends the input
// normally after checking that it names `file` (the input's name as given) — any other
// exception escapes to the fuzzer.
void expectRefusalOrSuccess(const std::string& file, const std::function<void()>& parse);

// Findings about accepted values.
void requireFinite(double value, const char* what);

}  // namespace signstim::fuzz
