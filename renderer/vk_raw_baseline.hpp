#pragma once
// The raw baseline of `signstim bench render`: a minimal draw-and-readback loop written
// directly against Vulkan (own instance, device, pipeline, target; SwiftShader's
// VulkanBenchmarks in spirit), drawing the same mesh on the same device as the Renderer so
// the renderer's overhead is a ratio measured in one run. Not used for stimuli.
#include "renderer/scene.hpp"

#include <cstdint>
#include <memory>
#include <string>

namespace signstim::render {

struct RawBaselineSettings {
    std::string device;  // as RendererOptions::device
    std::uint32_t width = 640, height = 480;
    std::uint32_t msaa = 1;
};

// Draws every primitive of the first mesh in `mesh` (rigid, at the origin) from a fixed
// camera and reads each frame back into host memory, one frame at a time.
class RawBaseline {
public:
    RawBaseline(const Scene& mesh, const RawBaselineSettings& settings);
    ~RawBaseline();
    RawBaseline(const RawBaseline&) = delete;
    RawBaseline& operator=(const RawBaseline&) = delete;

    // Draws and reads back `frames` frames, one at a time (for callers that time it).
    void run(std::uint32_t frames);
    // Frames per second over `frames` frames (after one warm-up frame).
    double measure(std::uint32_t frames);
    // Sum of the bytes of the last frame read back (keeps the copy observable).
    std::uint64_t checksum() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace signstim::render
