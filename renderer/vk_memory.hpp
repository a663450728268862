#pragma once
// Buffers and images with their own memory (one allocation per resource: simple and correct;
// the renderer makes few, long-lived resources). Host-visible buffers stay mapped.
#include "renderer/vk_device.hpp"
#include "renderer/vk_handle.hpp"

#include <cstddef>

namespace signstim::render::vk {

enum class MemoryUse {
    DeviceLocal,  // GPU only
    Upload,       // host writes, GPU reads (host-visible, coherent)
    Readback,     // GPU writes, host reads (host-visible, cached when the device offers it)
};

struct Buffer {
    VkDevice device = VK_NULL_HANDLE;
    UniqueBuffer buffer;
    UniqueMemory memory;
    VkDeviceSize size = 0;
    void* mapped = nullptr;  // non-null for Upload/Readback
    bool coherent = true;

    // Makes GPU writes visible to the host (no-op on coherent memory).
    void invalidate() const;
};

Buffer createBuffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
                    MemoryUse use);

struct ImageDesc {
    VkExtent2D extent{1, 1};
    VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
    VkImageUsageFlags usage = 0;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    std::uint32_t mipLevels = 1;
    VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
};

struct GpuImage {
    UniqueImage image;
    UniqueMemory memory;
    UniqueImageView view;
    ImageDesc desc;
};

GpuImage createImage(const Device& device, const ImageDesc& desc);

// Index of a memory type allowed by `typeBits` having `required` (and `preferred` if any).
std::uint32_t findMemoryType(const Device& device, std::uint32_t typeBits,
                             VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred = 0);

}  // namespace signstim::render::vk
