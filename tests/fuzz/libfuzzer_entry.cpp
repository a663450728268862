// The libFuzzer entry: one binary, signstim_fuzz, runs the target named by --target=NAME (or
// the environment variable SIGNSTIM_FUZZ_TARGET). libFuzzer ignores flags that begin with
// "--", so the option sits among its own:
//   signstim_fuzz --target=story -max_total_time=60 -dict=tests/fuzz/dictionaries/json.dict CORPUS
// One binary instead of one per target: a single link of the instrumented libraries.
#include "tests/fuzz/fuzz_target.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

const signstim::fuzz::Target* chosen = nullptr;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    const char* name = std::getenv("SIGNSTIM_FUZZ_TARGET");
    for (int i = 1; i < *argc; ++i)
        if (std::strncmp((*argv)[i], "--target=", 9) == 0) name = (*argv)[i] + 9;
    if (name) chosen = signstim::fuzz::findTarget(name);
    if (!chosen) {
        std::fprintf(stderr, "signstim_fuzz: %s; the targets (tests/fuzz/targets.txt):\n",
                     name ? "no such target" : "say which target: --target=NAME");
        for (const auto& t : signstim::fuzz::targets())
            if (std::strcmp(t.name, "harness_selftest") != 0) std::fprintf(stderr, "  %s\n", t.name);
        std::exit(2);
    }
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    signstim::fuzz::runTarget(*chosen, std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}
