#pragma once
// What an interrupted run leaves behind: nothing but the outputs it had completed.
//
// Design. One process-wide registry, guarded by one mutex, lists every temporary file and
// folder that exists right now and every child process (ffmpeg) that is running.
//  - main() calls startInterruptHandling() before any thread exists. It blocks SIGINT,
//    SIGTERM and SIGHUP in every thread (threads inherit the mask) and starts one thread
//    that waits for them with sigwait(); no code runs in an asynchronous signal handler.
//  - On a signal, that thread takes the registry lock and never gives it back: it sends
//    SIGTERM to the registered children (SIGKILL after a short grace period) and reaps them,
//    removes every registered temporary (folders with their contents), prints one line and
//    calls _exit(128 + signal) while still holding the lock.
//  - Everything that creates a temporary (open with O_CREAT, mkdir, spawning ffmpeg, which
//    writes its own temporary) does so while holding a CleanupLock and registers it before
//    letting go. So a temporary is either registered before the cleanup runs (and removed by
//    it), or its creation waits for the lock forever (and never happens): nothing can be
//    created after the cleanup ran. Renames onto final names need no lock: a rename that
//    lands before the cleanup leaves a complete file, one that does not never happens.
//  - A child is forgotten only after it has exited (waitForChild), so the cleanup never
//    signals a process id the system has given to someone else.
// Signals that were ignored when signstim started (`signstim ... &` in a script ignores
// SIGINT) stay ignored. Tests that use the libraries without main() get no signal thread;
// the registry then only records.
#include <filesystem>
#include <mutex>
#include <spawn.h>
#include <sys/types.h>

namespace signstim {

// Holds the registry lock while it lives. Create a temporary, then register it, under one.
class CleanupLock {
public:
    CleanupLock();
    CleanupLock(const CleanupLock&) = delete;
    CleanupLock& operator=(const CleanupLock&) = delete;

    // A file or folder (removed with its contents) to delete if the run is interrupted.
    void addTemporary(const std::filesystem::path& path);
    // Forget a temporary that was renamed onto its final name or removed.
    void removeTemporary(const std::filesystem::path& path);
    // A child process to end if the run is interrupted.
    void addChild(pid_t pid);

private:
    std::unique_lock<std::mutex> lock_;
};

// Waits for the registered child `pid` to exit, forgets it, and returns its wait status
// (as waitpid gives it; -1 if it could not be waited for).
int waitForChild(pid_t pid);

// Spawn attributes for a child: no blocked signals, default actions for the signals signstim
// handles or ignores (a child inherits the blocked mask otherwise, and would ignore SIGTERM;
// and SIGPIPE, which main() ignores), and a process group of its own (terminal and batch
// signals reach signstim alone; its cleanup ends the child). Call posix_spawnattr_destroy
// afterwards.
void initChildSpawnAttributes(posix_spawnattr_t* attributes);

// Called first in main(): see the design above. Exit status on a signal: 128 + its number
// (130 SIGINT, 143 SIGTERM, 129 SIGHUP).
void startInterruptHandling();

}  // namespace signstim
