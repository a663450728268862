#include "analysis/child_process.hpp"

#include "common/cleanup.hpp"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <sys/personality.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

namespace signstim::analysis {

namespace {

// True once `pid` has exited; the child is not reaped (waitForChild does that, so the cleanup
// never signals an id the system has reused).
bool hasExited(pid_t pid) {
    siginfo_t info{};
    for (;;) {
        if (::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0) return info.si_pid == pid;
        if (errno != EINTR) return true;  // cannot be waited for: waitForChild will say so
    }
}

}  // namespace

ChildRun runChild(const std::vector<std::string>& argv, const std::filesystem::path& logFile, double timeoutSeconds,
                  bool fixedAddresses) {
    using Clock = std::chrono::steady_clock;
    ChildRun run;
    std::vector<std::string> args = argv;
    std::vector<char*> pointers;
    for (std::string& a : args) pointers.push_back(a.data());
    pointers.push_back(nullptr);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, logFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    posix_spawnattr_t attributes;
    initChildSpawnAttributes(&attributes);
    pid_t pid = -1;
    int rc = 0;
    const Clock::time_point start = Clock::now();
    {
        // Started and registered in one step (as ffmpeg): a signal finds it registered.
        CleanupLock lock;
        // The child inherits the personality at the spawn; ours is restored right after. Other
        // children are spawned under this lock too, so none inherits it by accident.
        const int previous = fixedAddresses ? ::personality(0xffffffff) : -1;
        if (previous != -1) ::personality(static_cast<unsigned long>(previous) | ADDR_NO_RANDOMIZE);
        rc = ::posix_spawnp(&pid, pointers[0], &actions, &attributes, pointers.data(), environ);
        if (previous != -1) ::personality(static_cast<unsigned long>(previous));
        if (rc == 0) lock.addChild(pid);
    }
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
    if (rc == ENOENT) {
        run.notFound = true;
        return run;
    }
    if (rc != 0) {
        run.startError = std::strerror(rc);
        return run;
    }

    const auto limit = std::chrono::duration<double>(timeoutSeconds);
    while (!hasExited(pid)) {
        if (Clock::now() - start > limit) {
            run.timedOut = true;
            // Its process group: Rscript runs R through a shell script, which may leave children.
            ::kill(-pid, SIGTERM);
            const Clock::time_point asked = Clock::now();
            while (!hasExited(pid) && Clock::now() - asked < std::chrono::seconds(3))
                std::this_thread::sleep_for(std::chrono::milliseconds(20));
            if (!hasExited(pid)) ::kill(-pid, SIGKILL);
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    const int status = waitForChild(pid);
    run.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (status != -1 && WIFEXITED(status)) run.exitCode = WEXITSTATUS(status);
    if (status != -1 && WIFSIGNALED(status)) run.signal = WTERMSIG(status);
    if (status == -1) run.startError = "its exit status could not be read (waitpid failed)";
    std::ifstream in(logFile, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    run.output = text.str();
    return run;
}

}  // namespace signstim::analysis
