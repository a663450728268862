#pragma once
// Staging buffer -> render::Image. Rgba8 frames are rendered into an sRGB target and copied
// as they are; Rgba16 frames are rendered into a linear half-float target (no 16-bit sRGB
// format exists) and encoded to 16-bit sRGB here through a table over all half values.
#include "renderer/image.hpp"
#include "renderer/vk_memory.hpp"

namespace signstim::render::vk {

VkFormat colorFormatFor(PixelFormat format);

void convertReadback(const Buffer& staging, VkExtent2D extent, PixelFormat format, render::Image& out);

// Exposed for tests: IEEE half -> float.
float halfToFloat(std::uint16_t half);

}  // namespace signstim::render::vk
