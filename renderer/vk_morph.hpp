#pragma once
// Morph targets on the GPU (shaders/mesh_vertex.glsl, MORPH): one scene's displacements in
// storage buffers behind one descriptor set (set 2), and a frame's weights as (target,
// weight) pairs. Plain storage buffers, no descriptor indexing, so lavapipe runs it.
#include "renderer/scene.hpp"
#include "renderer/vk_commands.hpp"
#include "renderer/vk_memory.hpp"
#include "renderer/vk_scene.hpp"

#include <cstdint>
#include <vector>

namespace signstim::render::vk {

// Set 2 of the mesh pipeline layout: displacements (binding 0), per-vertex slots (binding 1).
UniqueDescriptorSetLayout createMorphSetLayout(VkDevice device);

// One (target, weight) pair of the per-frame weights buffer (set 0, binding 1).
struct MorphEntry {
    std::uint32_t target = 0;
    float weight = 0.0f;
};
static_assert(sizeof(MorphEntry) == 8, "shaders/mesh_vertex.glsl reads uvec2 pairs");

// Appends the non-zero weights of `weights` as pairs (zero weights cost nothing on the GPU).
void appendActiveWeights(const std::vector<float>& weights, std::vector<MorphEntry>& out);

class GpuMorphs {
public:
    // Uploads the targets of every primitive of `gpu`'s scene, vertex-major: for each vertex
    // some target moves, 2 x targets vec4s (position, normal displacement per target); other
    // vertices get no storage. Throws InputError naming the scene when the displacements
    // exceed the device's maxStorageBufferRange.
    GpuMorphs(const Device& device, const CommandPool& commands, const GpuScene& gpu,
              VkDescriptorSetLayout layout);

    VkDescriptorSet set() const { return set_; }
    std::size_t movedVertices() const { return moved_; }

private:
    Buffer deltas_, slots_;
    UniqueDescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    std::size_t moved_ = 0;
};

}  // namespace signstim::render::vk
