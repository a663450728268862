#pragma once
// jsPsych for `signstim study --experiment jspsych` (docs/experiment.md): the npm packages that
// scripts/fetch-jspsych.sh (run by scripts/setup.sh) unpacks into third_party/jspsych/, found at
// run time like the scenes/ folder (stimuli/scenes_path.hpp) and read into memory before any
// rendering, so that a missing folder fails in the first second, not after the clips.
#include <filesystem>
#include <string>
#include <vector>

namespace signstim::stimuli {

struct JspsychBundle {
    std::filesystem::path folder;  // where the packages were found
    struct File {
        std::string path;      // relative to the study folder: "experiment/jspsych/jspsych.js"
        std::string contents;  // the bytes, as fetched
    };
    std::vector<File> files;   // stimuli::jspsychLibraryFiles(), in its order
};

// The packages' folder: $SIGNSTIM_JSPSYCH when set, else the first of
// <exe dir>/../third_party/jspsych, <exe dir>/../../third_party/jspsych (the build tree) and the
// source tree's third_party/jspsych that holds the pins file (PINS.txt). Then every file of
// stimuli::jspsychLibraryFiles(). Throws EnvironmentError (exit 3) naming what is missing and
// saying to run scripts/setup.sh; IoError when a file cannot be read.
JspsychBundle loadJspsychBundle();

}  // namespace signstim::stimuli
