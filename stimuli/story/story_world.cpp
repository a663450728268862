#include "stimuli/story/story_world.hpp"

#include "common/error.hpp"
#include "stimuli/scenes_path.hpp"
#include "stimuli/story/gloss.hpp"

#include <algorithm>
#include "stimuli/verbs/verb_synthesis.hpp"

namespace signstim::stimuli {

using namespace signstim::stimuli;

StoryWorld::StoryWorld(const std::string& scenesDir, const std::string& lexiconFile)
    : scenes(resolveScenesDir(scenesDir)),
      lexiconPath(scenes / "lexicon"),
      labLexiconPath(lexiconFile) {
    shapes = loadHandshapes(scenes / "handshapes.json", handModel);
    verbs = loadVerbLibrary(scenes / "verbs.json");
    models = loadVerbModels(scenes / "models" / "verb_models.json", verbs);
    lexicon = loadLexicon(lexiconPath, labLexiconPath, shapes, handModel);
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
    s.transitions = transitionPacer;
    s.reach = reach;
    s.verbs = [this, &story](const std::string& verb, VerbVersion version, double subject, double object, int line,
                             int column) {
        try {
            VerbPerformance p = synthesizeVerb(VerbSources{&verbs, &models, scenes / "animator", &shapes}, verb, version,
                                               subject, object);
            if (p.draft && !allowDraftAnimator)
                throw InputError(p.handshapeFile, readJsonFile(p.handshapeFile).lineAt("/draft"), "/draft",
                                 "a draft (\"draft\": true): have an animator work on it and delete \"draft\", or pass "
                                 "--allow-draft-animator to use it as it is");
            return p;
        } catch (const MissingAnimatorFile& e) {
            // Kept as such: the timeline decides whether the version that needs it is asked for.
            throw MissingAnimatorFile(story.file, line, column, std::string(e.what()), e.animatorFile());
        } catch (const InputError& e) {
            // Say which sentence needs it (a missing animator file, most often).
            if (e.isCommandLine()) throw InputError(story.file, line, column, "", e.detail());
            throw InputError(story.file, line, column, "", std::string(e.what()));
        }
    };
    return s;
}

namespace {

// Each animator keyframe file the story's verb instances name that exists, once, in the order
// the story first needs it: f(file, verb, subject, object, gloss).
template <typename F>
void forEachAnimatorFile(const StoryWorld& world, const Story& story, F&& f) {
    std::vector<std::string> seen;
    for (const StorySentence& sentence : story.sentences)
        for (const StoryItem& item : sentence.items) {
            if (item.kind != StoryItemKind::Verb) continue;
            const VerbDefinition& verb = world.verbs.get(item.gloss);
            const double subject = item.subject >= 0 ? story.characters[static_cast<std::size_t>(item.subject)].position : 0.0;
            const double object = story.characters[static_cast<std::size_t>(item.object)].position;
            const std::filesystem::path file = world.scenes / "animator" / animatorFileName(verb, subject, object);
            if (!std::filesystem::exists(file) || std::find(seen.begin(), seen.end(), file.string()) != seen.end()) continue;
            seen.push_back(file.string());
            f(file, verb, subject, object, item.gloss);
        }
}

}  // namespace

std::vector<std::string> StoryWorld::draftAnimatorFiles(const Story& story) const {
    std::vector<std::string> drafts;
    forEachAnimatorFile(*this, story,
                        [&](const std::filesystem::path& file, const VerbDefinition& verb, double subject, double object,
                            const std::string&) {
                            if (loadAnimatorPerformance(file, verb, subject, object).draft) drafts.push_back(file.string());
                        });
    return drafts;
}

std::vector<std::string> StoryWorld::copiedDraftNotes(const Story& story) const {
    std::vector<std::string> notes;
    const VerbSources sources{&verbs, &models, scenes / "animator", &shapes};
    forEachAnimatorFile(*this, story,
                        [&](const std::filesystem::path& file, const VerbDefinition& verb, double subject, double object,
                            const std::string& gloss) {
                            const VerbPerformance animator = loadAnimatorPerformance(file, verb, subject, object);
                            if (animator.draft) return;
                            if (sameKeyframes(animator, synthesizeVerb(sources, gloss, VerbVersion::Point, subject, object)))
                                notes.push_back(file.string() +
                                                ": its keyframes are the point model's output, but the file is not "
                                                "marked \"draft\": the animator version would show the point version; "
                                                "have an animator work on it, or mark it \"draft\": true");
                        });
    return notes;
}

std::vector<std::string> StoryWorld::lexiconOverrideNotes() const {
    std::vector<std::string> notes;
    for (const LexiconOverride& o : lexicon.overrides)
        notes.push_back("lexicon: " + o.file + ":" + std::to_string(o.line) + ": " + o.what + " overrides " + o.replacedFile +
                        ":" + std::to_string(o.replacedLine));
    return notes;
}

std::vector<std::string> StoryWorld::fingerspellingNotes(const Story& story) const {
    std::vector<std::string> notes;
    const std::vector<std::string> glosses = lexicon.glosses();
    for (const StoryCharacter& c : story.characters) {
        if (!c.nameSign.empty() || c.spelledGiven) continue;
        std::string letters;
        for (char letter : c.spelled) letters += (letters.empty() ? "" : "-") + std::string(1, letter);
        std::string note = story.file + ":" + std::to_string(c.line) + ": " + c.gloss + " will be fingerspelled (" + letters +
                           "): no sign of the lexicon has the gloss " + c.gloss;
        const std::vector<std::string> close = closestNames(c.gloss, glosses);
        if (!close.empty()) {
            note += " (closest: ";
            for (std::size_t i = 0; i < close.size(); ++i) note += (i ? ", " : "") + close[i];
            note += ")";
        }
        notes.push_back(note + "; add the sign with --lexicon, give \"nameSign\", or write \"spelled\" to say the letters are meant");
    }
    // Issue 24: words of a question's gloss that no sign has are fingerspelled.
    for (std::size_t q = 0; q < story.questions.size(); ++q)
        for (const std::string& word : story.questions[q].fingerspelled)
            notes.push_back(story.file + ":" + std::to_string(story.questions[q].line) + ": question " + std::to_string(q + 1) +
                            ": " + word + " will be fingerspelled: no sign of the lexicon has the gloss " + word +
                            "; add the sign with --lexicon, or write fs-" + word + " to say the letters are meant");
    return notes;
}

}  // namespace signstim::stimuli
