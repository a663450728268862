#include "stimuli/story/story_world.hpp"

#include "common/error.hpp"
#include "stimuli/scenes_path.hpp"
#include "stimuli/verbs/verb_synthesis.hpp"

namespace signstim::stimuli {

using namespace signstim::stimuli;

StoryWorld::StoryWorld(const std::string& scenesDir, const std::string& lexiconFile)
    : scenes(resolveScenesDir(scenesDir)),
      lexiconPath(lexiconFile.empty() ? scenes / "lexicon" : std::filesystem::path(lexiconFile)) {
    shapes = loadHandshapes(scenes / "handshapes.json", handModel);
    verbs = loadVerbLibrary(scenes / "verbs.json");
    models = loadVerbModels(scenes / "models" / "verb_models.json", verbs);
    lexicon = loadLexicon(lexiconPath, shapes, handModel);
}

StoryVocabulary StoryWorld::vocabulary() const {
    StoryVocabulary vocabulary;
    vocabulary.verbs = &verbs;
    vocabulary.signs = lexicon.glosses();
    // J and Z are a handshape (I, 1) plus a path; the other letters are their handshape.
    vocabulary.canFingerspell = [this](char letter) {
        const std::string shape = letter == 'J' ? "I" : letter == 'Z' ? "1" : std::string(1, letter);
        return shapes.find(shape) != nullptr;
    };
    return vocabulary;
}

Story StoryWorld::loadStory(const std::filesystem::path& file) const { return stimuli::loadStory(file, vocabulary()); }

TimelineSources StoryWorld::sources(const Story& story) const {
    TimelineSources s;
    s.lexicon = &lexicon;
    s.shapes = &shapes;
    s.verbs = [this, &story](const std::string& verb, VerbVersion version, double subject, double object, int line,
                             int column) {
        try {
            return synthesizeVerb(VerbSources{&verbs, &models, scenes / "animator", &shapes}, verb, version, subject,
                                  object);
        } catch (const InputError& e) {
            // Say which sentence needs it (a missing animator file, most often).
            if (e.isCommandLine()) throw InputError(story.file, line, column, "", e.detail());
            throw InputError(story.file, line, column, "", std::string(e.what()));
        }
    };
    return s;
}

}  // namespace signstim::stimuli
