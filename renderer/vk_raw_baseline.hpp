#pragma once
// The raw baseline of `signstim bench render`: a minimal draw-and-readback loop written
// directly against Vulkan (own instance, device, pipeline, target; SwiftShader's
// VulkanBenchmarks in spirit), drawing the same mesh on the same device as the Renderer so
// the renderer's overhead is a ratio measured in one run. Not used for stimuli.
//
// Two shadings: OneLine (shaders/bench_raw.*: one dot product, the floor of any lit draw)
// and Lit (the Renderer's own SPIR-V, shaders/mesh.vert + mesh.frag, with the same
// specialisation constants, descriptor data and push constants the Renderer uses for the
// mesh's materials and lighting, so it draws the Renderer's image). Renderer / Lit is the
// renderer's overhead; Renderer / OneLine is the cost of lighting plus overhead.
#include "renderer/renderer.hpp"
#include "renderer/scene.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace signstim::render {

enum class RawShading { OneLine, Lit };

struct RawBaselineSettings {
    std::string device;  // as RendererOptions::device
    std::uint32_t width = 640, height = 480;
    std::uint32_t msaa = 1;
    RawShading shading = RawShading::OneLine;
    Lighting lighting;        // Lit only: as RendererOptions::lighting
    bool validation = false;  // as RendererOptions::validation
};

// Draws every primitive of the first mesh in `mesh` (rigid; OneLine at the origin, Lit with
// the rest-pose world matrix of the first node holding it) from a fixed camera (eye
// (0, 0, 2.2) looking at the origin, 30 degree vertical field of view, near 0.1, far 10) and
// reads each frame back into host memory, one frame at a time.
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
    // The last frame read back: width x height RGBA8 (sRGB), rows top to bottom, as
    // render::Image::bytes for PixelFormat::Rgba8.
    const std::vector<std::uint8_t>& pixels() const;
    bool validationEnabled() const;
    std::vector<std::string> validationMessages() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace signstim::render
