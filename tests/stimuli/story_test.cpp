// Gloss sentences and story files (SPEC §4.1, docs/stories.md): what a sentence means, and
// every kind of mistake reported at its file, line and column.
#include "stimuli/story/gloss.hpp"
#include "stimuli/story/lexicon.hpp"
#include "stimuli/story/story.hpp"
#include "stimuli/verbs/verbs.hpp"
#include "tests/stimuli/story_vocabulary.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <set>
#include <string>

namespace signstim::stimuli {
namespace {

using test::sceneVerbs;
using test::storyVocabulary;

StoryVocabulary vocabulary() {
    StoryVocabulary v = storyVocabulary({"STUDENT", "TEACHER", "HOMEWORK", "YESTERDAY", "BOOK", "FRIEND", "FINISH"});
    v.canFingerspell = [](char c) { return c != 'Q'; };  // a library without Q, to test the check
    return v;
}

// A story file with `sentences` (one per line, each line as written) and one question.
std::string storyText(const std::string& sentences, const std::string& question = "") {
    return "{\n"
           "  \"format\": \"signstim-story\",\n"
           "  \"version\": 1,\n"
           "  \"title\": \"Test\",\n"
           "  \"characters\": [\n"
           "    {\"gloss\": \"JOHN\", \"position\": 0.9},\n"
           "    {\"gloss\": \"MARY\", \"position\": -0.6}\n"
           "  ],\n"
           "  \"sentences\": [\n" +
           sentences +
           "\n  ],\n"
           "  \"questions\": [\n" +
           (question.empty() ? std::string("    {\"question\": \"Who asked?\", \"choices\": [\"John\", \"Mary\", \"Nobody\"], "
                                           "\"answer\": \"A\", \"probes\": {\"sentence\": 1, \"verb\": \"ASK\"}}")
                             : question) +
           "\n  ]\n}\n";
}

Story parse(const std::string& text) { return parseStory(parseJsonText(text, "story.json"), vocabulary()); }

// The InputError thrown for `text`, which must fail.
InputError errorOf(const std::string& text) {
    try {
        parse(text);
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return InputError("none");
}

TEST(Gloss, ItemsKeepTheirColumns) {
    const GlossParse p = parseGloss("JOHN IX(0.9) ASK(JOHN, MARY) fs-BOB HOLD(0.5)");
    ASSERT_FALSE(p.error) << p.error->message;
    ASSERT_EQ(p.items.size(), 5u);
    EXPECT_EQ(p.items[0].column, 1);
    EXPECT_EQ(p.items[1].kind, GlossItemKind::Pointing);
    EXPECT_EQ(p.items[1].column, 6);
    EXPECT_DOUBLE_EQ(*p.items[1].arguments[0].position, 0.9);
    EXPECT_EQ(p.items[2].word, "ASK");
    ASSERT_EQ(p.items[2].arguments.size(), 2u);
    EXPECT_EQ(p.items[2].arguments[1].name, "MARY");
    EXPECT_EQ(p.items[2].arguments[1].column, 24);
    EXPECT_EQ(p.items[3].kind, GlossItemKind::Fingerspelling);
    EXPECT_EQ(p.items[3].word, "BOB");
    EXPECT_DOUBLE_EQ(*p.items[4].holdSeconds, 0.5);
}

TEST(Gloss, MistakesPointAtTheirColumn) {
    struct Case {
        const char* sentence;
        int column;
        const char* says;
    };
    for (const Case& c : {Case{"JOHN IX(1.2)", 9, "outside [-1, 1]"}, Case{"JOHN IX", 6, "IX needs a place"},
                          Case{"JOHN IX(abc", 12, "missing ')'"}, Case{"JOHN ask", 6, "capitals"},
                          Case{"fs-JO3", 6, "cannot be fingerspelled"}, Case{"HOLD(20)", 6, "0.05 to 10 s"},
                          Case{"IX(0.x)", 4, "not a number"}, Case{"", 1, "empty sentence"}}) {
        const GlossParse p = parseGloss(c.sentence);
        ASSERT_TRUE(p.error) << c.sentence;
        EXPECT_EQ(p.error->column, c.column) << c.sentence << ": " << p.error->message;
        EXPECT_NE(p.error->message.find(c.says), std::string::npos) << c.sentence << ": " << p.error->message;
    }
}

TEST(Gloss, ClosestNamesSuggestNearMisses) {
    const std::vector<std::string> names{"STUDENT", "TEACHER", "HOMEWORK", "STUDY"};
    EXPECT_EQ(closestNames("STUDNET", names).front(), "STUDENT");
    EXPECT_TRUE(closestNames("ELEPHANT", names).empty());
}

TEST(Story, ThePapersSentenceGivesSubjectAndObjectFromTheReferentsAroundTheVerb) {
    const Story story = parse(storyText("    \"JOHN IX(0.9) ASK MARY IX(-0.6)\""));
    ASSERT_EQ(story.sentences.size(), 1u);
    const auto& items = story.sentences[0].items;
    ASSERT_EQ(items.size(), 5u);
    EXPECT_EQ(items[0].kind, StoryItemKind::Name);
    EXPECT_EQ(items[0].letters, "JOHN");  // fingerspelled: no name sign
    EXPECT_TRUE(items[1].placesCharacter);
    EXPECT_EQ(items[2].kind, StoryItemKind::Verb);
    EXPECT_EQ(items[2].subject, story.characterIndex("JOHN"));
    EXPECT_EQ(items[2].object, story.characterIndex("MARY"));
    EXPECT_EQ(items[2].line, 10);
    EXPECT_EQ(items[2].column, 19);  // 4 spaces, the quote, then "JOHN IX(0.9) " is 13 characters
}

TEST(Story, ObjectOnlyVerbsTakeTheFirstReferentAfterThem) {
    const Story story = parse(storyText("    \"JOHN IX(0.9) MARY IX(-0.6) HOLD\",\n"
                                        "    \"IX(JOHN) SCOLD IX(MARY)\",\n    \"JOHN ASK MARY\"",
                                        "    {\"question\": \"Who asked?\", \"choices\": [\"a\", \"b\", \"c\"], "
                                        "\"answer\": \"B\", \"probes\": {\"sentence\": 3, \"verb\": \"ASK\"}}"));
    const StoryItem& scold = story.sentences[1].items[1];
    EXPECT_EQ(scold.gloss, "SCOLD");
    EXPECT_EQ(scold.subject, -1);
    EXPECT_EQ(scold.object, story.characterIndex("MARY"));
}

TEST(Story, ExplicitArgumentsOverrideTheRule) {
    const Story story = parse(storyText("    \"JOHN IX(0.9) MARY IX(-0.6) ASK(MARY,JOHN)\""));
    const StoryItem& ask = story.sentences[0].items[4];
    EXPECT_EQ(ask.subject, story.characterIndex("MARY"));
    EXPECT_EQ(ask.object, story.characterIndex("JOHN"));
}

TEST(Story, EachMistakeNamesFileLineColumnAndWhatToChange) {
    struct Case {
        std::string text;
        int line;
        int column;
        const char* says;
    };
    const std::string q = "    {\"question\": \"Q\", \"choices\": [\"a\", \"b\", \"c\"], \"answer\": \"A\", "
                          "\"probes\": {\"sentence\": 1, \"verb\": \"ASK\"}}";
    const Case cases[] = {
        {storyText("    \"JOHN IX(0.9) ASK MARY IX(-0.6)\",\n    \"STUDNET JOHN\""), 11, 6, "closest known: STUDENT"},
        {storyText("    \"JOHN IX(0.9) ASK MARY IX(-1.5)\""), 10, 31, "outside [-1, 1]"},
        {storyText("    \"JOHN IX(0.9) ASK HOMEWORK\""), 10, 19, "needs its object"},
        {storyText("    \"HOMEWORK ASK MARY IX(-0.6)\""), 10, 15, "needs its subject"},
        {storyText("    \"JOHN IX(0.9) ASK MARY\""), 10, 19, "MARY is used before being placed"},
        {storyText("    \"JOHN IX(0.5) ASK MARY IX(-0.6)\""), 10, 14, "JOHN stands at 0.9"},
        {storyText("    \"JOHN IX(0.9) ASK MARY IX(-0.6) fs-QUIZ\""), 10, 40, "Q has no handshape"},
        {storyText("    \"JOHN IX(0.9) ASK MARY IX(-0.6)\"",
                   "    {\"question\": \"Q\", \"choices\": [\"a\", \"b\", \"c\"], \"answer\": \"D\", "
                   "\"probes\": {\"sentence\": 1, \"verb\": \"ASK\"}}"),
         13, 0, "not one of the choices"},
        {storyText("    \"JOHN IX(0.9) ASK MARY IX(-0.6)\"",
                   "    {\"question\": \"Q\", \"choices\": [\"a\", \"b\", \"c\"], \"answer\": \"A\", "
                   "\"probes\": {\"sentence\": 1, \"verb\": \"GIVE\"}}"),
         13, 0, "has no verb GIVE"},
        {storyText("    \"JOHN IX(0.9) ASK(JOHN,JOHN)\""), 10, 19, "both JOHN"},
    };
    for (const Case& c : cases) {
        const InputError e = errorOf(c.text);
        EXPECT_EQ(e.file(), "story.json");
        EXPECT_EQ(e.line(), c.line) << e.what();
        EXPECT_EQ(e.column(), c.column) << e.what();
        EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
    }
}

TEST(Story, CharactersMustStandApartAndNotShadowSigns) {
    auto withCharacters = [](const std::string& second) {
        return "{\"format\": \"signstim-story\", \"version\": 1, \"title\": \"T\",\n"
               "\"characters\": [{\"gloss\": \"JOHN\", \"position\": 0.9},\n" +
               second + "],\n\"sentences\": [\"JOHN IX(0.9)\"], \"questions\": []}";
    };
    EXPECT_NE(std::string(errorOf(withCharacters("{\"gloss\": \"BOB\", \"position\": 0.8}")).what())
                  .find("too close"),
              std::string::npos);
    EXPECT_EQ(errorOf(withCharacters("{\"gloss\": \"BOB\", \"position\": 0.8}")).line(), 3);
    EXPECT_NE(std::string(errorOf(withCharacters("{\"gloss\": \"ASK\", \"position\": 0}")).what())
                  .find("is a verb"),
              std::string::npos);
    EXPECT_NE(std::string(errorOf(withCharacters("{\"gloss\": \"BOB\", \"position\": 1.1}")).what())
                  .find("outside [-1, 1]"),
              std::string::npos);
}

TEST(Story, ACharacterNamedBySignIsSignedWithIt) {
    std::string text = storyText("    \"JOHN IX(0.9) ASK TEACHER IX(-0.6)\"");
    text.replace(text.find("\"MARY\""), 6, "\"TEACHER\"");
    const Story story = parse(text);
    EXPECT_EQ(story.characters[1].nameSign, "TEACHER");
    EXPECT_EQ(story.sentences[0].items[3].kind, StoryItemKind::Name);
    EXPECT_EQ(story.sentences[0].items[2].object, 1);
}

TEST(Story, WrongFormatOrVersionIsRefused) {
    std::string text = storyText("    \"JOHN IX(0.9) ASK MARY IX(-0.6)\"");
    std::string wrongVersion = text;
    wrongVersion.replace(wrongVersion.find("\"version\": 1"), 12, "\"version\": 2");
    EXPECT_EQ(errorOf(wrongVersion).line(), 3);
    std::string unknownField = text;
    unknownField.replace(unknownField.find("\"title\""), 7, "\"titel\"");
    EXPECT_NE(std::string(errorOf(unknownField).what()).find("unknown field 'titel'"), std::string::npos);
}

}  // namespace
}  // namespace signstim::stimuli

namespace signstim::stimuli {
namespace {

// The default stories (scenes/stories/, issue 10 §4): 12 stories, 3-4 characters each at
// distinct arc positions, the eight verbs each in at least 3 stories, 4 questions per story
// each probing a verb of the story, every sign in the lexicon (scenes/lexicon/).
TEST(DefaultStories, TwelveStoriesUseEveryVerbInAtLeastThreeWithFourQuestionsEachAndOnlyLexiconSigns) {
    const hand::HandModel model = hand::buildHandModel();
    const HandshapeLibrary shapes = loadHandshapes(std::string(SIGNSTIM_SOURCE_DIR) + "/scenes/handshapes.json", model);
    const Lexicon lexicon = loadLexicon(std::string(SIGNSTIM_SOURCE_DIR) + "/scenes/lexicon", shapes, model);
    StoryVocabulary any;
    any.verbs = &sceneVerbs();
    any.signs = lexicon.glosses();
    any.canFingerspell = [&](char letter) {
        return shapes.find(letter == 'J' ? "I" : letter == 'Z' ? "1" : std::string(1, letter)) != nullptr;
    };
    std::map<std::string, std::set<int>> storiesWithVerb;
    std::set<std::string> signs;
    for (int n = 1; n <= 12; ++n) {
        char name[64];
        std::snprintf(name, sizeof name, "%s/scenes/stories/story-%02d.json", SIGNSTIM_SOURCE_DIR, n);
        const Story story = loadStory(name, any);
        EXPECT_GE(story.characters.size(), 3u) << name;
        EXPECT_LE(story.characters.size(), 4u) << name;
        EXPECT_EQ(story.questions.size(), 4u) << name;
        for (const StorySentence& sentence : story.sentences)
            for (const StoryItem& item : sentence.items) {
                if (item.kind == StoryItemKind::Verb) storiesWithVerb[item.gloss].insert(n);
                if (item.kind == StoryItemKind::Sign) signs.insert(item.gloss);
            }
        for (const StoryCharacter& c : story.characters)
            if (!c.nameSign.empty()) signs.insert(c.nameSign);
    }
    EXPECT_EQ(storiesWithVerb.size(), sceneVerbs().verbs.size());
    for (const VerbDefinition& verb : sceneVerbs().verbs)
        EXPECT_GE(storiesWithVerb[verb.name].size(), 3u) << verb.name;
    EXPECT_GE(signs.size(), 60u);
}

}  // namespace
}  // namespace signstim::stimuli

#include "stimuli/story/timeline_builder.hpp"
#include "stimuli/verbs/verb_models.hpp"

namespace signstim::stimuli {
namespace {

// What `signstim story FILE --check` asks of each default story: its timeline builds in all
// four versions (every sign in the lexicon, every letter with a handshape, a trained model
// and an animator file for every verb instance), with the verb slots as long in each.
TEST(DefaultStories, EveryStoryBuildsInAllFourVersionsWithEqualSlots) {
    const std::string scenes = std::string(SIGNSTIM_SOURCE_DIR) + "/scenes";
    const hand::HandModel model = hand::buildHandModel();
    const HandshapeLibrary shapes = loadHandshapes(scenes + "/handshapes.json", model);
    const Lexicon lexicon = loadLexicon(scenes + "/lexicon", shapes, model);
    const TrainedVerbModels models = loadVerbModels(scenes + "/models/verb_models.json", sceneVerbs());
    StoryVocabulary vocabulary;
    vocabulary.verbs = &sceneVerbs();
    vocabulary.signs = lexicon.glosses();
    TimelineSources sources;
    sources.lexicon = &lexicon;
    sources.shapes = &shapes;
    sources.verbs = [&](const std::string& verb, VerbVersion version, double subject, double object, int, int) {
        return synthesizeVerb(VerbSources{&sceneVerbs(), &models, scenes + "/animator", &shapes}, verb, version, subject, object);
    };
    for (int n = 1; n <= 12; ++n) {
        char name[64];
        std::snprintf(name, sizeof name, "/stories/story-%02d.json", n);
        const Story story = loadStory(scenes + name, vocabulary);
        std::vector<double> durations;
        for (VerbVersion v : {VerbVersion::Point, VerbVersion::Vector, VerbVersion::Animator, VerbVersion::Uninflected})
            durations.push_back(buildTimeline(story, v, sources).durationSeconds);
        for (double d : durations) EXPECT_EQ(d, durations.front()) << name;
        EXPECT_GT(durations.front(), 10.0) << name;
        EXPECT_LT(durations.front(), 60.0) << name;
    }
}

}  // namespace
}  // namespace signstim::stimuli
