#include "tests/fuzz/fuzz_target.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <typeinfo>

namespace signstim::fuzz {
namespace {

std::vector<Target>& registry() {
    static std::vector<Target> all;
    return all;
}

}  // namespace

Registration::Registration(const char* name, TargetFunction run) {
    auto& all = registry();
    all.push_back({name, run});
    std::sort(all.begin(), all.end(),
              [](const Target& a, const Target& b) { return std::string_view(a.name) < std::string_view(b.name); });
}

const std::vector<Target>& targets() { return registry(); }

const Target* findTarget(std::string_view name) {
    for (const Target& t : registry())
        if (name == t.name) return &t;
    return nullptr;
}

void runTarget(const Target& target, std::string_view input) {
    try {
        target.run(input);
    } catch (const std::exception& e) {
        fail(std::string("an exception escaped (the command would exit 4, internal error): ") + typeid(e).name() +
             ": " + e.what());
    } catch (...) {
        fail("an exception of an unknown type escaped");
    }
}

void fail(const std::string& message) {
    std::fprintf(stderr, "signstim fuzz finding: %s\n", message.c_str());
    std::fflush(stderr);
    std::abort();
}

}  // namespace signstim::fuzz
