#include "common/atomic_file.hpp"
#include "common/error.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <cerrno>
#include <cstring>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

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

// Array tasks on several machines writing one shared study folder can have the same process
// id: the name this process would use next may be another machine's temporary. It is passed
// over and left alone, for files and for folders.
TEST(AtomicFile, TemporaryNameHeldByAnotherMachineIsPassedOver) {
    const fs::path dir = freshDir("taken");
    fs::create_directories(dir);
    const auto nextTemporary = [](const fs::path& target) {  // TARGET.tmp-PID-N, N one ahead
        const std::string name = temporaryPathFor(target).filename().string();
        const std::size_t dash = name.rfind('-');
        return target.parent_path() / (name.substr(0, dash + 1) + std::to_string(std::stoul(name.substr(dash + 1)) + 1));
    };
    const fs::path plan = dir / "plan.json";
    const fs::path takenFile = nextTemporary(plan);
    std::ofstream(takenFile) << "another machine's";
    writeFileAtomic(plan, "mine");
    EXPECT_EQ(readAll(plan), "mine");
    EXPECT_EQ(readAll(takenFile), "another machine's");

    const fs::path frames = dir / "frames";
    const fs::path takenFolder = nextTemporary(frames);
    fs::create_directory(takenFolder);
    {
        TemporaryFolder folder(frames);
        writeNewFile(folder.path() / "frame_00001.png", "x");
        folder.commit();
    }
    EXPECT_EQ(readAll(frames / "frame_00001.png"), "x");
    EXPECT_TRUE(fs::is_directory(takenFolder));
    EXPECT_EQ(fileCount(dir), 4u);  // plan.json, frames, and the two that are not ours
}

TEST(AtomicFile, UnwritableDirectoryNamesThePath) {
    const fs::path dir = freshDir("blocked");
    fs::create_directories(dir);
    const fs::path blocker = dir / "not-a-dir";
    std::ofstream(blocker) << "x";
    try {
        writeFileAtomic(blocker / "out.txt", "data");
        FAIL() << "expected IoError";
    } catch (const IoError& e) {  // a failed write: exit 3, naming the path and the reason
        EXPECT_NE(std::string(e.what()).find("not-a-dir"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("Not a directory"), std::string::npos) << e.what();
    }
}

TEST(InputErrorMessage, NamesFileLineAndField) {
    InputError e("scenes/verbs.json", 12, "verbs[3].hands", "must be 1 or 2");
    EXPECT_STREQ(e.what(), "scenes/verbs.json:12: field 'verbs[3].hands': must be 1 or 2");
}

TEST(AtomicFile, ProbeNamesTheTargetAndTheSystemReason) {
    try {
        checkOutputWritable("/proc/signstim-probe/x.mp4");
        FAIL() << "expected IoError";
    } catch (const IoError& e) {
        const std::string text = e.what();
        EXPECT_EQ(text.rfind("/proc/signstim-probe/x.mp4: cannot write: ", 0), 0u) << text;
        EXPECT_EQ(text.find("Success"), std::string::npos) << text;
    }
}

TEST(AtomicFile, TemporaryFolderReplacesAnEarlierFolderWhole) {
    const fs::path dir = freshDir("folder");
    fs::create_directories(dir / "out");
    std::ofstream(dir / "out" / "old.txt") << "old";
    {
        TemporaryFolder folder(dir / "out");
        std::ofstream(folder.path() / "new.txt") << "new";
        folder.commit();
    }
    EXPECT_FALSE(fs::exists(dir / "out" / "old.txt"));
    EXPECT_EQ(readAll(dir / "out" / "new.txt"), "new");
    EXPECT_EQ(fileCount(dir), 1u);  // no temporary left beside it
    {
        TemporaryFolder abandoned(dir / "out");
        writeNewFile(abandoned.path() / "x.txt", "partial");
    }
    EXPECT_EQ(readAll(dir / "out" / "new.txt"), "new");
    EXPECT_EQ(fileCount(dir), 1u);
}

// "frames/" (tab completion): the temporary is a sibling of the folder, never inside it.
TEST(AtomicFile, TrailingSeparatorIsIgnored) {
    EXPECT_EQ(withoutTrailingSeparators("out/frames//"), fs::path("out/frames"));
    EXPECT_EQ(withoutTrailingSeparators("/"), fs::path("/"));
    const fs::path tmp = temporaryPathFor("out/frames/");
    EXPECT_EQ(tmp.parent_path(), fs::path("out"));
    EXPECT_EQ(tmp.filename().string().rfind("frames.tmp-", 0), 0u) << tmp;

    const fs::path dir = freshDir("slash");
    fs::create_directories(dir / "out");
    std::ofstream(dir / "out" / "old.txt") << "old";
    {
        TemporaryFolder folder(fs::path(dir / "out").string() + "/");
        EXPECT_EQ(folder.path().parent_path(), dir);
        std::ofstream(folder.path() / "new.txt") << "new";
        folder.commit();
    }
    EXPECT_EQ(readAll(dir / "out" / "new.txt"), "new");
    EXPECT_FALSE(fs::exists(dir / "out" / "old.txt"));
    EXPECT_EQ(fileCount(dir), 1u);
}

// A character device as the target (/dev/full, /dev/null) is written into: the system's
// reason for a failed write is the message, and the device node is never replaced by a
// renamed file (as root, /dev is writable). Root writes to a device node made in a scratch
// folder (mknod: the same device as /dev/full), so a regression cannot replace /dev/full.
TEST(AtomicFile, ACharacterDeviceTargetIsWrittenDirectlyAndAFullOneSaysNoSpace) {
    const fs::path dir = freshDir("chardev");
    fs::create_directories(dir);
    fs::path full = "/dev/full";
    if (::geteuid() == 0) {
        full = dir / "full";
        ASSERT_EQ(::mknod(full.c_str(), S_IFCHR | 0666, makedev(1, 7)), 0) << std::strerror(errno);
    }
    try {
        writeFileAtomic(full, std::string(100000, 'x'));
        ADD_FAILURE() << "no IoError";
    } catch (const IoError& e) {
        EXPECT_EQ(std::string(e.what()), full.string() + ": cannot write: No space left on device");
    }
    struct stat info {};
    ASSERT_EQ(::stat(full.c_str(), &info), 0);
    EXPECT_TRUE(S_ISCHR(info.st_mode)) << full << " is no longer a device";
    if (full.parent_path() == dir) {
        EXPECT_EQ(fileCount(dir), 1u);  // no temporary beside it
    }
    fs::remove_all(dir);
}
