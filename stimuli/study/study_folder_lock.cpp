#include "stimuli/study/study_folder_lock.hpp"

#include "common/error.hpp"
#include "stimuli/study/study_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <system_error>

namespace signstim::stimuli {

namespace fs = std::filesystem;

namespace {

int openLockFile(const fs::path& file) {
    const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) {
        const int error = errno;
        throw IoError(file.string(), "cannot open the study folder's lock", error);
    }
    return fd;
}

void flockOrThrow(int fd, int operation, const fs::path& file) {
    while (::flock(fd, operation) != 0) {
        if (errno == EINTR) continue;
        const int error = errno;
        throw IoError(file.string(), "cannot lock", error);
    }
}

}  // namespace

StudyFolderLock::StudyFolderLock(const fs::path& dir) : dir_(dir) {
    std::error_code error;
    fs::create_directories(dir / ".signstim", error);
    if (error) throw IoError((dir / ".signstim").string(), "cannot create", error.value());
    lockFd_ = openLockFile(dir / ".signstim" / "lock");
    try {
        runningFd_ = openLockFile(dir / ".signstim" / "running");
        lock();
    } catch (...) {
        ::close(lockFd_);
        if (runningFd_ >= 0) ::close(runningFd_);
        throw;
    }
}

StudyFolderLock::~StudyFolderLock() {
    // Closing the descriptors releases both locks.
    ::close(runningFd_);
    ::close(lockFd_);
}

void StudyFolderLock::lock() {
    if (locked_) return;
    flockOrThrow(lockFd_, LOCK_EX, dir_ / ".signstim" / "lock");
    locked_ = true;
}

void StudyFolderLock::unlock() {
    if (!locked_) return;
    ::flock(lockFd_, LOCK_UN);
    locked_ = false;
}

bool StudyFolderLock::othersRunning() {
    while (::flock(runningFd_, LOCK_EX | LOCK_NB) != 0) {
        if (errno == EINTR) continue;
        if (errno == EWOULDBLOCK) return true;
        const int error = errno;
        throw IoError((dir_ / ".signstim" / "running").string(), "cannot lock", error);
    }
    return false;
}

void StudyFolderLock::beginRun() {
    // From exclusive (othersRunning said none) or nothing to shared: never waits, as no run
    // takes `running` exclusively without holding `lock`, which we hold.
    flockOrThrow(runningFd_, LOCK_SH, dir_ / ".signstim" / "running");
    char host[256] = "";
    ::gethostname(host, sizeof host - 1);
    const std::string text = "PID " + std::to_string(::getpid()) + " on host " + host + "\n";
    if (::ftruncate(runningFd_, 0) == 0) {
        [[maybe_unused]] const ssize_t written = ::pwrite(runningFd_, text.data(), text.size(), 0);
    }
}

std::string StudyFolderLock::holder() const {
    char buffer[300] = "";
    const ssize_t n = ::pread(runningFd_, buffer, sizeof buffer - 1, 0);
    std::string text = n > 0 ? std::string(buffer, static_cast<std::size_t>(n)) : "";
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    return text.empty() ? "another signstim run" : text;
}

void checkStudyOutFolder(const fs::path& dir, bool force) {
    std::error_code error;
    const fs::path absolute = fs::weakly_canonical(fs::absolute(dir, error), error);
    const auto refuse = [&](const std::string& why) { return InputError(dir.string(), 0, "--out", why); };
    if (!absolute.empty()) {
        if (absolute == absolute.root_path())
            throw refuse("is the root of the file system: give the study a folder of its own (nothing was written)");
        if (const char* home = std::getenv("HOME"); home && *home && fs::equivalent(absolute, fs::path(home), error))
            throw refuse("is your home folder: give the study a folder of its own, e.g. --out ~/my-study (nothing was written)");
        if (fs::equivalent(absolute, fs::current_path(error), error))
            throw refuse("is the working directory itself: give the study a folder of its own, e.g. --out out/study (nothing "
                         "was written)");
    }
    if (!fs::exists(dir, error)) return;
    if (!fs::is_directory(dir, error)) throw refuse("is a file; a study is a folder: choose a new or empty folder");
    if (fs::exists(dir / kStudyPlanFile, error) || force) return;
    for (const fs::directory_entry& e : fs::directory_iterator(dir, error)) {
        // Another run (a shard) may have just taken the folder: its lock comes before its plan.
        if (e.path().filename() == ".signstim") continue;
        throw refuse("holds '" + e.path().filename().string() +
                     "' and is not a study folder (no .signstim/plan.json): choose a new or empty folder, or give --force "
                     "to write the study beside what is there (nothing is deleted that signstim did not write)");
    }
}

}  // namespace signstim::stimuli
