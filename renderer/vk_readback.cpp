#include "renderer/vk_readback.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

namespace signstim::render::vk {

namespace {

float linearToSrgb(float linear) {
    linear = std::clamp(linear, 0.0f, 1.0f);
    return linear <= 0.0031308f ? linear * 12.92f
                                : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

std::uint16_t toUnorm16(float value) {
    if (!(value > 0.0f)) return 0;  // also NaN
    return static_cast<std::uint16_t>(std::lround(std::min(value, 1.0f) * 65535.0f));
}

struct HalfTables {
    std::vector<std::uint16_t> srgb, linear;
    HalfTables() : srgb(65536), linear(65536) {
        for (std::uint32_t h = 0; h < 65536; ++h) {
            float value = halfToFloat(static_cast<std::uint16_t>(h));
            srgb[h] = toUnorm16(std::isnan(value) ? 0.0f : linearToSrgb(value));
            linear[h] = toUnorm16(value);
        }
    }
};

}  // namespace

float halfToFloat(std::uint16_t half) {
    std::uint32_t sign = (half >> 15) & 1u, exponent = (half >> 10) & 0x1fu, mantissa = half & 0x3ffu;
    float value;
    if (exponent == 0)
        value = std::ldexp(static_cast<float>(mantissa), -24);
    else if (exponent == 31)
        value = mantissa ? NAN : INFINITY;
    else
        value = std::ldexp(static_cast<float>(mantissa | 0x400u), static_cast<int>(exponent) - 25);
    return sign ? -value : value;
}

VkFormat colorFormatFor(PixelFormat format) {
    return format == PixelFormat::Rgba8 ? VK_FORMAT_R8G8B8A8_SRGB
                                        : VK_FORMAT_R16G16B16A16_SFLOAT;
}

void convertReadback(const Buffer& staging, VkExtent2D extent, PixelFormat format, render::Image& out) {
    staging.invalidate();
    out.width = extent.width;
    out.height = extent.height;
    out.format = format;
    const std::size_t pixels = std::size_t(extent.width) * extent.height;
    out.bytes.resize(pixels * out.bytesPerPixel());
    if (format == PixelFormat::Rgba8) {
        std::memcpy(out.bytes.data(), staging.mapped, out.bytes.size());
        return;
    }
    static const HalfTables tables;
    const auto* source = static_cast<const std::uint16_t*>(staging.mapped);
    auto* target = reinterpret_cast<std::uint16_t*>(out.bytes.data());
    for (std::size_t i = 0; i < pixels * 4; i += 4) {
        target[i + 0] = tables.srgb[source[i + 0]];
        target[i + 1] = tables.srgb[source[i + 1]];
        target[i + 2] = tables.srgb[source[i + 2]];
        target[i + 3] = tables.linear[source[i + 3]];
    }
}

}  // namespace signstim::render::vk
