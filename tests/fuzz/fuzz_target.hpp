#pragma once
// Fuzz targets: one function per parser, fed arbitrary bytes (issue 13 §2).
//
// A target returns normally when the input is accepted or refused the way a user's mistake
// must be refused (signstim::InputError: file, line, field; exit 2 in the command). Anything
// else escaping — another exception (the command's "internal error", exit 4), an abort, a
// sanitizer report, an accepted value that breaks the parser's own promises (a NaN read, a
// line number of 0 in a refusal) — is a finding. The same targets run two ways:
//   - the libFuzzer binary signstim_fuzz --target=NAME (built with -DSIGNSTIM_FUZZ=ON and
//     clang; scripts/fuzz.sh);
//   - signstim_fuzz_replay NAME FILE|DIR..., in the ordinary test suite: every seed and every
//     kept finding (tests/fuzz/regressions/NAME/) through its target, so a fixed crash stays
//     fixed in every build, sanitized or not.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace signstim::fuzz {

using TargetFunction = void (*)(std::string_view input);

struct Target {
    const char* name;
    TargetFunction run;
};

// Registered at static initialization by SIGNSTIM_FUZZ_TARGET; sorted by name.
const std::vector<Target>& targets();
const Target* findTarget(std::string_view name);

struct Registration {
    Registration(const char* name, TargetFunction run);
};

// Runs `target` on `input`; an exception it lets escape is a finding, reported with its type
// and message (what the command would print as an internal error) before aborting.
void runTarget(const Target& target, std::string_view input);

// A finding that is not a crash by itself: aborts with the message (libFuzzer then keeps the
// input). Used for broken promises such as a non-finite number accepted.
[[noreturn]] void fail(const std::string& message);

}  // namespace signstim::fuzz

#define SIGNSTIM_FUZZ_TARGET(name)                                                                \
    static void signstimFuzz_##name(std::string_view input);                                     \
    static const ::signstim::fuzz::Registration signstimFuzzRegistration_##name(#name,           \
                                                                                signstimFuzz_##name); \
    static void signstimFuzz_##name(std::string_view input)
