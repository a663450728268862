// The study's documents for other tools and for paper (stimuli/study/study_exports.hpp): the
// jsPsych JSON and the overview CSV carry the schedule of the listing; the printable sheets
// escape their text and the response sheet never shows the mapping. The listing is the small
// synthetic fixture of study_exports_fixture.hpp, not a rendered study.
#include "tests/stimuli/study_exports_fixture.hpp"

#include "stimuli/study/study_exports.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace signstim::stimuli {
namespace {

using namespace exports_test;

// ---- jsPsych JSON ---------------------------------------------------------------------------

TEST(StudyExports, JsPsychJsonParsesAndHasTheScheduledOrder) {
    const StudyListing listing = fixture();
    for (std::size_t p = 0; p < listing.participants.size(); ++p) {
        const ListedParticipant& participant = listing.participants[p];
        const std::string text = jspsychTimelineVariables(listing, p);
        EXPECT_TRUE(text.starts_with("{\n  \"")) << "2-space indentation";
        nlohmann::json json;
        ASSERT_NO_THROW(json = nlohmann::json::parse(text));
        EXPECT_EQ(json["participant"], participant.id);
        EXPECT_EQ(json["group"], participant.group + 1);
        EXPECT_EQ(json["study"]["seed"], "18446744073709551557");
        EXPECT_EQ(json["likert"]["minimum"], 1);
        EXPECT_EQ(json["likert"]["maximum"], 10);

        ASSERT_EQ(json["phase1"].size(), participant.phase1.size());
        for (std::size_t i = 0; i < participant.phase1.size(); ++i) {
            const nlohmann::json& element = json["phase1"][i];
            const ListedPhase1Trial& trial = participant.phase1[i];
            const ListedStory& story = listing.stories[trial.story];
            EXPECT_EQ(element["trial"], i + 1);
            EXPECT_EQ(element["story"], story.id);
            EXPECT_EQ(element["title"], story.title);
            EXPECT_EQ(element["version"], listing.versions[trial.version]);
            ASSERT_TRUE(element["video"].is_array()) << "jsPsych's video stimulus is an array";
            EXPECT_EQ(element["video"], nlohmann::json::array({story.clips[trial.version].video}));
            EXPECT_EQ(element["poster"], story.clips[trial.version].poster);
            EXPECT_TRUE(element["duration_s"].is_number());
            ASSERT_EQ(element["questions"].size(), story.questions.size());
            for (std::size_t q = 0; q < story.questions.size(); ++q) {
                const nlohmann::json& question = element["questions"][q];
                const ListedQuestion& listed = story.questions[q];
                EXPECT_EQ(question["name"], "q" + std::to_string(q + 1));
                EXPECT_EQ(question["required"], true);
                EXPECT_EQ(question["options"].size(), listed.choices.size());
                EXPECT_EQ(question["correct"], listed.answer);
                EXPECT_EQ(question["correct_letter"], std::string(1, static_cast<char>('A' + listed.answer)));
                EXPECT_EQ(question["correct_text"], listed.choices[static_cast<std::size_t>(listed.answer)]);
            }
        }
        ASSERT_EQ(json["phase2"].size(), participant.phase2.size());
        for (std::size_t i = 0; i < participant.phase2.size(); ++i) {
            const nlohmann::json& element = json["phase2"][i];
            const ListedSentence& sentence = listing.sentences[participant.phase2[i].sentence];
            EXPECT_EQ(element["trial"], i + 1);
            EXPECT_EQ(element["sentence"], sentence.id);
            EXPECT_EQ(element["gloss"], sentence.gloss);
            EXPECT_EQ(element["video"], nlohmann::json::array({sentence.clip.video}));
            EXPECT_EQ(element["panel_code"], sentence.panelCode);
            for (std::size_t k = 0; k < sentence.panelVersion.size(); ++k)
                EXPECT_EQ(element["panels"][std::string(1, static_cast<char>('A' + k))],
                          listing.versions[sentence.panelVersion[k]]);
        }
    }
}

TEST(StudyExports, JsPsychQuestionsAreEscapedForThePluginAndScoredOnPlainText) {
    const StudyListing listing = fixture();
    const nlohmann::json json = nlohmann::json::parse(jspsychTimelineVariables(listing, 0));
    bool sawHtmlQuestion = false;
    for (const nlohmann::json& element : json["phase1"]) {
        if (element["story"] != "story-02") continue;
        sawHtmlQuestion = true;
        EXPECT_EQ(element["title"], htmlTitle) << "plain fields stay plain";
        const nlohmann::json& question = element["questions"][0];
        EXPECT_EQ(question["prompt"], "Is 2 &lt; 3 &amp; is &quot;yes&quot; right?");
        EXPECT_EQ(question["options"][2], "Zo\u00eb asked &quot;nobody&quot;");
    }
    EXPECT_TRUE(sawHtmlQuestion);
    for (const nlohmann::json& element : json["phase1"])
        for (const nlohmann::json& question : element["questions"])
            if (question["correct"] == 2) {
                EXPECT_EQ(question["correct_text"], "Zo\u00eb asked \"nobody\"");
            }
}

TEST(StudyExports, JsPsychDurationsAreTheCsvMilliseconds) {
    const StudyListing listing = fixture();
    const nlohmann::json json = nlohmann::json::parse(jspsychTimelineVariables(listing, 0));
    const std::vector<Row> rows = conditionRows(listing, 0);
    for (std::size_t i = 0; i < json["phase1"].size(); ++i)
        EXPECT_EQ(json["phase1"][i]["duration_s"].get<double>(), std::stod(rows[i].at("duration_s")));
}

// ---- overview -------------------------------------------------------------------------------

TEST(StudyExports, OverviewCoversEveryStoryAndGroup) {
    StudyListing listing = fixture();
    // Only groups 1 and 2 have participants: the overview is the design, so it still has 4 groups.
    listing.participants.resize(2);
    const Records records = parseCsv(overviewCsv(listing));
    EXPECT_EQ(records[0], (std::vector<std::string>{"story", "title", "group_1", "group_2", "group_3", "group_4"}));
    ASSERT_EQ(records.size(), 1 + listing.stories.size());
    std::set<std::pair<std::string, std::string>> cells;
    for (std::size_t s = 0; s < listing.stories.size(); ++s) {
        const std::vector<std::string>& record = records[s + 1];
        ASSERT_EQ(record.size(), records[0].size());
        EXPECT_EQ(record[0], listing.stories[s].id);
        EXPECT_EQ(record[1], listing.stories[s].title);
        for (std::size_t g = 0; g < 4; ++g) {
            EXPECT_EQ(record[2 + g], listing.versions[listing.groupVersion[s][g]]);
            cells.insert({record[0], record[2 + g]});
        }
    }
    EXPECT_EQ(cells.size(), 4u * 4u) << "a Latin square: every story in every version once";
}

TEST(StudyExports, OverviewAgreesWithTheParticipantsTrials) {
    const StudyListing listing = fixture();
    const std::vector<Row> overview = rowsOf(parseCsv(overviewCsv(listing)));
    for (std::size_t p = 0; p < listing.participants.size(); ++p)
        for (const Row& row : conditionRows(listing, p)) {
            if (row.at("phase") != "1") continue;
            const auto story = std::find_if(overview.begin(), overview.end(),
                                            [&](const Row& r) { return r.at("story") == row.at("story_id"); });
            ASSERT_NE(story, overview.end());
            EXPECT_EQ(story->at("group_" + row.at("group")), row.at("version"));
        }
}

// ---- sheets ---------------------------------------------------------------------------------

TEST(StudyExports, QuestionSheetEscapesHtml) {
    const StudyListing listing = fixture();
    const std::string sheet = questionSheetHtml(listing);
    EXPECT_TRUE(sheet.starts_with("<!DOCTYPE html>"));
    EXPECT_TRUE(contains(sheet, "Tom &amp; &lt;Jerry&gt;"));
    EXPECT_FALSE(contains(sheet, "<Jerry>"));
    EXPECT_TRUE(contains(sheet, "Is 2 &lt; 3 &amp; is &quot;yes&quot; right?"));
    EXPECT_TRUE(contains(sheet, "Zo\u00eb&#39;s &quot;big&quot; day, part 1\nand after"));
    EXPECT_TRUE(contains(sheet, "<meta charset=\"utf-8\">"));
    // Self-contained and printable, a story to a page.
    EXPECT_FALSE(contains(lowercase(sheet), "<script"));
    EXPECT_FALSE(contains(sheet, "http://"));
    EXPECT_FALSE(contains(sheet, "https://"));
    EXPECT_FALSE(contains(sheet, "<link"));
    EXPECT_TRUE(contains(sheet, "@media print"));
    EXPECT_TRUE(contains(sheet, "break-after: page"));
}

TEST(StudyExports, QuestionSheetHasEveryStoryGlossAndQuestionWithTheAnswerMarked) {
    const StudyListing listing = fixture();
    const std::string sheet = questionSheetHtml(listing);
    std::size_t questions = 0;
    for (const ListedStory& story : listing.stories) {
        EXPECT_TRUE(contains(sheet, "<section class=\"story\" id=\"" + story.id + "\">"));
        for (const std::string& gloss : story.sentences) EXPECT_TRUE(contains(sheet, "<li>" + escapeHtml(gloss) + "</li>"));
        for (const ListedQuestion& question : story.questions) {
            ++questions;
            EXPECT_TRUE(contains(sheet, escapeHtml(question.text)));
            const std::size_t answer = static_cast<std::size_t>(question.answer);
            const std::string letter(1, static_cast<char>('A' + answer));
            EXPECT_TRUE(contains(sheet, "<li class=\"answer\"><span class=\"letter\">" + letter + "</span> " +
                                            escapeHtml(question.choices[answer]) + " <span class=\"mark\">"));
        }
    }
    EXPECT_EQ(occurrences(sheet, "<li class=\"answer\">"), questions);
    EXPECT_EQ(occurrences(sheet, "<section class=\"story\""), listing.stories.size());
}

TEST(StudyExports, ResponseSheetNeverRevealsTheMapping) {
    const StudyListing listing = fixture();
    for (std::size_t p = 0; p < listing.participants.size(); ++p) {
        const std::string sheet = likertResponseSheetHtml(listing, p);
        const std::string folded = lowercase(sheet);
        for (const std::string& version : listing.versions) EXPECT_FALSE(contains(folded, version)) << version;
        for (const ListedSentence& sentence : listing.sentences) {
            EXPECT_FALSE(contains(sheet, sentence.panelCode)) << sentence.panelCode;
            EXPECT_FALSE(contains(sheet, sentence.clip.video));
        }
        EXPECT_FALSE(contains(folded, ".mp4"));
        EXPECT_FALSE(contains(folded, "<script"));
    }
}

TEST(StudyExports, ResponseSheetHasABlockPerTrialInTheParticipantsOrder) {
    const StudyListing listing = fixture();
    for (std::size_t p = 0; p < listing.participants.size(); ++p) {
        const ListedParticipant& participant = listing.participants[p];
        const std::string sheet = likertResponseSheetHtml(listing, p);
        EXPECT_TRUE(contains(sheet, participant.id));
        std::size_t previous = 0;
        for (const ListedPhase2Trial& trial : participant.phase2) {
            const std::string heading = "Trial " + std::to_string(trial.trial) + "<span class=\"sentence\">" +
                                        listing.sentences[trial.sentence].id + "</span>";
            const std::size_t at = sheet.find(heading);
            ASSERT_NE(at, std::string::npos) << heading;
            EXPECT_GT(at, previous) << "trials out of order";
            previous = at;
        }
        const std::size_t points = static_cast<std::size_t>(listing.likertMaximum - listing.likertMinimum + 1);
        EXPECT_EQ(occurrences(sheet, "<span class=\"box\">"), participant.phase2.size() * listing.versions.size() * points);
        EXPECT_EQ(occurrences(sheet, "<th scope=\"row\">Panel D</th>"), participant.phase2.size());
    }
}

}  // namespace
}  // namespace signstim::stimuli
