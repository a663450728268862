#pragma once
// Manifests: the one writer of the `manifest.json` that says "this folder is complete" (the
// study folder's, stimuli/study/study_folder.hpp, and `demo`'s). Every file is listed with its
// path relative to the folder, its kind, its size and its SHA-256, so that a reviewer can check
// that a stimulus set is the one that was generated (docs/study.md, docs/errors.md).
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>

namespace signstim {

// {"path", "kind", "sha256", "bytes"} of `root/relative`; a folder (kind "frames") is described
// by folderDigest and folderBytes, with "files" its number of files. Throws InputError naming a
// file that cannot be read.
nlohmann::json describeFile(const std::filesystem::path& root, const std::string& relative, const std::string& kind);

// The digest of a folder of files (a clip's PNG frames): each file's name and SHA-256, one per
// line, sorted by name, hashed. `files`, when given, receives how many there are.
std::string folderDigest(const std::filesystem::path& folder, std::uint64_t* files = nullptr);
std::uint64_t folderBytes(const std::filesystem::path& folder);

// The manifest (and a study's review page with it) goes before the first of the files it lists
// is overwritten, and the new one is written last (writeManifest, atomically), so that a folder
// with a manifest is complete and one without is visibly not. removeStaleFile throws IoError
// (exit 3) when an existing file cannot be removed; an absent one is no error.
void removeStaleFile(const std::filesystem::path& file);
void writeManifest(const std::filesystem::path& manifestFile, const nlohmann::json& manifest);

}  // namespace signstim
