#pragma once
// Experiment results, one CSV per participant (docs/analysis.md, "Inputs"), read and checked
// against the study that was shown (its manifest's listing, stimuli/study/study_listing.hpp):
//  - every participant, story, sentence and version must be the study's, and each trial what
//    the design showed that participant (the version of each story, the panel code of each
//    sentence); a mistake is an InputError naming file:line and the column (exit 2);
//  - correctness is recomputed from the answer keys, and phase-2 ratings of panels A, B, ... are
//    turned into ratings of versions from the panel code; where the file's own qN_correct,
//    n_correct or rating_<version> disagree, that is a warning (the recomputed values are the
//    ones analysed), as are missing answers, ratings and trials.
// Columns are found by name (any order; other columns are ignored); a ColumnMap renames them
// for files written by PsychoPy, Gorilla or other software.
#include "stimuli/study/study_listing.hpp"

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace signstim::stimuli {
struct JsonSource;
}

namespace signstim::analysis {

// The results columns, in the order signstim (and the jsPsych experiment) writes them.
const std::vector<std::string>& resultsColumns();

// Our column names -> the names in another program's files (docs/analysis.md, "Column map").
struct ColumnMap {
    std::string file;  // the map's file, "" when none
    std::map<std::string, std::string> theirs;
    // The name to look for in a results file: the mapped name, else ours.
    const std::string& nameOf(const std::string& ours) const;
    // "resp.q2 (q2_response)" for messages when mapped, else "q2_response".
    std::string describe(const std::string& ours) const;
};

// {"format": "signstim-results-columns", "version": 1, "columns": {"q1_response": "key_resp_1.keys", ...}}.
// Keys must be our column names, values distinct non-empty names. InputError naming file:line:field.
ColumnMap parseColumnMap(const stimuli::JsonSource& source);
ColumnMap readColumnMap(const std::filesystem::path& file);

inline constexpr int kNoAnswer = -1;

struct Phase1Result {
    int line = 0;
    std::size_t trial = 0;
    std::size_t story = 0;    // index into StudyListing::stories
    std::size_t version = 0;  // index into StudyListing::versions
    std::vector<int> choices;   // per question: 0-based choice, kNoAnswer when not answered
    std::vector<bool> correct;  // per question, recomputed from the answer key (no answer: incorrect)
};

struct Phase2Result {
    int line = 0;
    std::size_t trial = 0;
    std::size_t sentence = 0;    // index into StudyListing::sentences
    std::vector<double> ratings; // per version (study order), unmapped from the panels; NaN when not rated
};

struct ParticipantResults {
    std::string file;       // as given
    std::string fileName;   // its last component (reports: the same bytes wherever the files are)
    std::string sha256;     // of the file's bytes
    std::string participant;
    std::size_t participantIndex = 0;  // into StudyListing::participants
    bool synthetic = false;            // a comment line before the header says SYNTHETIC
    std::vector<Phase1Result> phase1;  // in file order
    std::vector<Phase2Result> phase2;
};

// One participant's file. Problems the analysis can go on with are appended to `warnings`
// ("FILE:LINE: field 'q2_correct': ..."); anything else throws InputError.
ParticipantResults parseResults(std::string_view text, const std::string& file, const stimuli::StudyListing& study,
                                const ColumnMap& columns, std::vector<std::string>& warnings);
ParticipantResults readResults(const std::filesystem::path& file, const stimuli::StudyListing& study,
                               const ColumnMap& columns, std::vector<std::string>& warnings);

// Every file, sorted by participant (the order of the study's participants). Refuses two files
// of one participant, naming both.
std::vector<ParticipantResults> readResultsFiles(const std::vector<std::filesystem::path>& files,
                                                 const stimuli::StudyListing& study, const ColumnMap& columns,
                                                 std::vector<std::string>& warnings);

// The study listing of a rendered study: DIR/manifest.json (or the manifest file itself), its
// "study" member. InputError when it is not a study manifest or has no listing.
stimuli::StudyListing readStudyManifest(const std::filesystem::path& studyDirOrManifest, std::string* manifestPath = nullptr);

}  // namespace signstim::analysis
