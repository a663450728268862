// `signstim analyze` and `signstim simulate-results` as a researcher runs them, on the small
// study rendered by the built binary: synthetic results of its 4 participants analysed into a
// report folder (the same bytes on a second run), and each kind of mistake refused with its
// exit status and a message naming the file, line and column (or the flag).
#include "tests/app/run_command.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using signstim::test::Capture;
using signstim::test::runSignstim;
using signstim::test::shellQuote;

const std::string kScenes = fs::path(SIGNSTIM_SOURCE_DIR).append("scenes").string();
const std::string kSmall = fs::path(SIGNSTIM_SOURCE_DIR).append("tests/app/data/small-study.json").string();

fs::path freshDir(const std::string& name) {
    const fs::path dir = fs::path(SIGNSTIM_BINARY_DIR) / "analysis_cli_test" / name;
    fs::remove_all(dir);
    fs::create_directories(dir.parent_path());
    return dir;
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void writeFile(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

// The small study, rendered once per test process: CTest runs this file's tests in one process
// (tests/app/study_tests.cmake, ONE_PROCESS; 14 s of CPU a render under gcc). Read only.
const fs::path& smallStudy() {
    static const fs::path dir = [] {
        const fs::path d = freshDir(std::string("study-") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        const auto r = runSignstim("study " + shellQuote(kSmall) + " --quiet --quick --out " + shellQuote(d.string()) + " --scenes " +
                                   shellQuote(kScenes));
        EXPECT_EQ(r.status, 0) << r.output;
        return d;
    }();
    return dir;
}

fs::path simulate(const std::string& name, const std::string& flags = "") {
    const fs::path out = freshDir(name);
    const auto r = runSignstim("simulate-results --study " + shellQuote(smallStudy().string()) + " --out " + shellQuote(out.string()) + " " + flags);
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("4 SYNTHETIC results files"), std::string::npos) << r.output;
    return out;
}

// Without the mixed models unless `flags` asks for them (R takes seconds; its tests are below).
std::string analyze(const fs::path& results, const fs::path& out, const std::string& flags = "") {
    return "analyze " + shellQuote(results.string()) + " --study " + shellQuote(smallStudy().string()) + " --out " +
           shellQuote(out.string()) + " " + (flags.find("--models") == std::string::npos ? "--models none " : "") + flags;
}

TEST(AnalysisCli, SyntheticResultsOfARenderedStudyBecomeAReportWithTheSameBytesTwice) {
    const fs::path results = simulate("synthetic");
    ASSERT_TRUE(fs::exists(results / "signstim-results_P01_SYNTHETIC.csv"));
    const fs::path first = freshDir("report-1"), second = freshDir("report-2");
    const auto r = runSignstim(analyze(results, first));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("report.html: SYNTHETIC DATA; 4 of 4 participants; 0 data warning(s)"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("phase 1 comprehension: "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("Kruskal-Wallis H(3) = "), std::string::npos) << r.output;
    ASSERT_EQ(runSignstim(analyze(results, second)).status, 0);
    std::size_t files = 0;
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(first)) {
        if (!e.is_regular_file()) continue;
        ++files;
        const fs::path relative = fs::relative(e.path(), first);
        EXPECT_EQ(readFile(e.path()), readFile(second / relative)) << relative;
        EXPECT_EQ(relative.string().find(".tmp"), std::string::npos) << relative;
    }
    EXPECT_EQ(files, 5u + 2u * 4u + 3u);  // report, 3 CSVs, JSON; 4 figures as SVG and PNG; models.R and its 2 CSVs
    const nlohmann::json summary = nlohmann::json::parse(readFile(first / "summary.json"));
    EXPECT_EQ(summary["study"]["participants"], 4);
    EXPECT_TRUE(summary["synthetic"].get<bool>());
    // A second analysis into the same folder replaces the report.
    ASSERT_EQ(runSignstim(analyze(results, first, "--alpha 0.01")).status, 0);
    EXPECT_EQ(nlohmann::json::parse(readFile(first / "summary.json"))["settings"]["alpha"], 0.01);
}

TEST(AnalysisCli, MistakesExitWithTheirStatusNamingWhatToChange) {
    const fs::path results = simulate("mistakes", "--effect none --seed 3");
    const fs::path p1 = results / "signstim-results_P01_SYNTHETIC.csv";
    std::string text = readFile(p1);
    const std::size_t firstRow = text.find("\r\nP01,1,") + 2;
    const std::size_t versionAt = text.find(",story-", firstRow);
    const std::size_t comma = text.find(',', versionAt + 1);  // story_id,sentence_id,version
    const std::size_t versionStart = text.find(',', comma + 1) + 1;
    const std::size_t versionEnd = text.find(',', versionStart);
    std::string bad = text;
    bad.replace(versionStart, versionEnd - versionStart, "vectr");
    const fs::path badDir = freshDir("bad-results");
    writeFile(badDir / "signstim-results_P01.csv", bad);
    const fs::path out = freshDir("mistakes-report");
    auto r = runSignstim(analyze(badDir, out));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("signstim-results_P01.csv:3: field 'version': 'vectr' is not a version of this study"),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(out));

    r = runSignstim(analyze(results, out, "--alpha 0"));
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("field '--alpha'"), std::string::npos) << r.output;

    r = runSignstim("analyze " + shellQuote(results.string()) + " --study " + shellQuote(results.string()) + " --out " +
                    shellQuote(out.string()));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("no manifest.json"), std::string::npos) << r.output;

    // A folder holding someone's files is not replaced.
    const fs::path busy = freshDir("busy");
    writeFile(busy / "notes.txt", "mine");
    r = runSignstim(analyze(results, busy));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("holds 'notes.txt', which is not part of an analysis report"), std::string::npos) << r.output;
    EXPECT_EQ(readFile(busy / "notes.txt"), "mine");

    // A scoring disagreement is a warning (exit 0, listed) and with --strict an error.
    std::string disagreeing = text;
    const std::size_t correctAt = disagreeing.find(",1,", disagreeing.find("\r\nP01,1,") + 20);
    disagreeing.replace(correctAt, 3, ",0,");  // some qN_correct or n_correct now disagrees
    const fs::path warnDir = freshDir("warn-results");
    writeFile(warnDir / "signstim-results_P01.csv", disagreeing);
    r = runSignstim(analyze(warnDir, freshDir("warn-report")));
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("signstim: warning: "), std::string::npos) << r.output;
    r = runSignstim(analyze(warnDir, freshDir("strict-report"), "--strict"));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("--strict makes them errors"), std::string::npos) << r.output;

    r = runSignstim("simulate-results --study " + shellQuote(smallStudy().string()) + " --out " + shellQuote(freshDir("x").string()) +
                    " --accuracy animator=1.5");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("field '--accuracy': animator: expected a number between 0 and 1 (exclusive)"), std::string::npos)
        << r.output;
}

TEST(AnalysisCli, AColumnMapReadsAnotherProgramsColumnNames) {
    const fs::path results = simulate("mapped", "--seed 8");
    const fs::path renamed = freshDir("renamed");
    for (const fs::directory_entry& e : fs::directory_iterator(results)) {
        std::string text = readFile(e.path());
        text.replace(text.find("participant,phase,trial"), 23, "participant_id,phase,trial");
        writeFile(renamed / e.path().filename(), text);
    }
    const fs::path map = renamed.parent_path() / "gorilla-columns.json";
    writeFile(map, "{\"format\": \"signstim-results-columns\", \"version\": 1, \"columns\": {\"participant\": \"participant_id\"}}\n");
    auto r = runSignstim(analyze(renamed, freshDir("mapped-report-no-map")));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("field 'participant': this column is missing from the header"), std::string::npos) << r.output;
    r = runSignstim(analyze(renamed, freshDir("mapped-report"), "--columns " + shellQuote(map.string())));
    EXPECT_EQ(r.status, 0) << r.output;
}

// Without Rscript on PATH the analysis runs, says on stderr and in the report that the models
// were not fitted and how to get them, and exits 0; --models require makes that exit 3 with
// nothing written. The report holds the script and its data to run elsewhere.
TEST(AnalysisCli, WithoutRTheReportSaysHowToGetTheModelsAndRequireFails) {
    const fs::path results = simulate("no-r", "--seed 5");
    // A PATH without Rscript (an empty folder: signstim is run by its full path).
    const fs::path bin = freshDir("no-r-bin");
    fs::create_directories(bin);
    const fs::path out = freshDir("no-r-report");
    auto r = runSignstim(analyze(results, out, "--models auto"), Capture::StdoutAndStderr, "PATH=" + shellQuote(bin.string()));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("warning: 'Rscript' was not found on PATH"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("apt install r-base-core r-cran-lme4 r-cran-ordinal"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("mixed models not fitted (R not found)"), std::string::npos) << r.output;
    const std::string html = readFile(out / "report.html");
    EXPECT_NE(html.find("The mixed models were not fitted</b> (R not found)"), std::string::npos);
    EXPECT_TRUE(fs::exists(out / "models/models.R"));
    EXPECT_TRUE(fs::exists(out / "models/comprehension.csv"));
    EXPECT_FALSE(fs::exists(out / "models/models-output.csv"));
    EXPECT_EQ(nlohmann::json::parse(readFile(out / "summary.json"))["mixedModels"]["status"], "R not found");

    const fs::path required = freshDir("no-r-required");
    r = runSignstim(analyze(results, required, "--models require"), Capture::StdoutAndStderr,
                    "PATH=" + shellQuote(bin.string()));
    EXPECT_EQ(r.status, 3) << r.output;
    EXPECT_NE(r.output.find("the mixed models were not fitted (--models require)"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(required));

    r = runSignstim(analyze(results, required, "--models maybe"));
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("field '--models'"), std::string::npos) << r.output;
    r = runSignstim(analyze(results, required, "--reference nosuch"));
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("'nosuch' is not a version of this study"), std::string::npos) << r.output;
}

// SIGTERM while R runs: signstim ends R (its registered child) and removes the temporary
// folder with R's data, exits 143, and writes no report. The "R" here is a stand-in that
// records its process id and sleeps (the real one would do the same, only less predictably).
TEST(AnalysisCli, SigtermWhileRRunsEndsRAndLeavesNothing) {
    const fs::path results = simulate("sigterm", "--seed 6");
    const fs::path dir = freshDir("sigterm-run");
    const fs::path tmp = dir / "tmp", fake = dir / "slow-Rscript", pidFile = dir / "r.pid";
    fs::create_directories(tmp);
    writeFile(fake, "#!/bin/sh\necho $$ > " + shellQuote(pidFile.string()) + "\nexec sleep 60\n");
    fs::permissions(fake, fs::perms::owner_all);
    const fs::path out = dir / "report";
    // signstim in the background; once R has started, SIGTERM to signstim alone.
    const std::string then = " & pid=$!; i=0; while [ ! -s " + shellQuote(pidFile.string()) +
                             " ] && [ $i -lt 600 ]; do sleep 0.1; i=$((i+1)); done; kill -TERM $pid; wait $pid; echo status=$?";
    const auto r = runSignstim(analyze(results, out, "--models require --rscript " + shellQuote(fake.string())) + then,
                               Capture::StdoutAndStderr, "TMPDIR=" + shellQuote(tmp.string()));
    EXPECT_NE(r.output.find("status=143"), std::string::npos) << r.output;
    const std::string pid = readFile(pidFile);
    ASSERT_FALSE(pid.empty());
    EXPECT_NE(signstim::test::runShell("kill -0 " + pid.substr(0, pid.find('\n')) + " 2>/dev/null").status, 0)
        << "R's stand-in still runs";
    EXPECT_TRUE(fs::is_empty(tmp)) << "the temporary folder with R's data was left";
    EXPECT_FALSE(fs::exists(out));
}

}  // namespace
