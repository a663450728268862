#pragma once
// Every output file goes through here (docs/errors.md, "What is left on disk").
//  - A file is written to a temporary beside its target and renamed onto it only when every
//    byte was written and the file closed without error: a failure (disk full, I/O error) or
//    an interruption never leaves an incomplete file under the final name.
//  - A folder of frames is written as a unit: into a temporary sibling folder, renamed into
//    place at the end (TemporaryFolder).
//  - Each write, close and rename is checked; errno is captured right after the failing call
//    and reported as IoError ("out/a.png: cannot write: No space left on device", exit 3).
//  - Temporaries are created under the cleanup registry's lock and registered
//    (common/cleanup.hpp), so a signal removes them too.
// No fsync: the promise is about failed and interrupted runs, not power loss, and syncing
// every frame of a PNG sequence would cost more than encoding it.
#include <filesystem>
#include <string>
#include <string_view>

namespace signstim {

// Writes `bytes` to `path` atomically. Creates missing parent folders. Throws IoError naming
// `path` with the system's reason.
void writeFileAtomic(const std::filesystem::path& path, std::string_view bytes);

// Creates `path` (which must not exist: typically inside a TemporaryFolder) and writes
// `bytes` to it, removing it again on failure. Errors name `nameInMessages` (the file's
// final name; default `path`).
void writeNewFile(const std::filesystem::path& path, std::string_view bytes,
                  const std::filesystem::path& nameInMessages = {});

// A temporary name next to `target` (same folder, so rename() is atomic), unique per process
// and call: TARGET.tmp-HOST-PID-N. Trailing separators of `target` are ignored ("frames/").
// Not unique across machines that share a folder and a host name, or PID namespaces on one
// host: TemporaryFile and TemporaryFolder pass over a name that exists.
std::filesystem::path temporaryPathFor(const std::filesystem::path& target);

// Removes, under `dir`, the temporaries this machine's processes left when they were killed
// outright (SIGKILL, a power cut: no chance to clean up): TARGET.tmp-HOST-PID-N of this host
// whose PID no longer runs. Another machine's temporaries (a shared cluster folder) are left
// alone. Returns how many were removed.
std::size_t removeStaleTemporaries(const std::filesystem::path& dir);

// `path` without trailing '/' ("frames/" -> "frames"; "/" stays): tab completion adds one to
// folder names, and a temporary built from "frames/" would land inside the folder.
std::filesystem::path withoutTrailingSeparators(const std::filesystem::path& path);

// True when `dir` is an existing folder that is the root of a mount (a container's bind mount,
// a tmpfs): it cannot be renamed or replaced, only written inside.
bool isMountPoint(const std::filesystem::path& dir);

// Makes sure `dir` exists (creating it and its parents) and that a file can be created in it,
// by creating and removing one. Throws IoError naming `dir` with the system's reason. Call
// before long work so a bad output location fails in the first second.
void ensureWritableDirectory(const std::filesystem::path& dir);

// The same check for an output `target` (a file, or a frame folder written as a unit): its
// parent folder is created if missing and must accept a new file; for a frame folder that is
// a mount point (isMountPoint), the folder itself must. Errors name `target`.
void checkOutputWritable(const std::filesystem::path& target);

// A temporary file beside `target`, created empty (O_EXCL) and registered for removal on a
// signal. Removed when destroyed without commit(). Write it with write(), or let another
// program write it (ffmpeg), then commit().
// A target that is a character device (/dev/null, /dev/full, a terminal) is written into
// directly: renaming a file onto it would replace the device node (as root, in a container);
// path() is then the target, and nothing can be left incomplete under a name.
class TemporaryFile {
public:
    explicit TemporaryFile(std::filesystem::path target);
    ~TemporaryFile();
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;

    const std::filesystem::path& path() const { return temporary_; }
    const std::filesystem::path& target() const { return target_; }
    // The open file (write-only), e.g. to hand to a child process as its output.
    int descriptor() const { return descriptor_; }
    // Appends all of `bytes`; IoError naming the target on failure.
    void write(std::string_view bytes);
    // Closes the file (checked) and renames it onto the target.
    void commit();

private:
    std::filesystem::path target_;
    std::filesystem::path temporary_;
    int descriptor_ = -1;
    bool committed_ = false;
    bool direct_ = false;  // the target is a character device, written into as it is
};

// A temporary folder beside `target` (TARGET.tmp-HOST-PID-N), created and registered for removal
// on a signal; removed with its contents when destroyed without commit(). commit() puts it in
// place of `target`: renamed when `target` does not exist, else exchanged with it atomically
// (renameat2 RENAME_EXCHANGE) and the old folder removed (the caller checks beforehand that
// replacing it is wanted). Where the file system has no exchange, the old folder is renamed
// aside and the new one in (two steps). When `target` is a mount point, the temporary folder
// is inside it (TARGET/.signstim-frames.tmp-PID-N) and commit() renames each file into
// `target` and removes the files it did not write: each file is replaced atomically, the
// folder is not.
class TemporaryFolder {
public:
    explicit TemporaryFolder(std::filesystem::path target);
    ~TemporaryFolder();
    TemporaryFolder(const TemporaryFolder&) = delete;
    TemporaryFolder& operator=(const TemporaryFolder&) = delete;

    const std::filesystem::path& path() const { return temporary_; }
    const std::filesystem::path& target() const { return target_; }
    void commit();

private:
    void commitInside();

    std::filesystem::path target_;
    std::filesystem::path temporary_;
    bool inside_ = false;  // staged inside a mount-point target
    bool committed_ = false;
};

}  // namespace signstim
