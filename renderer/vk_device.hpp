#pragma once
// Physical-device listing and selection (discrete > integrated > virtual > cpu), and the
// logical device with one graphics queue and the Vulkan 1.3 features we rely on
// (dynamic rendering, synchronization2).
#include "renderer/device_info.hpp"

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

namespace signstim::render::vk {

struct PhysicalDevice {
    VkPhysicalDevice handle = VK_NULL_HANDLE;
    DeviceInfo info;
    std::uint32_t graphicsQueueFamily = 0;
    VkSampleCountFlags sampleCounts = 0;
    int preference = 0;  // higher is better
};

std::vector<PhysicalDevice> enumeratePhysicalDevices(VkInstance instance);

// Index into `devices` of the best usable device, or -1 when none is usable.
int automaticChoice(const std::vector<PhysicalDevice>& devices);

// `request`: "" (automatic), an index, or a case-insensitive name substring. Throws
// EnvironmentError when nothing is usable, InputError for an unknown or unusable choice.
const PhysicalDevice& selectPhysicalDevice(const std::vector<PhysicalDevice>& devices,
                                           const std::string& request);

class Device {
public:
    explicit Device(const PhysicalDevice& physical);
    ~Device();
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;

    VkDevice get() const { return device_; }
    VkPhysicalDevice physical() const { return physical_; }
    VkQueue queue() const { return queue_; }
    std::uint32_t queueFamily() const { return queueFamily_; }
    const VkPhysicalDeviceProperties& properties() const { return properties_; }
    const VkPhysicalDeviceMemoryProperties& memory() const { return memory_; }
    VkFormatProperties formatProperties(VkFormat format) const;

private:
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    std::uint32_t queueFamily_ = 0;
    VkPhysicalDeviceProperties properties_{};
    VkPhysicalDeviceMemoryProperties memory_{};
};

}  // namespace signstim::render::vk
