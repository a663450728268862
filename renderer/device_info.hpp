#pragma once
// What the renderer knows of a Vulkan device (`signstim devices`, Renderer::device): plain
// values, so the device code (renderer/vk_device.hpp) needs no more of the renderer than this.
#include <cstdint>
#include <string>
#include <vector>

namespace signstim::render {

struct DeviceInfo {
    std::uint32_t index = 0;
    std::string name;
    std::string type;        // "discrete", "integrated", "virtual", "cpu", "other"
    std::string driver;      // driver name and info
    std::string apiVersion;  // "1.3.230"
    std::vector<std::uint32_t> sampleCounts;  // supported colour+depth MSAA counts
    bool usable = false;     // Vulkan 1.3 with dynamic rendering and synchronization2
    bool automatic = false;  // the device chosen when RendererOptions::device is empty
};

}  // namespace signstim::render
