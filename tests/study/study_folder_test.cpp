// The study folder's resume, shard, merge and verify rules (stimuli/study/study_folder.hpp), on
// synthetic folders (tests/study/study_folder_fixture.hpp): no renderer, milliseconds.
#include "common/error.hpp"
#include "common/file_manifest.hpp"
#include "tests/study/study_folder_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace signstim::stimuli::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

void writeAllUnits(const fs::path& dir, const FolderFixture& study) {
    writePlan(dir, study);
    for (const StudyUnit& u : study.units) writeUnit(dir, study, u);
}

std::string firstClip(const FolderFixture& study) { return study.listing.stories.front().clips.front().video; }

TEST(StudyUnits, ShardsDealEveryUnitOnceInSortedOrder) {
    const FolderFixture study = folderFixture();
    ASSERT_EQ(study.units.size(), 8u);
    EXPECT_TRUE(std::is_sorted(study.units.begin(), study.units.end(),
                               [](const StudyUnit& a, const StudyUnit& b) { return a.id < b.id; }));
    for (std::size_t count : {1u, 2u, 4u, 7u}) {
        std::multiset<std::string> dealt;
        for (std::size_t i = 0; i < count; ++i)
            for (const StudyUnit& u : shardUnits(study.units, i, count)) dealt.insert(u.id);
        std::multiset<std::string> all;
        for (const StudyUnit& u : study.units) all.insert(u.id);
        EXPECT_EQ(dealt, all) << count << " shards";
    }
    // Shard 1 of 4 takes units 1 and 5 of the sorted list.
    const std::vector<StudyUnit> one = shardUnits(study.units, 1, 4);
    ASSERT_EQ(one.size(), 2u);
    EXPECT_EQ(one[0].id, study.units[1].id);
    EXPECT_EQ(one[1].id, study.units[5].id);
}

TEST(StudyFolder, IsCompleteAndVerifiedOnlyWhenEveryUnitHasItsRecord) {
    const fs::path dir = freshFolder("complete");
    const FolderFixture study = folderFixture();
    writePlan(dir, study);
    for (std::size_t i = 0; i + 1 < study.units.size(); ++i) writeUnit(dir, study, study.units[i]);
    StudyFolderState state = finishStudyFolder(dir, study.plan, nullptr);
    EXPECT_FALSE(state.complete);
    EXPECT_EQ(state.missing, std::vector<std::string>{study.units.back().id});
    EXPECT_FALSE(fs::exists(dir / kStudyManifestFile));
    EXPECT_THROW(verifyStudyFolder(dir), InputError);

    writeUnit(dir, study, study.units.back());
    state = finishStudyFolder(dir, study.plan, nullptr);
    EXPECT_TRUE(state.complete);
    EXPECT_TRUE(fs::exists(dir / kStudyManifestFile));
    EXPECT_TRUE(fs::exists(dir / kStudyReviewPage));
    const StudyVerification verified = verifyStudyFolder(dir);
    EXPECT_TRUE(verified.problems.empty()) << verified.problems.front();
    EXPECT_EQ(verified.checked, verified.listed);
}

TEST(StudyFolder, AUnitRecordedForOtherInputsIsRenderedAgain) {
    const fs::path dir = freshFolder("other-inputs");
    const FolderFixture study = folderFixture();
    writeAllUnits(dir, study);
    const StudyUnit& unit = study.units.front();
    EXPECT_TRUE(unitComplete(dir, unit.id, "inputs-" + unit.id));
    EXPECT_FALSE(unitComplete(dir, unit.id, "inputs-" + unit.id + "-after-a-changed-setting"));
    fs::remove(dir / study.listing.sentences.front().clip.video);
    EXPECT_FALSE(unitComplete(dir, study.units.front().id, "inputs-" + study.units.front().id));
}

TEST(StudyFolder, AFlippedByteOfTheSameSizeFailsVerifyAndMakesItsUnitIncomplete) {
    const fs::path dir = freshFolder("flipped");
    const FolderFixture study = folderFixture();
    writeAllUnits(dir, study);
    ASSERT_TRUE(finishStudyFolder(dir, study.plan, nullptr).complete);
    const fs::path clip = dir / firstClip(study);
    std::string bytes = readBytes(clip);
    bytes[3] ^= 0x01;
    writeBytes(clip, bytes);
    const StudyVerification verified = verifyStudyFolder(dir);
    ASSERT_EQ(verified.problems.size(), 1u);
    EXPECT_NE(verified.problems.front().find(firstClip(study)), std::string::npos);
    EXPECT_NE(verified.problems.front().find("SHA-256"), std::string::npos);
    // A re-run renders that unit again (it is not complete), and only it.
    std::size_t incomplete = 0;
    for (const StudyUnit& u : study.units)
        if (!unitComplete(dir, u.id, "inputs-" + u.id)) {
            ++incomplete;
            EXPECT_EQ(u.id, study.listing.stories.front().id);
        }
    EXPECT_EQ(incomplete, 1u);
}

TEST(StudyFolder, MergeJoinsShardFoldersIntoOneVerifiedStudy) {
    const FolderFixture study = folderFixture();
    const fs::path a = freshFolder("shard-a"), b = freshFolder("shard-b"), target = freshFolder("merged");
    writePlan(a, study);
    writePlan(b, study);
    for (const StudyUnit& u : shardUnits(study.units, 0, 2)) writeUnit(a, study, u);
    for (const StudyUnit& u : shardUnits(study.units, 1, 2)) writeUnit(b, study, u);
    EXPECT_FALSE(finishStudyFolder(a, study.plan, nullptr).complete);
    const StudyMerge merged = mergeStudyFolders({a, b}, target);
    EXPECT_TRUE(merged.state.complete);
    EXPECT_EQ(merged.copied, study.units.size());
    EXPECT_TRUE(verifyStudyFolder(target).problems.empty());
    // Into the first shard's folder, as `study merge A B` does: only B's units are copied.
    const StudyMerge intoA = mergeStudyFolders({a, b}, a);
    EXPECT_TRUE(intoA.state.complete);
    EXPECT_EQ(intoA.copied, shardUnits(study.units, 1, 2).size());
    EXPECT_EQ(readBytes(a / kStudyManifestFile), readBytes(target / kStudyManifestFile));
}

// Issue 24: the signed question and instruction clips are units like the stories: a folder is
// complete only with them, a changed byte in one is found by verify and re-renders its unit, and
// shards merge to the same manifest as one run.
TEST(StudyFolder, SignedQuestionUnitsResumeShardMergeAndVerifyLikeStories) {
    const FolderFixture study = folderFixture("", true);
    ASSERT_EQ(study.units.size(), 8u + 4u + 1u);  // stories, sentences, questions-01..04, instructions
    const StudyUnit& questions = *std::find_if(study.units.begin(), study.units.end(),
                                               [](const StudyUnit& u) { return u.id == "questions-02"; });
    EXPECT_EQ(questions.kind, StudyUnitKind::Questions);

    const fs::path whole = freshFolder("signed-whole");
    writePlan(whole, study);
    for (const StudyUnit& u : study.units)
        if (u.kind != StudyUnitKind::Instructions) writeUnit(whole, study, u);
    StudyFolderState state = finishStudyFolder(whole, study.plan, nullptr);
    EXPECT_FALSE(state.complete);
    EXPECT_EQ(state.missing, std::vector<std::string>{"instructions"});
    writeUnit(whole, study, study.units[std::size_t(std::find_if(study.units.begin(), study.units.end(), [](const StudyUnit& u) {
                                                     return u.kind == StudyUnitKind::Instructions;
                                                 }) - study.units.begin())]);
    state = finishStudyFolder(whole, study.plan, nullptr);
    ASSERT_TRUE(state.complete);
    EXPECT_TRUE(verifyStudyFolder(whole).problems.empty());
    // The manifest lists each question clip once, with its duration filled into the listing.
    const json manifest = json::parse(readBytes(whole / kStudyManifestFile));
    const std::string clip = study.listing.stories[1].questions[0].clip.video;
    EXPECT_EQ(std::count_if(manifest["files"].begin(), manifest["files"].end(),
                            [&](const json& f) { return f["path"] == clip; }),
              1);
    EXPECT_EQ(manifest["study"]["stories"][1]["questions"][0]["clip"]["video"], clip);

    // A changed byte of a question clip: verify names it, and its unit is incomplete again.
    std::string bytes = readBytes(whole / clip);
    bytes[0] = bytes[0] == 'X' ? 'Y' : 'X';
    writeBytes(whole / clip, bytes);
    const StudyVerification verified = verifyStudyFolder(whole);
    ASSERT_FALSE(verified.problems.empty());
    EXPECT_NE(verified.problems.front().find(clip), std::string::npos) << verified.problems.front();
    EXPECT_FALSE(unitComplete(whole, "questions-02", "inputs-questions-02"));
    EXPECT_TRUE(unitComplete(whole, "questions-01", "inputs-questions-01"));

    // Three shards merged: the same manifest as one run.
    const fs::path fresh = freshFolder("signed-one");
    writeAllUnits(fresh, study);
    ASSERT_TRUE(finishStudyFolder(fresh, study.plan, nullptr).complete);
    std::vector<fs::path> shards;
    for (std::size_t i = 0; i < 3; ++i) {
        shards.push_back(freshFolder("signed-shard-" + std::to_string(i)));
        writePlan(shards.back(), study);
        for (const StudyUnit& u : shardUnits(study.units, i, 3)) writeUnit(shards.back(), study, u);
    }
    const fs::path merged = freshFolder("signed-merged");
    ASSERT_TRUE(mergeStudyFolders(shards, merged).state.complete);
    EXPECT_EQ(readBytes(merged / kStudyManifestFile), readBytes(fresh / kStudyManifestFile));
}

TEST(StudyFolder, MergeRefusesFoldersOfAnotherStudyOrSettings) {
    const fs::path a = freshFolder("study-a"), b = freshFolder("study-b");
    writeAllUnits(a, folderFixture());
    writeAllUnits(b, folderFixture("-other-settings"));
    EXPECT_THROW(mergeStudyFolders({a, b}, a), InputError);
    EXPECT_FALSE(fs::exists(a / kStudyManifestFile));
}

// A record whose path leaves the folder, with the size and hash of what it would copy, must not
// make merge write (or verify read) outside the folders.
TEST(StudyFolder, RecordPathsThatLeaveTheFolderAreRefused) {
    const FolderFixture study = folderFixture();
    const fs::path root = freshFolder("escape");
    const fs::path source = root / "deep" / "source", target = root / "deep" / "target";
    fs::create_directories(source);
    writeAllUnits(source, study);
    const fs::path victim = root / "victim.txt";
    writeBytes(victim, "someone's notes\n");
    const StudyUnit& unit = study.units.front();
    const std::string evil = "SYNTHETIC replacement for the victim\n";
    writeBytes(source / "payload.txt", evil);
    const std::vector<std::string> escapes = {"../../victim.txt", (root / "victim.txt").string(), "clips/../../../victim.txt"};
    for (const std::string& path : escapes) {
        json record = json::parse(readBytes(unitRecordPath(source, unit.id)));
        json entry = describeFile(source, "payload.txt", "video");
        entry["path"] = path;
        record["files"] = json::array({entry});
        writeBytes(unitRecordPath(source, unit.id), record.dump(2));
        EXPECT_THROW(mergeStudyFolders({source}, target), InputError) << path;
        EXPECT_EQ(readBytes(victim), "someone's notes\n") << path;
    }
    // A symbolic link inside the folder that points out of it.
    fs::create_directories(target);
    fs::create_directory_symlink(root, target / "clips-link");
    json record = json::parse(readBytes(unitRecordPath(source, unit.id)));
    json entry = describeFile(source, "payload.txt", "video");
    entry["path"] = "clips-link/victim.txt";
    record["files"] = json::array({entry});
    writeBytes(unitRecordPath(source, unit.id), record.dump(2));
    fs::create_directories(source / "clips-link");
    writeBytes(source / "clips-link" / "victim.txt", evil);
    EXPECT_THROW(mergeStudyFolders({source}, target), InputError);
    EXPECT_EQ(readBytes(victim), "someone's notes\n");
    EXPECT_THROW(pathInStudyFolder(target, "clips-link/victim.txt", "record"), InputError);
    EXPECT_THROW(pathInStudyFolder(target, "", "record"), InputError);
    EXPECT_EQ(pathInStudyFolder(target, "clips/a.mp4", "record"), target / "clips" / "a.mp4");
}

TEST(StudyFolder, VerifyRefusesAManifestThatListsPathsOutsideTheFolder) {
    const fs::path dir = freshFolder("manifest-escape");
    const FolderFixture study = folderFixture();
    writeAllUnits(dir, study);
    ASSERT_TRUE(finishStudyFolder(dir, study.plan, nullptr).complete);
    json manifest = json::parse(readBytes(dir / kStudyManifestFile));
    manifest["files"][0]["path"] = "../outside.txt";
    writeBytes(dir / kStudyManifestFile, manifest.dump(2));
    const StudyVerification verified = verifyStudyFolder(dir);
    ASSERT_EQ(verified.problems.size(), 1u);
    EXPECT_NE(verified.problems.front().find("outside the folder"), std::string::npos);
}

}  // namespace
}  // namespace signstim::stimuli::testing
