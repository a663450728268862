#pragma once
// How much of the default data a property test sweeps. The ordinary suite (./run.sh test, gcc)
// always sweeps all of it. scripts/sanitize.sh runs the same tests a second time under
// ASan+UBSan, where the question is whether any code path misbehaves (memory, undefined
// behaviour), not whether every story or every verb instance meets the property: it sets
// SIGNSTIM_TEST_BREADTH=sanitizer, and the few sweeps that cost minutes there take a smaller
// sample that still runs every code path (docs/fuzzing.md, "The sanitizer suite's breadth").
// Anything else, or nothing, means the full breadth.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>

namespace signstim::test {

inline bool sanitizerBreadth() {
    const char* value = std::getenv("SIGNSTIM_TEST_BREADTH");
    return value != nullptr && std::strcmp(value, "sanitizer") == 0;
}

// Whether a default story (its file's stem, "story-06") is swept: always at the full breadth;
// under the sanitizer three of the twelve, the ones the full sweep names for their extremes
// (story-01 the slowest pace, story-06 IX -> EMAIL, story-10 BOSS -> NICE, the fastest wrists
// before pacing), which between them have fingerspelling, settled touches, routed transitions
// and every verb slot kind the timeline code takes. One sample for the motion, in-frame and
// clearance tests.
inline bool storySwept(std::string_view stem) {
    return !sanitizerBreadth() || stem == "story-01" || stem == "story-06" || stem == "story-10";
}

// Says in the test's output that it ran a sample, so a log never passes it off as the sweep.
inline void noteSanitizerBreadth(const char* what) {
    if (sanitizerBreadth()) std::printf("SIGNSTIM_TEST_BREADTH=sanitizer: %s (the gcc suite sweeps all of it)\n", what);
}

}  // namespace signstim::test
