#include "renderer/vk_morph.hpp"

#include "common/error.hpp"
#include "renderer/vk_descriptors.hpp"

#include <glm/glm.hpp>

namespace signstim::render::vk {

UniqueDescriptorSetLayout createMorphSetLayout(VkDevice device) {
    return createSetLayout(device, {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT}});
}

GpuMorphs::GpuMorphs(const Device& device, const CommandPool& commands, const GpuScene& gpu,
                     VkDescriptorSetLayout layout) {
    const Scene& scene = gpu.cpu();
    std::vector<std::uint32_t> slots;
    meshes_.resize(scene.meshes.size());
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        const auto& primitives = scene.meshes[m].primitives;
        meshes_[m].resize(primitives.size());
        for (std::size_t p = 0; p < primitives.size(); ++p) {
            const Primitive& primitive = primitives[p];
            const auto offset = static_cast<std::size_t>(gpu.primitives(static_cast<int>(m))[p].vertexOffset);
            if (slots.size() < offset + primitive.vertices.size()) slots.resize(offset + primitive.vertices.size(), kNoMorph);
            Moved& moved = meshes_[m][p];
            moved.targets = primitive.targets.size();
            for (std::size_t v = 0; v < primitive.vertices.size() && moved.targets > 0; ++v) {
                bool moves = false;
                for (const MorphTarget& target : primitive.targets)
                    moves = moves || (v < target.position.size() && target.position[v] != glm::vec3(0.0f)) ||
                            (v < target.normal.size() && target.normal[v] != glm::vec3(0.0f));
                if (!moves) continue;
                slots[offset + v] = static_cast<std::uint32_t>(moved.position.size());
                moved.position.push_back(primitive.vertices[v].position);
                moved.normal.push_back(primitive.vertices[v].normal);
                for (const MorphTarget& target : primitive.targets) {
                    moved.positionDelta.push_back(v < target.position.size() ? target.position[v] : glm::vec3(0.0f));
                    moved.normalDelta.push_back(v < target.normal.size() ? target.normal[v] : glm::vec3(0.0f));
                }
            }
        }
    }
    // Device limit, checked when the scene is added: one binding holds every vertex's slot.
    const VkDeviceSize bytes = slots.size() * sizeof(std::uint32_t);
    const VkDeviceSize range = device.properties().limits.maxStorageBufferRange;
    if (bytes > range)
        throw InputError(scene.sourceName, 0, "/meshes",
                         "morph targets need " + std::to_string(bytes) + " bytes of vertex slots; device '" +
                             std::string(device.properties().deviceName) + "' allows " + std::to_string(range) +
                             " per storage buffer (maxStorageBufferRange)");
    slots_ = uploadBuffer(device, commands, slots.empty() ? nullptr : slots.data(), bytes,
                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    pool_ = createDescriptorPool(device.get(), 1, {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}});
    set_ = allocateSet(device.get(), pool_.get(), layout);
    DescriptorWriter()
        .buffer(0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, slots_.buffer.get(), slots_.size)
        .update(device.get(), set_);
}

std::size_t GpuMorphs::movedVertices() const {
    std::size_t count = 0;
    for (const auto& mesh : meshes_)
        for (const Moved& moved : mesh) count += moved.position.size();
    return count;
}

void GpuMorphs::appendMorphed(int mesh, const std::vector<float>& weights, std::vector<glm::vec4>& out,
                              std::vector<std::uint32_t>& bases) const {
    bases.clear();
    if (mesh < 0 || static_cast<std::size_t>(mesh) >= meshes_.size()) return;
    // The non-zero weights once per node, not per vertex.
    std::vector<std::pair<std::size_t, float>> active;
    for (std::size_t t = 0; t < weights.size(); ++t)
        if (weights[t] != 0.0f) active.emplace_back(t, weights[t]);
    for (const Moved& moved : meshes_[static_cast<std::size_t>(mesh)]) {
        if (active.empty() || moved.position.empty() || moved.targets != weights.size()) {
            bases.push_back(kNoMorph);
            continue;
        }
        bases.push_back(static_cast<std::uint32_t>(out.size()));
        for (std::size_t c = 0; c < moved.position.size(); ++c) {
            glm::vec3 position = moved.position[c], normal = moved.normal[c];
            const std::size_t row = c * moved.targets;
            for (const auto& [t, w] : active) {
                position += w * moved.positionDelta[row + t];
                normal += w * moved.normalDelta[row + t];
            }
            out.emplace_back(position, 1.0f);
            out.emplace_back(normal, 0.0f);
        }
    }
}

}  // namespace signstim::render::vk
