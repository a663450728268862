#include "renderer/vk_device.hpp"

#include "common/error.hpp"
#include "renderer/vk_check.hpp"

#include <algorithm>
#include <cctype>

namespace signstim::render::vk {

namespace {

std::string typeName(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
    default: return "other";
    }
}

int typePreference(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 1;
    default: return 0;
    }
}

std::string versionString(std::uint32_t version) {
    return std::to_string(VK_API_VERSION_MAJOR(version)) + "." +
           std::to_string(VK_API_VERSION_MINOR(version)) + "." +
           std::to_string(VK_API_VERSION_PATCH(version));
}

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

std::string describeList(const std::vector<PhysicalDevice>& devices) {
    std::string text;
    for (const auto& device : devices) {
        if (!text.empty()) text += ", ";
        text += std::to_string(device.info.index) + " '" + device.info.name + "'";
        if (!device.info.usable) text += " (unusable)";
    }
    return text.empty() ? "none" : text;
}

}  // namespace

std::vector<PhysicalDevice> enumeratePhysicalDevices(VkInstance instance) {
    std::uint32_t count = 0;
    check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> handles(count);
    check(vkEnumeratePhysicalDevices(instance, &count, handles.data()),
          "vkEnumeratePhysicalDevices");

    std::vector<PhysicalDevice> devices;
    for (std::uint32_t i = 0; i < count; ++i) {
        PhysicalDevice device;
        device.handle = handles[i];
        auto driver = make<VkPhysicalDeviceDriverProperties>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES);
        auto properties = make<VkPhysicalDeviceProperties2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver);
        vkGetPhysicalDeviceProperties2(handles[i], &properties);
        const auto& p = properties.properties;
        device.info.index = i;
        device.info.name = p.deviceName;
        device.info.type = typeName(p.deviceType);
        device.info.driver = std::string(driver.driverName) +
                             (driver.driverInfo[0] != '\0' ? std::string(" ") + driver.driverInfo
                                                           : std::string());
        device.info.apiVersion = versionString(p.apiVersion);
        device.preference = typePreference(p.deviceType);
        device.sampleCounts = p.limits.framebufferColorSampleCounts &
                              p.limits.framebufferDepthSampleCounts;
        for (std::uint32_t samples = 1; samples <= 64; samples *= 2)
            if (device.sampleCounts & samples) device.info.sampleCounts.push_back(samples);

        bool hasGraphicsQueue = false;
        std::uint32_t familyCount = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(handles[i], &familyCount, nullptr);
        std::vector<VkQueueFamilyProperties> families(familyCount);
        vkGetPhysicalDeviceQueueFamilyProperties(handles[i], &familyCount, families.data());
        for (std::uint32_t f = 0; f < familyCount; ++f) {
            if (families[f].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
                device.graphicsQueueFamily = f;
                hasGraphicsQueue = true;
                break;
            }
        }
        bool hasFeatures = false;
        if (p.apiVersion >= VK_API_VERSION_1_3) {
            auto features13 = make<VkPhysicalDeviceVulkan13Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
            auto features = make<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &features13);
            vkGetPhysicalDeviceFeatures2(handles[i], &features);
            hasFeatures = features13.dynamicRendering && features13.synchronization2;
        }
        device.info.usable = hasGraphicsQueue && hasFeatures;
        devices.push_back(std::move(device));
    }
    return devices;
}

int automaticChoice(const std::vector<PhysicalDevice>& devices) {
    int best = -1;
    for (std::size_t i = 0; i < devices.size(); ++i) {
        if (!devices[i].info.usable) continue;
        if (best < 0 || devices[i].preference > devices[static_cast<std::size_t>(best)].preference)
            best = static_cast<int>(i);
    }
    return best;
}

const PhysicalDevice& selectPhysicalDevice(const std::vector<PhysicalDevice>& devices,
                                           const std::string& request) {
    if (request.empty()) {
        int choice = automaticChoice(devices);
        if (choice < 0)
            throw EnvironmentError(
                "no usable Vulkan 1.3 device (found: " + describeList(devices) +
                "); install a driver, e.g. `apt install mesa-vulkan-drivers` for lavapipe");
        return devices[static_cast<std::size_t>(choice)];
    }
    const PhysicalDevice* chosen = nullptr;
    bool numeric = std::all_of(request.begin(), request.end(),
                               [](unsigned char c) { return std::isdigit(c) != 0; });
    if (numeric) {
        unsigned long index = std::stoul(request);
        if (index < devices.size()) chosen = &devices[index];
    } else {
        for (const auto& device : devices) {
            if (lower(device.info.name).find(lower(request)) != std::string::npos) {
                chosen = &device;
                break;
            }
        }
    }
    if (chosen == nullptr)
        throw InputError("<command line>", 0, "--device",
                         "no Vulkan device '" + request + "'; devices: " + describeList(devices));
    if (!chosen->info.usable)
        throw InputError("<command line>", 0, "--device",
                         "device '" + chosen->info.name +
                             "' lacks Vulkan 1.3 dynamic rendering/synchronization2");
    return *chosen;
}

Device::Device(const PhysicalDevice& physical)
    : physical_(physical.handle), queueFamily_(physical.graphicsQueueFamily) {
    vkGetPhysicalDeviceProperties(physical_, &properties_);
    vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);

    float priority = 1.0f;
    auto queueInfo = make<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
    queueInfo.queueFamilyIndex = queueFamily_;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;

    auto features13 = make<VkPhysicalDeviceVulkan13Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
    features13.dynamicRendering = VK_TRUE;
    features13.synchronization2 = VK_TRUE;
    auto features = make<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &features13);

    auto info = make<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &features);
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    check(vkCreateDevice(physical_, &info, nullptr, &device_), "vkCreateDevice");
    vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
}

Device::~Device() {
    if (device_ != VK_NULL_HANDLE) {
        vkDeviceWaitIdle(device_);
        vkDestroyDevice(device_, nullptr);
    }
}

VkFormatProperties Device::formatProperties(VkFormat format) const {
    VkFormatProperties properties{};
    vkGetPhysicalDeviceFormatProperties(physical_, format, &properties);
    return properties;
}

}  // namespace signstim::render::vk
