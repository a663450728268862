// Where a view lands in the image and how its camera projects (renderer/frame.hpp): one
// definition, used by the renderer's draws and by whoever maps world points to pixels.
#include "renderer/frame.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace signstim::render {

ViewCell viewCell(std::uint32_t width, std::uint32_t height, std::uint32_t columns, std::uint32_t rows,
                  std::size_t index) {
    const auto column = static_cast<std::uint32_t>(index % columns);
    const auto row = static_cast<std::uint32_t>(index / columns);
    ViewCell cell;
    cell.x = column * width / columns;
    cell.y = row * height / rows;
    cell.width = (column + 1) * width / columns - cell.x;
    cell.height = (row + 1) * height / rows - cell.y;
    return cell;
}

glm::mat4 viewProjection(const Camera& camera, float aspect) {
    const glm::mat4 projection =
        camera.orthographic
            ? glm::ortho(-0.5f * camera.orthographicHeight * aspect, 0.5f * camera.orthographicHeight * aspect,
                         -0.5f * camera.orthographicHeight, 0.5f * camera.orthographicHeight, camera.nearPlane,
                         camera.farPlane)
            : glm::perspective(glm::radians(camera.verticalFovDegrees), aspect, camera.nearPlane, camera.farPlane);
    return projection * glm::lookAt(camera.eye, camera.target, camera.up);
}

}  // namespace signstim::render
