#pragma once
// Runs a helper program (Rscript) to its end or a time limit, the way signstim runs ffmpeg
// (renderer/video_encoder.cpp): spawned with initChildSpawnAttributes (its own process group,
// default signal actions) and registered with the cleanup under one CleanupLock, so that
// SIGINT/SIGTERM to signstim end it too (common/cleanup.hpp). Its standard output and error
// go to one log file (the caller's temporary folder, removed with it).
#include <filesystem>
#include <string>
#include <vector>

namespace signstim::analysis {

struct ChildRun {
    bool notFound = false;   // the program is not on PATH (or the path does not exist)
    std::string startError;  // another reason it could not be started ("" when it started)
    bool timedOut = false;   // ended by SIGTERM (SIGKILL after a grace period) at the limit
    int exitCode = -1;       // its exit status; -1 when killed by a signal
    int signal = 0;          // the signal that ended it, 0 when it exited
    std::string output;      // what it printed (stdout and stderr, interleaved)
    double seconds = 0;      // wall time
    bool succeeded() const { return startError.empty() && !notFound && !timedOut && exitCode == 0; }
};

// argv[0] is looked up on PATH (posix_spawnp). Waits at most `timeoutSeconds`.
// `fixedAddresses`: the child runs without address-space randomization (Linux personality
// ADDR_NO_RANDOMIZE, as `setarch -R` does; best effort). lme4's Eigen code takes different
// vectorized paths at different memory alignments, so the same fit can differ in its last
// digits from run to run; at fixed addresses it gives the same bytes every time.
ChildRun runChild(const std::vector<std::string>& argv, const std::filesystem::path& logFile, double timeoutSeconds,
                  bool fixedAddresses = false);

}  // namespace signstim::analysis
