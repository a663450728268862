#pragma once
// A frame read back from the GPU: tightly packed RGBA rows, top row first.
#include <cstdint>
#include <vector>

namespace signstim::render {

enum class PixelFormat {
    Rgba8,   // 8 bits per channel, sRGB-encoded colour, linear alpha
    Rgba16,  // 16 bits per channel (native endian), sRGB-encoded colour, linear alpha
};

struct Image {
    std::uint32_t width = 0, height = 0;
    PixelFormat format = PixelFormat::Rgba8;
    std::vector<std::uint8_t> bytes;  // width * height * 4 * (1 or 2)

    std::size_t bytesPerPixel() const { return format == PixelFormat::Rgba8 ? 4 : 8; }
};

}  // namespace signstim::render
