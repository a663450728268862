#pragma once
// The seam between whoever decides what to show (app/stimuli) and the renderer: a frame is
// a grid of views; each view has a camera, a posed scene and a caption label. All views of
// one frame are drawn into the same image, so they stay in sync (SPEC §4.3 side-by-side).
#include "renderer/scene.hpp"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace signstim::render {

struct Camera {
    glm::vec3 eye{0.0f, 1.4f, 2.0f};
    glm::vec3 target{0.0f, 1.2f, 0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float verticalFovDegrees = 30.0f;
    float nearPlane = 0.05f;
    float farPlane = 100.0f;
    bool orthographic = false;
    float orthographicHeight = 1.0f;  // world units visible vertically when orthographic
};

// Places a camera looking along -Z (from +Z) so `bounds` fills the view with a margin.
Camera frameBounds(const Bounds& bounds, float aspect, float verticalFovDegrees = 30.0f,
                   glm::vec3 viewDirection = {0.0f, 0.0f, -1.0f});

// Empty when `camera` can be rendered; otherwise what is wrong with it ("eye and target
// must differ", ...). The renderer refuses such a view; callers whose camera comes from the
// user check first, so that the message names the flag or file it came from.
std::string cameraProblem(const Camera& camera);

// The pixels of view `index` in a width × height image whose views fill a columns × rows grid
// row by row: the renderer's viewport and scissor for that view (the boundaries at
// column·width/columns, integer division).
struct ViewCell {
    std::uint32_t x = 0, y = 0, width = 0, height = 0;
};
ViewCell viewCell(std::uint32_t width, std::uint32_t height, std::uint32_t columns, std::uint32_t rows,
                  std::size_t index);
// The renderer's projection · view matrix of `camera` for a cell of aspect width/height (clip
// space +Y up, depth 0..1 with GLM_FORCE_DEPTH_ZERO_TO_ONE). Whoever must know where something
// lands in a rendered image (signer/screen_regions.hpp) projects with this.
glm::mat4 viewProjection(const Camera& camera, float aspect);

struct View {
    int scene = 0;         // handle returned by Renderer::addScene
    Pose pose;             // empty: the scene's rest pose; morph weights by target name
                           // in pose.morphByName (docs/morph-targets.md)
    Camera camera;
    std::string label;     // caption drawn in the view's corner ("A" .. "D", "bent-B"); may be empty
};

struct Frame {
    std::uint32_t columns = 1, rows = 1;  // grid; views fill it row by row
    std::vector<View> views;
};

}  // namespace signstim::render
