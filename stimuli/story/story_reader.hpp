#pragma once
// The reader behind parseStory and parseSignedGloss (stimuli/story/story.hpp), internal to
// story.cpp (the file's fields, its characters, its questions, the text positions of errors)
// and story_sentences.cpp (sentences of gloss: signs, names, pointing, verbs and their subject
// and object).
#include "common/error.hpp"
#include "stimuli/story/gloss.hpp"
#include "stimuli/story/story.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <functional>
#include <initializer_list>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace signstim::stimuli::story_detail {

using nlohmann::json;

// Where a character of the story file's text is: its line and its column on that line.
struct TextPosition {
    int line = 0;
    int column = 0;
};

class StoryReader {
public:
    StoryReader(const JsonSource& source, const StoryVocabulary& vocabulary)
        : source_(source), vocabulary_(vocabulary) {
        if (!vocabulary_.verbs) throw std::invalid_argument("parseStory: no verb library");
    }

    Story read();

    // parseSignedGloss: the characters of `context` (placed), then one sentence of signed text.
    StorySentence signedGloss(const std::string& gloss, const Story* context, int line, int column,
                              const std::string& field, std::vector<std::string>* fingerspelled);

private:
    [[noreturn]] void fail(int line, const std::string& field, const std::string& message, int column = 0) const {
        throw InputError(source_.file, line, column, field, message);
    }

    // The line of member `key` of the object at `pointer`, from the parser's index.
    int lineOfKey(const std::string& pointer, const std::string& key) const {
        return source_.lineAt(pointer + "/" + jsonPointerToken(key));
    }

    const json& required(const json& object, const std::string& key, const std::string& pointer) const {
        if (!object.contains(key)) fail(source_.lineAt(pointer), pointer + "/" + key, "missing field '" + key + "'");
        return object[key];
    }

    std::string requiredString(const json& object, const std::string& key, const std::string& pointer) const {
        const json& value = required(object, key, pointer);
        if (!value.is_string()) fail(lineOfKey(pointer, key), pointer + "/" + key, "expected text in quotes");
        return value.get<std::string>();
    }

    void checkKnownKeys(const json& object, std::initializer_list<const char*> known, const std::string& pointer) const {
        for (const auto& [key, value] : object.items()) {
            bool found = false;
            std::string list;
            for (const char* k : known) {
                found = found || key == k;
                list += (list.empty() ? "" : ", ") + std::string(k);
            }
            if (!found)
                fail(lineOfKey(pointer, key), pointer + "/" + key, "unknown field '" + key + "' (known: " + list + ")");
        }
    }

    // ---- fields and characters (story.cpp) ---------------------------------------------------

    TextPosition elementPosition(const std::string& key, std::size_t index) const;
    void readCharacters(const json& list);
    bool isSign(const std::string& gloss) const;
    void requireSign(const std::string& gloss, int line, int column, const std::string& field) const;
    bool spellable(const std::string& word) const;
    void requireSpellable(const std::string& letters, int line, int column, const std::string& field) const;

    // ---- sentences (story_sentences.cpp) -----------------------------------------------------

    void readSentences(const json& list);
    StorySentence readSentence(const std::string& gloss, int line, int firstColumn, const std::string& field);
    void readVerbArguments(const VerbDefinition& verb, const GlossItem& written, StoryItem& item, int line,
                           const std::function<int(int)>& column, const std::string& field);
    void resolveVerb(StorySentence& sentence, std::size_t index, const std::string& field);

    static bool isReferent(const StoryItem& item) {
        return (item.kind == StoryItemKind::Name || item.kind == StoryItemKind::Pointing) && item.character >= 0;
    }

    void requirePlaced(int character, int line, int column, const std::string& field) const;
    int characterAt(double position) const;
    std::string characterList() const;

    // ---- questions (story.cpp) ---------------------------------------------------------------

    void readQuestions(const json& list);
    void readQuestionGloss(const json& value, std::size_t index, StoryQuestion& question);

    const JsonSource& source_;
    const StoryVocabulary& vocabulary_;
    Story story_;
    std::vector<bool> placed_;
    bool signedText_ = false;                 // reading signed text (parseSignedGloss's rules)
    std::vector<std::string> spelledWords_;   // words signed text fingerspells, in order
    mutable std::map<std::string, std::vector<std::size_t>> elementOffsets_;  // elementPosition's cache
};

}  // namespace signstim::stimuli::story_detail
