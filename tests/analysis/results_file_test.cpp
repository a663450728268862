// Results files read against the study they came from: a synthetic participant's file reads
// back without a warning; every kind of mistake is refused naming file:line and the column;
// scoring and panel mappings that disagree with the study are warnings, and the study's
// answer keys and panel codes win; other software's column names map onto ours.
#include "analysis/results_file.hpp"
#include "analysis/simulation.hpp"
#include "common/error.hpp"
#include "common/input_limits.hpp"
#include "stimuli/json_source.hpp"
#include "tests/stimuli/review_page_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

using namespace signstim::analysis;
using signstim::InputError;
namespace fs = std::filesystem;
namespace limits = signstim::limits;
using signstim::stimuli::StudyListing;

const StudyListing& study() {
    static const StudyListing listing = signstim::stimuli::testing::reviewFixtureListing();
    return listing;
}

// P01's synthetic file (planted effect, seed 5).
std::string participantFile() {
    return simulateResults(study(), plantedEffect(study(), 5)).front().text;
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t end = text.find("\r\n", at);
        out.push_back(text.substr(at, end - at));
        at = end + 2;
    }
    return out;
}

std::string joined(const std::vector<std::string>& rows) {
    std::string out;
    for (const std::string& r : rows) out += r + "\r\n";
    return out;
}

std::vector<std::string> fields(const std::string& row) {
    std::vector<std::string> out;
    std::size_t at = 0;
    for (;;) {
        const std::size_t comma = row.find(',', at);
        out.push_back(row.substr(at, comma == std::string::npos ? std::string::npos : comma - at));
        if (comma == std::string::npos) return out;
        at = comma + 1;
    }
}

std::string rowOf(const std::vector<std::string>& f) {
    std::string out;
    for (std::size_t i = 0; i < f.size(); ++i) out += (i ? "," : "") + f[i];
    return out;
}

std::size_t column(const std::string& name) {
    const auto& c = resultsColumns();
    return static_cast<std::size_t>(std::find(c.begin(), c.end(), name) - c.begin());
}

// The file with field `name` of data row `row` (0-based after the header) set to `value`.
std::string withField(std::size_t row, const std::string& name, const std::string& value) {
    std::vector<std::string> rows = lines(participantFile());
    std::vector<std::string> f = fields(rows[2 + row]);  // comment line, header
    f[column(name)] = value;
    rows[2 + row] = rowOf(f);
    return joined(rows);
}

ParticipantResults parse(const std::string& text, std::vector<std::string>& warnings, const ColumnMap& map = {}) {
    return parseResults(text, "results/P01.csv", study(), map, warnings);
}

std::string errorOf(const std::string& text, const ColumnMap& map = {}) {
    std::vector<std::string> warnings;
    try {
        parse(text, warnings, map);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(ResultsFile, SyntheticFileReadsBackWithoutWarnings) {
    std::vector<std::string> warnings;
    const ParticipantResults r = parse(participantFile(), warnings);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    EXPECT_EQ(r.participant, "P01");
    EXPECT_TRUE(r.synthetic);
    ASSERT_EQ(r.phase1.size(), 12u);
    ASSERT_EQ(r.phase2.size(), 8u);
    for (const Phase1Result& t : r.phase1) {
        EXPECT_EQ(t.version, study().participants[0].phase1[t.trial - 1].version);
        EXPECT_EQ(t.correct.size(), 4u);
    }
    for (const Phase2Result& t : r.phase2)
        for (double rating : t.ratings) EXPECT_FALSE(std::isnan(rating));
}

TEST(ResultsFile, MistakesAreRefusedNamingFileLineAndColumn) {
    struct Case {
        std::size_t row;
        std::string column, value, expect;
    };
    // Rows 0-11 are phase 1, 12-19 phase 2; data row r is on line r + 3.
    const std::vector<Case> cases = {
        {0, "version", "vectr", "results/P01.csv:3: field 'version': 'vectr' is not a version of this study"},
        {1, "story_id", "story-13", "results/P01.csv:4: field 'story_id': 'story-13' is not a story"},
        {2, "phase", "3", "results/P01.csv:5: field 'phase': expected 1"},
        {3, "trial", "x", "results/P01.csv:6: field 'trial': expected a trial number"},
        {4, "q1_response", "E", "results/P01.csv:7: field 'q1_response': expected a choice letter A to D"},
        {4, "q2_response", "D", "results/P01.csv:7: field 'q2_response': expected a choice letter A to C"},
        {5, "q3_correct", "yes", "results/P01.csv:8: field 'q3_correct': expected 1 or 0"},
        {6, "participant", "P02", "results/P01.csv:9: field 'participant': 'P02' in a file of 'P01'"},
        {0, "participant", "P99", "results/P01.csv:3: field 'participant': 'P99' is not a participant of this study (it has P01 to P24)"},
        {12, "rating_b", "11", "results/P01.csv:15: field 'rating_b': expected a whole number 1 to 10"},
        {12, "rating_a", "7.5", "results/P01.csv:15: field 'rating_a': expected a whole number 1 to 10"},
        {13, "panel_code", "XXXX", "results/P01.csv:16: field 'panel_code': the study showed"},
        {14, "sentence_id", "likert-09", "results/P01.csv:17: field 'sentence_id': 'likert-09' is not a phase-2 sentence"},
        {15, "rt_ms", "-4", "results/P01.csv:18: field 'rt_ms': expected a response time"},
    };
    for (const Case& c : cases) {
        const std::string message = errorOf(withField(c.row, c.column, c.value));
        EXPECT_NE(message.find(c.expect), std::string::npos) << c.column << "=" << c.value << ": " << message;
    }
}

TEST(ResultsFile, AVersionOtherThanTheDesignsIsRefused) {
    // P01 saw their first story in one version; the file claiming another is not this study's.
    const std::size_t shown = study().participants[0].phase1[0].version;
    const std::string other = study().versions[(shown + 1) % 4];
    const std::string message = errorOf(withField(0, "version", other));
    EXPECT_NE(message.find("results/P01.csv:3: field 'version': the design showed"), std::string::npos) << message;
    EXPECT_NE(message.find("the file says '" + other + "'"), std::string::npos) << message;
}

TEST(ResultsFile, DuplicateStoriesMissingColumnsAndEmptyFilesAreRefused) {
    std::vector<std::string> rows = lines(participantFile());
    rows.push_back(rows[2]);
    EXPECT_NE(errorOf(joined(rows)).find(":23: field 'story_id': story-"), std::string::npos) << errorOf(joined(rows));
    std::string noColumn = participantFile();
    noColumn.replace(noColumn.find(",rt_ms"), 6, ",rt");
    EXPECT_NE(errorOf(noColumn).find("results/P01.csv:2: field 'rt_ms': this column is missing"), std::string::npos)
        << errorOf(noColumn);
    EXPECT_NE(errorOf("").find("no header row"), std::string::npos);
    rows = lines(participantFile());
    rows[4] += ",extra";
    EXPECT_NE(errorOf(joined(rows)).find("results/P01.csv:5: this row has 26 fields, the header 25"), std::string::npos)
        << errorOf(joined(rows));
}

// Bounded input (docs/errors.md, Limits): a file of more rows than one participant could have
// is refused at the first row too many, before the rest is read or checked.
TEST(ResultsFile, AFileOverTheRowLimitIsRefusedAtTheFirstRowTooMany) {
    std::vector<std::string> rows = lines(participantFile());
    const std::string row = rows[2];
    const std::size_t have = rows.size() - 2;  // comment line, header
    rows.reserve(2 + limits::kResultRows + 1);
    for (std::size_t i = have; i <= limits::kResultRows; ++i) rows.push_back(row);
    const std::string error = errorOf(joined(rows));
    const std::string line = std::to_string(2 + limits::kResultRows + 1);  // the comment, the header, then rows
    EXPECT_NE(error.find("results/P01.csv:" + line + ": more than 100000 rows"), std::string::npos) << error.substr(0, 300);
}

TEST(ResultsFile, AResultsFileOverItsSizeIsRefusedBeforeItIsRead) {
    const fs::path path = fs::temp_directory_path() / "signstim_results_too_large.csv";
    {
        std::ofstream out(path, std::ios::binary);
        out << participantFile();
        out.seekp(static_cast<std::streamoff>(limits::kCsvFileBytes));  // sparse: costs no disk
        out << '\n';
    }
    std::vector<std::string> warnings;
    try {
        readResults(path, study(), {}, warnings);
        ADD_FAILURE() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_NE(e.detail().find("over the limit of 64 MiB"), std::string::npos) << e.what();
    }
    fs::remove(path);
}

TEST(ResultsFile, ScoringThatDisagreesWithTheAnswerKeyIsAWarningAndTheKeyWins) {
    std::vector<std::string> rows = lines(participantFile());
    std::vector<std::string> f = fields(rows[2]);
    const bool wasCorrect = f[column("q1_correct")] == "1";
    f[column("q1_correct")] = wasCorrect ? "0" : "1";
    rows[2] = rowOf(f);
    std::vector<std::string> warnings;
    const ParticipantResults r = parse(joined(rows), warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("results/P01.csv:3: field 'q1_correct': says " + std::string(wasCorrect ? "0" : "1") +
                               ", but the answer key of story-"),
              std::string::npos)
        << warnings[0];
    EXPECT_EQ(r.phase1[0].correct[0], wasCorrect);
}

TEST(ResultsFile, RatingsAreUnmappedFromThePanelCodeNotFromTheFilesVersionColumns) {
    std::vector<std::string> rows = lines(participantFile());
    std::vector<std::string> f = fields(rows[2 + 12]);
    const std::string code = f[column("panel_code")];
    // Swap the file's own version columns of panels A and B: the analysis must not believe them.
    const auto versionOf = [&](char letter) {
        for (std::size_t v = 0; v < 4; ++v)
            if (study().versionLetters[v][0] == letter) return study().versions[v];
        return std::string();
    };
    const std::string a = versionOf(code[0]), b = versionOf(code[1]);
    f[column("rating_a")] = "2";
    f[column("rating_b")] = "9";
    f[column("rating_" + a)] = "9";
    f[column("rating_" + b)] = "2";
    rows[2 + 12] = rowOf(f);
    std::vector<std::string> warnings;
    const ParticipantResults r = parse(joined(rows), warnings);
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_NE(warnings[0].find("field 'rating_"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("the panel's rating is analysed"), std::string::npos) << warnings[0];
    const std::size_t va = static_cast<std::size_t>(std::find(study().versions.begin(), study().versions.end(), a) - study().versions.begin());
    const std::size_t vb = static_cast<std::size_t>(std::find(study().versions.begin(), study().versions.end(), b) - study().versions.begin());
    EXPECT_EQ(r.phase2[0].ratings[va], 2.0);
    EXPECT_EQ(r.phase2[0].ratings[vb], 9.0);
}

TEST(ResultsFile, MissingAnswersRatingsAndTrialsAreWarnings) {
    std::vector<std::string> rows = lines(participantFile());
    std::vector<std::string> f = fields(rows[3]);
    f[column("q2_response")] = "";
    f[column("q2_correct")] = "";
    f[column("n_correct")] = "";
    rows[3] = rowOf(f);
    f = fields(rows[2 + 13]);
    f[column("rating_c")] = "";
    for (std::size_t v = 0; v < 4; ++v)  // and the file's own column of that panel's version
        if (study().versionLetters[v][0] == f[column("panel_code")][2]) f[column("rating_" + study().versions[v])] = "";
    rows[2 + 13] = rowOf(f);
    rows.erase(rows.begin() + 2 + 19);  // the last phase-2 trial
    rows.erase(rows.begin() + 2 + 5);   // a phase-1 trial
    std::vector<std::string> warnings;
    const ParticipantResults r = parse(joined(rows), warnings);
    ASSERT_EQ(warnings.size(), 4u);
    EXPECT_NE(warnings[0].find(":4: field 'q2_response': no answer; counted as incorrect"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[1].find("field 'rating_c': no rating of panel C"), std::string::npos) << warnings[1];
    EXPECT_NE(warnings[2].find("P01 has 11 of 12 phase-1 trials (missing story-"), std::string::npos) << warnings[2];
    EXPECT_NE(warnings[3].find("P01 has 7 of 8 phase-2 trials (missing likert-"), std::string::npos) << warnings[3];
    EXPECT_FALSE(r.phase1[1].correct[1]);
    EXPECT_EQ(r.phase1[1].choices[1], kNoAnswer);
}

TEST(ResultsFile, CsvQuotingLineEndsByteOrderMarkAndCommentsAreRead) {
    std::string text = participantFile();
    std::string lf;
    for (char c : text)
        if (c != '\r') lf += c;
    lf = "\xEF\xBB\xBF# a comment\n\n" + lf;
    // Quote the first participant field, as spreadsheet programs may.
    const std::size_t first = lf.find("\nP01,");
    lf.replace(first + 1, 3, "\"P01\"");
    std::vector<std::string> warnings;
    const ParticipantResults r = parse(lf, warnings);
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(r.phase1.size(), 12u);
    EXPECT_NE(errorOf("participant\n\"P01\n").find("a quoted field is never closed"), std::string::npos);
}

TEST(ResultsFile, OtherSoftwaresColumnNamesMapOntoOurs) {
    const std::string mapText = R"({
  "format": "signstim-results-columns",
  "version": 1,
  "columns": {
    "participant": "participant_id",
    "q1_response": "resp_q1.keys",
    "rt_ms": "RT"
  }
})";
    const ColumnMap map = parseColumnMap(signstim::stimuli::parseJsonText(mapText, "gorilla.json"));
    std::string text = participantFile();
    const std::string header = "participant,phase";
    text.replace(text.find(header), header.size(), "participant_id,phase");
    text.replace(text.find("q1_response"), 11, "resp_q1.keys");
    text.replace(text.find(",rt_ms"), 6, ",RT");
    std::vector<std::string> warnings;
    EXPECT_EQ(parse(text, warnings, map).phase1.size(), 12u);
    // Without the map, the missing column is named with a hint; with it, mistakes name both names.
    EXPECT_NE(errorOf(text).find("field 'participant': this column is missing from the header (files of other software: --columns"),
              std::string::npos)
        << errorOf(text);
    std::vector<std::string> rows = lines(text);
    std::vector<std::string> f = fields(rows[2]);
    f[column("q1_response")] = "Z";
    rows[2] = rowOf(f);
    EXPECT_NE(errorOf(joined(rows), map).find("field 'resp_q1.keys (q1_response)': expected a choice letter"), std::string::npos)
        << errorOf(joined(rows), map);

    const auto mapError = [](const std::string& json) {
        try {
            parseColumnMap(signstim::stimuli::parseJsonText(json, "map.json"));
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(mapError("{\n  \"columns\": {\n    \"q9_response\": \"x\"\n  }\n}").find("map.json:3: field '/columns/q9_response'"),
              std::string::npos);
    EXPECT_NE(mapError("{\n  \"columns\": {\n    \"q1_response\": \"x\",\n    \"q2_response\": \"x\"\n  }\n}")
                  .find("'x' is already the column of 'q1_response'"),
              std::string::npos);
}

TEST(ResultsFile, TwoFilesOfOneParticipantAreRefused) {
    const std::string dir = ::testing::TempDir() + "analysis_results_duplicate";
    std::filesystem::create_directories(dir);
    const std::string text = participantFile();
    for (const char* name : {"/a.csv", "/b.csv"}) {
        std::ofstream out(dir + name, std::ios::binary);
        out << text;
    }
    std::vector<std::string> warnings;
    try {
        readResultsFiles({dir + "/a.csv", dir + "/b.csv"}, study(), {}, warnings);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("P01 has results in " + dir + "/a.csv too"), std::string::npos) << e.what();
    }
}

}  // namespace
