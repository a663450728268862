#pragma once
// Command pools, one-shot submissions (uploads at start-up) and synchronization2 barriers.
#include "renderer/vk_device.hpp"
#include "renderer/vk_handle.hpp"

#include <functional>

namespace signstim::render::vk {

class CommandPool {
public:
    explicit CommandPool(const Device& device);
    VkCommandPool get() const { return pool_.get(); }
    VkCommandBuffer allocate() const;

    // Records with `record`, submits, and waits for completion.
    void submitAndWait(const std::function<void(VkCommandBuffer)>& record) const;

private:
    const Device* device_;
    UniqueCommandPool pool_;
};

UniqueFence createFence(const Device& device, bool signaled);

struct ImageTransition {
    VkImage image = VK_NULL_HANDLE;
    VkImageLayout from = VK_IMAGE_LAYOUT_UNDEFINED, to = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags2 srcStage = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 srcAccess = VK_ACCESS_2_NONE;
    VkPipelineStageFlags2 dstStage = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 dstAccess = VK_ACCESS_2_NONE;
    VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
    std::uint32_t baseMip = 0, mipCount = VK_REMAINING_MIP_LEVELS;
};

VkImageMemoryBarrier2 imageBarrier(const ImageTransition& transition);
void transitionImages(VkCommandBuffer cmd, std::initializer_list<ImageTransition> transitions);

}  // namespace signstim::render::vk
