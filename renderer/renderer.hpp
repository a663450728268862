#pragma once
// Headless Vulkan 1.3 renderer: offscreen colour + depth, MSAA 1x/4x with resolve, readback
// to host memory. Prefers a discrete, then integrated GPU, else Mesa lavapipe (CPU).
// Owned by the Vulkan side (renderer/vk_*.cpp, renderer/renderer.cpp).
#include "renderer/device_info.hpp"
#include "renderer/frame.hpp"
#include "renderer/image.hpp"
#include "renderer/scene.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace signstim::render {

struct Lighting {
    // Defaults suit sign-language video: key from front-above, fill, rim; hands and face
    // evenly lit, no harsh shadows.
    glm::vec3 keyDirection{-0.3f, -0.5f, -1.0f};  // direction light travels (world)
    float keyIntensity = 2.2f;
    float fillIntensity = 0.9f;   // from the other side, lower
    float rimIntensity = 0.8f;    // from behind-above: separates the signer from the background
    float ambient = 0.35f;
};

struct RendererOptions {
    std::string device;  // "" = automatic; a name substring or an index from listDevices()
    std::uint32_t width = 640, height = 480;
    std::uint32_t msaa = 1;  // 1 or 4 (checked against the device's limits)
    PixelFormat format = PixelFormat::Rgba8;
    glm::vec4 background{0.16f, 0.17f, 0.19f, 1.0f};  // linear RGBA; alpha 0 = transparent
    Lighting lighting;
    bool validation = false;  // enable VK_LAYER_KHRONOS_validation and collect messages
};

class Renderer {
public:
    // Enumerates physical devices (creates a short-lived instance).
    static std::vector<DeviceInfo> listDevices();

    // Throws EnvironmentError when no usable device exists, InputError for unsupported
    // settings (e.g. MSAA 8 on lavapipe), naming the setting and what the device supports.
    explicit Renderer(const RendererOptions& options);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    const DeviceInfo& device() const;
    const RendererOptions& options() const;

    // Uploads a scene (meshes, textures, materials) once; returns its handle for View::scene.
    int addScene(const Scene& scene);

    // Draws `frame` and reads it back into `out` (synchronous; no frame may be in flight).
    // Invalid frames (unknown scene handle, pose of the wrong size, more views than cells,
    // eye == target) throw InputError.
    void render(const Frame& frame, Image& out);

    // Pipelined use: submit() starts drawing and returns at once; retrieve() waits for the
    // oldest submitted frame. At most framesInFlight() frames may be outstanding (more is a
    // programming error: std::logic_error). Frames come back in submission order.
    void submit(const Frame& frame);
    void retrieve(Image& out);
    std::uint32_t framesInFlight() const;
    std::uint32_t framesPending() const;

    // Validation-layer messages collected so far (empty unless validation is on).
    std::vector<std::string> validationMessages() const;
    // True when VK_LAYER_KHRONOS_validation is active (options.validation or the environment
    // variable SIGNSTIM_VALIDATION=1).
    bool validationEnabled() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace signstim::render
