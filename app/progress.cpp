#include "app/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace signstim::app {

using Clock = std::chrono::steady_clock;

ProgressReporter::ProgressReporter(std::string label, double total, bool quiet)
    : label_(std::move(label)), total_(std::max(1.0, total)), quiet_(quiet), terminal_(::isatty(STDERR_FILENO) == 1),
      start_(Clock::now()), last_(start_) {}

ProgressReporter::~ProgressReporter() { end(); }

double ProgressReporter::elapsedSeconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

void ProgressReporter::update(double done, const std::string& what) {
    done_ = done;
    if (quiet_) return;
    const auto now = Clock::now();
    if (now - last_ < std::chrono::milliseconds(terminal_ ? 250 : 10000)) return;
    last_ = now;
    print(what, false);
}

void ProgressReporter::stepDone(double done, const std::string& what) {
    done_ = done;
    if (quiet_) return;
    last_ = Clock::now();
    print(what, !terminal_);
}

void ProgressReporter::end() {
    if (ended_) return;
    ended_ = true;
    if (!quiet_ && terminal_ && printed_) std::fputc('\n', stderr);
}

void ProgressReporter::print(const std::string& what, bool step) {
    const double elapsed = elapsedSeconds();
    const double fraction = std::min(1.0, done_ / total_);
    std::string eta = ", estimating";
    if (fraction >= 1.0) {
        eta.clear();
    } else if (done_ > 0.0 && elapsed > 1.0) {
        const double left = elapsed / fraction - elapsed;
        char text[32];
        std::snprintf(text, sizeof text, ", %d:%02d left", static_cast<int>(left) / 60, static_cast<int>(left) % 60);
        eta = text;
    }
    if (terminal_) {
        const int width = 24;
        std::string bar(static_cast<std::size_t>(fraction * width), '#');
        bar.resize(width, '.');
        std::fprintf(stderr, "\r%s [%s] %3.0f%%  %s%s   ", label_.c_str(), bar.c_str(), 100.0 * fraction, what.c_str(),
                     eta.c_str());
        printed_ = true;
    } else {
        std::fprintf(stderr, "%s: %.0f%% %s%s%s\n", label_.c_str(), 100.0 * fraction, what.c_str(), step ? " done" : "",
                     eta.c_str());
    }
    std::fflush(stderr);
}

}  // namespace signstim::app
