#pragma once
// One RAII owner per Vulkan object (Magnum Vk style): a move-only wrapper that destroys its
// handle with the matching vkDestroy* call. Members declared in creation order are then
// destroyed in the right order without any hand-written teardown.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <utility>

namespace signstim::render::vk {

template <typename T, void (*Destroy)(VkDevice, T, const VkAllocationCallbacks*)>
class DeviceOwned {
public:
    DeviceOwned() = default;
    DeviceOwned(VkDevice device, T handle) : device_(device), handle_(handle) {}
    ~DeviceOwned() { reset(); }
    DeviceOwned(const DeviceOwned&) = delete;
    DeviceOwned& operator=(const DeviceOwned&) = delete;
    DeviceOwned(DeviceOwned&& other) noexcept
        : device_(other.device_), handle_(std::exchange(other.handle_, VK_NULL_HANDLE)) {}
    DeviceOwned& operator=(DeviceOwned&& other) noexcept {
        if (this != &other) {
            reset();
            device_ = other.device_;
            handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
        }
        return *this;
    }

    void reset() {
        if (handle_ != VK_NULL_HANDLE) Destroy(device_, handle_, nullptr);
        handle_ = VK_NULL_HANDLE;
    }
    T get() const { return handle_; }
    explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }

private:
    VkDevice device_ = VK_NULL_HANDLE;
    T handle_ = VK_NULL_HANDLE;
};

using UniqueBuffer = DeviceOwned<VkBuffer, &vkDestroyBuffer>;
using UniqueMemory = DeviceOwned<VkDeviceMemory, &vkFreeMemory>;
using UniqueImage = DeviceOwned<VkImage, &vkDestroyImage>;
using UniqueImageView = DeviceOwned<VkImageView, &vkDestroyImageView>;
using UniqueSampler = DeviceOwned<VkSampler, &vkDestroySampler>;
using UniqueFence = DeviceOwned<VkFence, &vkDestroyFence>;
using UniqueCommandPool = DeviceOwned<VkCommandPool, &vkDestroyCommandPool>;
using UniqueDescriptorSetLayout = DeviceOwned<VkDescriptorSetLayout, &vkDestroyDescriptorSetLayout>;
using UniqueDescriptorPool = DeviceOwned<VkDescriptorPool, &vkDestroyDescriptorPool>;
using UniquePipelineLayout = DeviceOwned<VkPipelineLayout, &vkDestroyPipelineLayout>;
using UniquePipeline = DeviceOwned<VkPipeline, &vkDestroyPipeline>;
using UniqueShaderModule = DeviceOwned<VkShaderModule, &vkDestroyShaderModule>;

}  // namespace signstim::render::vk
