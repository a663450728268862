#pragma once
// glTF 2.0 morph targets (§3.7.2.2), converted and validated: the part of the conversion
// (gltf_loader.cpp) that reads primitive.targets, mesh.weights, mesh.extras.targetNames,
// node.weights and "weights" animation channels. Broken input throws InputError naming the
// file and the JSON pointer, as the rest of the loader does. Internal to the renderer.
//
// Refused: primitives of one mesh with different target counts; more than kMaxMorphTargets
// targets, or more than kMaxMorphElements vertex x target pairs in a primitive (a file's claim
// on memory); a target attribute the base primitive lacks; POSITION/NORMAL targets that are
// not VEC3 FLOAT or whose count differs from the base's; target values outside the
// accessor's declared min/max; non-finite values; weights (mesh, node) whose length is not
// the target count; targetNames that are not as many strings as targets; a "weights" channel
// whose node has no morph targets, or whose output is not SCALAR (FLOAT or normalized
// integers) with keys x targets values (x 3 for CUBICSPLINE). Sparse accessors (indices in
// range and strictly increasing) are checked by ValidatedGltf::readAccessor.
// Ignored with a warning: TANGENT and other target attributes (the renderer has no tangents).
#include "renderer/gltf_validate.hpp"
#include "renderer/scene.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace signstim::render::gltf_morph {

constexpr std::size_t kMaxMorphTargets = 256;         // ARKit faces have 52; 64 is the renderer's promise
constexpr std::size_t kMaxMorphElements = 1u << 24;   // vertices x targets per primitive

// Mesh-level checks and data for mesh `mesh`: equal target counts across its primitives,
// mesh.weights (or zeros), extras.targetNames. Call before its primitives' targets.
void convertMeshMorphs(const ValidatedGltf& gltf, std::size_t mesh, Mesh& out);

// The targets of primitive `primitive` of mesh `mesh` into out.targets (out.vertices set).
void convertPrimitiveTargets(const ValidatedGltf& gltf, std::size_t mesh, std::size_t primitive,
                             Primitive& out, std::vector<std::string>* warnings);

// node.weights of every node (meshes converted first: the length is their target count).
void convertNodeWeights(const ValidatedGltf& gltf, Scene& scene);

// A "weights" channel `channel` of animation `animation`: checks its sampler's output (already
// read into sampler.weights) against the target node's mesh and sets sampler.weightCount.
void convertWeightsChannel(const ValidatedGltf& gltf, const Scene& scene, std::size_t animation,
                           std::size_t channel, AnimationSampler& sampler);

}  // namespace signstim::render::gltf_morph
