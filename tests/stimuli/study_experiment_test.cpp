// The jsPsych experiment's files (stimuli/study/study_experiment.hpp) read as text: every participant's
// script holds their timeline-variables JSON verbatim, the page loads jsPsych, its plugins and the
// session from relative paths in the right order, nothing needs fetch() or modules (refused from
// file://), the session writes the documented results header, and the same listing gives the
// same bytes. The session itself runs in Chromium in tests/browser/run_experiment.py.
#include "stimuli/study/study_experiment.hpp"
#include "stimuli/study/study_exports.hpp"
#include "tests/stimuli/review_page_fixture.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <regex>
#include <stdexcept>

namespace signstim::stimuli {
namespace {

using testing::ReviewFixtureShape;
using testing::reviewFixtureListing;

StudyListing smallListing() {
    ReviewFixtureShape shape;
    shape.stories = 4;
    shape.participants = 6;
    shape.likertSentences = 4;
    return reviewFixtureListing(shape);
}

std::map<std::string, ExperimentFile> byPath(const std::vector<ExperimentFile>& files) {
    std::map<std::string, ExperimentFile> out;
    for (const ExperimentFile& file : files) EXPECT_TRUE(out.emplace(file.path, file).second) << "twice: " << file.path;
    return out;
}

// The JSON value a generated script assigns: "// comment\nwindow.NAME = VALUE;\n".
nlohmann::json assigned(const std::string& script, const std::string& name) {
    const std::string prefix = "window." + name + " = ";
    const std::size_t start = script.find(prefix);
    EXPECT_NE(start, std::string::npos) << script.substr(0, 200);
    EXPECT_EQ(script.substr(script.size() - 2), ";\n");
    return nlohmann::json::parse(script.substr(start + prefix.size(), script.size() - 2 - start - prefix.size()));
}

TEST(StudyExperiment, EveryParticipantsScriptHoldsTheirTimelineVariablesVerbatim) {
    const StudyListing listing = smallListing();
    const auto files = byPath(jspsychExperimentFiles(listing));
    for (std::size_t p = 0; p < listing.participants.size(); ++p) {
        const std::string& id = listing.participants[p].id;
        const auto it = files.find("experiment/participants/" + id + ".js");
        ASSERT_NE(it, files.end()) << id;
        EXPECT_EQ(it->second.participant, id);
        const std::string json = jspsychTimelineVariables(listing, p);
        // Byte for byte the exported JSON (without its final newline), assigned to one global.
        EXPECT_NE(it->second.contents.find("\nwindow.signstimTimeline = " + json.substr(0, json.size() - 1) + ";\n"),
                  std::string::npos)
            << id;
        EXPECT_EQ(assigned(it->second.contents, "signstimTimeline"), nlohmann::json::parse(json));
    }
}

TEST(StudyExperiment, ParticipantListNamesEveryParticipantInOrder) {
    const StudyListing listing = smallListing();
    const auto files = byPath(jspsychExperimentFiles(listing));
    const nlohmann::json study = assigned(files.at("experiment/participants/index.js").contents, "signstimStudy");
    ASSERT_EQ(study["participants"].size(), listing.participants.size());
    for (std::size_t p = 0; p < listing.participants.size(); ++p)
        EXPECT_EQ(study["participants"][p], listing.participants[p].id);
    EXPECT_EQ(study["title"], listing.title);
    EXPECT_EQ(study["design_hash"], listing.designHash);
    // Only the study's own files besides: the page, the session, its style, the list.
    EXPECT_EQ(files.size(), 4 + listing.participants.size());
}

TEST(StudyExperiment, PageLoadsJsPsychThePluginsAndTheSessionFromRelativePathsInOrder) {
    const StudyListing listing = smallListing();
    const std::string page = byPath(jspsychExperimentFiles(listing)).at("experiment/index.html").contents;
    static const std::regex reference(R"re(\s(src|href)="([^"]*)")re");
    std::vector<std::string> scripts, links;
    for (auto it = std::sregex_iterator(page.begin(), page.end(), reference); it != std::sregex_iterator(); ++it)
        ((*it)[1] == "src" ? scripts : links).push_back((*it)[2]);
    std::vector<std::string> expected;
    for (const ExperimentLibraryFile& file : jspsychLibraryFiles())
        if (file.path.ends_with(".js")) expected.push_back(file.path.substr(std::string("experiment/").size()));
    ASSERT_GE(expected.size(), 6u);  // jsPsych and five plugins
    EXPECT_EQ(expected.front(), "jspsych/jspsych.js");  // plugins need it loaded first
    expected.push_back("participants/index.js");
    expected.push_back("experiment.js");  // last: it uses all of the above
    EXPECT_EQ(scripts, expected);
    EXPECT_EQ(links, (std::vector<std::string>{"data:,", "jspsych/jspsych.css", "experiment.css"}));
    for (const std::string& url : scripts) EXPECT_EQ(url.find("//"), std::string::npos) << url;
    EXPECT_EQ(page.find("type=\"module\""), std::string::npos);  // module scripts are refused from file://
    // The title is escaped (the fixture's has & < > " ').
    EXPECT_NE(page.find("<title>" + escapeHtml(listing.title) + "</title>"), std::string::npos);
    EXPECT_NE(listing.title, escapeHtml(listing.title));
}

TEST(StudyExperiment, LibraryFilesComeFromTheFetchedPackagesIntoExperimentJspsych) {
    for (const ExperimentLibraryFile& file : jspsychLibraryFiles()) {
        EXPECT_EQ(file.path.rfind("experiment/jspsych/", 0), 0u) << file.path;
        EXPECT_EQ(file.source.find(".."), std::string::npos) << file.source;
    }
    const auto has = [](const std::string& source) {
        for (const ExperimentLibraryFile& file : jspsychLibraryFiles())
            if (file.source == source) return true;
        return false;
    };
    EXPECT_TRUE(has("LICENSE.txt"));  // the licence travels with the code
    EXPECT_TRUE(has("PINS.txt"));     // and which versions, with their SHA-512
    EXPECT_TRUE(has("jspsych/css/jspsych.css"));
}

TEST(StudyExperiment, SessionWritesTheDocumentedResultsHeaderWithoutFetchOrModules) {
    const std::string script = byPath(jspsychExperimentFiles(smallListing())).at("experiment/experiment.js").contents;
    // docs/experiment.md: the analysis reads these columns by name, in this order.
    const std::vector<std::string> header = {
        "participant", "phase", "trial", "story_id", "sentence_id", "version", "panel_code",
        "q1_response", "q1_correct", "q2_response", "q2_correct", "q3_response", "q3_correct",
        "q4_response", "q4_correct", "n_correct", "rating_a", "rating_b", "rating_c", "rating_d",
        "rating_point", "rating_vector", "rating_animator", "rating_uninflected", "rt_ms",
        "bg_hearing", "bg_asl_age", "bg_asl_school", "bg_daily_use"};
    const std::size_t start = script.find("const RESULT_COLUMNS = [");
    ASSERT_NE(start, std::string::npos);
    const std::string list = script.substr(start, script.find("];", start) - start);
    static const std::regex quoted(R"re("([a-z0-9_]+)")re");
    std::vector<std::string> columns;
    for (auto it = std::sregex_iterator(list.begin(), list.end(), quoted); it != std::sregex_iterator(); ++it)
        columns.push_back((*it)[1]);
    EXPECT_EQ(columns, header);
    // The code, without its comment lines (which say why there is no fetch).
    std::string code;
    for (std::size_t at = 0; at < script.size();) {
        const std::size_t end = std::min(script.find('\n', at), script.size());
        const std::string line = script.substr(at, end - at);
        if (line.find_first_not_of(' ') == std::string::npos || line.compare(line.find_first_not_of(' '), 2, "//") != 0)
            code += line + "\n";
        at = end + 1;
    }
    EXPECT_EQ(code.find("fetch("), std::string::npos);
    EXPECT_EQ(code.find("import "), std::string::npos);
    EXPECT_EQ(code.find("export "), std::string::npos);
    EXPECT_NE(script.find("\"signstim-results_\" + vars.participant + \".csv\""), std::string::npos);
}

TEST(StudyExperiment, SameListingGivesTheSameBytes) {
    const auto first = jspsychExperimentFiles(smallListing());
    const auto second = jspsychExperimentFiles(smallListing());
    ASSERT_EQ(first.size(), second.size());
    for (std::size_t i = 0; i < first.size(); ++i) {
        EXPECT_EQ(first[i].path, second[i].path);
        EXPECT_EQ(first[i].contents, second[i].contents) << first[i].path;
    }
}

TEST(StudyExperiment, StoriesWithMoreQuestionsThanTheResultsHoldAreRefused) {
    StudyListing listing = smallListing();
    while (listing.stories[1].questions.size() <= kExperimentMaxQuestions)
        listing.stories[1].questions.push_back(listing.stories[1].questions.front());
    EXPECT_THROW(jspsychExperimentFiles(listing), std::invalid_argument);
}

}  // namespace
}  // namespace signstim::stimuli
