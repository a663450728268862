#include "stimuli/story/story.hpp"

#include "common/input_limits.hpp"
#include "stimuli/story/story_markers.hpp"
#include "stimuli/story/story_reader.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace signstim::stimuli::story_detail {
namespace {

// ---- where things are in the file's text ----------------------------------------------------
// nlohmann::json keeps no positions; story errors need the line and column of a sentence's
// characters, so the few arrays a story has are located by scanning the text itself.

// The line from the parser's index (JsonSource::lineOfOffset: no scan from the start, so a
// story of many sentences costs no more than linear time); the column counted on its line.
TextPosition positionOf(const JsonSource& source, std::size_t offset) {
    const std::string& text = source.text;
    offset = std::min(offset, text.size());
    const std::size_t lineStart = offset == 0 ? 0 : text.rfind('\n', offset - 1) + 1;  // npos + 1 == 0
    TextPosition p{source.lineOfOffset(offset), 1};
    for (std::size_t i = lineStart; i < offset; ++i)
        if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) ++p.column;  // count UTF-8 characters
    return p;
}

std::size_t skipSpace(const std::string& text, std::size_t at) {
    while (at < text.size() && (text[at] == ' ' || text[at] == '\t' || text[at] == '\n' || text[at] == '\r')) ++at;
    return at;
}

// Offset just past one JSON value starting at `at` (the text is known to be valid JSON).
std::size_t skipValue(const std::string& text, std::size_t at) {
    if (at >= text.size()) return at;
    if (text[at] == '"') {
        for (++at; at < text.size() && text[at] != '"'; ++at)
            if (text[at] == '\\') ++at;
        return at + 1;
    }
    if (text[at] == '[' || text[at] == '{') {
        int depth = 0;
        for (; at < text.size(); ++at) {
            const char c = text[at];
            if (c == '"') {
                at = skipValue(text, at) - 1;
            } else if (c == '[' || c == '{') {
                ++depth;
            } else if (c == ']' || c == '}') {
                if (--depth == 0) return at + 1;
            }
        }
        return at;
    }
    while (at < text.size() && text[at] != ',' && text[at] != ']' && text[at] != '}' && text[at] != ' ' &&
           text[at] != '\n')
        ++at;
    return at;
}

// Offsets of the elements of the top-level array `key` ("sentences"); empty when not found.
std::vector<std::size_t> topLevelArrayElements(const std::string& text, const std::string& key) {
    std::vector<std::size_t> offsets;
    // The top-level object's members, scanned in order so a key inside a nested value is
    // never mistaken for the top-level one.
    std::size_t at = skipSpace(text, 0);
    if (at >= text.size() || text[at] != '{') return offsets;
    at = skipSpace(text, at + 1);
    while (at < text.size() && text[at] == '"') {
        const std::size_t keyEnd = skipValue(text, at);
        const std::string name = text.substr(at + 1, keyEnd - at - 2);
        at = skipSpace(text, keyEnd);
        if (at < text.size() && text[at] == ':') at = skipSpace(text, at + 1);
        if (name == key && at < text.size() && text[at] == '[') {
            std::size_t element = skipSpace(text, at + 1);
            while (element < text.size() && text[element] != ']') {
                offsets.push_back(element);
                element = skipSpace(text, skipValue(text, element));
                if (element < text.size() && text[element] == ',') element = skipSpace(text, element + 1);
            }
            return offsets;
        }
        at = skipSpace(text, skipValue(text, at));
        if (at < text.size() && text[at] == ',') at = skipSpace(text, at + 1);
    }
    return offsets;
}

}  // namespace

// ---- fields and characters --------------------------------------------------------------------

Story StoryReader::read() {
    const json& root = source_.root;
    if (!root.is_object()) fail(1, "", "a story file is a JSON object {\"format\": \"signstim-story\", ...}");
    checkKnownKeys(root, {"format", "version", "title", "characters", "sentences", "questions", "notes", "timing", "nonManuals"}, "");
    const std::string format = requiredString(root, "format", "");
    if (format != "signstim-story")
        fail(lineOfKey("", "format"), "/format", "expected \"signstim-story\", got \"" + format + "\"");
    const json& version = required(root, "version", "");
    if (!version.is_number_integer() || version.get<long long>() != kStoryFormatVersion)
        fail(lineOfKey("", "version"), "/version",
             "this signstim reads story files of version " + std::to_string(kStoryFormatVersion) + ", got " +
                 version.dump());
    story_.file = source_.file;
    story_.title = requiredString(root, "title", "");
    if (root.contains("notes")) story_.notes = requiredString(root, "notes", "");
    if (root.contains("timing")) story_.timing = parseStoryTiming(source_, root["timing"], "/timing");
    if (root.contains("nonManuals")) {
        if (!root["nonManuals"].is_boolean())
            fail(lineOfKey("", "nonManuals"), "/nonManuals", "expected true or false (false: no non-manuals; docs/nonmanuals.md)");
        story_.nonManuals = root["nonManuals"].get<bool>();
    }
    readCharacters(required(root, "characters", ""));
    readSentences(required(root, "sentences", ""));
    // A story for phase 1 has questions (the study requires them); the sentences of phase 2
    // are a story without any.
    if (root.contains("questions")) readQuestions(root["questions"]);
    return std::move(story_);
}

// Line of element `index` of the top-level array `key`, from its offset in the text.
// The offsets of each array are found once (a scan of the text), not once per element.
TextPosition StoryReader::elementPosition(const std::string& key, std::size_t index) const {
    auto found = elementOffsets_.find(key);
    if (found == elementOffsets_.end()) found = elementOffsets_.emplace(key, topLevelArrayElements(source_.text, key)).first;
    const std::vector<std::size_t>& offsets = found->second;
    if (index < offsets.size()) return positionOf(source_, offsets[index]);
    return {lineOfKey("", key), 0};
}

void StoryReader::readCharacters(const json& list) {
    const int listLine = lineOfKey("", "characters");
    if (!list.is_array() || list.size() < 2 || list.size() > 6)
        fail(listLine, "/characters", "expected 2 to 6 characters, each {\"gloss\": \"JOHN\", \"position\": 0.9}");
    for (std::size_t i = 0; i < list.size(); ++i) {
        const json& entry = list[i];
        const std::string pointer = "/characters/" + std::to_string(i);
        const int line = elementPosition("characters", i).line;
        if (!entry.is_object()) fail(line, pointer, "expected {\"gloss\": \"JOHN\", \"position\": 0.9}");
        for (const auto& [key, value] : entry.items())
            if (key != "gloss" && key != "position" && key != "nameSign" && key != "spelled" && key != "description")
                fail(line, pointer + "/" + key,
                     "unknown field '" + key + "' (known: gloss, position, nameSign, spelled, description)");
        StoryCharacter character;
        character.line = line;
        if (!entry.contains("gloss") || !entry["gloss"].is_string())
            fail(line, pointer + "/gloss", "each character needs a \"gloss\": the name the sentences use, e.g. \"JOHN\"");
        character.gloss = entry["gloss"].get<std::string>();
        const GlossParse parsed = parseGloss(character.gloss);
        if (parsed.error || parsed.items.size() != 1 || parsed.items[0].kind != GlossItemKind::Word ||
            parsed.items[0].hasArgumentList)
            fail(line, pointer + "/gloss", "'" + character.gloss + "' is not a gloss name (capitals, e.g. JOHN)");
        if (vocabulary_.verbs->find(character.gloss) || character.gloss == "IX" || character.gloss == "HOLD")
            fail(line, pointer + "/gloss",
                 "'" + character.gloss + "' is a verb or a gloss keyword; give the character another gloss name");
        if (isSign(character.gloss)) character.nameSign = character.gloss;
        if (story_.characterIndex(character.gloss) >= 0)
            fail(line, pointer + "/gloss", "two characters are called " + character.gloss);
        if (!entry.contains("position") || !entry["position"].is_number())
            fail(line, pointer + "/position", "each character needs an arc \"position\" in [-1, 1], e.g. 0.9");
        character.position = entry["position"].get<double>();
        if (!(character.position >= -1.0 && character.position <= 1.0))
            fail(line, pointer + "/position",
                 "arc position " + entry["position"].dump() + " is outside [-1, 1] (-1 the signer's far left, 1 far right)");
        for (const StoryCharacter& other : story_.characters)
            if (std::abs(other.position - character.position) < kMinimumCharacterSeparation - 1e-9)
                fail(line, pointer + "/position",
                     character.gloss + " at " + entry["position"].dump() + " and " + other.gloss + " at " +
                         json(other.position).dump() +
                         " are too close to tell apart when pointing; keep characters at least 0.2 apart");
        if (entry.contains("nameSign")) {
            if (!character.nameSign.empty())
                fail(line, pointer + "/nameSign", character.gloss + " is a sign and is signed with it; drop \"nameSign\"");
            if (!entry["nameSign"].is_string()) fail(line, pointer + "/nameSign", "expected a lexicon gloss in quotes");
            character.nameSign = entry["nameSign"].get<std::string>();
            requireSign(character.nameSign, line, 0, pointer + "/nameSign");
        }
        character.spelled = character.gloss;
        if (entry.contains("spelled")) {
            if (!entry["spelled"].is_string()) fail(line, pointer + "/spelled", "expected letters in quotes");
            character.spelled = entry["spelled"].get<std::string>();
            character.spelledGiven = true;
        }
        if (character.nameSign.empty()) requireSpellable(character.spelled, line, 0, pointer + "/spelled");
        if (entry.contains("description")) {
            if (!entry["description"].is_string()) fail(line, pointer + "/description", "expected text in quotes");
            character.description = entry["description"].get<std::string>();
        }
        story_.characters.push_back(std::move(character));
    }
}

bool StoryReader::isSign(const std::string& gloss) const {
    if (vocabulary_.isSign) return vocabulary_.isSign(gloss);
    return std::find(vocabulary_.signs.begin(), vocabulary_.signs.end(), gloss) != vocabulary_.signs.end();
}

void StoryReader::requireSign(const std::string& gloss, int line, int column, const std::string& field) const {
    if (isSign(gloss)) return;
    std::vector<std::string> known = vocabulary_.signs;
    for (const VerbDefinition& verb : vocabulary_.verbs->verbs) known.push_back(verb.name);
    for (const StoryCharacter& character : story_.characters) known.push_back(character.gloss);
    const std::vector<std::string> close = closestNames(gloss, known);
    std::string hint;
    for (const std::string& name : close) hint += (hint.empty() ? "" : ", ") + name;
    fail(line, field,
         "unknown gloss '" + gloss + "'" + (hint.empty() ? std::string() : " (closest known: " + hint + ")") +
             "; signs come from the lexicon, names from the story's characters, fs-WORD fingerspells",
         column);
}

bool StoryReader::spellable(const std::string& word) const {
    if (word.empty() || word.size() > limits::kFingerspelledLetters) return false;
    return std::all_of(word.begin(), word.end(), [&](char c) {
        return c >= 'A' && c <= 'Z' && (!vocabulary_.canFingerspell || vocabulary_.canFingerspell(c));
    });
}

void StoryReader::requireSpellable(const std::string& letters, int line, int column, const std::string& field) const {
    if (letters.empty()) fail(line, field, "nothing to fingerspell", column);
    if (letters.size() > limits::kFingerspelledLetters)
        fail(line, field,
             std::to_string(letters.size()) + " letters to fingerspell; at most " +
                 std::to_string(limits::kFingerspelledLetters) + " (docs/errors.md, Limits)",
             column);
    for (std::size_t i = 0; i < letters.size(); ++i) {
        const char c = letters[i];
        if (c < 'A' || c > 'Z')
            fail(line, field, "'" + std::string(1, c) + "' cannot be fingerspelled (letters A to Z)",
                 column > 0 ? column + static_cast<int>(i) : 0);
        if (vocabulary_.canFingerspell && !vocabulary_.canFingerspell(c))
            fail(line, field,
                 "the letter " + std::string(1, c) + " has no handshape in the handshape library; add it there",
                 column > 0 ? column + static_cast<int>(i) : 0);
    }
}

// ---- questions -----------------------------------------------------------------------------

void StoryReader::readQuestions(const json& list) {
    if (!list.is_array())
        fail(lineOfKey("", "questions"), "/questions", "expected a list of multiple-choice questions");
    for (std::size_t i = 0; i < list.size(); ++i) {
        const json& entry = list[i];
        const std::string pointer = "/questions/" + std::to_string(i);
        const int line = elementPosition("questions", i).line;
        if (!entry.is_object()) fail(line, pointer, "expected {\"question\": ..., \"choices\": [...], \"answer\": \"A\"}");
        for (const auto& [key, value] : entry.items())
            if (key != "question" && key != "choices" && key != "answer" && key != "probes" && key != "gloss")
                fail(line, pointer + "/" + key,
                     "unknown field '" + key + "' (known: question, gloss, choices, answer, probes)");
        StoryQuestion question;
        question.line = line;
        if (!entry.contains("question") || !entry["question"].is_string() || entry["question"].get<std::string>().empty())
            fail(line, pointer + "/question", "each question needs its \"question\" text");
        question.text = entry["question"].get<std::string>();
        const json& choices = entry.contains("choices") ? entry["choices"] : json();
        if (!choices.is_array() || choices.size() < 3 || choices.size() > 4)
            fail(line, pointer + "/choices", "expected 3 or 4 choices");
        for (const json& choice : choices) {
            if (!choice.is_string() || choice.get<std::string>().empty())
                fail(line, pointer + "/choices", "each choice is non-empty text");
            question.choices.push_back(choice.get<std::string>());
        }
        const std::string lastLetter = choiceLetter(static_cast<int>(question.choices.size()) - 1);
        if (!entry.contains("answer") || !entry["answer"].is_string() || entry["answer"].get<std::string>().size() != 1)
            fail(line, pointer + "/answer", "the answer key is the letter of the right choice, \"A\" to \"" + lastLetter + "\"");
        question.answer = entry["answer"].get<std::string>()[0] - 'A';
        if (question.answer < 0 || question.answer >= static_cast<int>(question.choices.size()))
            fail(line, pointer + "/answer",
                 "answer \"" + entry["answer"].get<std::string>() + "\" is not one of the choices (\"A\" to \"" +
                     lastLetter + "\")");
        const json& probes = entry.contains("probes") ? entry["probes"] : json();
        if (!probes.is_object() || !probes.contains("sentence") || !probes["sentence"].is_number_integer() ||
            !probes.contains("verb") || !probes["verb"].is_string())
            fail(line, pointer + "/probes",
                 "say what the question probes: {\"sentence\": N (1-based), \"verb\": \"ASK\"}");
        const long long sentence = probes["sentence"].get<long long>();
        if (sentence < 1 || sentence > static_cast<long long>(story_.sentences.size()))
            fail(line, pointer + "/probes/sentence",
                 "sentence " + std::to_string(sentence) + " does not exist (1 to " +
                     std::to_string(story_.sentences.size()) + ")");
        question.probeSentence = static_cast<int>(sentence - 1);
        question.probeVerb = probes["verb"].get<std::string>();
        const StorySentence& probed = story_.sentences[static_cast<std::size_t>(question.probeSentence)];
        const bool hasVerb = std::any_of(probed.items.begin(), probed.items.end(), [&](const StoryItem& item) {
            return item.kind == StoryItemKind::Verb && item.gloss == question.probeVerb;
        });
        if (!hasVerb)
            fail(line, pointer + "/probes/verb",
                 "sentence " + std::to_string(sentence) + " (\"" + probed.gloss + "\") has no verb " + question.probeVerb);
        if (entry.contains("gloss")) readQuestionGloss(entry["gloss"], i, question);
        story_.questions.push_back(std::move(question));
    }
}

// Issue 24: the question in gloss, read like a sentence of the story (after all of them: the
// characters are placed) as signed text.
void StoryReader::readQuestionGloss(const json& value, std::size_t index, StoryQuestion& question) {
    const std::string pointer = "/questions/" + std::to_string(index) + "/gloss";
    const int line = question.line;
    if (!value.is_string() || value.get<std::string>().empty())
        fail(line, pointer, "expected the question in gloss, e.g. \"TOM ASK WHO\"");
    question.gloss = value.get<std::string>();
    if (question.gloss.find_first_of("\"\\") != std::string::npos)
        fail(line, pointer, "a question in gloss holds no quotes or backslashes");
    // The column of its first character: the value's opening quote after "gloss" in the question.
    TextPosition where{line, 0};
    const auto found = elementOffsets_.find("questions");
    if (found != elementOffsets_.end() && index < found->second.size()) {
        const std::size_t key = source_.text.find("\"gloss\"", found->second[index]);
        const std::size_t quote = key == std::string::npos ? key : source_.text.find('"', key + 7);
        if (quote != std::string::npos) where = positionOf(source_, quote);
    }
    const bool wasSignedText = signedText_;
    signedText_ = true;
    spelledWords_.clear();
    question.sentence = readSentence(question.gloss, where.line, where.column > 0 ? where.column + 1 : 0, pointer);
    question.fingerspelled = spelledWords_;
    signedText_ = wasSignedText;
}

// parseSignedGloss: the characters of `context` (placed), then one sentence of signed text.
StorySentence StoryReader::signedGloss(const std::string& gloss, const Story* context, int line, int column,
                                       const std::string& field, std::vector<std::string>* fingerspelled) {
    if (context) story_.characters = context->characters;
    story_.file = source_.file;
    placed_.assign(story_.characters.size(), true);
    signedText_ = true;
    if (gloss.empty()) fail(line, field, "expected signed text in gloss");
    if (gloss.find_first_of("\"\\") != std::string::npos) fail(line, field, "gloss holds no quotes or backslashes", column);
    StorySentence sentence = readSentence(gloss, line, column, field);
    if (fingerspelled) *fingerspelled = spelledWords_;
    return sentence;
}

}  // namespace signstim::stimuli::story_detail

namespace signstim::stimuli {

using story_detail::StoryReader;

int Story::characterIndex(std::string_view gloss) const {
    for (std::size_t i = 0; i < characters.size(); ++i)
        if (characters[i].gloss == gloss) return static_cast<int>(i);
    return -1;
}

std::string choiceLetter(int index) { return std::string(1, static_cast<char>('A' + index)); }

Story parseStory(const JsonSource& source, const StoryVocabulary& vocabulary) {
    return StoryReader(source, vocabulary).read();
}

StorySentence parseSignedGloss(const std::string& gloss, const Story* context, const StoryVocabulary& vocabulary,
                               const std::string& file, int line, int column, const std::string& field,
                               std::vector<std::string>* fingerspelled) {
    JsonSource source;
    source.file = file;
    return StoryReader(source, vocabulary).signedGloss(gloss, context, line, column, field, fingerspelled);
}

Story loadStory(const std::filesystem::path& file, const StoryVocabulary& vocabulary) {
    return parseStory(readJsonFile(file, limits::kStoryFileBytes), vocabulary);
}

}  // namespace signstim::stimuli
