// The libFuzzer entry of one target, chosen at compile time (SIGNSTIM_FUZZ_TARGET_NAME).
#include "tests/fuzz/fuzz_target.hpp"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const signstim::fuzz::Target* target = [] {
        const auto* t = signstim::fuzz::findTarget(SIGNSTIM_FUZZ_TARGET_NAME);
        if (!t) {
            std::fprintf(stderr, "no fuzz target named %s\n", SIGNSTIM_FUZZ_TARGET_NAME);
            std::abort();
        }
        return t;
    }();
    signstim::fuzz::runTarget(*target, std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}
