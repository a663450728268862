#pragma once
// The files a glTF model names, for the validator (gltf_validate.cpp): the model file itself,
// and the images and buffers its URIs name, which must stay inside the model's folder.
#include "renderer/gltf_validate.hpp"

#include <filesystem>
#include <string>

namespace signstim::render::gltf_detail {

// Reads the file `path` whole; `file` names it in errors.
std::string readGltfFile(const std::filesystem::path& path, const std::string& file);

// The file name tinygltf will open for `uri`: it percent-decodes exactly like this
// (dlib::urldecode: "%20" and "+" are spaces), so the checks look at the same file.
std::string decodedUri(const std::string& uri);

// The file `name` (decoded from `uri`) relative to `modelFolder`, refused with
// InputError(errorFile, 0, field, ...) if absolute or outside modelFolder and
// options.allowedDirectories (symbolic links followed).
std::filesystem::path checkInsideAllowedFolders(const std::string& name, const std::string& uri,
                                                const std::string& field, const std::filesystem::path& modelFolder,
                                                const GltfLoadOptions& options, const std::string& errorFile);

}  // namespace signstim::render::gltf_detail
