// The study's exports (stimuli/study/study_exports.hpp): the conditions CSV (PsychoPy) and the
// Gorilla spreadsheet read back as what they claim to be and carry the schedule of the listing;
// the same listing gives the same bytes and a contradictory one is refused. The jsPsych JSON,
// the overview and the sheets: study_exports_documents_test.cpp. The listing is the small
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

// ---- helpers -------------------------------------------------------------------------------

TEST(StudyExports, CsvFieldQuotesOnlyWhatRfc4180Requires) {
    EXPECT_EQ(csvField("story-01"), "story-01");
    EXPECT_EQ(csvField(""), "");
    EXPECT_EQ(csvField("Zo\u00eb"), "Zo\u00eb");
    EXPECT_EQ(csvField(" spaced "), " spaced ");
    EXPECT_EQ(csvField("a,b"), "\"a,b\"");
    EXPECT_EQ(csvField("say \"hi\""), "\"say \"\"hi\"\"\"");
    EXPECT_EQ(csvField("two\nlines"), "\"two\nlines\"");
    EXPECT_EQ(csvField("carriage\rreturn"), "\"carriage\rreturn\"");
    EXPECT_EQ(parseCsv(csvField(awkwardTitle) + "\r\n"), (Records{{awkwardTitle}}));
}

TEST(StudyExports, EscapeHtmlReplacesTheFiveSpecialCharactersAndKeepsTheRest) {
    EXPECT_EQ(escapeHtml("Tom & <Jerry> said \"hi\" and 'bye'"),
              "Tom &amp; &lt;Jerry&gt; said &quot;hi&quot; and &#39;bye&#39;");
    EXPECT_EQ(escapeHtml("&amp;"), "&amp;amp;");  // text, not markup: escaped again
    EXPECT_EQ(escapeHtml("Zo\u00eb \u2603"), "Zo\u00eb \u2603");
    EXPECT_EQ(escapeHtml(""), "");
}

// ---- conditions CSV ------------------------------------------------------------------------

TEST(StudyExports, ConditionsCsvIsRectangularAndParsesBack) {
    const StudyListing listing = fixture();
    for (std::size_t p = 0; p < listing.participants.size(); ++p) {
        const std::string text = conditionsCsv(listing, p);
        ASSERT_FALSE(text.starts_with("\xEF\xBB\xBF")) << "no byte-order mark";
        Records records;
        ASSERT_NO_THROW(records = parseCsv(text));
        ASSERT_EQ(records.size(), 1 + listing.participants[p].phase1.size() + listing.participants[p].phase2.size());
        for (const std::vector<std::string>& record : records) EXPECT_EQ(record.size(), records[0].size());
        // Fields round-trip: the awkward title and the non-ASCII choice come back byte for byte.
        std::set<std::string> titles;
        for (const Row& row : rowsOf(records)) titles.insert(row.at("story_title"));
        EXPECT_TRUE(titles.count(awkwardTitle));
        EXPECT_TRUE(titles.count(htmlTitle));
        EXPECT_EQ(rowsOf(records)[0].at("q1_choice_c"), "Zo\u00eb asked \"nobody\"");
    }
}

TEST(StudyExports, ConditionsCsvHeaderIsTheSameValidVariableNamesForEveryParticipant) {
    const StudyListing listing = fixture();
    const std::vector<std::string> header = parseCsv(conditionsCsv(listing, 0))[0];
    std::set<std::string> unique;
    for (const std::string& name : header) {
        ASSERT_FALSE(name.empty());
        EXPECT_TRUE(name[0] >= 'a' && name[0] <= 'z') << name;  // PsychoPy: starts with a letter
        for (char c : name) EXPECT_TRUE((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_') << name;
        unique.insert(name);
    }
    EXPECT_EQ(unique.size(), header.size()) << "column names repeat";
    for (const char* expected : {"phase", "trial", "participant_id", "group", "story_id", "story_title", "version",
                                        "sentence_id", "video_file", "poster_file", "duration_s", "q4_text",
                                        "q4_choice_d", "q4_answer", "q4_answer_index", "q4_answer_text", "panel_d_version", "panel_code"})
        EXPECT_NE(std::find(header.begin(), header.end(), expected), header.end()) << expected;
    for (std::size_t p = 1; p < listing.participants.size(); ++p)
        EXPECT_EQ(parseCsv(conditionsCsv(listing, p))[0], header);
}

TEST(StudyExports, ConditionsCsvAvoidsPsychopysSessionFieldsAndBuilderNames) {
    // PsychoPy saves its session dialog's fields (expInfo) beside the conditions' columns; a
    // column of the same name is overwritten in the saved data. The Python check
    // (check_conditions_for_psychopy.py) holds the whole of PsychoPy's reserved names.
    const std::vector<std::string> header = parseCsv(conditionsCsv(fixture(), 0))[0];
    for (const char* reserved : {"participant", "session", "date", "expName", "psychopyVersion", "frameRate",
                                 "expStart", "win", "t", "thisExp", "filename", "trials"})
        EXPECT_EQ(std::find(header.begin(), header.end(), reserved), header.end()) << reserved;
}

TEST(StudyExports, WholeNumberColumnsAreNeverEmptySoPandasReadsThemAsIntegers) {
    const StudyListing listing = fixture();
    for (std::size_t p = 0; p < listing.participants.size(); ++p) {
        for (const Row& row : conditionRows(listing, p)) {
            for (const auto& cell : row) {
                const bool whole = cell.first == "phase" || cell.first == "trial" || cell.first == "group" ||
                                   cell.first.ends_with("_answer_index");
                if (!whole) continue;
                ASSERT_FALSE(cell.second.empty()) << cell.first << " empty in a " << row.at("display") << " row";
                EXPECT_EQ(cell.second.find('.'), std::string::npos) << cell.first;
            }
            if (row.at("phase") == "2") {
                EXPECT_EQ(row.at("q1_answer_index"), "-1") << "no question: -1";
            }
        }
    }
}

TEST(StudyExports, GorillaSpreadsheetHasInstructionBreakAndEndRowsAroundTheTrials) {
    const StudyListing listing = fixture();
    for (std::size_t p = 0; p < listing.participants.size(); ++p) {
        const std::vector<Row> sheet = rowsOf(parseCsv(gorillaSpreadsheetCsv(listing, p)));
        const std::vector<Row> trials = conditionRows(listing, p);
        ASSERT_EQ(sheet.size(), trials.size() + 3);
        EXPECT_EQ(sheet.front().at("display"), "instructions");
        EXPECT_EQ(sheet.back().at("display"), "end");
        const std::size_t phase1 = listing.participants[p].phase1.size();
        EXPECT_EQ(sheet[1 + phase1].at("display"), "break");
        for (const std::size_t text : {std::size_t{0}, 1 + phase1, sheet.size() - 1}) EXPECT_FALSE(sheet[text].at("text").empty());
        // The trials are the conditions file's rows, cell for cell, in the same order.
        for (std::size_t i = 0; i < trials.size(); ++i) {
            const Row& row = sheet[i < phase1 ? 1 + i : 2 + i];
            for (const auto& cell : trials[i]) EXPECT_EQ(row.at(cell.first), cell.second) << cell.first << " row " << i;
            EXPECT_EQ(row.at("randomise_trials"), "") << "the schedule's order, never reshuffled";
            if (row.at("display") == "story") {
                EXPECT_EQ(row.at("ANSWER"), row.at("q1_answer_text")) << "ANSWER is a button's text";
            }
        }
    }
}

TEST(StudyExports, SignedQuestionClipsAreColumnsOnlyWhenTheStudySignsItsQuestions) {
    // An English-only study: the question columns are as before, no clip columns.
    const Records englishRecords = parseCsv(conditionsCsv(fixture(), 0));
    for (const std::string& name : englishRecords[0])
        EXPECT_FALSE(name.ends_with("_video_file") && name != "video_file") << name;
    const StudyListing listing = signedFixture();
    const std::vector<std::string> header = parseCsv(conditionsCsv(listing, 0))[0];
    EXPECT_EQ(std::set<std::string>(header.begin(), header.end()).size(), header.size()) << "column names repeat";
    for (std::size_t q = 1; q <= 4; ++q) {
        const std::string prefix = "q" + std::to_string(q) + "_";
        const auto text = std::find(header.begin(), header.end(), prefix + "text");
        // Next to the question's text, before its choices: the order a participant meets them.
        ASSERT_NE(text, header.end());
        ASSERT_LT(text + 2, header.end());
        EXPECT_EQ(*(text + 1), prefix + "video_file");
        EXPECT_EQ(*(text + 2), prefix + "video_name");
    }
    for (std::size_t p = 0; p < listing.participants.size(); ++p) {
        const std::vector<Row> rows = conditionRows(listing, p);
        for (const Row& row : rows) {
            if (row.at("display") != "story") {
                EXPECT_EQ(row.at("q1_video_file"), "") << "a phase-2 row asks no question";
                continue;
            }
            const auto story = std::find_if(listing.stories.begin(), listing.stories.end(),
                                            [&row](const ListedStory& s) { return s.id == row.at("story_id"); });
            ASSERT_NE(story, listing.stories.end());
            for (std::size_t q = 0; q < story->questions.size(); ++q) {
                const std::string prefix = "q" + std::to_string(q + 1) + "_";
                const ListedClip& clip = story->questions[q].clip;
                // Relative to the study folder like video_file; the bare name for a flat pool.
                EXPECT_EQ(row.at(prefix + "video_file"), clip.video) << row.at("story_id") << " " << prefix;
                EXPECT_EQ(clip.video.empty() ? "" : "clips/" + row.at(prefix + "video_name"), clip.video);
            }
        }
        // The Gorilla sheet: the same cells on its trial rows.
        const std::vector<Row> sheet = rowsOf(parseCsv(gorillaSpreadsheetCsv(listing, p)));
        for (std::size_t i = 0; i < rows.size(); ++i) {
            const Row& row = sheet[i < listing.participants[p].phase1.size() ? 1 + i : 2 + i];
            for (std::size_t q = 1; q <= 4; ++q)
                EXPECT_EQ(row.at("q" + std::to_string(q) + "_video_name"), rows[i].at("q" + std::to_string(q) + "_video_name"));
        }
    }
}

TEST(StudyExports, GorillaInstructionAndBreakRowsCarryTheSignedPagesClipsAndText) {
    const std::vector<Row> english = rowsOf(parseCsv(gorillaSpreadsheetCsv(fixture(), 0)));
    EXPECT_EQ(english.front().at("video_name"), "") << "English-only instructions: no clip";
    const StudyListing listing = signedFixture();
    const std::vector<Row> sheet = rowsOf(parseCsv(gorillaSpreadsheetCsv(listing, 0)));
    const Row& welcome = sheet.front();
    const Row& part2 = sheet[1 + listing.participants[0].phase1.size()];
    ASSERT_EQ(welcome.at("display"), "instructions");
    ASSERT_EQ(part2.at("display"), "break");
    for (const ListedInstruction& page : listing.instructions) {
        const Row& row = page.page == "welcome" ? welcome : part2;
        EXPECT_EQ(row.at("video_file"), page.clip.video);
        EXPECT_EQ("clips/" + row.at("video_name"), page.clip.video);
        EXPECT_EQ("posters/" + row.at("poster_name"), page.clip.poster);
        EXPECT_EQ(row.at("duration_s"), "6.250");
        EXPECT_EQ(row.at("text"), page.text) << "the text the clip signs";
        EXPECT_EQ(row.at("trial"), "0");
    }
    EXPECT_EQ(sheet.back().at("display"), "end");
    EXPECT_EQ(sheet.back().at("video_file"), "") << "the end page has no clip";
}

TEST(StudyExports, EveryTrialOfTheScheduleIsARowInOrder) {
    const StudyListing listing = fixture();
    for (std::size_t p = 0; p < listing.participants.size(); ++p) {
        const ListedParticipant& participant = listing.participants[p];
        const std::vector<Row> rows = conditionRows(listing, p);
        ASSERT_EQ(rows.size(), participant.phase1.size() + participant.phase2.size());
        for (std::size_t i = 0; i < participant.phase1.size(); ++i) {
            const Row& row = rows[i];
            const ListedPhase1Trial& trial = participant.phase1[i];
            const ListedClip& clip = listing.stories[trial.story].clips[trial.version];
            EXPECT_EQ(row.at("phase"), "1");
            EXPECT_EQ(row.at("display"), "story");
            EXPECT_EQ(row.at("trial"), std::to_string(i + 1));
            EXPECT_EQ(row.at("participant_id"), participant.id);
            EXPECT_EQ(row.at("group"), std::to_string(participant.group + 1));
            EXPECT_EQ(row.at("story_id"), listing.stories[trial.story].id);
            EXPECT_EQ(row.at("story_title"), listing.stories[trial.story].title);
            EXPECT_EQ(row.at("version"), listing.versions[trial.version]);
            EXPECT_EQ(row.at("video_file"), clip.video);
            EXPECT_EQ(row.at("poster_file"), clip.poster);
            EXPECT_EQ("clips/" + row.at("video_name"), clip.video);
            EXPECT_EQ("posters/" + row.at("poster_name"), clip.poster);
        }
        for (std::size_t i = 0; i < participant.phase2.size(); ++i) {
            const Row& row = rows[participant.phase1.size() + i];
            const ListedSentence& sentence = listing.sentences[participant.phase2[i].sentence];
            EXPECT_EQ(row.at("phase"), "2");
            EXPECT_EQ(row.at("display"), "likert");
            EXPECT_EQ(row.at("trial"), std::to_string(i + 1));
            EXPECT_EQ(row.at("participant_id"), participant.id);
            EXPECT_EQ(row.at("sentence_id"), sentence.id);
            EXPECT_EQ(row.at("gloss"), sentence.gloss);
            EXPECT_EQ(row.at("video_file"), sentence.clip.video);
        }
    }
    // The fixture's orders differ between participants, so the rows do too.
    EXPECT_NE(conditionRows(listing, 0)[0].at("story_id"), conditionRows(listing, 1)[0].at("story_id"));
}

TEST(StudyExports, PhaseTwoRowsCarryTheMappingAndPhaseOneRowsDoNot) {
    const StudyListing listing = fixture();
    const std::vector<std::string> panelColumns = {"panel_a_version", "panel_b_version", "panel_c_version",
                                                   "panel_d_version", "panel_code"};
    for (std::size_t p = 0; p < listing.participants.size(); ++p) {
        for (const Row& row : conditionRows(listing, p)) {
            if (row.at("phase") == "1") {
                for (const std::string& column : panelColumns) EXPECT_EQ(row.at(column), "") << column;
                EXPECT_EQ(row.at("sentence_id"), "");
                EXPECT_NE(row.at("q1_text"), "");
                continue;
            }
            const auto sentence = std::find_if(listing.sentences.begin(), listing.sentences.end(),
                                               [&](const ListedSentence& s) { return s.id == row.at("sentence_id"); });
            ASSERT_NE(sentence, listing.sentences.end());
            for (std::size_t k = 0; k < 4; ++k)
                EXPECT_EQ(row.at(panelColumns[k]), listing.versions[sentence->panelVersion[k]]);
            EXPECT_EQ(row.at("panel_code"), sentence->panelCode);
            EXPECT_EQ(row.at("version"), "") << "a side-by-side trial shows every version";
            EXPECT_EQ(row.at("story_id"), "");
            EXPECT_EQ(row.at("q1_text"), "");
            EXPECT_EQ(row.at("q1_answer"), "");
        }
    }
}

TEST(StudyExports, AnswersAreLettersAndIndicesAndAMissingChoiceIsEmpty) {
    const StudyListing listing = fixture();
    for (const Row& row : conditionRows(listing, 0)) {
        if (row.at("phase") != "1") continue;
        const auto story = std::find_if(listing.stories.begin(), listing.stories.end(),
                                        [&](const ListedStory& s) { return s.id == row.at("story_id"); });
        ASSERT_NE(story, listing.stories.end());
        for (std::size_t q = 0; q < 4; ++q) {
            const ListedQuestion& question = story->questions[q];
            const std::string prefix = "q" + std::to_string(q + 1) + "_";
            EXPECT_EQ(row.at(prefix + "text"), question.text);
            EXPECT_EQ(row.at(prefix + "answer"), std::string(1, static_cast<char>('A' + question.answer)));
            EXPECT_EQ(row.at(prefix + "answer_index"), std::to_string(question.answer));
            EXPECT_EQ(row.at(prefix + "answer_text"), question.choices[static_cast<std::size_t>(question.answer)]);
            EXPECT_EQ(row.at(prefix + "choice_a"), question.choices[0]);
            EXPECT_EQ(row.at(prefix + "choice_d"), question.choices.size() > 3 ? question.choices[3] : "");
        }
    }
    // story-01's third question has 3 choices: its d column is there and empty.
    const std::vector<Row> rows = conditionRows(listing, 0);
    const auto first = std::find_if(rows.begin(), rows.end(), [](const Row& r) { return r.at("story_id") == "story-01"; });
    ASSERT_NE(first, rows.end());
    EXPECT_EQ(first->at("q3_choice_c"), listing.stories[0].questions[2].choices[2]);
    EXPECT_EQ(first->at("q3_choice_d"), "");
}

TEST(StudyExports, DurationsAreSecondsWithThreeDecimals) {
    const StudyListing listing = fixture();
    for (const Row& row : conditionRows(listing, 0)) {
        const std::string& text = row.at("duration_s");
        ASSERT_GE(text.size(), 5u);
        EXPECT_EQ(text[text.size() - 4], '.') << text;
        if (row.at("phase") == "2") {
            EXPECT_EQ(text, "4.500");
        }
    }
    // 10 + s + 0.25 v + 0.0004 s reads as 10 + s + 0.25 v to the millisecond.
    const ListedPhase1Trial& trial = listing.participants[0].phase1[0];
    const double expected = 10.0 + static_cast<double>(trial.story) + 0.25 * static_cast<double>(trial.version);
    EXPECT_EQ(std::stod(conditionRows(listing, 0)[0].at("duration_s")), expected);
}

TEST(StudyExports, OtherVersionCountsGiveAsManyPanelsInEveryExport) {
    for (std::size_t versions : {3u, 5u}) {
        const StudyListing listing = fixture(versions);
        const Records records = parseCsv(conditionsCsv(listing, 0));
        const std::vector<std::string>& header = records[0];
        const auto panels = std::count_if(header.begin(), header.end(), [](const std::string& name) {
            return name.starts_with("panel_") && name.ends_with("_version");
        });
        EXPECT_EQ(static_cast<std::size_t>(panels), versions);
        for (const std::vector<std::string>& record : records) EXPECT_EQ(record.size(), header.size());
        const Row last = rowsOf(records).back();
        const ListedSentence& sentence = listing.sentences[listing.participants[0].phase2.back().sentence];
        EXPECT_EQ(last.at(versions == 3 ? "panel_c_version" : "panel_e_version"),
                  listing.versions[sentence.panelVersion.back()]);

        const nlohmann::json json = nlohmann::json::parse(jspsychTimelineVariables(listing, 0));
        EXPECT_EQ(json["phase2"][0]["panels"].size(), versions);

        const std::vector<std::string> overview = parseCsv(overviewCsv(listing))[0];
        EXPECT_EQ(overview.size(), 2 + versions);

        const std::string sheet = likertResponseSheetHtml(listing, 0);
        EXPECT_EQ(contains(sheet, "Panel E"), versions == 5);
        EXPECT_TRUE(contains(sheet, "Panel C"));
    }
}

// ---- determinism and refusals ---------------------------------------------------------------

TEST(StudyExports, SameListingGivesByteIdenticalExports) {
    // Two listings built apart (different addresses, same values) give the same bytes.
    const StudyListing first = fixture();
    const StudyListing second = fixture();
    EXPECT_EQ(overviewCsv(first), overviewCsv(second));
    EXPECT_EQ(questionSheetHtml(first), questionSheetHtml(second));
    for (std::size_t p = 0; p < first.participants.size(); ++p) {
        EXPECT_EQ(conditionsCsv(first, p), conditionsCsv(second, p));
        EXPECT_EQ(jspsychTimelineVariables(first, p), jspsychTimelineVariables(second, p));
        EXPECT_EQ(likertResponseSheetHtml(first, p), likertResponseSheetHtml(second, p));
    }
    // ... and a different schedule gives different bytes.
    StudyListing reordered = fixture();
    std::swap(reordered.participants[0].phase1[0].story, reordered.participants[0].phase1[1].story);
    std::swap(reordered.participants[0].phase1[0].version, reordered.participants[0].phase1[1].version);
    EXPECT_NE(conditionsCsv(reordered, 0), conditionsCsv(first, 0));
    EXPECT_NE(jspsychTimelineVariables(reordered, 0), jspsychTimelineVariables(first, 0));
}

TEST(StudyExports, NonFiniteOrNegativeDurationsAreRefused) {
    for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(), -1.0}) {
        StudyListing listing = fixture();
        listing.stories[2].clips[1].durationSeconds = bad;
        EXPECT_THROW(conditionsCsv(listing, 0), std::invalid_argument);
        EXPECT_THROW(jspsychTimelineVariables(listing, 0), std::invalid_argument);
        StudyListing sentence = fixture();
        sentence.sentences[1].clip.durationSeconds = bad;
        EXPECT_THROW(jspsychTimelineVariables(sentence, 0), std::invalid_argument);
    }
}

TEST(StudyExports, ListingsThatContradictThemselvesAreRefused) {
    const auto refusedEverywhere = [](const StudyListing& listing) {
        EXPECT_THROW(conditionsCsv(listing, 0), std::invalid_argument);
        EXPECT_THROW(jspsychTimelineVariables(listing, 0), std::invalid_argument);
        EXPECT_THROW(likertResponseSheetHtml(listing, 0), std::invalid_argument);
        EXPECT_THROW(overviewCsv(listing), std::invalid_argument);
    };
    {
        const StudyListing listing = fixture();
        EXPECT_THROW(conditionsCsv(listing, 4), std::invalid_argument);
        EXPECT_THROW(jspsychTimelineVariables(listing, 4), std::invalid_argument);
        EXPECT_THROW(likertResponseSheetHtml(listing, 4), std::invalid_argument);
    }
    {
        StudyListing listing = fixture();
        listing.participants[0].phase1[2].trial = 7;  // not numbered 1, 2, 3, ...
        refusedEverywhere(listing);
    }
    {
        StudyListing listing = fixture();
        listing.participants[0].phase2[0].sentence = 9;
        refusedEverywhere(listing);
    }
    {
        StudyListing listing = fixture();
        listing.stories[0].questions[2].answer = 3;  // the question has 3 choices
        refusedEverywhere(listing);
        EXPECT_THROW(questionSheetHtml(listing), std::invalid_argument);
    }
    {
        StudyListing listing = fixture();
        listing.sentences[0].panelVersion.pop_back();
        refusedEverywhere(listing);
    }
    {
        StudyListing listing = fixture();
        listing.participants[0].phase1[0].version = (listing.participants[0].phase1[0].version + 1) % 4;
        refusedEverywhere(listing);  // disagrees with groupVersion
    }
    {
        StudyListing listing = fixture();
        listing.groupVersion.clear();
        EXPECT_THROW(overviewCsv(listing), std::invalid_argument);
        EXPECT_NO_THROW(conditionsCsv(listing, 0)) << "only the overview needs the group table";
    }
}

}  // namespace
}  // namespace signstim::stimuli
