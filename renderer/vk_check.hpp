#pragma once
// Turns a failed Vulkan call into an EnvironmentError naming the call and the result code.
// Vulkan failures after start-up (out of memory, device lost) are not the user's input.
#include <vulkan/vulkan.h>

namespace signstim::render::vk {

const char* resultName(VkResult result);

// Throws signstim::EnvironmentError("Vulkan: <what> failed: VK_ERROR_...") unless VK_SUCCESS.
void check(VkResult result, const char* what);

// A zero-initialised Vulkan structure with its sType (and optional pNext chain) set.
template <typename T>
T make(VkStructureType type, const void* next = nullptr) {
    T value{};
    value.sType = type;
    value.pNext = const_cast<void*>(next);
    return value;
}

}  // namespace signstim::render::vk
