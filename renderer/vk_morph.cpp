#include "renderer/vk_morph.hpp"

#include "common/error.hpp"
#include "renderer/vk_descriptors.hpp"

#include <glm/glm.hpp>

#include <limits>

namespace signstim::render::vk {

UniqueDescriptorSetLayout createMorphSetLayout(VkDevice device) {
    return createSetLayout(device, {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT},
                                    {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT}});
}

void appendActiveWeights(const std::vector<float>& weights, std::vector<MorphEntry>& out) {
    for (std::size_t t = 0; t < weights.size(); ++t)
        if (weights[t] != 0.0f) out.push_back({static_cast<std::uint32_t>(t), weights[t]});
}

GpuMorphs::GpuMorphs(const Device& device, const CommandPool& commands, const GpuScene& gpu,
                     VkDescriptorSetLayout layout) {
    const Scene& scene = gpu.cpu();
    constexpr std::uint32_t kUnmoved = 0xFFFFFFFFu;  // mesh_vertex.glsl: no displacement
    std::vector<glm::vec4> deltas;
    std::vector<std::uint32_t> slots;
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        const auto& primitives = scene.meshes[m].primitives;
        for (std::size_t p = 0; p < primitives.size(); ++p) {
            const Primitive& primitive = primitives[p];
            const auto offset = static_cast<std::size_t>(gpu.primitives(static_cast<int>(m))[p].vertexOffset);
            if (slots.size() < offset + primitive.vertices.size()) slots.resize(offset + primitive.vertices.size(), kUnmoved);
            if (primitive.targets.empty()) continue;
            const std::size_t targets = primitive.targets.size();
            for (std::size_t v = 0; v < primitive.vertices.size(); ++v) {
                bool moved = false;
                for (const MorphTarget& target : primitive.targets)
                    moved = moved || (v < target.position.size() && target.position[v] != glm::vec3(0.0f)) ||
                            (v < target.normal.size() && target.normal[v] != glm::vec3(0.0f));
                if (!moved) continue;
                if (deltas.size() > std::numeric_limits<std::uint32_t>::max() - 2 * targets)
                    throw InputError(scene.sourceName, 0, "/meshes/" + std::to_string(m), "too many morph displacements");
                slots[offset + v] = static_cast<std::uint32_t>(deltas.size());
                for (const MorphTarget& target : primitive.targets) {
                    deltas.push_back(glm::vec4(v < target.position.size() ? target.position[v] : glm::vec3(0.0f), 0.0f));
                    deltas.push_back(glm::vec4(v < target.normal.size() ? target.normal[v] : glm::vec3(0.0f), 0.0f));
                }
                ++moved_;
            }
        }
    }
    // Device limit, checked when the scene is added: one binding holds all displacements.
    const VkDeviceSize bytes = deltas.size() * sizeof(glm::vec4);
    const VkDeviceSize range = device.properties().limits.maxStorageBufferRange;
    if (bytes > range || slots.size() * sizeof(std::uint32_t) > range)
        throw InputError(scene.sourceName, 0, "/meshes",
                         "morph targets need " + std::to_string(bytes) + " bytes of displacements; device '" +
                             std::string(device.properties().deviceName) + "' allows " + std::to_string(range) +
                             " per storage buffer (maxStorageBufferRange)");
    deltas_ = uploadBuffer(device, commands, deltas.empty() ? nullptr : deltas.data(), bytes,
                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    slots_ = uploadBuffer(device, commands, slots.empty() ? nullptr : slots.data(),
                          slots.size() * sizeof(std::uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    pool_ = createDescriptorPool(device.get(), 1, {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2}});
    set_ = allocateSet(device.get(), pool_.get(), layout);
    DescriptorWriter()
        .buffer(0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, deltas_.buffer.get(), deltas_.size)
        .buffer(1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, slots_.buffer.get(), slots_.size)
        .update(device.get(), set_);
}

}  // namespace signstim::render::vk
