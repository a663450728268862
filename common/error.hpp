#pragma once
// One error path for user mistakes (STYLE.md: "Errors, output, determinism").
// Anything the user can fix — a malformed file, an unknown name, a value out of range —
// is thrown as InputError naming the input, the line (when known) and the field. The
// `signstim` command turns it into one clear message and exit status 2; it never aborts.
#include <stdexcept>
#include <string>

namespace signstim {

// The "file" of errors about flags and arguments. An InputError naming it is a usage error:
// exit status 1 in every command (docs/errors.md), whatever the check that found it.
inline constexpr const char* kCommandLine = "<command line>";
// The "file" of errors about environment variables that stand for an option (SLURM_ARRAY_TASK_ID
// for --shard): a usage error too, exit status 1 (docs/errors.md).
inline constexpr const char* kEnvironment = "<environment>";

class InputError : public std::runtime_error {
public:
    // file: path or other name of the input ("<command line>" for flags); line: 1-based, 0
    // if unknown; field: JSON pointer, CSV column, flag name... (may be empty).
    InputError(std::string file, int line, std::string field, const std::string& message);
    // With a 1-based column as well ("story.json:12:31: ..."), for gloss and other text
    // where the line alone does not say where.
    InputError(std::string file, int line, int column, std::string field, const std::string& message);
    explicit InputError(const std::string& message);

    const std::string& file() const { return file_; }
    int line() const { return line_; }
    int column() const { return column_; }
    const std::string& field() const { return field_; }
    const std::string& detail() const { return detail_; }
    bool isCommandLine() const { return file_ == kCommandLine; }
    // A mistake in how signstim was started (flags, or the environment standing for a flag):
    // exit status 1 rather than 2.
    bool isUsage() const { return isCommandLine() || file_ == kEnvironment; }

private:
    std::string file_;
    int line_ = 0;
    int column_ = 0;
    std::string field_;
    std::string detail_;
};

// Errors that are not the user's fault but the environment's (no Vulkan device, ffmpeg
// missing, disk full). Exit status 3.
class EnvironmentError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A read or write the system refused (disk full, permission denied, I/O error): exit status 3.
// The message names the path and what the system said: "out/a.png: cannot write: No space
// left on device". Pass the errno captured right after the failing call (0: no system text).
class IoError : public EnvironmentError {
public:
    IoError(std::string path, const std::string& action, int errorNumber);
    IoError(std::string path, const std::string& action, const std::string& reason);

    const std::string& path() const { return path_; }

private:
    std::string path_;
};

}  // namespace signstim
