#include "common/file_manifest.hpp"

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/sha256.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <vector>

namespace signstim {

namespace fs = std::filesystem;

std::string folderDigest(const fs::path& folder, std::uint64_t* files) {
    Sha256 hash;
    std::vector<fs::path> names;
    for (const fs::directory_entry& e : fs::directory_iterator(folder)) names.push_back(e.path());
    std::sort(names.begin(), names.end());
    for (const fs::path& f : names) hash.update(f.filename().string() + " " + sha256File(f) + "\n");
    if (files) *files = names.size();
    return hash.hexDigest();
}

std::uint64_t folderBytes(const fs::path& folder) {
    std::uint64_t bytes = 0;
    for (const fs::directory_entry& e : fs::directory_iterator(folder)) bytes += e.file_size();
    return bytes;
}

nlohmann::json describeFile(const fs::path& root, const std::string& relative, const std::string& kind) {
    const fs::path path = root / relative;
    nlohmann::json entry;
    entry["path"] = relative;
    entry["kind"] = kind;
    if (kind == "frames") {
        std::uint64_t files = 0;
        entry["sha256"] = folderDigest(path, &files);
        entry["bytes"] = folderBytes(path);
        entry["files"] = files;
    } else {
        entry["sha256"] = sha256File(path);
        entry["bytes"] = static_cast<std::uint64_t>(fs::file_size(path));
    }
    return entry;
}

void removeStaleFile(const fs::path& file) {
    if (::unlink(file.c_str()) != 0 && errno != ENOENT) {
        const int error = errno;
        throw IoError(file.string(), "cannot remove the earlier " + file.filename().string(), error);
    }
}

void writeManifest(const fs::path& manifestFile, const nlohmann::json& manifest) {
    writeFileAtomic(manifestFile, manifest.dump(2) + "\n");
}

}  // namespace signstim
