// Questions and instructions in ASL (issue 24 §1; stimuli/study/question_clips.hpp): a question's
// gloss read by the story's own gloss parser, the study's "session.questions"/"instructions"
// choices, the clips in the plan's listing (one per question, the same for every version), their
// units, and what the jsPsych experiment is given.
#include "common/error.hpp"
#include "stimuli/json_source.hpp"
#include "stimuli/story/story.hpp"
#include "stimuli/study/question_clips.hpp"
#include "stimuli/study/review_page.hpp"
#include "stimuli/study/study.hpp"
#include "stimuli/study/study_exports.hpp"
#include "stimuli/study/study_folder.hpp"
#include "tests/stimuli/review_page_fixture.hpp"
#include "tests/stimuli/story_vocabulary.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using namespace signstim;
using namespace signstim::stimuli;

namespace {

StoryVocabulary vocabulary() { return test::storyVocabulary({"WHO", "WHAT", "HOMEWORK", "HELP", "TEACHER"}); }

// A story whose one question carries `gloss` (written on line 12 of the file).
std::string storyWithQuestion(const std::string& gloss) {
    return "{\n"
           "  \"format\": \"signstim-story\",\n"
           "  \"version\": 1,\n"
           "  \"title\": \"Test\",\n"
           "  \"characters\": [\n"
           "    {\"gloss\": \"JOHN\", \"position\": 0.9},\n"
           "    {\"gloss\": \"MARY\", \"position\": -0.6}\n"
           "  ],\n"
           "  \"sentences\": [\"JOHN IX(0.9) ASK MARY IX(-0.6) HELP\"],\n"
           "  \"questions\": [\n"
           "    {\"question\": \"Whom did John ask?\",\n"
           "     \"gloss\": \"" + gloss + "\", \"choices\": [\"John\", \"Mary\", \"Nobody\"], \"answer\": \"B\",\n"
           "     \"probes\": {\"sentence\": 1, \"verb\": \"ASK\"}}\n"
           "  ]\n}\n";
}

Story parse(const std::string& text) { return parseStory(parseJsonText(text, "story.json"), vocabulary()); }

const std::string kStudy = R"({
  "format": "signstim-study", "version": 1, "title": "T", "seed": 3, "participants": 4,
  "versions": ["point", "vector", "animator", "uninflected"],
  "stories": ["a.json", "b.json", "c.json", "d.json"],
  "render": {"size": "640x480"}
})";

StudyFile parseStudy(const std::string& session) {
    std::string text = kStudy;
    if (!session.empty()) text.insert(text.rfind('}'), ", \"session\": " + session + "\n");
    return parseStudyFile(parseJsonText(text, "study.json"));
}

std::vector<Story> storiesWithGloss(bool withGloss) {
    std::vector<Story> stories(4);
    for (std::size_t i = 0; i < stories.size(); ++i) {
        stories[i].title = "Story " + std::to_string(i + 1);
        stories[i].sentences.push_back({"JOHN IX(0.9) ASK MARY IX(-0.6)", {}, 1});
        for (int q = 0; q < 2; ++q) {
            StoryQuestion question{"Who asked?", {"John", "Mary", "Nobody"}, 0, 0, "ASK", 1};
            if (withGloss) question.gloss = q == 0 ? "WHO ASK MARY" : "JOHN ASK WHO";
            stories[i].questions.push_back(question);
        }
    }
    return stories;
}

}  // namespace

TEST(QuestionGloss, IsReadByTheStorysGlossParserWithTheStorysCharacters) {
    const Story story = parse(storyWithQuestion("JOHN ASK WHO"));
    ASSERT_EQ(story.questions.size(), 1u);
    const StoryQuestion& q = story.questions[0];
    EXPECT_EQ(q.gloss, "JOHN ASK WHO");
    ASSERT_EQ(q.sentence.items.size(), 3u);
    EXPECT_EQ(q.sentence.items[0].kind, StoryItemKind::Name);
    EXPECT_EQ(q.sentence.items[0].character, 0);
    EXPECT_EQ(q.sentence.items[1].kind, StoryItemKind::Verb);
    EXPECT_EQ(q.sentence.items[2].kind, StoryItemKind::Sign);
    EXPECT_EQ(q.sentence.items[2].gloss, "WHO");
    // Its columns are those of the file: the gloss's first character on line 12.
    EXPECT_EQ(q.sentence.line, 12);
    EXPECT_EQ(q.sentence.items[0].column, 16);
    EXPECT_TRUE(q.fingerspelled.empty());
}

TEST(QuestionGloss, AVerbMayLackTheArgumentTheQuestionAsksFor) {
    // "JOHN ASK WHO": no object; "WHO ASK MARY": no subject. In a story sentence both are errors.
    const StoryItem noObject = parse(storyWithQuestion("JOHN ASK WHO")).questions[0].sentence.items[1];  // a copy: the story is a temporary
    EXPECT_EQ(noObject.subject, 0);
    EXPECT_EQ(noObject.object, -1);
    const StoryItem noSubject = parse(storyWithQuestion("WHO ASK MARY")).questions[0].sentence.items[1];
    EXPECT_EQ(noSubject.subject, -1);
    EXPECT_EQ(noSubject.object, 1);
}

TEST(QuestionGloss, AWordTheLexiconLacksIsFingerspelledAndListed) {
    const StoryQuestion q = parse(storyWithQuestion("HOMEWORK COPY FROM WHO")).questions[0];
    ASSERT_EQ(q.sentence.items.size(), 4u);
    EXPECT_EQ(q.sentence.items[2].kind, StoryItemKind::Fingerspelling);
    EXPECT_EQ(q.sentence.items[2].letters, "FROM");
    EXPECT_EQ(q.fingerspelled, std::vector<std::string>{"FROM"});
}

TEST(QuestionGloss, AMistakeNamesTheFileLineColumnAndField) {
    try {
        parse(storyWithQuestion("JOHN IX(0.1) ASK WHO"));  // nobody stands at 0.1
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "story.json");
        EXPECT_EQ(e.line(), 12);
        EXPECT_EQ(e.field(), "/questions/0/gloss");
        EXPECT_NE(std::string(e.what()).find(":12:"), std::string::npos) << e.what();
    }
    try {
        parse(storyWithQuestion(""));
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), "/questions/0/gloss");
    }
}

TEST(SignedText, InstructionsAreParsedWithoutCharactersAndNameTheirField) {
    std::vector<std::string> spelled;
    const StorySentence sentence =
        parseSignedGloss("HELP WHAT STORY", nullptr, vocabulary(), "instructions.json", 7, 0, "/welcome/gloss", &spelled);
    ASSERT_EQ(sentence.items.size(), 3u);
    EXPECT_EQ(spelled, std::vector<std::string>{"STORY"});
    try {
        parseSignedGloss("HELP IX(JOHN)", nullptr, vocabulary(), "instructions.json", 7, 0, "/welcome/gloss", nullptr);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "instructions.json");
        EXPECT_EQ(e.line(), 7);
        EXPECT_EQ(e.field(), "/welcome/gloss");
    }
}

TEST(StudySession, QuestionsAndInstructionsAreShownInAslAndEnglishByDefault) {
    const StudyFile plain = parseStudy("");
    EXPECT_EQ(plain.questionsShown, "both");
    EXPECT_EQ(plain.instructionsShown, "both");
    const StudyFile asl = parseStudy(R"({"questions": "asl", "instructions": {"show": "english",
        "welcome": {"text": "Hello.", "gloss": ["HELP", "WHAT"]}}})");
    EXPECT_EQ(asl.questionsShown, "asl");
    EXPECT_EQ(asl.instructionsShown, "english");
    ASSERT_EQ(asl.instructions.size(), 1u);
    EXPECT_EQ(asl.instructions[0].page, "welcome");
    EXPECT_EQ(asl.instructions[0].gloss, (std::vector<std::string>{"HELP", "WHAT"}));
    for (const std::string bad : {R"({"questions": "ASL"})", R"({"instructions": {"show": "sign"}})",
                                  R"({"instructions": {"intro": {"text": "x", "gloss": "HELP"}}})",
                                  R"({"instructions": {"welcome": {"text": "x"}}})"}) {
        EXPECT_THROW(parseStudy(bad), InputError) << bad;
    }
}

TEST(StudyPlan, SignedQuestionsGetOneClipEachTheSameForEveryVersion) {
    const StudyFile study = parseStudy("");
    const StudyListing listing = planStudy(study, storiesWithGloss(true), nullptr, "test", false);
    const ListedStory& story = listing.stories.at(2);
    ASSERT_EQ(story.questions.size(), 2u);
    EXPECT_EQ(story.questions[1].clip.video, "clips/story-03_question-2.mp4");
    EXPECT_EQ(story.questions[1].clip.poster, "posters/story-03_question-2.png");
    EXPECT_EQ(story.questions[1].gloss, "JOHN ASK WHO");
    // One unit per story of questions, between likert and story in the sorted order.
    const std::vector<StudyUnit> units = studyUnits(listing);
    const auto questions = std::count_if(units.begin(), units.end(),
                                         [](const StudyUnit& u) { return u.kind == StudyUnitKind::Questions; });
    EXPECT_EQ(questions, 4);
    EXPECT_TRUE(std::any_of(units.begin(), units.end(), [](const StudyUnit& u) { return u.id == "questions-03"; }));
}

TEST(StudyPlan, InEnglishTheGlossIsIgnoredAndTheDesignIsUnchanged) {
    const StudyFile english = parseStudy(R"({"questions": "english", "instructions": {"show": "english"}})");
    const StudyListing withGloss = planStudy(english, storiesWithGloss(true), nullptr, "test", false);
    const StudyListing withoutGloss = planStudy(english, storiesWithGloss(false), nullptr, "test", false);
    EXPECT_EQ(withGloss.designHash, withoutGloss.designHash);
    EXPECT_TRUE(withGloss.stories[0].questions[0].clip.video.empty());
    EXPECT_EQ(studyUnits(withGloss).size(), 4u);  // the stories only
    // Signed, the question's gloss is part of the design.
    const StudyListing signedListing = planStudy(parseStudy(""), storiesWithGloss(true), nullptr, "test", false);
    EXPECT_NE(signedListing.designHash, withGloss.designHash);
}

TEST(StudyListing, SignedQuestionsAndInstructionsSurviveTheJsonRoundTrip) {
    signstim::stimuli::testing::ReviewFixtureShape shape{.stories = 4, .participants = 4, .likertSentences = 4};
    shape.signedQuestions = true;
    StudyListing listing = signstim::stimuli::testing::reviewFixtureListing(shape);
    const StudyListing back = listingFromJson(listingToJson(listing), "plan.json");
    EXPECT_EQ(listingToJson(back), listingToJson(listing));
    EXPECT_EQ(back.questionsShown, "both");
    ASSERT_EQ(back.instructions.size(), 2u);
    EXPECT_EQ(back.instructions[1].clip.video, "clips/instructions-part2.mp4");
    EXPECT_EQ(back.stories[1].questions[2].clip.video, listing.stories[1].questions[2].clip.video);
    // A listing written before issue 24 reads as English only.
    nlohmann::json old = listingToJson(listing);
    for (const char* key : {"questionsShown", "instructionsShown", "instructions"}) old.erase(key);
    for (auto& story : old["stories"])
        for (auto& question : story["questions"]) {
            question.erase("gloss");
            question.erase("clip");
        }
    const StudyListing older = listingFromJson(old, "plan.json");
    EXPECT_EQ(older.questionsShown, "english");
    EXPECT_TRUE(older.instructions.empty());
    EXPECT_TRUE(studyUnits(older).size() < studyUnits(listing).size());
}

TEST(ExperimentTimeline, ASignedQuestionCarriesItsClipForEveryVersion) {
    signstim::stimuli::testing::ReviewFixtureShape shape{.stories = 4, .participants = 4, .likertSentences = 4};
    shape.signedQuestions = true;
    const StudyListing listing = signstim::stimuli::testing::reviewFixtureListing(shape);
    const nlohmann::json vars = nlohmann::json::parse(jspsychTimelineVariables(listing, 0));
    for (const nlohmann::json& trial : vars["phase1"]) {
        const std::string story = trial["story"].get<std::string>();
        for (std::size_t q = 0; q < trial["questions"].size(); ++q)
            EXPECT_EQ(trial["questions"][q]["video"][0], "clips/" + story + "_question-" + std::to_string(q + 1) + ".mp4")
                << "the clip is the story's, whatever the version shown";
    }
    const StudyListing english = signstim::stimuli::testing::reviewFixtureListing({.stories = 4, .participants = 4, .likertSentences = 4});
    const nlohmann::json plain = nlohmann::json::parse(jspsychTimelineVariables(english, 0));
    EXPECT_FALSE(plain["phase1"][0]["questions"][0].contains("video"));
}

TEST(ReviewPage, ASignedQuestionsClipComesBeforeItsTextAndTheInstructionsAreShown) {
    signstim::stimuli::testing::ReviewFixtureShape shape{.stories = 4, .participants = 4, .likertSentences = 4};
    shape.signedQuestions = true;
    const StudyListing listing = signstim::stimuli::testing::reviewFixtureListing(shape);
    const std::string html = reviewPageHtml(listing);
    const ListedQuestion& question = listing.stories[1].questions[2];
    const std::size_t clip = html.find("src=\"" + question.clip.video + "\"");
    ASSERT_NE(clip, std::string::npos);
    const std::size_t text = html.find(escapeHtml(question.text), clip);
    ASSERT_NE(text, std::string::npos);
    EXPECT_LT(html.find("data-expected-duration", clip), text) << "the clip carries its duration for the checker";
    EXPECT_NE(html.find("id=\"instructions\""), std::string::npos);
    EXPECT_NE(html.find("src=\"clips/instructions-welcome.mp4\""), std::string::npos);
    // In English, no question clip and no instruction clip.
    const std::string english =
        reviewPageHtml(signstim::stimuli::testing::reviewFixtureListing({.stories = 4, .participants = 4, .likertSentences = 4}));
    EXPECT_EQ(english.find("_question-"), std::string::npos);
    EXPECT_EQ(english.find("instructions-welcome"), std::string::npos);
}
