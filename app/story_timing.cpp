#include "app/story_timing.hpp"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace signstim::app {
namespace {

// SPEC §6.2 and §6.3.
constexpr double kMostWristMmPerSecond = 2500.0;     // SPEC §6.2: wrist ≤ 2.5 m/s
constexpr double kMostHeadDegreesPerSecond = 300.0;  // SPEC §6.2: head ≤ 300°/s
constexpr double kFewestSignsPerSecond = 1.7;        // SPEC §6.3: conversational ≈ 2-2.3 signs/s
constexpr double kMostSignsPerSecond = 2.3;          //   (Bellugi & Fischer 1972)
constexpr double kFewestLettersPerSecond = 2.0;      // SPEC §6.3: 2-6 letters/s (Reed et al. 1990)
constexpr double kMostLettersPerSecond = 6.0;

std::string text(const char* format, double a, double b = 0.0) {
    char out[300];
    std::snprintf(out, sizeof out, format, a, b);
    return out;
}

}  // namespace

StoryPace measurePace(const signer::SignerRig& rig, const signer::TimelineClip& clip) {
    StoryPace pace;
    pace.measures = stimuli::measureTimeline(clip.timeline());
    signer::ClipPoser poser(rig, clip);
    const auto samples = static_cast<std::uint64_t>(std::floor(clip.durationSeconds() * kPaceSamplesPerSecond + 1e-9)) + 1;
    signer::PoseReport previous;
    for (std::uint64_t i = 0; i < samples; ++i) {
        const double t = static_cast<double>(i) / kPaceSamplesPerSecond;
        signer::PoseReport report;
        poser.next(t, nullptr, &report);
        if (i > 0) {
            const double dt = 1.0 / kPaceSamplesPerSecond;
            const double wrist = std::max(glm::distance(report.right.wristMm, previous.right.wristMm),
                                          glm::distance(report.left.wristMm, previous.left.wristMm)) / dt;
            if (wrist > pace.peakWristMmPerSecond) {
                pace.peakWristMmPerSecond = wrist;
                pace.peakWristSeconds = t;
            }
            const float dot = std::min(1.0f, std::abs(glm::dot(report.gaze.head, previous.gaze.head)));
            const double head = 2.0 * std::acos(static_cast<double>(dot)) * 180.0 / 3.14159265358979323846 / dt;
            if (head > pace.peakHeadDegreesPerSecond) {
                pace.peakHeadDegreesPerSecond = head;
                pace.peakHeadSeconds = t;
            }
        }
        previous = report;
    }
    return pace;
}

std::vector<std::string> paceWarnings(const StoryPace& pace) {
    std::vector<std::string> out;
    const stimuli::TimelineMeasures& m = pace.measures;
    if (m.signs > 0 && m.signsPerSecond() < kFewestSignsPerSecond)
        out.push_back(text("%.2f signs/s is slower than conversational signing (SPEC §6.3: %.1f-2.3)", m.signsPerSecond(),
                           kFewestSignsPerSecond));
    if (m.signsPerSecond() > kMostSignsPerSecond)
        out.push_back(text("%.2f signs/s is faster than conversational signing (SPEC §6.3: 1.7-%.1f)", m.signsPerSecond(),
                           kMostSignsPerSecond));
    if (m.letters > 0 && m.lettersPerSecond() < kFewestLettersPerSecond)
        out.push_back(text("fingerspelling at %.1f letters/s is slower than %.0f (SPEC §6.3, Reed et al. 1990)",
                           m.lettersPerSecond(), kFewestLettersPerSecond));
    if (m.lettersPerSecond() > kMostLettersPerSecond)
        out.push_back(text("fingerspelling at %.1f letters/s is faster than %.0f (SPEC §6.3, Reed et al. 1990)",
                           m.lettersPerSecond(), kMostLettersPerSecond));
    if (pace.peakWristMmPerSecond > kMostWristMmPerSecond)
        out.push_back(text("a wrist moves at %.2f m/s at %.2f s, faster than 2.5 m/s (SPEC §6.2)",
                           pace.peakWristMmPerSecond / 1000.0, pace.peakWristSeconds));
    if (pace.peakHeadDegreesPerSecond > kMostHeadDegreesPerSecond)
        out.push_back(text("the head turns at %.0f°/s at %.2f s, faster than 300°/s (SPEC §6.2)", pace.peakHeadDegreesPerSecond,
                           pace.peakHeadSeconds));
    return out;
}

}  // namespace signstim::app
