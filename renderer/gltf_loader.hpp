#pragma once
// glTF 2.0 loader (.gltf with external or data-URI buffers, .glb) into the CPU Scene.
// Everything is validated before any data is read: index references, accessor ranges against
// their bufferView and buffer, declared sizes against the actual data, index and joint values,
// NaN/Inf, the node graph (one parent per node, no cycles). Broken input throws
// signstim::InputError(file, line, field, message) with the glTF path of the offending field
// as a JSON pointer, as the Khronos glTF-Validator reports it (e.g. "/accessors/3/count");
// the loader never reads out of bounds.
//
// Also refused, as the Khronos glTF-Validator flags them: an extension in extensionsRequired
// (signstim implements none), negative byteOffsets, colour factors outside [0, 1], a texture
// sampled with a TEXCOORD_n set its primitive lacks, an animation without channels, a node
// with both a matrix and TRS, image/buffer URIs outside the model's folder (GltfLoadOptions).
//
// Deviations from the glTF spec, chosen for stimuli rendering:
//  - Missing normals are computed smooth (area weighted over shared vertices), not flat.
//  - Points and lines primitives are skipped (warning); strips and fans become lists.
//  - Morph targets, cameras, lights and "weights" animation channels are ignored (warning).
#include "renderer/scene.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace signstim::render {

// `warnings` (optional) receives notes about valid-but-unusual input (e.g. a skin without
// inverseBindMatrices, skipped primitives).
Scene loadGltf(const std::filesystem::path& path, std::vector<std::string>* warnings = nullptr);

struct GltfLoadOptions {
    // Images and buffers must lie in the model's folder (absolute paths and ".." out of it are
    // refused: a downloaded model must not read the user's other files) or in one of these.
    std::vector<std::filesystem::path> allowedDirectories;
    // The flag that adds to allowedDirectories, named in the refusal ("--allow-dir"); empty:
    // the message suggests none.
    std::string allowFlag;
};
Scene loadGltf(const std::filesystem::path& path, const GltfLoadOptions& options,
               std::vector<std::string>* warnings = nullptr);

}  // namespace signstim::render
