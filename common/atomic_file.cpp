#include "common/atomic_file.hpp"

#include "common/cleanup.hpp"
#include "common/error.hpp"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <fcntl.h>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>

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

void removeRegistered(const fs::path& path) {
    CleanupLock lock;
    std::error_code ignored;
    fs::remove_all(path, ignored);
    lock.removeTemporary(path);
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

// close() can report a write that failed late (NFS, quotas): it is a write error too.
int closeChecked(int descriptor) {
    return ::close(descriptor) == 0 ? 0 : errno;
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
    const fs::path probe = temporaryPathFor(folder / ".signstim-write-test");
    const int descriptor = createRegistered(probe, name);
    int error = writeAll(descriptor, "x");
    const int closeError = closeChecked(descriptor);
    if (error == 0) error = closeError;
    removeRegistered(probe);
    if (error != 0) throw IoError(name.string(), kCannotWrite, error);
}

}  // namespace

fs::path temporaryPathFor(const fs::path& target) {
    static std::atomic<unsigned> counter{0};
    fs::path tmp = target;
    tmp += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    return tmp;
}

void ensureWritableDirectory(const fs::path& dir) { probeFolder(dir, dir); }

void checkOutputWritable(const fs::path& target) { probeFolder(target.parent_path(), target); }

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

TemporaryFile::TemporaryFile(fs::path target)
    : target_(std::move(target)), temporary_(temporaryPathFor(target_)) {
    descriptor_ = createRegistered(temporary_, target_);
}

TemporaryFile::~TemporaryFile() {
    if (committed_) return;
    if (descriptor_ >= 0) ::close(descriptor_);
    removeRegistered(temporary_);
}

void TemporaryFile::write(std::string_view bytes) {
    if (descriptor_ < 0) throw std::logic_error("TemporaryFile::write after commit");
    if (const int error = writeAll(descriptor_, bytes); error != 0) throw IoError(target_.string(), kCannotWrite, error);
}

void TemporaryFile::commit() {
    const int descriptor = descriptor_;
    descriptor_ = -1;
    if (const int error = closeChecked(descriptor); error != 0) throw IoError(target_.string(), kCannotWrite, error);
    CleanupLock lock;
    if (std::rename(temporary_.c_str(), target_.c_str()) != 0) {
        const int error = errno;
        throw IoError(target_.string(), kCannotWrite, error);  // the destructor removes the temporary
    }
    lock.removeTemporary(temporary_);
    committed_ = true;
}

TemporaryFolder::TemporaryFolder(fs::path target)
    : target_(std::move(target)), temporary_(temporaryPathFor(target_)) {
    CleanupLock lock;
    if (::mkdir(temporary_.c_str(), 0777) != 0) {
        const int error = errno;
        throw IoError(target_.string(), kCannotWrite, error);
    }
    lock.addTemporary(temporary_);
}

TemporaryFolder::~TemporaryFolder() {
    if (!committed_) removeRegistered(temporary_);
}

void TemporaryFolder::commit() {
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
        if (::renameat2(AT_FDCWD, temporary_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) != 0) {
            const int exchangeError = errno;
            if (exchangeError != EINVAL && exchangeError != ENOSYS)
                throw IoError(target_.string(), kCannotWrite, exchangeError);
            // No atomic exchange on this file system: move the old folder aside (registered, so
            // an interruption removes it), then the new one in.
            const fs::path aside = temporaryPathFor(target_);
            if (std::rename(target_.c_str(), aside.c_str()) != 0) {
                const int asideError = errno;
                throw IoError(target_.string(), kCannotWrite, asideError);
            }
            lock.addTemporary(aside);
            if (std::rename(temporary_.c_str(), target_.c_str()) != 0) {
                const int renameError = errno;
                std::rename(aside.c_str(), target_.c_str());  // put the old one back
                lock.removeTemporary(aside);
                throw IoError(target_.string(), kCannotWrite, renameError);
            }
            lock.removeTemporary(temporary_);
            committed_ = true;
            temporary_ = aside;  // the old render, removed below
        }
        committed_ = true;
    }
    // The old render, under a registered temporary name.
    removeRegistered(temporary_);
}

}  // namespace signstim
