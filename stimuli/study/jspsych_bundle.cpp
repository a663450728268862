#include "stimuli/study/jspsych_bundle.hpp"

#include "common/error.hpp"
#include "stimuli/json_source.hpp"
#include "stimuli/scenes_path.hpp"
#include "stimuli/study/study_experiment.hpp"

#include <algorithm>
#include <cstdlib>
#include <system_error>

namespace signstim::stimuli {

namespace fs = std::filesystem;

namespace {

constexpr const char* kSetupHint =
    "run scripts/setup.sh (or scripts/fetch-jspsych.sh) in the signstim repository to fetch jsPsych, "
    "or set SIGNSTIM_JSPSYCH to a folder it filled";

fs::path findFolder() {
    std::error_code error;
    if (const char* env = std::getenv("SIGNSTIM_JSPSYCH"); env != nullptr && *env != '\0') {
        if (!fs::is_directory(env, error))
            throw EnvironmentError(std::string("SIGNSTIM_JSPSYCH: '") + env + "' is not a folder; " + kSetupHint);
        return env;
    }
    std::vector<fs::path> candidates;
    if (const fs::path exe = stimuli::executablePath(); !exe.empty()) {
        candidates.push_back(exe.parent_path() / ".." / "third_party" / "jspsych");
        candidates.push_back(exe.parent_path() / ".." / ".." / "third_party" / "jspsych");
    }
#ifdef SIGNSTIM_SOURCE_DIR
    candidates.push_back(fs::path(SIGNSTIM_SOURCE_DIR) / "third_party" / "jspsych");
#endif
    std::vector<fs::path> tried;
    for (const fs::path& candidate : candidates) {
        if (fs::is_regular_file(candidate / "PINS.txt", error)) return candidate.lexically_normal();
        if (std::find(tried.begin(), tried.end(), candidate.lexically_normal()) == tried.end())
            tried.push_back(candidate.lexically_normal());
    }
    std::string list;
    for (const fs::path& folder : tried) list += (list.empty() ? "" : ", ") + folder.string();
    throw EnvironmentError("--experiment jspsych: jsPsych is not installed (looked in " + list + "); " + kSetupHint);
}

}  // namespace

JspsychBundle loadJspsychBundle() {
    JspsychBundle bundle;
    bundle.folder = findFolder();
    std::string missing;
    for (const stimuli::ExperimentLibraryFile& file : stimuli::jspsychLibraryFiles()) {
        std::error_code error;
        if (!fs::is_regular_file(bundle.folder / file.source, error)) missing += (missing.empty() ? "" : ", ") + file.source;
    }
    if (!missing.empty())
        throw EnvironmentError("--experiment jspsych: " + bundle.folder.string() + " lacks " + missing +
                               " (fetched for another set of packages?); " + kSetupHint);
    for (const stimuli::ExperimentLibraryFile& file : stimuli::jspsychLibraryFiles())
        bundle.files.push_back({file.path, stimuli::readTextFile(bundle.folder / file.source)});
    return bundle;
}

}  // namespace signstim::stimuli
