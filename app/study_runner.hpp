#pragma once
// `signstim study`: a study file (docs/study.md) -> every stimulus clip, every participant's
// schedule and exports, a manifest and a review page, in one output folder. The folder's layout
// and rules (units, shards, records, plan, manifest, verify, merge, its lock) are
// stimuli/study/study_folder.hpp's; this renders the units (a phase-1 story's V versions
// together, the frames outside the verbs drawn once for all of them; a phase-2 sentence's
// versions side by side) and drains their encoders.
#include "stimuli/study/study_listing.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace signstim::app {

struct StudyRunOptions {
    std::filesystem::path studyFile;  // empty: SCENES/studies/default.json
    std::filesystem::path out;
    bool quick = false;               // the study's "quick" render settings
    unsigned jobs = 0;                // encoders at once; 0: the machine's cores
    std::size_t shardIndex = 0, shardCount = 1;
    bool pngFrames = false;           // also PNG frames (or the study file's outputs.pngFrames)
    std::string experiment;           // "jspsych": also experiment/ (or the study file's outputs.experiment)
    bool shareFrames = true;          // false: every version drawn in full (the naive cost, for bench)
    std::string device;
    std::string scenesDir;
    std::string lexicon;
    bool allowDraftAnimator = false;  // animator files marked "draft" may be used (listed as such)
    bool quiet = false;
    bool force = false;               // write into a folder that holds other files (never deleting them)
};

struct StudyRunReport {
    std::size_t units = 0, unitsInShard = 0, rendered = 0, skipped = 0;
    std::uint64_t clipFrames = 0;      // frames written to clips by this run
    std::uint64_t renderedImages = 0;  // images drawn by this run
    std::uint64_t sharedFrames = 0;    // story frames drawn once for all versions
    double timelineSeconds = 0.0, renderSeconds = 0.0, encodeWaitSeconds = 0.0, writeSeconds = 0.0;
    double totalSeconds = 0.0;
    double annotationSeconds = 0.0;    // eye-tracking regions and ELAN files (app/study_annotations.hpp)
    bool complete = false;             // every unit of the study is there (exports and manifest written)
    bool experiment = false;           // experiment/ was written with them
    std::string firstParticipant;      // "P01", for the message that says how to open it
    std::vector<std::string> missing;  // units not complete yet (other shards)
};

// Reads and checks the study file, its stories and phase-2 sentences, builds every timeline
// in every version (as the render would), and prints a summary. Throws InputError (exit 2).
void checkStudy(const StudyRunOptions& options);

StudyRunReport runStudy(const StudyRunOptions& options);

// "2/8" -> {2, 8}: shard I of N, 0-based (I = SLURM_ARRAY_TASK_ID of `sbatch --array=0-(N-1)`).
// Throws InputError naming --shard (exit 1).
std::pair<std::size_t, std::size_t> parseShard(const std::string& text);
// The shard from SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN of SLURM_ARRAY_TASK_COUNT, when
// set (an array declared 1-N works too); {0, 1} otherwise.
std::pair<std::size_t, std::size_t> shardFromEnvironment();

}  // namespace signstim::app
