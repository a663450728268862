// Every failed write, and signals (docs/errors.md): the built `signstim` binary on a full
// disk (a small tmpfs), with stdout on /dev/full, with an output name no writer handles, an
// unwritable place, a shorter re-render into a frame folder, and SIGTERM/SIGINT mid-render.
// The promise checked each time: a message naming the file and what the system said, the
// documented exit status, nothing incomplete under a final name, no temporary left.
#include "tests/app/run_command.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <spawn.h>
#include <sstream>
#include <string>
#include <sys/mount.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

extern char** environ;

using namespace signstim::test;
namespace fs = std::filesystem;

namespace {

const std::string kSigner = std::string(SIGNSTIM_SOURCE_DIR) + "/scenes/avatar/signer.glb";

fs::path testDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path dir = fs::path(SIGNSTIM_BINARY_DIR) / "test-tmp" / "output-failure" /
                         (std::string(info->test_suite_name()) + "." + info->name());
    ::umount2(dir.c_str(), MNT_DETACH);  // left mounted by an aborted run
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string signstimCommand() { return shellQuote(SIGNSTIM_EXE); }

std::vector<std::string> temporariesIn(const fs::path& dir) {
    std::vector<std::string> found;
    std::error_code ec;
    for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
        if (it->path().filename().string().find(".tmp-") != std::string::npos) found.push_back(it->path().string());
    return found;
}

std::string joined(const std::vector<std::string>& items) {
    std::string text;
    for (const std::string& item : items) text += item + " ";
    return text;
}

// A tmpfs of `size` mounted on `dir` for the test's lifetime: a disk that fills up.
class SmallDisk {
public:
    SmallDisk(const fs::path& dir, const std::string& size) : dir_(dir) {
        if (::mount("tmpfs", dir.c_str(), "tmpfs", 0, ("size=" + size).c_str()) != 0)
            failure_ = std::string("cannot mount a ") + size + " tmpfs on " + dir.string() + " (" +
                       std::strerror(errno) + "): the full-disk tests need root or CAP_SYS_ADMIN";
    }
    ~SmallDisk() {
        if (!failure_) ::umount2(dir_.c_str(), MNT_DETACH);
    }
    const std::optional<std::string>& failure() const { return failure_; }

private:
    fs::path dir_;
    std::optional<std::string> failure_;
};

#define MOUNT_OR_SKIP(disk)                                  \
    do {                                                     \
        if ((disk).failure()) GTEST_SKIP() << *(disk).failure(); \
    } while (0)

void fill(const fs::path& file, std::size_t bytes) { std::ofstream(file, std::ios::binary) << std::string(bytes, 'x'); }

std::string readAll(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// ---- running signstim as a child we can signal ---------------------------------------------

struct Running {
    pid_t pid = -1;
    fs::path log;  // its stdout and stderr
};

// Started with SIGINT and SIGTERM at their defaults: a test runner started in the background
// (`ctest &`) ignores SIGINT, and an ignored signal stays ignored across exec. In a process
// group of its own, so a signal can go to the whole group, as a terminal's Ctrl-C does.
Running start(const std::vector<std::string>& arguments, const fs::path& log) {
    std::vector<std::string> words = {SIGNSTIM_EXE};
    words.insert(words.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t defaults, none;
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGINT);
    sigaddset(&defaults, SIGTERM);
    sigemptyset(&none);
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    posix_spawnattr_setsigmask(&attributes, &none);
    posix_spawnattr_setpgroup(&attributes, 0);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETPGROUP);
    Running running;
    running.log = log;
    if (posix_spawn(&running.pid, SIGNSTIM_EXE, &actions, &attributes, argv.data(), environ) != 0) running.pid = -1;
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
    return running;
}

// Exit status, or -1 when it did not exit within `seconds` (it is then killed).
int waitFor(const Running& running, double seconds) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    int status = 0;
    while (std::chrono::steady_clock::now() < deadline) {
        if (::waitpid(running.pid, &status, WNOHANG) == running.pid)
            return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status) + 1000;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ::kill(running.pid, SIGKILL);
    ::waitpid(running.pid, &status, 0);
    return -1;
}

bool pollUntil(const std::function<bool()>& condition, double seconds) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < deadline) {
        if (condition()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return condition();
}

std::vector<pid_t> childrenOf(pid_t parent) {
    std::vector<pid_t> children;
    const CommandResult result = runShell("pgrep -P " + std::to_string(parent), Capture::StdoutOnly);
    std::istringstream lines(result.output);
    for (pid_t pid = 0; lines >> pid;) children.push_back(pid);
    return children;
}

// Gone, or a zombie (it has exited; only reaping is left to whoever adopted it).
bool processEnded(pid_t pid) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    if (!stat) return true;
    std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
    const std::size_t close = text.rfind(')');
    return close != std::string::npos && close + 2 < text.size() && text[close + 2] == 'Z';
}

// Starts a long render into `output` inside `dir`, waits until its temporary exists (and its
// ffmpeg when `video`), sends `signalNumber` to its whole process group (as a terminal's
// Ctrl-C and a batch system do), and checks what is left.
void interruptAndCheck(const std::vector<std::string>& arguments, const fs::path& dir, const fs::path& output,
                       int signalNumber, bool video) {
    const fs::path log = dir.parent_path() / (dir.filename().string() + ".log");
    const Running running = start(arguments, log);
    ASSERT_GT(running.pid, 0);
    // Begun: a temporary exists (for a folder: with a frame in it, so a partial render is there).
    auto entries = [&] {
        std::size_t n = 0;
        std::error_code ec;
        for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) ++n;
        return n;
    };
    // For a video, the MP4's temporary (the write probe, also a *.tmp-*, comes and goes first).
    const std::string videoTemporary = output.filename().string() + ".tmp-";
    auto videoBegun = [&] {
        for (const std::string& path : temporariesIn(dir))
            if (fs::path(path).filename().string().rfind(videoTemporary, 0) == 0) return true;
        return false;
    };
    const bool begun = pollUntil([&] { return video ? videoBegun() : !temporariesIn(dir).empty() && entries() >= 2; },
                                 60.0);
    std::vector<pid_t> encoders;
    if (begun && video) pollUntil([&] { return !(encoders = childrenOf(running.pid)).empty(); }, 10.0);
    // ffmpeg has a process group of its own: the group's signal reaches signstim alone.
    for (const pid_t encoder : encoders) EXPECT_NE(::getpgid(encoder), running.pid) << "ffmpeg " << encoder;
    ::kill(-running.pid, signalNumber);
    const int status = waitFor(running, 30.0);
    const std::string said = readAll(log);
    ASSERT_TRUE(begun) << "no temporary appeared in " << dir << "; it said:\n" << said;
    if (video) {
        EXPECT_FALSE(encoders.empty()) << "no ffmpeg child was seen";
    }
    EXPECT_EQ(status, 128 + signalNumber) << said;
    EXPECT_NE(said.find(signalNumber == SIGINT ? "interrupted by SIGINT" : "interrupted by SIGTERM"),
              std::string::npos)
        << said;
    EXPECT_FALSE(fs::exists(output)) << output;
    EXPECT_TRUE(temporariesIn(dir).empty()) << joined(temporariesIn(dir));
    for (const pid_t encoder : encoders) EXPECT_TRUE(processEnded(encoder)) << "ffmpeg " << encoder << " still runs";
    // ffmpeg's stderr is a pipe; no log file (an earlier design's) may appear in the system's
    // temporary folder.
    const std::string logPrefix = "signstim-ffmpeg-" + std::to_string(running.pid) + "-";
    for (const auto& entry : fs::directory_iterator(fs::temp_directory_path()))
        EXPECT_NE(entry.path().filename().string().rfind(logPrefix, 0), 0u) << entry.path();
}

}  // namespace

// ---- 1. full disk --------------------------------------------------------------------------

// `arguments` writes the still `name` (larger than 40 kB) onto a 40 kB disk: exit 3 naming it.
void stillOntoAFullDisk(const std::string& arguments, const std::string& name) {
    const fs::path dir = testDir();
    SmallDisk disk(dir, "40k");
    MOUNT_OR_SKIP(disk);
    const fs::path out = dir / name;
    const CommandResult r = runSignstim(arguments + " --out " + shellQuote(out.string()));
    EXPECT_EQ(r.status, 3) << r.output;
    EXPECT_NE(r.output.find(out.string() + ": cannot write: No space left on device"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_TRUE(temporariesIn(dir).empty()) << joined(temporariesIn(dir));
}

TEST(FullDisk, PngIsAnErrorNamingTheFileAndLeavesNothing) {
    stillOntoAFullDisk("pose --right A --size 1280x720", "pose.png");
}

// Stories write through the same path (app/clip_output): a full disk is exit 3 there too.
TEST(FullDisk, StoryStillIsAnErrorNamingTheFileAndLeavesNothing) {
    stillOntoAFullDisk("story " + shellQuote(std::string(SIGNSTIM_SOURCE_DIR) + "/scenes/stories/examples/the-question.json") +
                           " --version point --size 1280x720 --fps 2 --msaa 1 --quiet",
                       "story.png");
}

TEST(FullDisk, FrameFolderIsAnErrorAndLeavesTheEarlierRenderIntact) {
    const fs::path dir = testDir();
    SmallDisk disk(dir, "40k");
    MOUNT_OR_SKIP(disk);
    const fs::path out = dir / "give";
    // An earlier render that fits: two small frames.
    CommandResult r = runSignstim("render-gltf " + shellQuote(kSigner) + " -q --size 32x24 --frames 2 --out " +
                                  shellQuote(out.string()));
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string firstFrame = readAll(out / "frame_00001.png");
    ASSERT_FALSE(firstFrame.empty());
    // Sixteen 320x240 frames do not fit: some are written, then the disk is full.
    r = runSignstim("verb GIVE --subject 0.9 --object -0.6 --version point --size 320x240 --fps 10 --quiet --out " +
                    shellQuote(out.string()));
    EXPECT_EQ(r.status, 3) << r.output;
    EXPECT_NE(r.output.find(out.string() + "/frame_"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(out)) ++files;
    EXPECT_EQ(files, 2u);
    EXPECT_EQ(readAll(out / "frame_00001.png"), firstFrame);
    EXPECT_TRUE(temporariesIn(dir).empty()) << joined(temporariesIn(dir));

    // Without an earlier render the folder does not appear at all.
    fs::remove_all(out);
    r = runSignstim("verb GIVE --subject 0.9 --object -0.6 --version point --size 320x240 --fps 10 --quiet --out " +
                    shellQuote(out.string()));
    EXPECT_EQ(r.status, 3) << r.output;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_TRUE(temporariesIn(dir).empty()) << joined(temporariesIn(dir));
}

TEST(FullDisk, Mp4IsAnErrorNamingTheFileAndLeavesNothing) {
    const fs::path dir = testDir();
    SmallDisk disk(dir, "40k");
    MOUNT_OR_SKIP(disk);
    fill(dir / "filler", 32 * 1024);  // 8 kB left: room for the write probe, not for the video
    const fs::path out = dir / "give.mp4";
    const CommandResult r = runSignstim(
        "verb GIVE --subject 0.9 --object -0.6 --version point --size 320x240 --fps 10 --quiet --out " +
        shellQuote(out.string()));
    EXPECT_EQ(r.status, 3) << r.output;
    EXPECT_NE(r.output.find(out.string()), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_TRUE(temporariesIn(dir).empty()) << joined(temporariesIn(dir));
}

// ---- 2. stdout that cannot be written ------------------------------------------------------

TEST(StandardOutput, DevFullIsAnError) {
    // The story's timeline (44 KB) is larger than stdio's buffer: its failed write used to be
    // reported as "Input/output error" (issue 25 §10); common/standard_output keeps the reason.
    const std::string story = "story " + shellQuote(std::string(SIGNSTIM_SOURCE_DIR) + "/scenes/stories/story-01.json") +
                              " --version point --json";
    for (const std::string& command : {std::string("hand pose --shape A --json"),
                                      std::string("verb ASK --subject 0.9 --object -0.6 --version point --json"), story}) {
        // The braces: stdout goes to /dev/full, stderr to the capture.
        const CommandResult r = runShell("{ " + signstimCommand() + " " + command + " > /dev/full; }");
        EXPECT_EQ(r.status, 3) << command << "\n" << r.output;
        EXPECT_NE(r.output.find("signstim: error: cannot write to standard output: No space left on device"),
                  std::string::npos)
            << command << "\n" << r.output;
    }
}

// ---- 3. a closed pipe on stdout or stderr -------------------------------------------------

namespace {

// Runs signstim with `closed` (stdout or stderr) on a pipe whose reading end is already
// closed (`| head` that has exited, a dead `tee`); the other stream goes to `log`. Status as
// waitFor gives it (128 + signal + 1000 when killed by a signal).
int runIntoClosedPipe(const std::vector<std::string>& arguments, int closed, const fs::path& log) {
    int fds[2];
    if (::pipe(fds) != 0) return -1;
    ::close(fds[0]);
    std::vector<std::string> words = {SIGNSTIM_EXE};
    words.insert(words.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], closed);
    posix_spawn_file_actions_addopen(&actions, closed == STDOUT_FILENO ? STDERR_FILENO : STDOUT_FILENO, log.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t defaults;
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGPIPE);  // as a shell starts it, whatever the test runner does
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
    Running running;
    const int rc = posix_spawn(&running.pid, SIGNSTIM_EXE, &actions, &attributes, argv.data(), environ);
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[1]);
    return rc == 0 ? waitFor(running, 120.0) : -1;
}

}  // namespace

TEST(ClosedPipe, StdoutIsAnErrorNotADeathBySigpipe) {
    const fs::path dir = testDir();
    const fs::path log = dir / "stderr.log";
    const int status = runIntoClosedPipe({"hand", "pose", "--shape", "A", "--json"}, STDOUT_FILENO, log);
    const std::string said = readAll(log);
    EXPECT_EQ(status, 3) << "(1141: killed by SIGPIPE)\n" << said;
    EXPECT_NE(said.find("signstim: error: cannot write to standard output: Broken pipe"), std::string::npos) << said;
}

// Progress on stderr is best effort: a dead reader does not stop the render or change its
// result, and no temporary is left.
TEST(ClosedPipe, StderrDoesNotStopTheRender) {
    const fs::path dir = testDir();
    const fs::path out = dir / "ask.mp4";
    const int status = runIntoClosedPipe({"verb", "ASK", "--subject", "0.9", "--object", "-0.6", "--version", "point",
                                          "--size", "64x48", "--fps", "10", "--out", out.string()},
                                         STDERR_FILENO, dir.parent_path() / (dir.filename().string() + ".log"));
    EXPECT_EQ(status, 0) << "(1141: killed by SIGPIPE)";
    EXPECT_TRUE(fs::exists(out));
    EXPECT_TRUE(temporariesIn(dir).empty()) << joined(temporariesIn(dir));
}

// ---- 5. an output name no writer handles ---------------------------------------------------

TEST(OutputName, UnknownExtensionIsACommandLineErrorAndCreatesNothing) {
    const fs::path dir = testDir();
    const std::vector<std::string> commands = {
        "verb ASK --subject 0.9 --object -0.6 --version point --out " + shellQuote((dir / "a.jpg").string()),
        "render-gltf " + shellQuote(kSigner) + " --out " + shellQuote((dir / "b.gif").string()),
        "pose --right A --out " + shellQuote((dir / "c.jpeg").string()),
    };
    for (const std::string& command : commands) {
        const CommandResult r = runSignstim(command);
        EXPECT_EQ(r.status, 1) << command << "\n" << r.output;
        EXPECT_NE(r.output.find(".mp4"), std::string::npos) << r.output;  // lists what works
        EXPECT_NE(r.output.find("folder name without an extension"), std::string::npos) << r.output;
    }
    EXPECT_TRUE(fs::is_empty(dir));
}

// ---- 4. frame folders are written as a unit ------------------------------------------------

TEST(FrameFolder, ShorterRerenderLeavesNoStaleFrames) {
    const fs::path dir = testDir();
    const fs::path out = dir / "frames";
    const std::string render = "render-gltf " + shellQuote(kSigner) + " -q --size 32x24 --out " + shellQuote(out.string());
    CommandResult r = runSignstim(render + " --frames 5");
    ASSERT_EQ(r.status, 0) << r.output;
    ASSERT_TRUE(fs::exists(out / "frame_00005.png"));
    r = runSignstim(render + " --frames 2");
    ASSERT_EQ(r.status, 0) << r.output;
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(out)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"frame_00001.png", "frame_00002.png"}));
    EXPECT_TRUE(temporariesIn(dir).empty()) << joined(temporariesIn(dir));
}

// `--out frames/` (tab completion adds the '/'): the frames land in `frames`, first render
// and re-render alike; the temporary must be a sibling, not a folder inside the target.
TEST(FrameFolder, TrailingSlashWritesIntoTheFolder) {
    const fs::path dir = testDir();
    const fs::path out = dir / "frames";
    const std::string render = "render-gltf " + shellQuote(kSigner) + " -q --size 32x24 --out " +
                               shellQuote(out.string() + "/");
    for (const int frames : {3, 2}) {
        const CommandResult r = runSignstim(render + " --frames " + std::to_string(frames));
        ASSERT_EQ(r.status, 0) << r.output;
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(out)) names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        std::vector<std::string> expected = {"frame_00001.png", "frame_00002.png", "frame_00003.png"};
        expected.resize(static_cast<std::size_t>(frames));
        EXPECT_EQ(names, expected) << joined(names);
        EXPECT_TRUE(temporariesIn(dir).empty()) << joined(temporariesIn(dir));
    }
    // A trailing '/' on a file name asks for a folder and a file at once: a command-line error.
    const CommandResult r = runSignstim("render-gltf " + shellQuote(kSigner) + " -q --size 32x24 --out " +
                                        shellQuote((dir / "clip.mp4/").string()));
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("trailing '/'"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "clip.mp4"));
}

// A frame folder that is a mount point (docker -v, apptainer --bind) cannot be renamed or
// replaced: the render is staged inside it and moved into place; a shorter re-render leaves no
// stale frames, and nothing is written beside the folder.
TEST(FrameFolder, MountPointIsWrittenInside) {
    const fs::path dir = testDir();
    const fs::path out = dir / "frames";
    fs::create_directories(out);
    SmallDisk mount(out, "4m");
    MOUNT_OR_SKIP(mount);
    const std::string render = "render-gltf " + shellQuote(kSigner) + " -q --size 32x24 --out " +
                               shellQuote(out.string());
    for (const int frames : {4, 2}) {
        const CommandResult r = runSignstim(render + " --frames " + std::to_string(frames));
        ASSERT_EQ(r.status, 0) << r.output;
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(out)) names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        std::vector<std::string> expected = {"frame_00001.png", "frame_00002.png", "frame_00003.png",
                                             "frame_00004.png"};
        expected.resize(static_cast<std::size_t>(frames));
        EXPECT_EQ(names, expected) << joined(names);
        EXPECT_TRUE(temporariesIn(dir).empty()) << joined(temporariesIn(dir));
        std::vector<std::string> beside;
        for (const auto& entry : fs::directory_iterator(dir)) beside.push_back(entry.path().filename().string());
        EXPECT_EQ(beside, std::vector<std::string>{"frames"}) << joined(beside);
    }
}

TEST(FrameFolder, FolderHoldingOtherFilesIsRefusedBeforeRendering) {
    const fs::path dir = testDir();
    const fs::path out = dir / "mine";
    fs::create_directories(out);
    std::ofstream(out / "notes.txt") << "keep";
    const CommandResult r =
        runSignstim("verb ASK --subject 0.9 --object -0.6 --version point --out " + shellQuote(out.string()));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("notes.txt"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("choose a new or empty folder"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("frame "), std::string::npos) << r.output;  // nothing was rendered
    EXPECT_EQ(readAll(out / "notes.txt"), "keep");
    EXPECT_TRUE(temporariesIn(dir).empty()) << joined(temporariesIn(dir));
}

// ---- several outputs: a demo folder with a manifest is complete ----------------------------

// A re-run overwrites the files an earlier manifest lists: the earlier manifest goes first, so
// a re-run that fails part-way leaves no manifest over mixed contents.
TEST(Demo, FailedRerunLeavesNoManifest) {
    const fs::path dir = testDir();
    const fs::path out = dir / "demo";
    const std::string demo = "demo --verbs ASK --panel-size 64x64 --fps 10 --msaa 1 --quiet --out " +
                             shellQuote(out.string());
    CommandResult r = runSignstim(demo);
    ASSERT_EQ(r.status, 0) << r.output;
    ASSERT_TRUE(fs::exists(out / "manifest.json"));
    // The verb's video cannot be put in place on the re-run (a folder holds its name), after
    // the gallery has been written again.
    fs::path movie;
    for (const auto& entry : fs::directory_iterator(out / "verbs"))
        if (entry.path().extension() == ".mp4") movie = entry.path();
    ASSERT_FALSE(movie.empty());
    fs::remove(movie);
    fs::create_directories(movie / "blocker");
    r = runSignstim(demo);
    EXPECT_EQ(r.status, 3) << r.output;
    EXPECT_NE(r.output.find(movie.string() + ": cannot write: "), std::string::npos) << r.output;
    EXPECT_TRUE(fs::exists(out / "handshapes.png"));
    EXPECT_FALSE(fs::exists(out / "manifest.json"));
    EXPECT_TRUE(temporariesIn(dir).empty()) << joined(temporariesIn(dir));
}

// ---- bench: a refused write is exit 3, not an internal error -------------------------------

TEST(Bench, UnwritableScratchFolderIsAWriteError) {
    const CommandResult r =
        runSignstim("bench render --quick --frames 2 --rounds 1", Capture::StdoutAndStderr, "TMPDIR=/proc");
    EXPECT_EQ(r.status, 3) << r.output;
    EXPECT_NE(r.output.find("/proc/signstim-bench-"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
}

// ---- 6. signals ----------------------------------------------------------------------------
// The renders are long (thousands of frames at 160x120) so the signal always lands mid-render.

TEST(Interrupt, SigtermDuringMp4RemovesTemporariesAndEndsFfmpeg) {
    const fs::path dir = testDir();
    const fs::path out = dir / "ask.mp4";
    interruptAndCheck({"verb", "ASK", "--subject", "0.9", "--object", "-0.6", "--version", "point", "--size",
                       "160x120", "--fps", "1000", "--quiet", "--out", out.string()},
                      dir, out, SIGTERM, true);
}

TEST(Interrupt, SigtermDuringAStoryMp4RemovesTemporariesAndEndsFfmpeg) {
    const fs::path dir = testDir();
    const fs::path out = dir / "story.mp4";
    interruptAndCheck({"story", std::string(SIGNSTIM_SOURCE_DIR) + "/scenes/stories/examples/the-question.json",
                       "--version", "animator", "--size", "160x120", "--fps", "300", "--quiet", "--out", out.string()},
                      dir, out, SIGTERM, true);
}

TEST(Interrupt, SigintDuringMp4RemovesTemporariesAndEndsFfmpeg) {
    const fs::path dir = testDir();
    const fs::path out = dir / "signer.mp4";
    interruptAndCheck({"render-gltf", kSigner, "-q", "--size", "160x120", "--frames", "100000", "--out", out.string()},
                      dir, out, SIGINT, true);
}

TEST(Interrupt, SigtermDuringFrameFolderRemovesTheTemporaryFolder) {
    const fs::path dir = testDir();
    const fs::path out = dir / "frames";
    interruptAndCheck({"render-gltf", kSigner, "-q", "--size", "160x120", "--frames", "100000", "--out", out.string()},
                      dir, out, SIGTERM, false);
}

TEST(Interrupt, SigintDuringFrameFolderRemovesTheTemporaryFolder) {
    const fs::path dir = testDir();
    const fs::path out = dir / "frames";
    interruptAndCheck({"verb", "ASK", "--subject", "0.9", "--object", "-0.6", "--version", "point", "--size",
                       "160x120", "--fps", "1000", "--quiet", "--out", out.string()},
                      dir, out, SIGINT, false);
}

// ---- 7. an unwritable place is found before any work ---------------------------------------

TEST(OutputPlace, UnwritableLocationIsFoundBeforeRendering) {
    for (const std::string out : {"/proc/x.mp4", "/proc/signstim-frames"}) {
        const auto begin = std::chrono::steady_clock::now();
        const CommandResult r = runSignstim("verb ASK --subject 0.9 --object -0.6 --version point --size 160x120 --out " + out);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
        EXPECT_EQ(r.status, 3) << r.output;
        EXPECT_NE(r.output.find(out + ": cannot write: "), std::string::npos) << r.output;
        EXPECT_EQ(r.output.find("frame "), std::string::npos) << r.output;  // no frame was rendered
        EXPECT_EQ(r.output.find("Success"), std::string::npos) << r.output;
        EXPECT_LT(seconds, 5.0) << r.output;
    }
}
