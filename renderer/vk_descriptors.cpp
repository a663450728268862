#include "renderer/vk_descriptors.hpp"

#include "renderer/vk_check.hpp"

namespace signstim::render::vk {

UniqueDescriptorSetLayout createSetLayout(VkDevice device, const std::vector<Binding>& bindings) {
    std::vector<VkDescriptorSetLayoutBinding> vkBindings;
    for (const auto& b : bindings) {
        VkDescriptorSetLayoutBinding binding{};
        binding.binding = b.binding;
        binding.descriptorType = b.type;
        binding.descriptorCount = 1;
        binding.stageFlags = b.stages;
        vkBindings.push_back(binding);
    }
    auto info = make<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
    info.bindingCount = static_cast<std::uint32_t>(vkBindings.size());
    info.pBindings = vkBindings.data();
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    check(vkCreateDescriptorSetLayout(device, &info, nullptr, &layout),
          "vkCreateDescriptorSetLayout");
    return UniqueDescriptorSetLayout(device, layout);
}

UniqueDescriptorPool createDescriptorPool(VkDevice device, std::uint32_t maxSets,
                                          const std::vector<VkDescriptorPoolSize>& perSet) {
    std::vector<VkDescriptorPoolSize> sizes = perSet;
    for (auto& size : sizes) size.descriptorCount *= maxSets;
    auto info = make<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
    info.maxSets = maxSets;
    info.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
    info.pPoolSizes = sizes.data();
    VkDescriptorPool pool = VK_NULL_HANDLE;
    check(vkCreateDescriptorPool(device, &info, nullptr, &pool), "vkCreateDescriptorPool");
    return UniqueDescriptorPool(device, pool);
}

VkDescriptorSet allocateSet(VkDevice device, VkDescriptorPool pool, VkDescriptorSetLayout layout) {
    auto info = make<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
    info.descriptorPool = pool;
    info.descriptorSetCount = 1;
    info.pSetLayouts = &layout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    check(vkAllocateDescriptorSets(device, &info, &set), "vkAllocateDescriptorSets");
    return set;
}

DescriptorWriter& DescriptorWriter::buffer(std::uint32_t binding, VkDescriptorType type,
                                           VkBuffer buffer, VkDeviceSize size) {
    entries_.push_back({binding, type, {buffer, 0, size}, {}});
    return *this;
}

DescriptorWriter& DescriptorWriter::image(std::uint32_t binding, VkImageView view,
                                          VkSampler sampler) {
    entries_.push_back({binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, {},
                        {sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}});
    return *this;
}

void DescriptorWriter::update(VkDevice device, VkDescriptorSet set) {
    std::vector<VkWriteDescriptorSet> writes;
    for (const auto& entry : entries_) {
        auto write = make<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
        write.dstSet = set;
        write.dstBinding = entry.binding;
        write.descriptorCount = 1;
        write.descriptorType = entry.type;
        if (entry.type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER)
            write.pImageInfo = &entry.image;
        else
            write.pBufferInfo = &entry.buffer;
        writes.push_back(write);
    }
    vkUpdateDescriptorSets(device, static_cast<std::uint32_t>(writes.size()), writes.data(), 0,
                           nullptr);
}

}  // namespace signstim::render::vk
