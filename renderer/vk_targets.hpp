#pragma once
// Offscreen render target of one frame slot: colour (multisampled when MSAA > 1) resolved
// into a single-sample image, depth, and a host-visible staging buffer the resolved image is
// copied into at the end of the frame (Filament's VulkanReadPixels, without the swapchain).
#include "renderer/vk_memory.hpp"

namespace signstim::render::vk {

struct TargetFormats {
    VkFormat color = VK_FORMAT_R8G8B8A8_SRGB;
    VkFormat depth = VK_FORMAT_D32_SFLOAT;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
};

std::uint32_t bytesPerPixel(VkFormat colorFormat);

// First of D32, D32S8, D24S8, D16 usable as a depth attachment on `device`.
VkFormat chooseDepthFormat(const Device& device);

class OffscreenTarget {
public:
    OffscreenTarget(const Device& device, VkExtent2D extent, const TargetFormats& formats);

    // Transitions the attachments and begins dynamic rendering, clearing to `clear`.
    void beginRendering(VkCommandBuffer cmd, const VkClearColorValue& clear) const;
    // Ends rendering (resolving MSAA) and copies the result into readback().
    void endRenderingAndCopy(VkCommandBuffer cmd) const;

    const Buffer& readback() const { return readback_; }
    VkExtent2D extent() const { return extent_; }
    const TargetFormats& formats() const { return formats_; }

private:
    VkExtent2D extent_;
    TargetFormats formats_;
    GpuImage color_;
    GpuImage resolve_;  // only when multisampled
    GpuImage depth_;
    Buffer readback_;
};

}  // namespace signstim::render::vk
