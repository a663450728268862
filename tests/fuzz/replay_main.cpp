// signstim_fuzz_replay TARGET FILE|DIR...: runs every file (directories: every regular file in
// them, in name order, not recursive) through the fuzz target, as libFuzzer would run one
// input. Prints one line per file and a count; a finding aborts (the test fails and the
// message names the file). `signstim_fuzz_replay --list` prints the targets.
#include "common/error.hpp"
#include "tests/fuzz/fixtures.hpp"
#include "tests/fuzz/fuzz_target.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

// The harness checks itself (tests/fuzz/CMakeLists.txt, fuzz.harness.*): a refusal naming its
// file passes; another exception, or a refusal naming another file, must fail the replay.
SIGNSTIM_FUZZ_TARGET(harness_selftest) {
    signstim::fuzz::expectRefusalOrSuccess("selftest.txt", [&] {
        if (input == "refused") throw signstim::InputError("selftest.txt", 1, "field", "refused as a user's mistake");
        if (input == "misnamed") throw signstim::InputError("other.txt", 1, "field", "names the wrong file");
        if (input == "internal") throw std::runtime_error("an internal error");
    });
}

int main(int argc, char** argv) {
    using namespace signstim::fuzz;
    if (argc >= 2 && std::string_view(argv[1]) == "--list") {
        for (const Target& t : targets()) std::cout << t.name << '\n';
        return 0;
    }
    if (argc < 3) {
        std::cerr << "usage: signstim_fuzz_replay TARGET FILE|DIR...  (--list: the targets)\n";
        return 1;
    }
    const Target* target = findTarget(argv[1]);
    if (!target) {
        std::cerr << "signstim_fuzz_replay: no target '" << argv[1] << "' (--list shows them)\n";
        return 1;
    }
    std::vector<fs::path> files;
    for (int i = 2; i < argc; ++i) {
        const fs::path p = argv[i];
        if (fs::is_directory(p)) {
            std::vector<fs::path> in;
            for (const auto& e : fs::directory_iterator(p))
                if (e.is_regular_file() && e.path().filename().string().front() != '.') in.push_back(e.path());
            std::sort(in.begin(), in.end());
            files.insert(files.end(), in.begin(), in.end());
        } else if (fs::is_regular_file(p)) {
            files.push_back(p);
        } else {
            std::cerr << "signstim_fuzz_replay: " << p.string() << ": no such file or directory\n";
            return 1;
        }
    }
    for (const fs::path& file : files) {
        std::ifstream in(file, std::ios::binary);
        std::ostringstream bytes;
        bytes << in.rdbuf();
        if (!in && !in.eof()) {
            std::cerr << "signstim_fuzz_replay: " << file.string() << ": read error\n";
            return 3;
        }
        std::cout << target->name << ": " << file.string() << std::endl;
        runTarget(*target, bytes.str());
    }
    std::cout << target->name << ": " << files.size() << " input(s), no finding\n";
    return 0;
}
