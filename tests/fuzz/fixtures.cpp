#include "tests/fuzz/fixtures.hpp"

#include "common/error.hpp"
#include "tests/fuzz/fuzz_target.hpp"
#include "stimuli/json_source.hpp"
#include "stimuli/study/study.hpp"

#include <cmath>
#include <filesystem>

namespace signstim::fuzz {
namespace {

std::filesystem::path scenes() { return std::filesystem::path(SIGNSTIM_SOURCE_DIR) / "scenes"; }

}  // namespace

const hand::HandModel& handModel() {
    static const hand::HandModel model = hand::buildHandModel();
    return model;
}

const stimuli::HandshapeLibrary& handshapes() {
    static const stimuli::HandshapeLibrary shapes = stimuli::loadHandshapes(scenes() / "handshapes.json", handModel());
    return shapes;
}

const stimuli::VerbLibrary& verbs() {
    static const stimuli::VerbLibrary library = stimuli::loadVerbLibrary(scenes() / "verbs.json");
    return library;
}

const stimuli::Lexicon& lexicon() {
    static const stimuli::Lexicon signs = stimuli::loadLexicon(scenes() / "lexicon", handshapes(), handModel());
    return signs;
}

const stimuli::StoryVocabulary& storyVocabulary() {
    // As stimuli/story/story_world.cpp builds it: the lexicon's glosses; J and Z are a handshape plus a
    // path, the other letters their handshape.
    static const stimuli::StoryVocabulary vocabulary = [] {
        stimuli::StoryVocabulary v;
        v.verbs = &verbs();
        v.signs = lexicon().glosses();
        v.canFingerspell = [](char letter) {
            const std::string shape = letter == 'J' ? "I" : letter == 'Z' ? "1" : std::string(1, letter);
            return handshapes().find(shape) != nullptr;
        };
        return v;
    }();
    return vocabulary;
}

const stimuli::StudyListing& studyListing() {
    // The listing of tests/app/data/tiny-study.json as its plan.json holds it (the seed of the
    // study_listing target); the results seeds are simulate-results files of that study.
    static const stimuli::StudyListing listing = [] {
        const auto file = std::filesystem::path(SIGNSTIM_SOURCE_DIR) / "tests/fuzz/seeds/study_listing/tiny.json";
        const stimuli::JsonSource source = stimuli::readJsonFile(file);
        return stimuli::listingFromJson(source.root, file.string());
    }();
    return listing;
}

void expectRefusalOrSuccess(const std::string& file, const std::function<void()>& parse) {
    try {
        parse();
    } catch (const InputError& e) {
        // A refusal must say which input it is about (the command prints file:line: field).
        if (e.file().rfind(file, 0) != 0)
            fail("a refusal of '" + file + "' names '" + e.file() + "' instead: " + e.what());
        if (e.line() < 0 || e.column() < 0) fail(std::string("a refusal with a negative line or column: ") + e.what());
    }
}

void requireFinite(double value, const char* what) {
    if (!std::isfinite(value)) fail(std::string("accepted a non-finite ") + what);
}

}  // namespace signstim::fuzz
