#pragma once
// Finding the scenes/ data directory at run time (never ../shared): an explicit directory
// (e.g. the `--scenes DIR` option), else $SIGNSTIM_SCENES, else `<exe dir>/../scenes`, else
// `<exe dir>/../../scenes` (the build tree), else the source tree compiled in
// (SIGNSTIM_SOURCE_DIR). Shared by every command that reads scenes/.
#include <filesystem>
#include <string>

namespace signstim::stimuli {

// `explicitDir` empty = not given. Throws InputError naming what was tried when none exists
// (an explicit or $SIGNSTIM_SCENES directory that does not exist is an error, not skipped).
std::filesystem::path resolveScenesDir(const std::filesystem::path& explicitDir = {});

// The running executable's path (/proc/self/exe), empty if unknown.
std::filesystem::path executablePath();

}  // namespace signstim::stimuli
