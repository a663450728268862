#pragma once
// The seam between whoever decides what to show (app/stimuli) and the renderer: a frame is
// a grid of views; each view has a camera, a posed scene and a caption label. All views of
// one frame are drawn into the same image, so they stay in sync (SPEC §4.3 side-by-side).
#include "renderer/scene.hpp"

#include <glm/glm.hpp>

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
