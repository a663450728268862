#pragma once
// The study folder (docs/study.md): what `signstim study --out DIR` writes, and what
// `study verify`, `study merge` and `analyze --study` read. Its layout and rules live here, used
// by the app (which renders the units) and by analysis (which reads the manifest), and tested
// without a renderer (tests/study).
//
//   .signstim/plan.json           the study as planned: render settings, units with the hash of
//                                 their inputs, the listing (stimuli/study/study_listing.hpp)
//   .signstim/units/UNIT.json     a unit's record: its input hash, frames, and each file it
//                                 wrote with size and SHA-256; written when the unit's files are
//   .signstim/lock                held (flock) by the one run working in the folder
//   clips/ posters/ frames/ ...   the units' files; participants/, index.html, ... the documents
//   manifest.json                 written last, when every unit is complete: the folder is
//                                 complete and verified, or visibly incomplete
//
// Work units, sorted by name: one per phase-1 story (its V versions rendered together) and one
// per phase-2 sentence (the V versions side by side in one clip). A unit is complete when its
// record has the current input hash and every file it lists is there with its SHA-256; a re-run
// skips complete units and renders the others (a corrupted clip included). --shard i/N takes
// units i, i+N, i+2N, ... of the sorted list.
#include "stimuli/study/jspsych_bundle.hpp"
#include "stimuli/study/study.hpp"
#include "stimuli/study/study_listing.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace signstim::stimuli {

inline constexpr const char* kStudyPlanFile = ".signstim/plan.json";
inline constexpr const char* kStudyUnitFolder = ".signstim/units";
inline constexpr const char* kStudyManifestFile = "manifest.json";
inline constexpr const char* kStudyReviewPage = "index.html";

// ---- units and shards ------------------------------------------------------------------------

// Issue 24: a unit of signed questions or instructions (question_clips.hpp) besides the stimuli.
enum class StudyUnitKind { Stimulus, Questions, Instructions };

struct StudyUnit {
    std::string id;         // "likert-03", "story-07": sorted, the order shards are dealt from
    bool story = true;      // a phase-1 story, else a phase-2 sentence (kind Stimulus)
    std::size_t index = 0;  // into listing.stories or listing.sentences (Questions: the story)
    StudyUnitKind kind = StudyUnitKind::Stimulus;  // Questions, Instructions: `story` is false
};

// Every unit of the listing, sorted by id.
std::vector<StudyUnit> studyUnits(const StudyListing& listing);
// Shard `index` of `count` (0-based): units index, index + count, ... of the sorted list.
std::vector<StudyUnit> shardUnits(const std::vector<StudyUnit>& units, std::size_t index, std::size_t count);

// ---- what a unit depends on --------------------------------------------------------------------

// The data every unit depends on besides its story: the files (named by their file name) and
// folders (every file inside, by relative path) hashed into studyDataHash.
struct StudyInputs {
    std::vector<std::filesystem::path> files;
    std::vector<std::filesystem::path> folders;
};
// SCENES' handshapes, verbs, verb models and the avatar file; the lexicon, a lab's lexicon
// (`--lexicon`; empty: none) and the animator keyframes. The avatar's path is the signer's to
// say (signer::defaultAvatarPath).
StudyInputs studyInputs(const std::filesystem::path& scenes, const std::filesystem::path& lexicon,
                        const std::filesystem::path& labLexicon, const std::filesystem::path& avatar);
// The tool, the render settings, PNG frames or not, the versions and every input's SHA-256.
std::string studyDataHash(const std::string& toolVersion, const StudyRenderSettings& settings, bool pngFrames,
                          const std::vector<std::string>& versions, const StudyInputs& inputs);
// The data hash, the unit, its story file's bytes and the clips it writes.
std::string unitInputHash(const std::string& dataHash, const StudyUnit& unit, const StudyFile& study,
                          const StudyListing& listing);

// ---- the plan ----------------------------------------------------------------------------------

// The plan of a run: render settings, each unit's input hash, the listing, and (not part of what
// a unit depends on) whether the jsPsych experiment is written.
nlohmann::json studyPlan(const StudyListing& listing, const StudyRenderSettings& settings, bool pngFrames,
                         const std::vector<StudyUnit>& units, const std::vector<std::string>& inputHashes,
                         const std::string& experiment);
// DIR's plan; InputError when there is none or it is not a plan.
nlohmann::json readStudyPlan(const std::filesystem::path& dir);
bool hasStudyPlan(const std::filesystem::path& dir);
std::map<std::string, std::string> planInputHashes(const nlohmann::json& plan);
// "jspsych" when the run that wrote `plan` asked for the experiment, else empty.
std::string planExperiment(const nlohmann::json& plan);

// ---- unit records -------------------------------------------------------------------------------

std::filesystem::path unitRecordPath(const std::filesystem::path& dir, const std::string& unit);
// DIR / relative, when `relative` names a place inside DIR: not empty, not absolute, no "..",
// and no symbolic link on the way. Throws InputError naming `source` (the record or manifest
// that lists it) otherwise: a record must never make signstim read or write outside the folder.
std::filesystem::path pathInStudyFolder(const std::filesystem::path& dir, const std::string& relative,
                                        const std::string& source);
// Writes UNIT's record (atomically) with the entries (common/file_manifest.hpp describeFile) of
// the files it wrote, the last step of a unit.
void writeUnitRecord(const std::filesystem::path& dir, const std::string& unit, const std::string& inputHash,
                     std::uint64_t frames, const nlohmann::json& files);
// A unit is complete when its record has `inputHash` and every file it lists is in the folder
// with the recorded size and SHA-256 (every byte read: a flipped byte makes it incomplete, and
// a re-run renders it again).
bool unitComplete(const std::filesystem::path& dir, const std::string& unit, const std::string& inputHash);

// ---- finishing ----------------------------------------------------------------------------------

struct StudyFolderState {
    std::size_t units = 0;
    std::vector<std::string> missing;   // units not complete (other shards, a changed input)
    bool complete = false;              // every unit complete: documents and manifest written
    bool experiment = false;            // experiment/ written with them
    std::string firstParticipant;       // "P01"
};
// Writes the documents (and the experiment when `jspsych` is given), then the manifest, when
// every unit of `plan` is complete in DIR; otherwise says which are missing.
StudyFolderState finishStudyFolder(const std::filesystem::path& dir, const nlohmann::json& plan,
                                   const JspsychBundle* jspsych);

// ---- verify and merge ------------------------------------------------------------------------

// The study listing of a complete study: DIR/manifest.json (or the manifest file itself), its
// "study" member, as `analyze --study` reads it. InputError (naming `field` when DIR has no
// manifest) when it is not a study manifest or has no listing.
StudyListing readStudyManifestListing(const std::filesystem::path& studyDirOrManifest, const std::string& field,
                                      std::string* manifestPath = nullptr);

struct StudyVerification {
    std::vector<std::string> problems;  // empty: verified
    std::size_t checked = 0, listed = 0;  // files that match, files the manifest lists
};
// Every file of DIR's manifest present with its size and SHA-256 (every byte read), every unit of
// the plan listed. Throws InputError when DIR has no manifest (saying which units are missing).
StudyVerification verifyStudyFolder(const std::filesystem::path& dir);

struct StudyMerge {
    StudyFolderState state;
    std::size_t copied = 0;  // units copied into the target
};
// Copies the units of `sources` missing from `target` (which may be one of them), checking each
// file's SHA-256 against its record, then finishes the target (finishStudyFolder), with the
// jsPsych experiment when `experiment` is "jspsych" or any of the folders' runs asked for it.
// Throws InputError when the folders hold different studies or a record names a path outside
// its folder, and (EnvironmentError) while a run is rendering into the target.
StudyMerge mergeStudyFolders(const std::vector<std::filesystem::path>& sources, const std::filesystem::path& target,
                             const std::string& experiment = "");

}  // namespace signstim::stimuli
