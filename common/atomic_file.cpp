#include "common/atomic_file.hpp"

#include "common/cleanup.hpp"
#include "common/error.hpp"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <set>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace signstim {
namespace fs = std::filesystem;

namespace {

const char* const kCannotWrite = "cannot write";

// Creates `path` (must not exist) under the cleanup lock and registers it. Returns the
// descriptor; throws IoError naming `name` with errno taken right after open().
int createRegistered(const fs::path& path, const fs::path& name) {
    CleanupLock lock;
    const int descriptor = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (descriptor < 0) {
        const int error = errno;
        throw IoError(name.string(), kCannotWrite, error);
    }
    lock.addTemporary(path);
    return descriptor;
}

// Creates a new temporary beside `target` with `create` (0, or the errno of its failing call)
// under the cleanup lock, registers it and returns its path. A name that exists is passed
// over: TARGET.tmp-PID-N is unique within one machine, but array tasks on several machines
// writing one shared folder (docs/slurm.md) can have the same process id — in per-job PID
// namespaces, the same small one — and all write plan.json when they start.
template <class Create>
fs::path createTemporary(const fs::path& target, const fs::path& name, Create create) {
    for (int attempt = 1;; ++attempt) {
        fs::path path = temporaryPathFor(target);
        CleanupLock lock;
        const int error = create(path);
        if (error == 0) {
            lock.addTemporary(path);
            return path;
        }
        if (error != EEXIST || attempt == 1000) throw IoError(name.string(), kCannotWrite, error);
    }
}

int openNewFile(const fs::path& path, int& descriptor) {
    descriptor = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    return descriptor < 0 ? errno : 0;
}

// Removes a registered temporary, then forgets it. The removal runs without the cleanup lock:
// removing a large folder (an abandoned or replaced render) can take seconds, and a signal
// arriving meanwhile must not wait for it. Removing creates nothing, so the design in
// common/cleanup.hpp still holds; a cleanup racing with this removes what is left.
std::error_code removeRegistered(const fs::path& path) {
    std::error_code ec;
    fs::remove_all(path, ec);
    CleanupLock lock;
    lock.removeTemporary(path);
    return ec;
}

// All of `bytes` to `descriptor`: 0, or the errno of the write that failed.
int writeAll(int descriptor, std::string_view bytes) {
    const char* data = bytes.data();
    std::size_t left = bytes.size();
    while (left > 0) {
        const ssize_t n = ::write(descriptor, data, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        data += n;
        left -= static_cast<std::size_t>(n);
    }
    return 0;
}

// close() can report a write that failed late (NFS, quotas): it is a write error too. EINTR
// is not: Linux has released the descriptor by then (retrying could close another thread's
// new file), and the data went wherever it was going to go.
int closeChecked(int descriptor) {
    if (::close(descriptor) == 0 || errno == EINTR) return 0;
    return errno;
}

void createParents(const fs::path& dir, const fs::path& name) {
    if (dir.empty()) return;
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) throw IoError(name.string(), kCannotWrite, ENOTDIR);
    fs::create_directories(dir, ec);
    if (ec) throw IoError(name.string(), kCannotWrite, ec.message());
}

// Creates the folder if missing, then creates, writes one byte to, and removes a file in it:
// that catches a read-only or full file system, a missing permission and places like /proc.
void probeFolder(const fs::path& dir, const fs::path& name) {
    const fs::path folder = dir.empty() ? fs::path(".") : dir;
    createParents(folder, name);
    int descriptor = -1;
    const fs::path probe = createTemporary(folder / ".signstim-write-test", name,
                                           [&](const fs::path& path) { return openNewFile(path, descriptor); });
    int error = writeAll(descriptor, "x");
    const int closeError = closeChecked(descriptor);
    if (error == 0) error = closeError;
    removeRegistered(probe);
    if (error != 0) throw IoError(name.string(), kCannotWrite, error);
}

// True when `a` is `b` or inside it, comparing the folders as the system resolves them.
bool within(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    const fs::path inner = fs::weakly_canonical(fs::absolute(a, ec), ec);
    const fs::path outer = fs::weakly_canonical(fs::absolute(b, ec), ec);
    return std::mismatch(outer.begin(), outer.end(), inner.begin(), inner.end()).first == outer.end();
}

// The name a frame folder is staged under when the folder is a mount point (see
// TemporaryFolder): inside it, so that the frames can be renamed into place.
const char* const kStagingName = ".signstim-frames";

}  // namespace

fs::path withoutTrailingSeparators(const fs::path& path) {
    std::string text = path.native();
    while (text.size() > 1 && text.back() == '/') text.pop_back();
    return text;
}

bool isMountPoint(const fs::path& dir) {
    const fs::path folder = withoutTrailingSeparators(dir);
    struct statx info{};
    if (::statx(AT_FDCWD, folder.c_str(), 0, STATX_BASIC_STATS, &info) != 0 || !S_ISDIR(info.stx_mode)) return false;
    // A bind mount of a folder of the same file system has its parent's device number; the
    // kernel (5.8+) marks the root of every mount.
    if ((info.stx_attributes_mask & STATX_ATTR_MOUNT_ROOT) != 0) return (info.stx_attributes & STATX_ATTR_MOUNT_ROOT) != 0;
    const fs::path parent = folder.has_parent_path() ? folder.parent_path() : fs::path(".");
    struct stat here{}, above{};
    if (::stat(folder.c_str(), &here) != 0 || ::stat(parent.c_str(), &above) != 0) return false;
    return here.st_dev != above.st_dev;
}

namespace {

// This machine's name as it may appear in a file name (letters, digits, '-', '.').
const std::string& hostTag() {
    static const std::string tag = [] {
        char name[256] = {};
        if (::gethostname(name, sizeof name - 1) != 0 || name[0] == '\0') return std::string("host");
        std::string t;
        for (const char* c = name; *c; ++c)
            t += (std::isalnum(static_cast<unsigned char>(*c)) || *c == '-' || *c == '.') ? *c : '_';
        return t;
    }();
    return tag;
}

}  // namespace

fs::path temporaryPathFor(const fs::path& target) {
    static std::atomic<unsigned> counter{0};
    // Without the trailing '/' of "frames/": the temporary must be a sibling of the target,
    // not a file inside it. The host and PID say whose it is (removeStaleTemporaries).
    fs::path tmp = withoutTrailingSeparators(target);
    tmp += ".tmp-" + hostTag() + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    return tmp;
}

std::size_t removeStaleTemporaries(const fs::path& dir) {
    const std::string marker = ".tmp-" + hostTag() + "-";
    std::vector<fs::path> stale;
    std::error_code ec;
    for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        const std::size_t at = name.rfind(marker);
        if (at == std::string::npos) continue;
        // NAME.tmp-HOST-PID-N: the PID must be a number and no longer running here.
        const std::string rest = name.substr(at + marker.size());
        const std::size_t dash = rest.find('-');
        if (dash == std::string::npos || dash == 0) continue;
        const std::string pidText = rest.substr(0, dash);
        if (pidText.find_first_not_of("0123456789") != std::string::npos || pidText.size() > 9) continue;
        const pid_t pid = static_cast<pid_t>(std::stol(pidText));
        if (pid == ::getpid() || ::kill(pid, 0) == 0 || errno != ESRCH) continue;
        stale.push_back(it->path());
        if (it->is_directory(ec)) it.disable_recursion_pending();
    }
    for (const fs::path& p : stale) fs::remove_all(p, ec);
    return stale.size();
}

void ensureWritableDirectory(const fs::path& dir) { probeFolder(dir, dir); }

void checkOutputWritable(const fs::path& target) {
    const fs::path name = withoutTrailingSeparators(target);
    // A frame folder that is a mount point is written inside itself (TemporaryFolder); its
    // parent (often read-only in a container) is never written.
    if (isMountPoint(name)) {
        probeFolder(name, name);
        return;
    }
    probeFolder(name.parent_path(), name);
}

void writeFileAtomic(const fs::path& path, std::string_view bytes) {
    createParents(path.parent_path(), path);
    TemporaryFile temporary(path);
    temporary.write(bytes);
    temporary.commit();
}

void writeNewFile(const fs::path& path, std::string_view bytes, const fs::path& nameInMessages) {
    const fs::path& name = nameInMessages.empty() ? path : nameInMessages;
    const int descriptor = createRegistered(path, name);
    int error = writeAll(descriptor, bytes);
    const int closeError = closeChecked(descriptor);
    if (error == 0) error = closeError;
    if (error != 0) {
        removeRegistered(path);
        throw IoError(name.string(), kCannotWrite, error);
    }
    CleanupLock lock;
    lock.removeTemporary(path);
}

TemporaryFile::TemporaryFile(fs::path target) : target_(std::move(target)) {
    struct stat info {};
    if (::stat(target_.c_str(), &info) == 0 && S_ISCHR(info.st_mode)) {
        descriptor_ = ::open(target_.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
        if (descriptor_ < 0) {
            const int error = errno;
            throw IoError(target_.string(), kCannotWrite, error);
        }
        temporary_ = target_;
        direct_ = true;
        return;
    }
    temporary_ = createTemporary(target_, target_, [&](const fs::path& path) { return openNewFile(path, descriptor_); });
}

TemporaryFile::~TemporaryFile() {
    if (committed_) return;
    if (descriptor_ >= 0) ::close(descriptor_);
    if (!direct_) removeRegistered(temporary_);
}

void TemporaryFile::write(std::string_view bytes) {
    if (descriptor_ < 0) throw std::logic_error("TemporaryFile::write after commit");
    if (const int error = writeAll(descriptor_, bytes); error != 0) throw IoError(target_.string(), kCannotWrite, error);
}

void TemporaryFile::commit() {
    const int descriptor = descriptor_;
    descriptor_ = -1;
    if (const int error = closeChecked(descriptor); error != 0) throw IoError(target_.string(), kCannotWrite, error);
    if (direct_) {
        committed_ = true;
        return;
    }
    CleanupLock lock;
    if (std::rename(temporary_.c_str(), target_.c_str()) != 0) {
        const int error = errno;
        throw IoError(target_.string(), kCannotWrite, error);  // the destructor removes the temporary
    }
    lock.removeTemporary(temporary_);
    committed_ = true;
}

TemporaryFolder::TemporaryFolder(fs::path target) : target_(withoutTrailingSeparators(target)) {
    // A mount point (a container's bind mount) cannot be renamed or exchanged, and a sibling
    // would be on another file system: stage inside it instead (not atomic; see commit()).
    inside_ = isMountPoint(target_);
    temporary_ = createTemporary(inside_ ? target_ / kStagingName : target_, target_,
                                 [](const fs::path& path) { return ::mkdir(path.c_str(), 0777) == 0 ? 0 : errno; });
}

TemporaryFolder::~TemporaryFolder() {
    if (!committed_) removeRegistered(temporary_);
}

void TemporaryFolder::commit() {
    if (inside_) {
        commitInside();
        return;
    }
    fs::path old;  // the earlier render, under a registered temporary name, removed below
    {
        CleanupLock lock;
        if (std::rename(temporary_.c_str(), target_.c_str()) == 0) {
            lock.removeTemporary(temporary_);
            committed_ = true;
            return;
        }
        const int error = errno;
        if (error != ENOTEMPTY && error != EEXIST) throw IoError(target_.string(), kCannotWrite, error);
        // The target holds an earlier render: swap the two in one step, so the target always
        // names a complete folder; the temporary name then holds the old one.
        if (::renameat2(AT_FDCWD, temporary_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) == 0) {
            committed_ = true;
            old = temporary_;
        } else {
            const int exchangeError = errno;
            // EINVAL means "this file system has no exchange" except when one folder is inside
            // the other, which no fallback can fix either.
            if (exchangeError == EINVAL && (within(temporary_, target_) || within(target_, temporary_)))
                throw IoError(target_.string(), kCannotWrite,
                              "cannot replace a folder by one inside it (" + temporary_.string() + ")");
            if (exchangeError != EINVAL && exchangeError != ENOSYS)
                throw IoError(target_.string(), kCannotWrite, exchangeError);
            // No atomic exchange on this file system: move the old folder aside (registered, so
            // an interruption removes it), then the new one in. Between the two renames the
            // target does not exist (docs/errors.md).
            const fs::path aside = temporaryPathFor(target_);
            if (std::rename(target_.c_str(), aside.c_str()) != 0) {
                const int asideError = errno;
                throw IoError(target_.string(), kCannotWrite, asideError);
            }
            lock.addTemporary(aside);
            if (std::rename(temporary_.c_str(), target_.c_str()) != 0) {
                const int renameError = errno;
                if (std::rename(aside.c_str(), target_.c_str()) != 0) {
                    const int restoreError = errno;
                    // The only copy of the earlier render: never delete it; say where it is.
                    lock.removeTemporary(aside);
                    throw IoError(target_.string(), kCannotWrite,
                                  std::string(std::strerror(renameError)) +
                                      "; the earlier render could not be put back (" + std::strerror(restoreError) +
                                      ") and is kept as " + aside.string());
                }
                lock.removeTemporary(aside);
                throw IoError(target_.string(), kCannotWrite, renameError);
            }
            lock.removeTemporary(temporary_);
            committed_ = true;
            old = aside;
        }
    }
    // Outside the lock (removeRegistered): a big old render must not delay a signal's cleanup.
    if (const std::error_code ec = removeRegistered(old))
        throw IoError(target_.string(), "the new render is complete, but the earlier one could not be removed (it is "
                                        "left as " + old.string() + ")",
                      ec.message());
}

void TemporaryFolder::commitInside() {
    // Each frame is renamed onto its final name (one atomic step per file), then frames of an
    // earlier, longer render are removed. The folder as a whole is not replaced atomically: an
    // interruption here leaves new and earlier frames mixed (docs/errors.md).
    std::vector<fs::path> staged;
    std::error_code ec;
    for (fs::directory_iterator it(temporary_, ec), end; !ec && it != end; it.increment(ec)) staged.push_back(it->path());
    if (ec) throw IoError(target_.string(), "cannot read", ec.message());
    std::set<fs::path> fresh;
    for (const fs::path& file : staged) {
        const fs::path destination = target_ / file.filename();
        if (std::rename(file.c_str(), destination.c_str()) != 0) {
            const int error = errno;
            throw IoError(destination.string(), kCannotWrite, error);
        }
        fresh.insert(file.filename());
    }
    std::vector<fs::path> stale;
    for (fs::directory_iterator it(target_, ec), end; !ec && it != end; it.increment(ec)) {
        const fs::path name = it->path().filename();
        // Staging folders (this one, another run's) are not an earlier render's frames.
        if (fresh.count(name) == 0 && name.string().rfind(kStagingName, 0) != 0) stale.push_back(it->path());
    }
    if (ec) throw IoError(target_.string(), "cannot read", ec.message());
    for (const fs::path& file : stale)
        if (fs::remove(file, ec); ec) throw IoError(file.string(), "cannot remove an earlier frame", ec.message());
    committed_ = true;
    if (const std::error_code removeError = removeRegistered(temporary_))
        throw IoError(target_.string(), "the new render is complete, but its empty staging folder could not be "
                                        "removed (" + temporary_.string() + ")",
                      removeError.message());
}

}  // namespace signstim
