#pragma once
// Descriptor set layouts, pools and writes. Plain sets (lavapipe has no descriptor
// indexing): one set per frame slot, one per material.
#include "renderer/vk_handle.hpp"

#include <cstdint>
#include <vector>

namespace signstim::render::vk {

struct Binding {
    std::uint32_t binding;
    VkDescriptorType type;
    VkShaderStageFlags stages;
};

UniqueDescriptorSetLayout createSetLayout(VkDevice device, const std::vector<Binding>& bindings);

// Pool for `maxSets` sets, each with at most the given count of each type.
UniqueDescriptorPool createDescriptorPool(VkDevice device, std::uint32_t maxSets,
                                          const std::vector<VkDescriptorPoolSize>& perSet);

VkDescriptorSet allocateSet(VkDevice device, VkDescriptorPool pool, VkDescriptorSetLayout layout);

class DescriptorWriter {
public:
    DescriptorWriter& buffer(std::uint32_t binding, VkDescriptorType type, VkBuffer buffer,
                             VkDeviceSize size);
    DescriptorWriter& image(std::uint32_t binding, VkImageView view, VkSampler sampler);
    void update(VkDevice device, VkDescriptorSet set);

private:
    struct Entry {
        std::uint32_t binding;
        VkDescriptorType type;
        VkDescriptorBufferInfo buffer;
        VkDescriptorImageInfo image;
    };
    std::vector<Entry> entries_;
};

}  // namespace signstim::render::vk
