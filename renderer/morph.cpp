// Morph targets on the CPU (glTF 2.0 §3.7.2.2): which weights a node has in a pose, and a
// morphed vertex (for bounds; the renderer sums the same way per frame: vk_morph.cpp).
#include "renderer/scene.hpp"

#include <algorithm>
#include <cmath>

namespace signstim::render {

std::vector<float> resolveMorphWeights(const Scene& scene, const Pose& pose, int node) {
    if (node < 0 || static_cast<std::size_t>(node) >= scene.nodes.size()) return {};
    const Node& n = scene.nodes[static_cast<std::size_t>(node)];
    if (n.mesh < 0 || static_cast<std::size_t>(n.mesh) >= scene.meshes.size()) return {};
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(n.mesh)];
    const std::size_t count = mesh.targetCount();
    if (count == 0) return {};
    std::vector<float> weights(count, 0.0f);
    // glTF 2.0 §3.7.2.2: node.weights, when given, override mesh.weights; an animation's
    // "weights" channel overrides both (it lands in pose.morphWeights).
    const std::vector<float>* source = nullptr;
    const auto i = static_cast<std::size_t>(node);
    if (i < pose.morphWeights.size() && pose.morphWeights[i].size() == count) source = &pose.morphWeights[i];
    else if (n.weights.size() == count) source = &n.weights;
    else if (mesh.weights.size() == count) source = &mesh.weights;
    if (source) weights = *source;
    if (!pose.morphByName.empty()) {
        for (std::size_t t = 0; t < count && t < mesh.targetNames.size(); ++t) {
            const auto found = pose.morphByName.find(mesh.targetNames[t]);
            if (found != pose.morphByName.end())
                weights[t] = std::clamp(found->second, kMorphWeightMin, kMorphWeightMax);
        }
    }
    for (float& w : weights)
        if (!std::isfinite(w)) w = 0.0f;  // std::clamp keeps a NaN; a NaN would poison every vertex
    return weights;
}

std::string morphProblem(const Scene& scene, const Pose& pose) {
    if (!pose.morphWeights.empty() && pose.morphWeights.size() != scene.nodes.size())
        return "morphWeights has " + std::to_string(pose.morphWeights.size()) + " entries, scene '" +
               scene.sourceName + "' has " + std::to_string(scene.nodes.size()) + " nodes";
    for (std::size_t n = 0; n < pose.morphWeights.size(); ++n) {
        const std::vector<float>& weights = pose.morphWeights[n];
        if (weights.empty()) continue;
        const int mesh = scene.nodes[n].mesh;
        const std::size_t count =
            mesh >= 0 && static_cast<std::size_t>(mesh) < scene.meshes.size() ? scene.meshes[static_cast<std::size_t>(mesh)].targetCount() : 0;
        if (weights.size() != count)
            return "morphWeights[" + std::to_string(n) + "] has " + std::to_string(weights.size()) +
                   " weights, node '" + scene.nodes[n].name + "' has " + std::to_string(count) + " morph targets";
        for (float w : weights)
            if (!std::isfinite(w)) return "morphWeights[" + std::to_string(n) + "] holds a non-finite weight";
    }
    for (const auto& [name, weight] : pose.morphByName)
        if (!std::isfinite(weight)) return "morph weight '" + name + "' is not finite";
    return "";
}

void morphVertex(const Primitive& primitive, std::size_t v, const std::vector<float>& weights,
                 glm::vec3& position, glm::vec3& normal) {
    position = primitive.vertices[v].position;
    normal = primitive.vertices[v].normal;
    const std::size_t count = std::min(weights.size(), primitive.targets.size());
    for (std::size_t t = 0; t < count; ++t) {
        const float w = weights[t];
        if (w == 0.0f) continue;
        const MorphTarget& target = primitive.targets[t];
        if (v < target.position.size()) position += w * target.position[v];
        if (v < target.normal.size()) normal += w * target.normal[v];
    }
}

}  // namespace signstim::render
