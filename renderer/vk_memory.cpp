#include "renderer/vk_memory.hpp"

#include "common/error.hpp"
#include "renderer/vk_check.hpp"

namespace signstim::render::vk {

std::uint32_t findMemoryType(const Device& device, std::uint32_t typeBits,
                             VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) {
    const auto& memory = device.memory();
    for (int pass = 0; pass < 2; ++pass) {
        VkMemoryPropertyFlags wanted = pass == 0 ? required | preferred : required;
        for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
            if ((typeBits & (1u << i)) &&
                (memory.memoryTypes[i].propertyFlags & wanted) == wanted)
                return i;
        }
    }
    throw EnvironmentError("Vulkan: no suitable memory type on this device");
}

void Buffer::invalidate() const {
    if (coherent || mapped == nullptr) return;
    auto range = make<VkMappedMemoryRange>(VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE);
    range.memory = memory.get();
    range.offset = 0;
    range.size = VK_WHOLE_SIZE;
    check(vkInvalidateMappedMemoryRanges(device, 1, &range), "vkInvalidateMappedMemoryRanges");
}

Buffer createBuffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
                    MemoryUse use) {
    Buffer result;
    result.device = device.get();
    result.size = size;
    auto info = make<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkBuffer buffer = VK_NULL_HANDLE;
    check(vkCreateBuffer(device.get(), &info, nullptr, &buffer), "vkCreateBuffer");
    result.buffer = UniqueBuffer(device.get(), buffer);

    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device.get(), buffer, &requirements);
    VkMemoryPropertyFlags required = 0, preferred = 0;
    switch (use) {
    case MemoryUse::DeviceLocal: required = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT; break;
    case MemoryUse::Upload:
        required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        break;
    case MemoryUse::Readback:
        required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT;
        preferred = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
        break;
    }
    std::uint32_t type = findMemoryType(device, requirements.memoryTypeBits, required, preferred);
    auto allocate = make<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
    allocate.allocationSize = requirements.size;
    allocate.memoryTypeIndex = type;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    check(vkAllocateMemory(device.get(), &allocate, nullptr, &memory), "vkAllocateMemory");
    result.memory = UniqueMemory(device.get(), memory);
    check(vkBindBufferMemory(device.get(), buffer, memory, 0), "vkBindBufferMemory");
    if (use != MemoryUse::DeviceLocal) {
        check(vkMapMemory(device.get(), memory, 0, VK_WHOLE_SIZE, 0, &result.mapped),
              "vkMapMemory");
        result.coherent = (device.memory().memoryTypes[type].propertyFlags &
                           VK_MEMORY_PROPERTY_HOST_COHERENT_BIT) != 0;
    }
    return result;
}

GpuImage createImage(const Device& device, const ImageDesc& desc) {
    GpuImage result;
    result.desc = desc;
    auto info = make<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = desc.format;
    info.extent = {desc.extent.width, desc.extent.height, 1};
    info.mipLevels = desc.mipLevels;
    info.arrayLayers = 1;
    info.samples = desc.samples;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = desc.usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImage image = VK_NULL_HANDLE;
    check(vkCreateImage(device.get(), &info, nullptr, &image), "vkCreateImage");
    result.image = UniqueImage(device.get(), image);

    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(device.get(), image, &requirements);
    auto allocate = make<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
    allocate.allocationSize = requirements.size;
    allocate.memoryTypeIndex = findMemoryType(device, requirements.memoryTypeBits,
                                              VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VkDeviceMemory memory = VK_NULL_HANDLE;
    check(vkAllocateMemory(device.get(), &allocate, nullptr, &memory), "vkAllocateMemory");
    result.memory = UniqueMemory(device.get(), memory);
    check(vkBindImageMemory(device.get(), image, memory, 0), "vkBindImageMemory");

    auto viewInfo = make<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
    viewInfo.image = image;
    viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
    viewInfo.format = desc.format;
    viewInfo.subresourceRange = {desc.aspect, 0, desc.mipLevels, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    check(vkCreateImageView(device.get(), &viewInfo, nullptr, &view), "vkCreateImageView");
    result.view = UniqueImageView(device.get(), view);
    return result;
}

}  // namespace signstim::render::vk
