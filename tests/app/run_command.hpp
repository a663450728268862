#pragma once
// Running commands from the CLI tests: the built `signstim` binary (or any shell command),
// with its output and exit status, as a user would see them.
#include <filesystem>
#include <string>

namespace signstim::test {

struct CommandResult {
    int status = -1;     // exit status; -1 when the command could not run or did not exit
    std::string output;  // what it wrote (see Capture)
};

enum class Capture {
    StdoutAndStderr,  // both streams, interleaved (messages)
    StdoutOnly,       // stdout alone; stderr discarded (JSON on stdout)
};

// `command` through /bin/sh.
CommandResult runShell(const std::string& command, Capture capture = Capture::StdoutAndStderr);

// The signstim binary of this build with `arguments` (shell syntax: quote paths with
// shellQuote). `environment`: assignments put before the command, e.g. "SIGNSTIM_VALIDATION=1".
CommandResult runSignstim(const std::string& arguments, Capture capture = Capture::StdoutAndStderr,
                          const std::string& environment = "");

// The whole file (binary); empty when it cannot be read.
std::string readFile(const std::filesystem::path& path);

// `root`/`group`/`name`, removed if present; its parent created. With `create`, the folder
// itself is created too. For test outputs under the build tree.
std::filesystem::path freshDir(const std::filesystem::path& root, const std::string& group, const std::string& name,
                               bool create = false);

// `text` as one shell word: 'text', with any ' inside escaped.
std::string shellQuote(const std::string& text);

// A SYNTHETIC recording for the human-video tests, no person: `seconds` of ffmpeg's procedural
// test pattern (lavfi testsrc2) at `size` ("96x72") and `rate` fps, its hue turned by `hue`
// degrees so that each file differs, as H.264 yuv420p in `file` (its folder created). What
// ffmpeg said; status 0: written.
CommandResult writeSyntheticRecording(const std::filesystem::path& file, const std::string& size, int rate, double seconds,
                                      int hue);

}  // namespace signstim::test
