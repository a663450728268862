#pragma once
// The Vulkan instance: API 1.3, optionally with VK_LAYER_KHRONOS_validation and a debug
// messenger that collects every warning and error (tests fail on any message).
#include <vulkan/vulkan.h>

#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace signstim::render::vk {

// True when `requested` or the environment variable SIGNSTIM_VALIDATION=1 asks for it.
bool validationWanted(bool requested);

class Instance {
public:
    // Throws EnvironmentError when no Vulkan 1.3 loader/driver is installed, or when
    // validation is asked for but the Khronos validation layer is missing.
    explicit Instance(bool validation);
    ~Instance();
    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;

    VkInstance get() const { return instance_; }
    bool validation() const { return messenger_ != VK_NULL_HANDLE; }
    std::vector<std::string> messages() const;

private:
    struct MessageLog {
        mutable std::mutex mutex;
        std::vector<std::string> messages;
    };
    static VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(
        VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT types,
        const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);

    std::unique_ptr<MessageLog> log_ = std::make_unique<MessageLog>();
    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
};

}  // namespace signstim::render::vk
