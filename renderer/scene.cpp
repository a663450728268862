#include "renderer/frame.hpp"
#include "renderer/scene.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace signstim::render {

glm::mat4 Trs::matrix() const {
    // glTF: M = T * R * S.
    glm::mat4 m = glm::mat4_cast(rotation);
    m[0] *= scale.x;
    m[1] *= scale.y;
    m[2] *= scale.z;
    m[3] = glm::vec4(translation, 1.0f);
    return m;
}

int Scene::findNode(std::string_view name) const {
    for (std::size_t i = 0; i < nodes.size(); ++i)
        if (nodes[i].name == name) return static_cast<int>(i);
    return -1;
}

int Scene::findAnimation(std::string_view name) const {
    for (std::size_t i = 0; i < animations.size(); ++i)
        if (animations[i].name == name) return static_cast<int>(i);
    return -1;
}

void Bounds::add(const glm::vec3& p) {
    if (empty) {
        min = max = p;
        empty = false;
    } else {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
}

Pose restPose(const Scene& scene) {
    Pose pose;
    pose.local.reserve(scene.nodes.size());
    pose.useRestMatrix.reserve(scene.nodes.size());
    for (const Node& node : scene.nodes) {
        pose.local.push_back(node.rest);
        pose.useRestMatrix.push_back(node.restMatrix.has_value());
    }
    return pose;
}

namespace {

glm::mat4 localMatrix(const Scene& scene, const Pose& pose, std::size_t i) {
    const Node& node = scene.nodes[i];
    // A pose shorter than the scene (or empty) leaves the remaining nodes at rest.
    const bool posed = i < pose.local.size();
    const bool keepMatrix =
        node.restMatrix && (!posed || (i < pose.useRestMatrix.size() && pose.useRestMatrix[i]));
    if (keepMatrix) return *node.restMatrix;
    return posed ? pose.local[i].matrix() : node.rest.matrix();
}

}  // namespace

void computeWorldTransforms(const Scene& scene, const Pose& pose, std::vector<glm::mat4>& world) {
    const std::size_t count = scene.nodes.size();
    world.assign(count, glm::mat4(1.0f));
    // Walk each tree from its root, parents first. The loader guarantees a forest (no
    // cycles, one parent per node); `done` keeps a malformed hand-built scene from looping.
    std::vector<char> done(count, 0);
    std::vector<int> stack;
    for (std::size_t r = 0; r < count; ++r) {
        const int parent = scene.nodes[r].parent;
        if (parent >= 0 && static_cast<std::size_t>(parent) < count) continue;
        world[r] = localMatrix(scene, pose, r);
        done[r] = 1;
        stack.assign(1, static_cast<int>(r));
        while (!stack.empty()) {
            const int n = stack.back();
            stack.pop_back();
            for (int c : scene.nodes[static_cast<std::size_t>(n)].children) {
                if (c < 0 || static_cast<std::size_t>(c) >= count || done[c]) continue;
                world[c] = world[n] * localMatrix(scene, pose, static_cast<std::size_t>(c));
                done[c] = 1;
                stack.push_back(c);
            }
        }
    }
}

void computeJointMatrices(const Scene& scene, int skin, const std::vector<glm::mat4>& world,
                          std::vector<glm::mat4>& jointMatrices) {
    jointMatrices.clear();
    if (skin < 0 || static_cast<std::size_t>(skin) >= scene.skins.size()) return;
    const Skin& s = scene.skins[static_cast<std::size_t>(skin)];
    jointMatrices.resize(s.joints.size(), glm::mat4(1.0f));
    for (std::size_t j = 0; j < s.joints.size(); ++j) {
        const int node = s.joints[j];
        const glm::mat4 jointWorld = (node >= 0 && static_cast<std::size_t>(node) < world.size())
                                         ? world[static_cast<std::size_t>(node)]
                                         : glm::mat4(1.0f);
        const glm::mat4 inverseBind =
            j < s.inverseBindMatrices.size() ? s.inverseBindMatrices[j] : glm::mat4(1.0f);
        jointMatrices[j] = jointWorld * inverseBind;
    }
}

Bounds computeBounds(const Scene& scene, const Pose& pose) {
    Bounds bounds;
    std::vector<glm::mat4> world;
    computeWorldTransforms(scene, pose, world);
    std::vector<glm::mat4> joints;
    for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
        const Node& node = scene.nodes[n];
        if (node.mesh < 0 || static_cast<std::size_t>(node.mesh) >= scene.meshes.size()) continue;
        const bool hasSkin = node.skin >= 0 && static_cast<std::size_t>(node.skin) < scene.skins.size();
        if (hasSkin) computeJointMatrices(scene, node.skin, world, joints);
        const std::vector<float> weights = resolveMorphWeights(scene, pose, static_cast<int>(n));
        for (const Primitive& primitive : scene.meshes[static_cast<std::size_t>(node.mesh)].primitives) {
            const bool skinned = hasSkin && primitive.skinned;
            for (std::size_t i = 0; i < primitive.vertices.size(); ++i) {
                const Vertex& v = primitive.vertices[i];
                glm::vec3 position = v.position, normal;
                if (!weights.empty()) morphVertex(primitive, i, weights, position, normal);  // glTF: morph, then skin
                const glm::vec4 p(position, 1.0f);
                if (!skinned) {
                    bounds.add(glm::vec3(world[n] * p));
                    continue;
                }
                // glTF skinning: the mesh node's own transform is ignored; joints place it.
                glm::mat4 skinMatrix(0.0f);
                for (int k = 0; k < 4; ++k) {
                    const float w = v.weights[k];
                    if (w == 0.0f) continue;
                    const std::uint32_t j = v.joints[k];
                    skinMatrix += w * (j < joints.size() ? joints[j] : glm::mat4(1.0f));
                }
                bounds.add(glm::vec3(skinMatrix * p));
            }
        }
    }
    return bounds;
}

std::string cameraProblem(const Camera& camera) {
    const auto finite = [](const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    if (!finite(camera.eye) || !finite(camera.target) || !finite(camera.up))
        return "eye, target and up must be finite (a scene too large for 32-bit floats?)";
    if (glm::length(camera.target - camera.eye) < 1e-9f ||
        glm::length(glm::cross(camera.target - camera.eye, camera.up)) < 1e-12f)
        return "eye, target and up must span a view (eye != target, up not along the view direction)";
    if (!(camera.nearPlane > 0.0f) || !(camera.farPlane > camera.nearPlane) || !std::isfinite(camera.farPlane))
        return "needs 0 < near plane < far plane, both finite";
    if (!camera.orthographic && !(camera.verticalFovDegrees > 0.0f && camera.verticalFovDegrees < 180.0f))
        return "the vertical field of view must lie in (0, 180) degrees";
    if (camera.orthographic && !(camera.orthographicHeight > 0.0f && std::isfinite(camera.orthographicHeight)))
        return "the orthographic height must be > 0";
    return "";
}

Camera frameBounds(const Bounds& bounds, float aspect, float verticalFovDegrees,
                   glm::vec3 viewDirection) {
    Camera camera;
    camera.verticalFovDegrees = verticalFovDegrees;
    if (bounds.empty) return camera;
    if (!(aspect > 0.0f)) aspect = 1.0f;
    glm::vec3 forward = glm::length(viewDirection) > 0.0f ? glm::normalize(viewDirection)
                                                          : glm::vec3(0.0f, 0.0f, -1.0f);
    glm::vec3 up(0.0f, 1.0f, 0.0f);
    if (std::abs(glm::dot(forward, up)) > 0.999f) up = glm::vec3(0.0f, 0.0f, -1.0f);
    const glm::vec3 right = glm::normalize(glm::cross(forward, up));
    up = glm::cross(right, forward);

    constexpr float margin = 1.1f;  // 10 % free space around the bounds
    const float tanHalfV = std::tan(glm::radians(verticalFovDegrees) * 0.5f) / margin;
    const float tanHalfH = tanHalfV * aspect;
    const glm::vec3 center = bounds.center();
    // Smallest distance from the centre such that every corner of the box projects inside
    // the (shrunk) frustum: |x| <= tanH * depth and |y| <= tanV * depth.
    float distance = 0.0f;
    float radius = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 c((corner & 1) ? bounds.max.x : bounds.min.x,
                          (corner & 2) ? bounds.max.y : bounds.min.y,
                          (corner & 4) ? bounds.max.z : bounds.min.z);
        const glm::vec3 o = c - center;
        const float depth = glm::dot(o, forward);
        distance = std::max(distance, std::abs(glm::dot(o, right)) / tanHalfH - depth);
        distance = std::max(distance, std::abs(glm::dot(o, up)) / tanHalfV - depth);
        radius = std::max(radius, glm::length(o));
    }
    distance = std::max(distance, radius * 1.05f + 1e-3f);  // camera stays outside the box
    camera.target = center;
    camera.eye = center - forward * distance;
    camera.up = up;
    camera.nearPlane = std::max(1e-3f, (distance - radius) * 0.5f);
    camera.farPlane = distance + radius * 2.0f + 1.0f;
    camera.orthographicHeight = (bounds.max.y - bounds.min.y) * margin;
    return camera;
}

}  // namespace signstim::render
