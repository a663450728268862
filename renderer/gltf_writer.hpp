#pragma once
// glTF 2.0 writer for the CPU Scene: `.glb` (binary) or `.gltf` with the buffer embedded as a
// base64 data URI, chosen by extension. Writes nodes (TRS or matrix), meshes, materials,
// textures (images PNG-encoded), skins, morph targets (dense; names as
// mesh.extras.targetNames) and animations. Deterministic: the same Scene gives a
// byte-identical file. Atomic (temporary file, then rename).
#include "renderer/scene.hpp"

#include <filesystem>
#include <string>

namespace signstim::render {

// Throws InputError naming the path for an unknown extension or an unwritable location,
// std::invalid_argument for an inconsistent Scene (index out of range).
void writeGltf(const Scene& scene, const std::filesystem::path& path);

// The same document in memory (.glb bytes when `binary`, else .gltf JSON text).
std::string encodeGltf(const Scene& scene, bool binary);

}  // namespace signstim::render
