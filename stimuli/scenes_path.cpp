#include "stimuli/scenes_path.hpp"

#include "common/error.hpp"

#include <cstdlib>
#include <system_error>
#include <vector>

namespace signstim::stimuli {

std::filesystem::path executablePath() {
    std::error_code error;
    auto path = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::path{} : path;
}

std::filesystem::path resolveScenesDir(const std::filesystem::path& explicitDir) {
    namespace fs = std::filesystem;
    std::error_code error;
    if (!explicitDir.empty()) {
        if (!fs::is_directory(explicitDir, error)) {
            throw InputError("<command line>", 0, "--scenes", "'" + explicitDir.string() + "' is not a directory");
        }
        return explicitDir;
    }
    if (const char* env = std::getenv("SIGNSTIM_SCENES"); env != nullptr && *env != '\0') {
        if (!fs::is_directory(env, error)) {
            throw InputError("<environment>", 0, "SIGNSTIM_SCENES", std::string("'") + env + "' is not a directory");
        }
        return env;
    }
    std::vector<fs::path> candidates;
    if (const fs::path exe = executablePath(); !exe.empty()) {
        candidates.push_back(exe.parent_path() / ".." / "scenes");
        candidates.push_back(exe.parent_path() / ".." / ".." / "scenes");
    }
#ifdef SIGNSTIM_SOURCE_DIR
    candidates.push_back(fs::path(SIGNSTIM_SOURCE_DIR) / "scenes");
#endif
    std::string tried;
    for (const fs::path& candidate : candidates) {
        if (fs::is_directory(candidate, error)) return candidate.lexically_normal();
        tried += (tried.empty() ? "" : ", ") + candidate.lexically_normal().string();
    }
    throw InputError("<environment>", 0, "scenes",
                     "cannot find the scenes/ directory (tried " + tried +
                         "); pass --scenes DIR or set SIGNSTIM_SCENES");
}

}  // namespace signstim::stimuli
