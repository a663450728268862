#include "common/cleanup.hpp"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <time.h>
#include <unistd.h>
#include <vector>

namespace signstim {
namespace fs = std::filesystem;

namespace {

struct Registry {
    std::mutex mutex;
    std::vector<fs::path> temporaries;
    std::vector<pid_t> children;
    sigset_t handled;  // the signals the signal thread waits for (children get their defaults back)
};

// Never destroyed: the signal thread may use it while static destructors run at exit.
Registry& registry() {
    static Registry* instance = [] {
        auto* r = new Registry;
        sigemptyset(&r->handled);
        return r;
    }();
    return *instance;
}

const char* signalName(int signalNumber) {
    switch (signalNumber) {
        case SIGINT: return "SIGINT";
        case SIGTERM: return "SIGTERM";
        case SIGHUP: return "SIGHUP";
        default: return "a signal";
    }
}

void sleepMilliseconds(long milliseconds) {
    timespec pause{0, milliseconds * 1000000L};
    while (nanosleep(&pause, &pause) != 0 && errno == EINTR) {
    }
}

// Ends the children, removes the temporaries, says so, exits: all with the lock held, so that
// no other thread creates a temporary or starts a child after this has looked.
[[noreturn]] void stopEverything(int signalNumber) {
    Registry& r = registry();
    r.mutex.lock();  // never released: _exit below
    for (const pid_t child : r.children) ::kill(child, SIGTERM);
    // ffmpeg stops within milliseconds on SIGTERM; one that does not is killed after a second.
    std::vector<pid_t> running = r.children;
    for (int waited = 0; !running.empty() && waited < 100; ++waited) {
        std::erase_if(running, [](pid_t child) {
            int status = 0;
            return ::waitpid(child, &status, WNOHANG) != 0;
        });
        if (!running.empty()) sleepMilliseconds(10);
    }
    for (const pid_t child : running) {
        ::kill(child, SIGKILL);
        int status = 0;
        while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
        }
    }
    // Newest first: a file inside a temporary folder goes before the folder.
    for (auto it = r.temporaries.rbegin(); it != r.temporaries.rend(); ++it) {
        std::error_code ec;
        fs::remove_all(*it, ec);
    }
    const std::string line = std::string("signstim: interrupted by ") + signalName(signalNumber) +
                             ": stopped; the output being written was removed (nothing incomplete is left under "
                             "its name); outputs completed before stay\n";
    [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, line.data(), line.size());
    ::_exit(128 + signalNumber);
}

}  // namespace

CleanupLock::CleanupLock() : lock_(registry().mutex) {}

void CleanupLock::addTemporary(const fs::path& path) { registry().temporaries.push_back(path); }

void CleanupLock::removeTemporary(const fs::path& path) {
    auto& list = registry().temporaries;
    if (auto it = std::find(list.begin(), list.end(), path); it != list.end()) list.erase(it);
}

void CleanupLock::addChild(pid_t pid) { registry().children.push_back(pid); }

int waitForChild(pid_t pid) {
    // Wait without reaping: until the child is reaped its id cannot be reused, so the signal
    // thread may still signal it safely. Then forget and reap it under the lock.
    siginfo_t info{};
    while (::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOWAIT) < 0 && errno == EINTR) {
    }
    CleanupLock lock;
    auto& children = registry().children;
    std::erase(children, pid);
    int status = 0;
    pid_t reaped = -1;
    while ((reaped = ::waitpid(pid, &status, 0)) < 0 && errno == EINTR) {
    }
    return reaped == pid ? status : -1;
}

void initChildSpawnAttributes(posix_spawnattr_t* attributes) {
    posix_spawnattr_init(attributes);
    sigset_t none;
    sigemptyset(&none);
    posix_spawnattr_setsigmask(attributes, &none);
    // main() ignores SIGPIPE, and an ignored signal stays ignored across exec: the child gets
    // the default back, as it would from a shell.
    sigset_t defaults = registry().handled;
    sigaddset(&defaults, SIGPIPE);
    posix_spawnattr_setsigdefault(attributes, &defaults);
    // Its own process group: a terminal's Ctrl-C (sent to the foreground group) and a batch
    // system's SIGTERM to the job's group then reach signstim alone, whose cleanup ends the
    // child after it has stopped writing; a child that got the signal too would fail first
    // and could turn the interruption into an "ffmpeg failed" error.
    posix_spawnattr_setpgroup(attributes, 0);
    posix_spawnattr_setflags(attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETPGROUP);
}

void startInterruptHandling() {
    Registry& r = registry();
    for (const int signalNumber : {SIGINT, SIGTERM, SIGHUP}) {
        struct sigaction current{};
        if (::sigaction(signalNumber, nullptr, &current) == 0 && current.sa_handler == SIG_IGN) continue;
        sigaddset(&r.handled, signalNumber);
    }
    pthread_sigmask(SIG_BLOCK, &r.handled, nullptr);
    const sigset_t waitFor = r.handled;
    std::thread([waitFor] {
        int signalNumber = 0;
        while (sigwait(&waitFor, &signalNumber) != 0) {
        }
        stopEverything(signalNumber);
    }).detach();
}

}  // namespace signstim
