#pragma once
// A study folder made without rendering, for the folder's tests: the review page's fixture
// listing (tests/stimuli/review_page_fixture.hpp), a plan, and SYNTHETIC unit files (a few bytes
// of text standing in for each clip and poster) with their records, as the renderer would leave
// them.
#include "stimuli/study/study_folder.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace signstim::stimuli::testing {

struct FolderFixture {
    StudyListing listing;
    std::vector<StudyUnit> units;
    nlohmann::json plan;
    std::string salt;
};

// Four stories, four participants, four side-by-side sentences; every unit's input hash is
// "inputs-" + its id + `salt`.
// `signedQuestions` (issue 24): the questions and instructions in ASL, with their units.
FolderFixture folderFixture(const std::string& salt = "", bool signedQuestions = false);
// A fresh, empty folder under the system's temporary folder, named for the test.
std::filesystem::path freshFolder(const std::string& name);
// Writes the plan into DIR (as a run does before its first unit).
void writePlan(const std::filesystem::path& dir, const FolderFixture& study);
// Writes UNIT's synthetic files and its record.
void writeUnit(const std::filesystem::path& dir, const FolderFixture& study, const StudyUnit& unit);
std::string readBytes(const std::filesystem::path& file);
void writeBytes(const std::filesystem::path& file, const std::string& bytes);

}  // namespace signstim::stimuli::testing
