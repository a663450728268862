#pragma once
// glTF 2.0 loader (.gltf with external or data-URI buffers, .glb) into the CPU Scene, in two
// steps: validation (gltf_validate.hpp: the container, the JSON, every index reference and
// byte range, checked before any data is read) and conversion (this file: images, samplers,
// materials, nodes, meshes, skins, animations into a Scene). Broken input throws
// signstim::InputError(file, line, field, message) with the glTF path of the offending field
// as a JSON pointer (e.g. "/accessors/3/count"); the loader never reads out of bounds.
//
// Conversion refuses, in the same way, what only shows in the values: index values past the
// vertex count, joint indices past their skin's joints, negative weights, the node graph (one
// parent per node, no cycles), NaN/Inf in factors and transforms, unknown enum values (wrap
// modes, filters, alpha modes, interpolation), key times that do not increase, images that
// do not decode.
//
// Deviations from the glTF spec, chosen for stimuli rendering:
//  - Missing normals are computed smooth (area weighted over shared vertices), not flat.
//  - Points and lines primitives are skipped (warning); strips and fans become lists.
//  - Cameras and lights are ignored. Morph targets: POSITION and NORMAL are applied (with
//    mesh/node weights, "weights" channels and extras.targetNames: gltf_morph.hpp); other
//    target attributes (TANGENT, TEXCOORD_n, COLOR_n) are ignored (warning).
#include "renderer/gltf_validate.hpp"
#include "renderer/scene.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace signstim::render {

// `warnings` (optional) receives notes about valid-but-unusual input (e.g. a skin without
// inverseBindMatrices, skipped primitives).
Scene loadGltf(const std::filesystem::path& path, std::vector<std::string>* warnings = nullptr);

// GltfLoadOptions (which folders images and buffers may come from): gltf_validate.hpp.
Scene loadGltf(const std::filesystem::path& path, const GltfLoadOptions& options,
               std::vector<std::string>* warnings = nullptr);

// Loads the in-memory .gltf or .glb `bytes` as if they were the file `fileName` in
// `baseDirectory` (validateGltfBytes, then convertGltf): with a file's bytes,
// loadGltfBytes(bytes, path.string(), path.parent_path(), options) == loadGltf(path, options),
// errors included.
Scene loadGltfBytes(std::string bytes, const std::string& fileName, const std::filesystem::path& baseDirectory,
                    const GltfLoadOptions& options, std::vector<std::string>* warnings = nullptr);

// The conversion alone: a validated model into a Scene (scene.sourceName = its fileName()).
Scene convertGltf(ValidatedGltf gltf, std::vector<std::string>* warnings = nullptr);

}  // namespace signstim::render
