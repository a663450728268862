// signstim_review_page_fixture: writes a study output folder without the study renderer -- the
// review page of the fixture listing (review_page_fixture.hpp), tiny real H.264 MP4s and PNG
// posters made with ffmpeg -- and, given --python and --checker, runs the browser check
// (tests/browser/check_review_page.py) on it. CTest runs it (tests/stimuli/CMakeLists.txt):
//
//   --case pass            the check must pass (exit 0)
//   --case missing-video   one clip deleted: the check must fail naming it
//   --case wrong-duration  one clip listed 0.5 s longer than its file: the check must fail naming it
//   --case broken-video    one clip's bytes are not a video: the check must fail naming it
//   --case console-error   a script error added to the page: the check must fail on the console
//   --documents-only       only the study's documents (conditions, Gorilla sheets, overview.csv,
//                          sheets; no media, no browser): for check_conditions_for_psychopy.py
//   --experiment           also the study's documents (conditions, Gorilla sheets, overview.csv),
//                          the jsPsych experiment (third_party/jspsych) and manifest.json, and the
//                          checker is tests/browser/run_experiment.py (at 1366x768, the screen
//                          the rating page must fit), given --screenshots DIR for its pictures
//
// For the failing cases this program exits 0 only when the checker exits 1 and says what was
// expected, so a checker that crashes, or fails for another reason, fails the test. Exit 77
// (a CTest skip, never a pass) when ffmpeg, the Python or the browser is missing.
#include "common/atomic_file.hpp"
#include "stimuli/study/jspsych_bundle.hpp"
#include "stimuli/study/review_page.hpp"
#include "stimuli/study/study.hpp"
#include "stimuli/study/study_documents.hpp"
#include "stimuli/study/study_exports.hpp"
#include "tests/stimuli/review_page_fixture.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

extern char** environ;

namespace {

namespace fs = std::filesystem;
using namespace signstim::stimuli;

constexpr int skipped = 77;
constexpr const char* marker = ".review-page-fixture";  // only folders carrying it are replaced

struct Options {
    fs::path out;
    std::string testCase = "pass";
    bool small = false;
    std::string python, checker, screenshot;
    bool fullPage = false;
    bool experiment = false;
    bool documentsOnly = false;
    bool aslQuestions = false;  // issue 24: questions and instructions in ASL
    std::string screenshots;
};

struct RunResult {
    int status = -1;  // exit status, or -1 when it could not run or died of a signal
    std::string output;  // stdout and stderr together
};

// Runs argv[0] (looked up on PATH) with stdout and stderr captured; echoes the output when `echo`.
RunResult run(const std::vector<std::string>& argv, bool echo) {
    RunResult result;
    int pipeEnds[2];
    if (pipe(pipeEnds) != 0) return result;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addclose(&actions, pipeEnds[0]);
    posix_spawn_file_actions_adddup2(&actions, pipeEnds[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, pipeEnds[1], STDERR_FILENO);
    posix_spawn_file_actions_addclose(&actions, pipeEnds[1]);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", 0, 0);
    std::vector<char*> args;
    for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
    args.push_back(nullptr);
    pid_t pid = 0;
    const int spawned = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(pipeEnds[1]);
    if (spawned != 0) {
        close(pipeEnds[0]);
        result.output = argv[0] + ": " + std::strerror(spawned);
        return result;
    }
    std::array<char, 4096> buffer;
    for (ssize_t n; (n = read(pipeEnds[0], buffer.data(), buffer.size())) != 0;) {
        if (n < 0) {
            if (errno == EINTR) continue;
            break;
        }
        result.output.append(buffer.data(), static_cast<std::size_t>(n));
        if (echo) std::cout.write(buffer.data(), n).flush();
    }
    close(pipeEnds[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

void loudSkip(const std::string& what) {
    std::cerr << "==============================================================================\n"
              << "review_page_fixture: SKIPPED: " << what << "\n"
              << "==============================================================================\n";
}

bool ffmpeg(const std::vector<std::string>& arguments) {
    std::vector<std::string> argv = {"ffmpeg", "-nostdin", "-hide_banner", "-loglevel", "error", "-y"};
    argv.insert(argv.end(), arguments.begin(), arguments.end());
    const RunResult result = run(argv, false);
    if (result.status != 0) std::cerr << "review_page_fixture: ffmpeg failed:\n" << result.output << "\n";
    return result.status == 0;
}

std::string seconds(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3f", value);
    return buffer;
}

// The MP4s and posters: one pair per version (a different test pattern and length each) and
// one 2x2 clip, copied under every name the listing gives.
bool writeMedia(const StudyListing& listing, const fs::path& out) {
    const fs::path media = out / ".media";
    fs::create_directories(media);
    static const char* const patterns[] = {"testsrc", "testsrc2", "smptebars", "rgbtestsrc"};
    const std::string rate = std::to_string(static_cast<int>(testing::reviewFixtureFps));
    for (std::size_t v = 0; v < listing.versions.size(); ++v) {
        const std::string base = (media / ("version-" + std::to_string(v))).string();
        if (!ffmpeg({"-f", "lavfi", "-i", std::string(patterns[v % 4]) + "=size=160x120:rate=" + rate, "-t",
                     seconds(testing::reviewFixtureSeconds(v)), "-c:v", "libx264", "-pix_fmt", "yuv420p", "-movflags",
                     "+faststart", base + ".mp4", "-frames:v", "1", base + ".png"}))
            return false;
    }
    const std::string quad = (media / "quad").string();
    std::vector<std::string> quadArguments;
    for (std::size_t k = 0; k < 4; ++k)
        for (const std::string& a : {std::string("-f"), std::string("lavfi"), std::string("-t"),
                                     seconds(testing::reviewFixtureLikertSeconds), std::string("-i"),
                                     std::string(patterns[k]) + "=size=160x120:rate=" + rate})
            quadArguments.push_back(a);
    for (const char* a : {"-filter_complex", "[0][1][2][3]xstack=inputs=4:layout=0_0|w0_0|0_h0|w0_h0", "-c:v",
                                 "libx264", "-pix_fmt", "yuv420p", "-movflags", "+faststart"})
        quadArguments.push_back(a);
    quadArguments.push_back(quad + ".mp4");
    if (!ffmpeg(quadArguments) || !ffmpeg({"-i", quad + ".mp4", "-frames:v", "1", quad + ".png"})) return false;

    auto place = [&](const ListedClip& clip, const std::string& base) {
        for (const auto& [from, to] : {std::pair{base + ".mp4", clip.video}, std::pair{base + ".png", clip.poster}}) {
            if (to.empty()) continue;
            fs::create_directories((out / to).parent_path());
            fs::copy_file(from, out / to, fs::copy_options::overwrite_existing);
        }
        if (!clip.frames.empty()) {
            fs::create_directories(out / clip.frames);
            fs::copy_file(base + ".png", out / clip.frames / "frame_00001.png", fs::copy_options::overwrite_existing);
        }
    };
    for (const ListedStory& story : listing.stories)
        for (std::size_t v = 0; v < story.clips.size(); ++v)
            place(story.clips[v], (media / ("version-" + std::to_string(v))).string());
    for (const ListedSentence& sentence : listing.sentences) place(sentence.clip, quad);
    // Issue 24: the signed questions and instructions, as the last version's clip (its length is
    // reviewFixtureSignedSeconds).
    static_assert(testing::reviewFixtureSignedSeconds == 1.4, "the last version's clip lasts 1.4 s");
    const std::string signedMedia = (media / ("version-" + std::to_string(listing.versions.size() - 1))).string();
    for (const ListedStory& story : listing.stories)
        for (const ListedQuestion& question : story.questions)
            if (!question.clip.video.empty()) place(question.clip, signedMedia);
    for (const ListedInstruction& page : listing.instructions)
        if (!page.clip.video.empty()) place(page.clip, signedMedia);
    fs::remove_all(media);
    return true;
}

// What the checker must say for each failing case.
std::vector<std::string> expectedComplaints(const std::string& testCase) {
    if (testCase == "missing-video")
        return {"missing file clips/story-02_version-vector.mp4", "video clips/story-02_version-vector.mp4 does not load"};
    if (testCase == "wrong-duration") return {"video clips/story-03_version-animator.mp4: the browser reads"};
    if (testCase == "broken-video") return {"video clips/story-01_version-point.mp4 does not load"};
    if (testCase == "console-error") return {"console error", "reviewPageFixtureUndefined"};
    return {};
}

// The documents alone (conditions, Gorilla sheets, overview, sheets), as the study runner
// writes them: no ffmpeg, no browser.
int writeDocuments(const Options& options) {
    if (fs::exists(options.out) && !fs::exists(options.out / marker)) {
        std::cerr << "review_page_fixture: " << options.out.string() << " exists and is not a fixture folder\n";
        return 1;
    }
    fs::remove_all(options.out);
    fs::create_directories(options.out);
    signstim::writeFileAtomic(options.out / marker, "written by signstim_review_page_fixture\n");
    testing::ReviewFixtureShape shape;
    if (options.small) shape = {.stories = 4, .participants = 4, .likertSentences = 4};
    shape.signedQuestions = options.aslQuestions;  // issue 24: the clip columns of a signing study
    for (const StudyDocument& document : studyDocuments(testing::reviewFixtureListing(shape))) {
        fs::create_directories((options.out / document.path).parent_path());
        signstim::writeFileAtomic(options.out / document.path, document.contents);
    }
    std::cout << "review_page_fixture: wrote the study documents in " << options.out.string() << "\n";
    return 0;
}

int writeAndCheck(const Options& options) {
    if (options.documentsOnly) return writeDocuments(options);
    if (run({"ffmpeg", "-version"}, false).status != 0) {
        loudSkip("ffmpeg is not installed (apt-get install ffmpeg); it makes the fixture's MP4s");
        return skipped;
    }
    const std::vector<std::string> cases = {"pass", "missing-video", "wrong-duration", "broken-video", "console-error"};
    if (std::find(cases.begin(), cases.end(), options.testCase) == cases.end()) {
        std::cerr << "review_page_fixture: unknown --case " << options.testCase << "\n";
        return 2;
    }

    if (fs::exists(options.out)) {
        if (!fs::exists(options.out / marker)) {
            std::cerr << "review_page_fixture: " << options.out.string() << " exists and is not a fixture folder; "
                      << "not replacing it\n";
            return 1;
        }
        fs::remove_all(options.out);
    }
    fs::create_directories(options.out);
    signstim::writeFileAtomic(options.out / marker, "written by signstim_review_page_fixture\n");

    testing::ReviewFixtureShape shape;
    shape.withFrameFolders = true;
    shape.signedQuestions = options.aslQuestions;
    if (options.small) {
        shape.stories = 4;
        shape.participants = 4;
        shape.likertSentences = 4;
    }
    StudyListing listing = testing::reviewFixtureListing(shape);
    if (!writeMedia(listing, options.out)) return 1;

    if (options.testCase == "wrong-duration") listing.stories.at(2).clips.at(2).durationSeconds += 0.5;
    std::string page = reviewPageHtml(listing);
    if (options.testCase == "console-error")
        page.insert(page.rfind("</body>"), "<script>reviewPageFixtureUndefined();</script>\n");
    signstim::writeFileAtomic(options.out / "index.html", page);
    signstim::writeFileAtomic(options.out / "overview.csv", overviewCsv(listing));  // the page links it
    if (options.experiment) {
        std::vector<StudyDocument> documents = studyDocuments(listing);
        for (StudyDocument& document : experimentDocuments(listing, loadJspsychBundle())) documents.push_back(std::move(document));
        for (const StudyDocument& document : documents) {
            if (document.path == "index.html") continue;
            fs::create_directories((options.out / document.path).parent_path());
            signstim::writeFileAtomic(options.out / document.path, document.contents);
        }
        nlohmann::json manifest = nlohmann::json::object();
        manifest["study"] = listingToJson(listing);
        signstim::writeFileAtomic(options.out / "manifest.json", manifest.dump(1) + "\n");
    }
    if (options.testCase == "missing-video") fs::remove(options.out / "clips/story-02_version-vector.mp4");
    if (options.testCase == "broken-video")
        signstim::writeFileAtomic(options.out / "clips/story-01_version-point.mp4", "this is not an MP4 file\n");
    std::cout << "review_page_fixture: wrote " << (options.out / "index.html").string() << " (case "
              << options.testCase << ")\n";

    if (options.checker.empty()) return 0;
    if (access(options.python.c_str(), X_OK) != 0) {
        loudSkip(options.python + " is missing: the browser check runs with Debian's python3 and its "
                                  "python3-selenium (apt-get install chromium chromium-driver python3-selenium)");
        return skipped;
    }
    std::vector<std::string> argv = {options.python, options.checker, options.out.string()};
    if (options.experiment) {
        for (const char* a : {"--width", "1366", "--height", "768"}) argv.push_back(a);
        if (!options.screenshots.empty()) {
            argv.push_back("--screenshots");
            argv.push_back(options.screenshots);
        }
    } else if (!options.screenshot.empty()) {
        argv.push_back("--screenshot");
        argv.push_back(options.screenshot);
        if (options.fullPage) argv.push_back("--full-page");
    }
    const RunResult result = run(argv, true);
    if (result.status == skipped) return skipped;
    if (options.testCase == "pass") return result.status == 0 ? 0 : 1;

    if (result.status != 1) {
        std::cerr << "review_page_fixture: FAIL: the checker should have failed with exit 1 on case "
                  << options.testCase << ", it exited " << result.status << "\n";
        return 1;
    }
    for (const std::string& complaint : expectedComplaints(options.testCase)) {
        if (result.output.find(complaint) == std::string::npos) {
            std::cerr << "review_page_fixture: FAIL: the checker failed, but did not say \"" << complaint << "\"\n";
            return 1;
        }
    }
    std::cout << "review_page_fixture: the checker failed on case " << options.testCase << ", as it should\n";
    return 0;
}

int usage() {
    std::cerr << "usage: signstim_review_page_fixture --out DIR [--case pass|missing-video|wrong-duration|"
                 "broken-video|console-error] [--small] [--asl-questions] [--experiment | --documents-only]\n"
                 "         [--python PYTHON --checker check_review_page.py [--screenshot FILE.png [--full-page]]]\n"
                 "         [--experiment --python PYTHON --checker run_experiment.py [--screenshots DIR]]\n";
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
        const char* v = nullptr;
        if (arg == "--small") options.small = true;
        else if (arg == "--full-page") options.fullPage = true;
        else if (arg == "--experiment") options.experiment = true;
        else if (arg == "--documents-only") options.documentsOnly = true;
        else if (arg == "--asl-questions") options.aslQuestions = true;
        else if (arg == "--screenshots" && (v = value())) options.screenshots = v;
        else if (arg == "--out" && (v = value())) options.out = v;
        else if (arg == "--case" && (v = value())) options.testCase = v;
        else if (arg == "--python" && (v = value())) options.python = v;
        else if (arg == "--checker" && (v = value())) options.checker = v;
        else if (arg == "--screenshot" && (v = value())) options.screenshot = v;
        else return usage();
    }
    if (options.out.empty() || (!options.checker.empty() && options.python.empty())) return usage();
    try {
        return writeAndCheck(options);
    } catch (const std::exception& error) {
        std::cerr << "review_page_fixture: " << error.what() << "\n";
        return 1;
    }
}
