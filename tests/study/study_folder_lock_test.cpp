// One folder, one study (stimuli/study/study_folder_lock.hpp): runs of another plan are refused
// while one renders, shards of one plan share the folder, a dead holder's lock is taken over,
// and --out refuses places that are not a study's. Processes race with fork().
#include "common/error.hpp"
#include "stimuli/study/study_folder_lock.hpp"
#include "tests/study/study_folder_fixture.hpp"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>

namespace signstim::stimuli::testing {
namespace {

namespace fs = std::filesystem;

// A child process that has begun a run in DIR and holds it until killed. `pipe` says when.
pid_t startRunInChild(const fs::path& dir) {
    int ready[2];
    if (::pipe(ready) != 0) return -1;
    const pid_t child = ::fork();
    if (child == 0) {
        ::close(ready[0]);
        StudyFolderLock lock(dir);
        lock.beginRun();
        lock.unlock();
        const char byte = 1;
        [[maybe_unused]] const ssize_t n = ::write(ready[1], &byte, 1);
        for (;;) ::pause();
    }
    ::close(ready[1]);
    char byte = 0;
    [[maybe_unused]] const ssize_t n = ::read(ready[0], &byte, 1);
    ::close(ready[0]);
    return child;
}

void stop(pid_t child) {
    ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
}

TEST(StudyFolderLock, ARunOfAnotherPlanIsRefusedWhileOneRendersAndTakesOverWhenItDies) {
    const fs::path dir = freshFolder("lock-race");
    const pid_t child = startRunInChild(dir);
    ASSERT_GT(child, 0);
    {
        StudyFolderLock second(dir);
        EXPECT_TRUE(second.othersRunning());
        EXPECT_NE(second.holder().find("PID " + std::to_string(child) + " on host "), std::string::npos) << second.holder();
    }
    // Killed outright: the kernel released its locks; the next run takes the folder.
    stop(child);
    StudyFolderLock next(dir);
    EXPECT_FALSE(next.othersRunning());
}

TEST(StudyFolderLock, ShardsOfOnePlanRenderTogether) {
    const fs::path dir = freshFolder("lock-shards");
    const pid_t child = startRunInChild(dir);
    ASSERT_GT(child, 0);
    StudyFolderLock shard(dir);
    shard.beginRun();  // shared with the child: does not wait
    shard.unlock();
    SUCCEED();
    stop(child);
}

TEST(StudyFolderLock, MergeIsRefusedWhileARunRendersIntoTheTarget) {
    const FolderFixture study = folderFixture();
    const fs::path dir = freshFolder("lock-merge");
    writePlan(dir, study);
    for (const StudyUnit& u : study.units) writeUnit(dir, study, u);
    const pid_t child = startRunInChild(dir);
    ASSERT_GT(child, 0);
    EXPECT_THROW(mergeStudyFolders({dir}, dir), EnvironmentError);
    EXPECT_FALSE(fs::exists(dir / kStudyManifestFile));
    stop(child);
    EXPECT_TRUE(mergeStudyFolders({dir}, dir).state.complete);
}

TEST(StudyOutFolder, RefusesRootHomeTheWorkingDirectoryAndOtherPeoplesFiles) {
    EXPECT_THROW(checkStudyOutFolder("/", true), InputError);
    const fs::path home = freshFolder("home");
    const char* before = std::getenv("HOME");
    const std::string saved = before ? before : "";
    ::setenv("HOME", home.c_str(), 1);
    EXPECT_THROW(checkStudyOutFolder(home, true), InputError);
    if (before) ::setenv("HOME", saved.c_str(), 1); else ::unsetenv("HOME");
    EXPECT_THROW(checkStudyOutFolder(fs::current_path(), true), InputError);
    EXPECT_THROW(checkStudyOutFolder(".", true), InputError);

    const fs::path theirs = freshFolder("theirs");
    writeBytes(theirs / "notes.txt", "someone's notes\n");
    try {
        checkStudyOutFolder(theirs, false);
        ADD_FAILURE() << "a folder of other files was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("notes.txt"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("--force"), std::string::npos) << e.what();
    }
    EXPECT_NO_THROW(checkStudyOutFolder(theirs, true));
    EXPECT_TRUE(fs::exists(theirs / "notes.txt"));

    EXPECT_NO_THROW(checkStudyOutFolder(freshFolder("empty"), false));
    EXPECT_NO_THROW(checkStudyOutFolder(freshFolder("absent") / "new", false));
    const fs::path study = freshFolder("a-study");
    writePlan(study, folderFixture());
    writeBytes(study / "README-by-the-researcher.txt", "kept\n");
    EXPECT_NO_THROW(checkStudyOutFolder(study, false));
}

}  // namespace
}  // namespace signstim::stimuli::testing
