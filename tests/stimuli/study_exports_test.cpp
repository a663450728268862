// The study's exports (stimuli/study/study_exports.hpp): the conditions CSV, the jsPsych JSON and
// the overview CSV read back as what they claim to be and carry the schedule of the listing;
// the printable sheets escape their text and the response sheet never shows the mapping.
// The listing is a small synthetic fixture built here by hand, not a rendered study.
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

using Records = std::vector<std::vector<std::string>>;
using Row = std::map<std::string, std::string>;

// ---- a strict RFC 4180 reader --------------------------------------------------------------

// Records end in CRLF (the last one too), fields are separated by commas, a quoted field may
// hold anything with its quotes doubled. Anything else (a bare LF, a quote inside an unquoted
// field, text after a closing quote) throws.
Records parseCsv(const std::string& text) {
    Records records;
    std::vector<std::string> record;
    std::string field;
    std::size_t i = 0;
    while (i < text.size()) {
        if (text[i] == '"') {
            ++i;
            for (;;) {
                if (i >= text.size()) throw std::runtime_error("unterminated quoted field");
                if (text[i] == '"') {
                    if (i + 1 < text.size() && text[i + 1] == '"') {
                        field += '"';
                        i += 2;
                        continue;
                    }
                    ++i;
                    break;
                }
                field += text[i++];
            }
        } else {
            while (i < text.size() && text[i] != ',' && text[i] != '\r' && text[i] != '\n') {
                if (text[i] == '"') throw std::runtime_error("quote inside an unquoted field");
                field += text[i++];
            }
        }
        record.push_back(std::move(field));
        field.clear();
        if (i < text.size() && text[i] == ',') {
            ++i;
            continue;
        }
        if (text.compare(i, 2, "\r\n") != 0) throw std::runtime_error("expected ',' or CRLF at byte " + std::to_string(i));
        i += 2;
        records.push_back(std::move(record));
        record.clear();
    }
    if (!record.empty()) throw std::runtime_error("the last record does not end in CRLF");
    return records;
}

// The data rows of a parsed table as column -> value (the table must be rectangular).
std::vector<Row> rowsOf(const Records& records) {
    std::vector<Row> rows;
    for (std::size_t r = 1; r < records.size(); ++r) {
        Row row;
        for (std::size_t c = 0; c < records[0].size(); ++c) row[records[0][c]] = records[r].at(c);
        rows.push_back(std::move(row));
    }
    return rows;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::size_t occurrences(const std::string& text, const std::string& part) {
    std::size_t found = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size())) ++found;
    return found;
}

std::string lowercase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

// ---- the fixture -----------------------------------------------------------------------------

const std::vector<std::string> allVersions = {"point", "vector", "animator", "uninflected", "mirrored"};
const std::vector<std::string> allLetters = {"P", "V", "A", "U", "M"};

// Titles that exercise quoting and escaping: a comma, quotes, a newline, non-ASCII, HTML.
const std::string awkwardTitle = "Zo\u00eb's \"big\" day, part 1\nand after";
const std::string htmlTitle = "Tom & <Jerry>";
const std::string htmlQuestion = "Is 2 < 3 & is \"yes\" right?";

std::string padded(std::size_t number) { return (number < 10 ? "0" : "") + std::to_string(number); }

// 4 stories (4 questions each; story 1's third question has 3 choices) in `versions` versions,
// one participant per group, 2 phase-2 sentences. Story orders and sentence orders differ
// between participants; group g sees story s in version (s + g) mod versions.
StudyListing fixture(std::size_t versions = 4) {
    StudyListing listing;
    listing.title = "Verb agreement comprehension";
    listing.studyFile = "scenes/studies/exports-test.json";
    listing.toolVersion = "0.4.0";
    listing.seed = 18446744073709551557ull;  // above 2^53: JSON must not carry it as a number
    listing.designHash = "9f86d081884c7d659a2feaa0c55ad015a3bf4f1b2b0b822cd15d6c15b0f00a08";
    listing.versions.assign(allVersions.begin(), allVersions.begin() + static_cast<std::ptrdiff_t>(versions));
    listing.versionLetters.assign(allLetters.begin(), allLetters.begin() + static_cast<std::ptrdiff_t>(versions));
    listing.size = "1280x720";
    listing.fps = "30";

    const std::vector<std::string> titles = {awkwardTitle, htmlTitle, "The copied homework", "\u00dcber den Fluss"};
    for (std::size_t s = 0; s < 4; ++s) {
        ListedStory story;
        story.id = "story-" + padded(s + 1);
        story.title = titles[s];
        story.file = "stories/" + story.id + ".json";
        story.sentences = {"JOHN IX(0.9) ASK MARY IX(-0.6)", "MARY IX(-0.6) GIVE-BOOK JOHN IX(0.9)"};
        for (std::size_t q = 0; q < 4; ++q) {
            ListedQuestion question;
            question.text = s == 1 && q == 0 ? htmlQuestion : "Who asked whom, in part " + std::to_string(q + 1) + "?";
            question.choices = {"John asked Mary", "Mary asked John", "Zo\u00eb asked \"nobody\"", "Nobody, really"};
            if (s == 0 && q == 2) question.choices.pop_back();
            question.answer = static_cast<int>((s + q) % question.choices.size());
            question.probeVerb = "ASK";
            question.probeSentence = static_cast<int>(q % 2);
            story.questions.push_back(question);
        }
        for (std::size_t v = 0; v < versions; ++v) {
            ListedClip clip;
            const std::string stem = story.id + "_version-" + listing.versions[v];
            clip.video = "clips/" + stem + ".mp4";
            clip.poster = "posters/" + stem + ".png";
            clip.durationSeconds = 10.0 + static_cast<double>(s) + 0.25 * static_cast<double>(v) + 0.0004;
            clip.frameCount = static_cast<std::uint64_t>(std::lround(clip.durationSeconds * 30));
            story.clips.push_back(clip);
        }
        listing.stories.push_back(story);
        std::vector<std::size_t> row;
        for (std::size_t g = 0; g < versions; ++g) row.push_back((s + g) % versions);
        listing.groupVersion.push_back(row);
    }

    for (std::size_t t = 0; t < 2; ++t) {
        ListedSentence sentence;
        sentence.id = "likert-" + padded(t + 1);
        sentence.gloss = t == 0 ? "JOHN IX(0.9) ASK MARY IX(-0.6)" : "ZOE IX(0.3) SEND BOB IX(-0.8)";
        sentence.verb = t == 0 ? "ASK" : "SEND";
        for (std::size_t k = 0; k < versions; ++k) {
            sentence.panelVersion.push_back((k + 1 + t) % versions);
            sentence.panelCode += listing.versionLetters[sentence.panelVersion.back()];
        }
        sentence.clip.video = "clips/" + sentence.id + "_panels-" + sentence.panelCode + ".mp4";
        sentence.clip.poster = "posters/" + sentence.id + "_panels-" + sentence.panelCode + ".png";
        sentence.clip.durationSeconds = 4.5;
        listing.sentences.push_back(sentence);
    }

    for (std::size_t p = 0; p < versions; ++p) {
        ListedParticipant participant;
        participant.id = "P" + padded(p + 1);
        participant.group = p;
        const std::vector<std::size_t> order = {(p + 3) % 4, (p + 1) % 4, p % 4, (p + 2) % 4};
        for (std::size_t i = 0; i < order.size(); ++i)
            participant.phase1.push_back({i + 1, order[i], listing.groupVersion[order[i]][participant.group]});
        participant.phase2.push_back({1, p % 2});
        participant.phase2.push_back({2, 1 - p % 2});
        listing.participants.push_back(participant);
    }
    return listing;
}

std::vector<Row> conditionRows(const StudyListing& listing, std::size_t participant) {
    return rowsOf(parseCsv(conditionsCsv(listing, participant)));
}

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
