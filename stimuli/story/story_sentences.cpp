// Sentences of gloss in a story (docs/stories.md): each word a sign, a character's name, a
// pointing IX(...) or a verb, and each verb's subject and object by the rule of stimuli/story/story.hpp.
// Part of the story reader (story_reader.hpp; the file's other fields: story.cpp).
#include "common/input_limits.hpp"
#include "stimuli/story/story_markers.hpp"
#include "stimuli/story/story_reader.hpp"

#include <cmath>

namespace signstim::stimuli::story_detail {

void StoryReader::readSentences(const json& list) {
    if (!list.is_array() || list.empty())
        fail(lineOfKey("", "sentences"), "/sentences", "expected a list of sentences in gloss, e.g. \"JOHN IX(0.9) ASK MARY IX(-0.6)\"");
    // Refused before any sentence is checked (each costs a synthesis in four versions).
    if (list.size() > limits::kStorySentences)
        fail(lineOfKey("", "sentences"), "/sentences",
             std::to_string(list.size()) + " sentences; a story has at most " + std::to_string(limits::kStorySentences) +
                 " (docs/errors.md, Limits): split it into several stories");
    placed_.assign(story_.characters.size(), false);
    for (std::size_t i = 0; i < list.size(); ++i) {
        const TextPosition where = elementPosition("sentences", i);
        const std::string field = "/sentences/" + std::to_string(i);
        if (!list[i].is_string()) fail(where.line, field, "a sentence is one string of gloss");
        const std::string gloss = list[i].get<std::string>();
        if (gloss.find_first_of("\"\\") != std::string::npos)
            fail(where.line, field, "a sentence of gloss holds no quotes or backslashes", where.column);
        // Column of the sentence's first character: just after its opening quote.
        story_.sentences.push_back(readSentence(gloss, where.line, where.column + 1, field));
    }
}

StorySentence StoryReader::readSentence(const std::string& gloss, int line, int firstColumn, const std::string& field) {
    StorySentence sentence;
    sentence.gloss = gloss;
    sentence.line = line;
    const GlossParse parsed = parseGloss(gloss);
    // firstColumn 0: where the gloss stands is unknown (signed text given outside a JSON file's text).
    auto column = [&](int withinSentence) { return firstColumn > 0 ? firstColumn + withinSentence - 1 : 0; };
    if (parsed.error) fail(line, field, parsed.error->message, column(parsed.error->column));
    if (parsed.items.size() > limits::kSentenceSigns)
        fail(line, field,
             std::to_string(parsed.items.size()) + " signs in one sentence; at most " +
                 std::to_string(limits::kSentenceSigns) + " (docs/errors.md, Limits): split the sentence",
             column(parsed.items[limits::kSentenceSigns].column));

    std::vector<std::size_t> verbItems;
    for (const GlossItem& written : parsed.items) {
        StoryItem item;
        item.line = line;
        item.column = column(written.column);
        switch (written.kind) {
        case GlossItemKind::Hold:
            item.kind = StoryItemKind::Hold;
            item.holdSeconds = written.holdSeconds;
            break;
        case GlossItemKind::Fingerspelling:
            item.kind = StoryItemKind::Fingerspelling;
            item.letters = written.word;
            requireSpellable(written.word, line, item.column + 3, field);
            break;
        case GlossItemKind::Pointing: {
            item.kind = StoryItemKind::Pointing;
            const GlossArgument& place = written.arguments.front();
            const bool afterName = !sentence.items.empty() && sentence.items.back().kind == StoryItemKind::Name;
            if (place.position) {
                item.position = *place.position;
                item.character = characterAt(item.position);
                if (afterName) {
                    const StoryCharacter& named = story_.characters[static_cast<std::size_t>(sentence.items.back().character)];
                    if (item.character != sentence.items.back().character)
                        fail(line, field,
                             named.gloss + " stands at " + json(named.position).dump() + " (see \"characters\"), but IX(" +
                                 json(item.position).dump() + ") points elsewhere",
                             column(place.column));
                } else if (item.character < 0) {
                    fail(line, field,
                         "no character stands at " + json(item.position).dump() + " (" + characterList() +
                             "); point at a character, or name one before IX to introduce it",
                         column(place.column));
                }
            } else {
                item.character = story_.characterIndex(place.name);
                if (item.character < 0)
                    fail(line, field, "IX(" + place.name + "): " + place.name + " is not a character of this story (" +
                                          characterList() + ")",
                         column(place.column));
                item.position = story_.characters[static_cast<std::size_t>(item.character)].position;
                if (afterName && sentence.items.back().character != item.character)
                    fail(line, field, "IX(" + place.name + ") right after " + sentence.items.back().gloss +
                                          " points at another character",
                         column(place.column));
            }
            if (afterName) {
                item.placesCharacter = !placed_[static_cast<std::size_t>(item.character)];
                placed_[static_cast<std::size_t>(item.character)] = true;
            } else {
                requirePlaced(item.character, line, column(place.column), field);
            }
            break;
        }
        case GlossItemKind::Word: {
            const std::string& word = written.word;
            if (const VerbDefinition* verb = vocabulary_.verbs->find(word)) {
                item.kind = StoryItemKind::Verb;
                item.gloss = verb->name;
                verbItems.push_back(sentence.items.size());
                if (written.hasArgumentList) readVerbArguments(*verb, written, item, line, column, field);
            } else if (const int character = story_.characterIndex(word); character >= 0) {
                if (written.hasArgumentList)
                    fail(line, field, word + " is a character: write " + word + " IX(" +
                                          json(story_.characters[static_cast<std::size_t>(character)].position).dump() +
                                          ") to point at them",
                         item.column);
                item.kind = StoryItemKind::Name;
                item.gloss = word;
                item.character = character;
                const StoryCharacter& c = story_.characters[static_cast<std::size_t>(character)];
                if (c.nameSign.empty()) item.letters = c.spelled;
            } else if (signedText_ && !isSign(word) && !written.hasArgumentList && spellable(word)) {
                // Signed text (parseSignedGloss): a word the lexicon lacks is fingerspelled.
                item.kind = StoryItemKind::Fingerspelling;
                item.letters = word;
                spelledWords_.push_back(word);
            } else {
                requireSign(word, line, item.column, field);
                if (written.hasArgumentList)
                    fail(line, field, word + " is a plain sign and takes no arguments", item.column);
                item.kind = StoryItemKind::Sign;
                item.gloss = word;
            }
            break;
        }
        }
        sentence.items.push_back(std::move(item));
    }
    for (std::size_t index : verbItems) resolveVerb(sentence, index, field);
    sentence.markers = resolveMarkers(parsed.markers, story_, line, [&](int withinSentence, const std::string& message) {
        fail(line, field, message, column(withinSentence));
    });
    return sentence;
}

void StoryReader::readVerbArguments(const VerbDefinition& verb, const GlossItem& written, StoryItem& item, int line,
                                    const std::function<int(int)>& column, const std::string& field) {
    const std::size_t wanted = verb.objectOnly() ? 1 : 2;
    if (written.arguments.size() != wanted)
        fail(line, field,
             verb.objectOnly() ? verb.name + " inflects for its object only: " + verb.name + "(MARY)"
                               : verb.name + " takes a subject and an object: " + verb.name + "(JOHN,MARY)",
             item.column);
    std::vector<int> characters;
    for (const GlossArgument& argument : written.arguments) {
        int character = -1;
        if (argument.position) {
            if (!(*argument.position >= -1.0 && *argument.position <= 1.0))
                fail(line, field, "arc position outside [-1, 1]", column(argument.column));
            character = characterAt(*argument.position);
            if (character < 0)
                fail(line, field, "no character stands at " + json(*argument.position).dump() + " (" + characterList() + ")",
                     column(argument.column));
        } else {
            character = story_.characterIndex(argument.name);
            if (character < 0)
                fail(line, field, argument.name + " is not a character of this story (" + characterList() + ")",
                     column(argument.column));
        }
        characters.push_back(character);
    }
    item.object = characters.back();
    if (!verb.objectOnly()) item.subject = characters.front();
}

void StoryReader::resolveVerb(StorySentence& sentence, std::size_t index, const std::string& field) {
    StoryItem& verbItem = sentence.items[index];
    const VerbDefinition& verb = *vocabulary_.verbs->find(verbItem.gloss);
    const bool explicitArguments = verbItem.object >= 0;
    if (!explicitArguments) {
        // The rule (docs/stories.md): the object is the first character named or pointed
        // to after the verb; the subject the nearest one before it. A name followed by its
        // own IX counts once.
        for (std::size_t i = index + 1; i < sentence.items.size() && verbItem.object < 0; ++i)
            if (isReferent(sentence.items[i])) verbItem.object = sentence.items[i].character;
        if (!verb.objectOnly())
            for (std::size_t i = index; i-- > 0 && verbItem.subject < 0;)
                if (isReferent(sentence.items[i])) verbItem.subject = sentence.items[i].character;
        // Signed text may ask for an argument ("WHO ASK ANN"): signed uninflected (issue 24).
        if (signedText_) return;
        if (verbItem.object < 0)
            fail(verbItem.line, field,
                 verb.name + " needs its object: name or point to a character after the verb (" + verb.name +
                     " MARY IX(-0.6)), or write " + verb.name + (verb.objectOnly() ? "(MARY)" : "(JOHN,MARY)"),
                 verbItem.column);
        if (!verb.objectOnly() && verbItem.subject < 0)
            fail(verbItem.line, field,
                 verb.name + " needs its subject: name or point to a character before the verb (JOHN IX(0.9) " +
                     verb.name + " ...), or write " + verb.name + "(JOHN,MARY)",
                 verbItem.column);
    }
    if (verbItem.subject >= 0 && verbItem.subject == verbItem.object)
        fail(verbItem.line, field,
             verb.name + ": subject and object are both " +
                 story_.characters[static_cast<std::size_t>(verbItem.object)].gloss + "; write " + verb.name +
                 "(SUBJECT,OBJECT) if the rule read the sentence wrongly",
             verbItem.column);
    requirePlaced(verbItem.object, verbItem.line, verbItem.column, field);
    if (verbItem.subject >= 0) requirePlaced(verbItem.subject, verbItem.line, verbItem.column, field);
}

void StoryReader::requirePlaced(int character, int line, int column, const std::string& field) const {
    if (placed_[static_cast<std::size_t>(character)]) return;
    const StoryCharacter& c = story_.characters[static_cast<std::size_t>(character)];
    fail(line, field,
         c.gloss + " is used before being placed: introduce " + c.gloss + " first with " + c.gloss + " IX(" +
             json(c.position).dump() + ")",
         column);
}

int StoryReader::characterAt(double position) const {
    // Within half the minimum separation: IX(0.88) means the character at 0.9.
    for (std::size_t i = 0; i < story_.characters.size(); ++i)
        if (std::abs(story_.characters[i].position - position) < kMinimumCharacterSeparation / 2)
            return static_cast<int>(i);
    return -1;
}

std::string StoryReader::characterList() const {
    std::string list;
    for (const StoryCharacter& c : story_.characters)
        list += (list.empty() ? "" : ", ") + c.gloss + " at " + json(c.position).dump();
    return list;
}
}  // namespace signstim::stimuli::story_detail
