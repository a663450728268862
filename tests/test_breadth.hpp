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

namespace signstim::test {

inline bool sanitizerBreadth() {
    const char* value = std::getenv("SIGNSTIM_TEST_BREADTH");
    return value != nullptr && std::strcmp(value, "sanitizer") == 0;
}

// Says in the test's output that it ran a sample, so a log never passes it off as the sweep.
inline void noteSanitizerBreadth(const char* what) {
    if (sanitizerBreadth()) std::printf("SIGNSTIM_TEST_BREADTH=sanitizer: %s (the gcc suite sweeps all of it)\n", what);
}

}  // namespace signstim::test
