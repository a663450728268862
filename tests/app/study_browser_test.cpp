// A real study (rendered by the built signstim: real MP4s from our encoder) in headless Chromium:
//  - its review page, opened by tests/browser/check_review_page.py: no console errors, every
//    referenced file exists, every video loads with the duration the manifest gives;
//  - its jsPsych experiment (--experiment jspsych), run for two participants by a scripted
//    responder (tests/browser/run_experiment.py): the CSV each session saves has one row per
//    trial in the schedule's order, the answers' correct flags and the ratings unmapped to
//    versions, and the checker rejects a CSV with a swapped rating.
// Skipped, never passed, when Chromium, its driver or python3-selenium is missing, or (the
// experiment) when jsPsych has not been fetched (scripts/fetch-jspsych.sh).
#include "tests/app/run_command.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace {

namespace fs = std::filesystem;
using signstim::test::runShell;
using signstim::test::runSignstim;
using signstim::test::shellQuote;

TEST(StudyBrowser, ReviewPageOfARenderedStudyPassesInHeadlessChromium) {
    const std::string scenes = fs::path(SIGNSTIM_SOURCE_DIR).append("scenes").string();
    const std::string small = fs::path(SIGNSTIM_SOURCE_DIR).append("tests/app/data/small-study.json").string();
    const fs::path dir = fs::path(SIGNSTIM_BINARY_DIR) / "study_browser_test" / "study";
    fs::remove_all(dir);
    const auto run = runSignstim("study " + shellQuote(small) + " --quiet --out " + shellQuote(dir.string()) +
                                 " --scenes " + shellQuote(scenes));
    ASSERT_EQ(run.status, 0) << run.output;
    ASSERT_TRUE(fs::exists(dir / "index.html"));
    const fs::path checker = fs::path(SIGNSTIM_SOURCE_DIR) / "tests" / "browser" / "check_review_page.py";
    const auto check = runShell(shellQuote(SIGNSTIM_BROWSER_PYTHON) + " " + shellQuote(checker.string()) + " " +
                                shellQuote(dir.string()) + " --screenshot " +
                                shellQuote((dir.parent_path() / "review-page.png").string()));
    if (check.status == 77) GTEST_SKIP() << check.output;
    EXPECT_EQ(check.status, 0) << check.output;
}

TEST(StudyBrowser, JsPsychExperimentRunsTwoParticipantsAndSavesWhatTheyAnswered) {
    const std::string scenes = fs::path(SIGNSTIM_SOURCE_DIR).append("scenes").string();
    const std::string small = fs::path(SIGNSTIM_SOURCE_DIR).append("tests/app/data/small-study.json").string();
    const fs::path dir = fs::path(SIGNSTIM_BINARY_DIR) / "study_browser_test" / "experiment-study";
    fs::remove_all(dir);
    const auto run = runSignstim("study " + shellQuote(small) + " --quiet --experiment jspsych --out " +
                                 shellQuote(dir.string()) + " --scenes " + shellQuote(scenes));
    if (run.status == 3 && run.output.find("scripts/setup.sh") != std::string::npos)
        GTEST_SKIP() << "jsPsych is not fetched here: " << run.output;
    ASSERT_EQ(run.status, 0) << run.output;
    ASSERT_TRUE(fs::exists(dir / "experiment" / "index.html"));
    const fs::path runner = fs::path(SIGNSTIM_SOURCE_DIR) / "tests" / "browser" / "run_experiment.py";
    const fs::path results = dir.parent_path() / "experiment-results";
    fs::remove_all(results);
    fs::create_directories(results);
    const auto check = runShell(shellQuote(SIGNSTIM_BROWSER_PYTHON) + " " + shellQuote(runner.string()) + " " +
                                shellQuote(dir.string()) + " --screenshots " +
                                shellQuote((dir.parent_path() / "experiment-screens").string()) + " --results " +
                                shellQuote(results.string()));
    if (check.status == 77) GTEST_SKIP() << check.output;
    ASSERT_EQ(check.status, 0) << check.output;

    // The loop closes: what the two participants saved analyses into the report, as saved,
    // with no data warning (every answer re-scored and every rating unmapped agrees).
    const fs::path report = dir.parent_path() / "experiment-report";
    fs::remove_all(report);
    const auto analysis = runSignstim("analyze " + shellQuote(results.string()) + " --strict --study " +
                                      shellQuote(dir.string()) + " --out " + shellQuote(report.string()));
    ASSERT_EQ(analysis.status, 0) << analysis.output;
    EXPECT_TRUE(fs::exists(report / "report.html"));
    const std::string summary = signstim::test::readFile(report / "summary.json");
    EXPECT_NE(summary.find("P01"), std::string::npos) << summary.substr(0, 2000);
    EXPECT_NE(summary.find("P02"), std::string::npos) << summary.substr(0, 2000);
}

}  // namespace
