#include "common/atomic_file.hpp"
#include "common/error.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using namespace signstim;

namespace {
fs::path freshDir(const std::string& name) {
    fs::path dir = fs::temp_directory_path() / ("signstim_common_" + name);
    fs::remove_all(dir);
    return dir;
}
std::string readAll(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}
std::size_t fileCount(const fs::path& dir) {
    std::size_t n = 0;
    for ([[maybe_unused]] auto& e : fs::directory_iterator(dir)) ++n;
    return n;
}
}  // namespace

TEST(AtomicFile, WritesContentAndCreatesParents) {
    const fs::path dir = freshDir("parents");
    const fs::path target = dir / "a" / "b" / "out.txt";
    writeFileAtomic(target, "hello");
    EXPECT_EQ(readAll(target), "hello");
    EXPECT_EQ(fileCount(target.parent_path()), 1u);  // no temporary left beside it
}

TEST(AtomicFile, ReplacesExistingFileWhole) {
    const fs::path dir = freshDir("replace");
    const fs::path target = dir / "out.txt";
    writeFileAtomic(target, "a much longer first version");
    writeFileAtomic(target, "short");
    EXPECT_EQ(readAll(target), "short");
}

TEST(AtomicFile, UncommittedTemporaryLeavesNothingBehind) {
    const fs::path dir = freshDir("uncommitted");
    fs::create_directories(dir);
    {
        TemporaryFile tmp(dir / "out.bin");
        std::ofstream(tmp.path()) << "partial";
        EXPECT_TRUE(fs::exists(tmp.path()));
    }  // destroyed without commit(), as on an error path
    EXPECT_EQ(fileCount(dir), 0u);
}

TEST(AtomicFile, UnwritableDirectoryNamesThePath) {
    const fs::path dir = freshDir("blocked");
    fs::create_directories(dir);
    const fs::path blocker = dir / "not-a-dir";
    std::ofstream(blocker) << "x";
    try {
        writeFileAtomic(blocker / "out.txt", "data");
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("not-a-dir"), std::string::npos) << e.what();
    }
}

TEST(InputErrorMessage, NamesFileLineAndField) {
    InputError e("scenes/verbs.json", 12, "verbs[3].hands", "must be 1 or 2");
    EXPECT_STREQ(e.what(), "scenes/verbs.json:12: field 'verbs[3].hands': must be 1 or 2");
}
