#include "renderer/vk_commands.hpp"

#include "renderer/vk_check.hpp"

#include <vector>

namespace signstim::render::vk {

CommandPool::CommandPool(const Device& device) : device_(&device) {
    auto info = make<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
    info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    info.queueFamilyIndex = device.queueFamily();
    VkCommandPool pool = VK_NULL_HANDLE;
    check(vkCreateCommandPool(device.get(), &info, nullptr, &pool), "vkCreateCommandPool");
    pool_ = UniqueCommandPool(device.get(), pool);
}

VkCommandBuffer CommandPool::allocate() const {
    auto info = make<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
    info.commandPool = pool_.get();
    info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    info.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    check(vkAllocateCommandBuffers(device_->get(), &info, &cmd), "vkAllocateCommandBuffers");
    return cmd;
}

void CommandPool::submitAndWait(const std::function<void(VkCommandBuffer)>& record) const {
    VkCommandBuffer cmd = allocate();
    struct Free {
        VkDevice device;
        VkCommandPool pool;
        VkCommandBuffer cmd;
        ~Free() { vkFreeCommandBuffers(device, pool, 1, &cmd); }
    } freeLater{device_->get(), pool_.get(), cmd};

    auto begin = make<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
    record(cmd);
    check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");

    UniqueFence fence = createFence(*device_, false);
    auto cmdInfo = make<VkCommandBufferSubmitInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO);
    cmdInfo.commandBuffer = cmd;
    auto submit = make<VkSubmitInfo2>(VK_STRUCTURE_TYPE_SUBMIT_INFO_2);
    submit.commandBufferInfoCount = 1;
    submit.pCommandBufferInfos = &cmdInfo;
    VkFence handle = fence.get();
    check(vkQueueSubmit2(device_->queue(), 1, &submit, handle), "vkQueueSubmit2");
    check(vkWaitForFences(device_->get(), 1, &handle, VK_TRUE, UINT64_MAX), "vkWaitForFences");
}

UniqueFence createFence(const Device& device, bool signaled) {
    auto info = make<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
    if (signaled) info.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    VkFence fence = VK_NULL_HANDLE;
    check(vkCreateFence(device.get(), &info, nullptr, &fence), "vkCreateFence");
    return UniqueFence(device.get(), fence);
}

VkImageMemoryBarrier2 imageBarrier(const ImageTransition& t) {
    auto barrier = make<VkImageMemoryBarrier2>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2);
    barrier.srcStageMask = t.srcStage;
    barrier.srcAccessMask = t.srcAccess;
    barrier.dstStageMask = t.dstStage;
    barrier.dstAccessMask = t.dstAccess;
    barrier.oldLayout = t.from;
    barrier.newLayout = t.to;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = t.image;
    barrier.subresourceRange = {t.aspect, t.baseMip, t.mipCount, 0, 1};
    return barrier;
}

void transitionImages(VkCommandBuffer cmd, std::initializer_list<ImageTransition> transitions) {
    std::vector<VkImageMemoryBarrier2> barriers;
    for (const auto& t : transitions) barriers.push_back(imageBarrier(t));
    auto dependency = make<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
    dependency.imageMemoryBarrierCount = static_cast<std::uint32_t>(barriers.size());
    dependency.pImageMemoryBarriers = barriers.data();
    vkCmdPipelineBarrier2(cmd, &dependency);
}

}  // namespace signstim::render::vk
