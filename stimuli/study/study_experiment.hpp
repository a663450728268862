#pragma once
// A study's ready-to-run jsPsych 8 experiment (docs/experiment.md): the folder experiment/ of a
// study, which runs from disk (file://) and from any static web server:
//
//   experiment/index.html              ?participant=P07 runs P07's session; without it, the list
//   experiment/experiment.js, .css     the session (stimuli/experiment/*: the same for every study)
//   experiment/participants/index.js   the study's title and participant ids (window.signstimStudy)
//   experiment/participants/P07.js     P07's timeline variables (window.signstimTimeline), the
//                                      content of participants/P07/P07_timeline_variables.json
//   experiment/jspsych/...             jsPsych and its plugins (ExperimentLibraryFile), copied by
//                                      the study runner from the fetched packages
//
// Scripts, not JSON read with fetch(): browsers refuse fetch() and module scripts from file://.
// The clips stay in the study's clips/ folder (../clips/ from the page). A session saves one CSV
// row per trial as signstim-results_P07.csv (its columns: experiment.js, docs/experiment.md).
//
// Pure functions of a StudyListing, like the exports (stimuli/study/study_exports.hpp): the runner
// writes the contents atomically. Same listing -> the same bytes.
#include "stimuli/study/study_listing.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace signstim::stimuli {

struct ExperimentFile {
    std::string path;         // relative to the study folder: "experiment/index.html"
    std::string participant;  // "P07" for a participant's timeline, else empty
    std::string contents;
};

// A file of the jsPsych npm packages (scripts/fetch-jspsych.sh unpacks them into
// third_party/jspsych/<package>/) that the experiment loads.
struct ExperimentLibraryFile {
    std::string source;  // relative to the packages' folder: "jspsych/dist/index.browser.js"
    std::string path;    // relative to the study folder: "experiment/jspsych/jspsych.js"
};

// jsPsych, its stylesheet, the five plugins the session uses, the licence and the pins
// (name, version and SHA-512 of each tarball), in the order index.html loads the scripts.
const std::vector<ExperimentLibraryFile>& jspsychLibraryFiles();

// The experiment's own files: index.html, experiment.js, experiment.css,
// participants/index.js and one participants/PNN.js per participant.
// Throws std::invalid_argument when the listing contradicts itself (as the exports do).
std::vector<ExperimentFile> jspsychExperimentFiles(const StudyListing& listing);

// The most questions a phase-1 story may have in the experiment: the results have columns for
// q1 ... q4. A study whose stories have more is refused by the runner before rendering.
inline constexpr std::size_t kExperimentMaxQuestions = 4;

}  // namespace signstim::stimuli
