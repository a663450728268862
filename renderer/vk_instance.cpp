#include "renderer/vk_instance.hpp"

#include "common/error.hpp"
#include "renderer/vk_check.hpp"

#include <cstdlib>
#include <cstring>

namespace signstim::render::vk {

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
constexpr const char* kNoVulkanAdvice =
    "install a Vulkan 1.3 driver (Debian/Ubuntu: `apt install mesa-vulkan-drivers "
    "libvulkan1` gives the lavapipe CPU device)";

bool hasLayer(const char* name) {
    std::uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    for (const auto& layer : layers)
        if (std::strcmp(layer.layerName, name) == 0) return true;
    return false;
}

bool hasExtension(const char* name) {
    std::uint32_t count = 0;
    vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateInstanceExtensionProperties(nullptr, &count, extensions.data());
    for (const auto& extension : extensions)
        if (std::strcmp(extension.extensionName, name) == 0) return true;
    return false;
}

}  // namespace

bool validationWanted(bool requested) {
    if (requested) return true;
    const char* env = std::getenv("SIGNSTIM_VALIDATION");
    return env != nullptr && std::strcmp(env, "1") == 0;
}

VKAPI_ATTR VkBool32 VKAPI_CALL Instance::onMessage(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    auto* log = static_cast<MessageLog*>(user);
    std::string text = severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error: "
                                                                                 : "warning: ";
    if (data->pMessageIdName != nullptr) text += std::string("[") + data->pMessageIdName + "] ";
    text += data->pMessage != nullptr ? data->pMessage : "(no message)";
    std::lock_guard lock(log->mutex);
    log->messages.push_back(std::move(text));
    return VK_FALSE;
}

Instance::Instance(bool validation) {
    std::uint32_t loaderVersion = VK_API_VERSION_1_0;
    if (vkEnumerateInstanceVersion(&loaderVersion) != VK_SUCCESS ||
        loaderVersion < VK_API_VERSION_1_3)
        throw EnvironmentError(std::string("the Vulkan loader is older than 1.3; ") +
                               kNoVulkanAdvice);
    if (validation && !hasLayer(kValidationLayer))
        throw EnvironmentError(
            "Vulkan validation was requested but VK_LAYER_KHRONOS_validation is not installed "
            "(Debian/Ubuntu: `apt install vulkan-validationlayers`)");

    auto app = make<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
    app.pApplicationName = "signstim";
    app.pEngineName = "signstim";
    app.apiVersion = VK_API_VERSION_1_3;

    std::vector<const char*> extensions;
    std::vector<const char*> layers;
    auto info = make<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
    // Portability drivers (MoltenVK) are only listed when asked for.
    if (hasExtension(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME)) {
        extensions.push_back(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME);
        info.flags |= VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR;
    }
    auto messengerInfo = make<VkDebugUtilsMessengerCreateInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
    messengerInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                    VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messengerInfo.pfnUserCallback = &Instance::onMessage;
    messengerInfo.pUserData = log_.get();
    if (validation) {
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        info.pNext = &messengerInfo;  // also catches messages from vkCreate/DestroyInstance
    }
    info.pApplicationInfo = &app;
    info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();

    VkResult result = vkCreateInstance(&info, nullptr, &instance_);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw EnvironmentError(std::string("no Vulkan driver found; ") + kNoVulkanAdvice);
    check(result, "vkCreateInstance");

    if (validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
        if (create == nullptr) {
            vkDestroyInstance(instance_, nullptr);
            throw EnvironmentError("Vulkan: VK_EXT_debug_utils is not available");
        }
        result = create(instance_, &messengerInfo, nullptr, &messenger_);
        if (result != VK_SUCCESS) {
            vkDestroyInstance(instance_, nullptr);
            check(result, "vkCreateDebugUtilsMessengerEXT");
        }
    }
}

Instance::~Instance() {
    if (messenger_ != VK_NULL_HANDLE) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy != nullptr) destroy(instance_, messenger_, nullptr);
    }
    vkDestroyInstance(instance_, nullptr);
}

std::vector<std::string> Instance::messages() const {
    std::lock_guard lock(log_->mutex);
    return log_->messages;
}

}  // namespace signstim::render::vk
