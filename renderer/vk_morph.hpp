#pragma once
// Morph targets for the GPU (shaders/mesh_vertex.glsl, MORPH). Per frame, the CPU sums each
// morphed node's displacements (glTF 2.0 §3.7.2.2: p = p0 + sum w_i dp_i, the normal alike)
// for the vertices some target moves, and only those: a face's ~2k vertices of a ~15k-vertex
// signer, over its non-zero weights. The vertex shader reads the morphed position and normal
// of such a vertex from the frame's storage buffer and skins them (morph first, then skin).
// Plain storage buffers, no descriptor indexing, so lavapipe runs it. Measured on lavapipe
// (BENCHMARKS.md, bench render's morph row): summing 52 targets in the vertex shader, two
// bounds-checked gathers per target and vertex, cost 15-25 % of the signer's frame rate.
#include "renderer/scene.hpp"
#include "renderer/vk_commands.hpp"
#include "renderer/vk_memory.hpp"
#include "renderer/vk_scene.hpp"

#include <cstdint>
#include <vector>

namespace signstim::render::vk {

// Set 2 of the mesh pipeline layout: the per-vertex slots (binding 0).
UniqueDescriptorSetLayout createMorphSetLayout(VkDevice device);

constexpr std::uint32_t kNoMorph = 0xFFFFFFFFu;  // a primitive (or vertex) nothing moves

class GpuMorphs {
public:
    // Keeps the targets of every primitive of `gpu`'s scene for the vertices some target
    // moves (vertex-major: targets x (position, normal) per moved vertex) and uploads
    // morphSlots: for each vertex of the scene, its index among its primitive's moved
    // vertices, or kNoMorph. Throws InputError naming the scene when the slots exceed the
    // device's maxStorageBufferRange.
    GpuMorphs(const Device& device, const CommandPool& commands, const GpuScene& gpu,
              VkDescriptorSetLayout layout);

    VkDescriptorSet set() const { return set_; }
    std::size_t movedVertices() const;

    // Appends, for each primitive of mesh `mesh`, the morphed (position, normal) pairs of its
    // moved vertices at `weights` to `out`, and sets bases[p] to where primitive p's pairs
    // start (in vec4s), or kNoMorph when it has none. Zero weights cost nothing.
    void appendMorphed(int mesh, const std::vector<float>& weights, std::vector<glm::vec4>& out,
                       std::vector<std::uint32_t>& bases) const;

private:
    struct Moved {  // one primitive's moved vertices
        std::size_t targets = 0;
        std::vector<glm::vec3> position, normal;              // base, per moved vertex
        std::vector<glm::vec3> positionDelta, normalDelta;    // moved x targets
    };
    std::vector<std::vector<Moved>> meshes_;  // [mesh][primitive]
    Buffer slots_;
    UniqueDescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
};

}  // namespace signstim::render::vk
