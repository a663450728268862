#pragma once
// glTF 2.0 loader (.gltf with external or data-URI buffers, .glb) into the CPU Scene.
// Everything is validated before any data is read: index references, accessor ranges against
// their bufferView and buffer, declared sizes against the actual data, index and joint values,
// NaN/Inf, the node graph (one parent per node, no cycles). Broken input throws
// signstim::InputError(file, line, field, message) with the glTF path of the offending field
// (e.g. "accessors[3].count"); the loader never reads out of bounds.
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

}  // namespace signstim::render
