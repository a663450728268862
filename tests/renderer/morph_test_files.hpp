#pragma once
// A small morphing test model, built by hand as glTF (synthetic): a 1 m box with two morph
// targets, so the loader, the CPU side and the GPU side are checked on a file not written
// by our own writer.
//   target 0 "stretch": dense POSITION; the top half (y > 0) rises 0.5 m.
//   target 1 "pinch":   sparse POSITION (the 12 vertices with z > 0 move 40 % towards x = 0)
//                       and a sparse NORMAL (the 4 front-face normals tilt towards +x).
// mesh.weights [0, 0]; extras.targetNames ["stretch", "pinch"]; node 0 turned 30 deg about Y
// and 20 deg about X (as procedural::litCube) so three faces show; animation "morph": a
// weights channel, LINEAR, both weights 0 at t = 0 s and 1 at t = 1 s.
#include "tests/renderer/gltf_test_files.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace signstim::render::testing {

struct MorphBox {
    GltfBuilder gltf;
    std::vector<float> positions;        // base, 24 x 3
    std::vector<std::uint16_t> pinched;  // sparse indices of the pinch POSITION target
    std::vector<float> pinchValues;      // their displacements, 3 each
    int stretchAccessor = -1, pinchAccessor = -1, pinchNormalAccessor = -1, weightsOutput = -1;
};

inline MorphBox morphBox() {
    MorphBox box;
    GltfBuilder& b = box.gltf;
    std::vector<float> normals;
    std::vector<std::uint16_t> indices;
    for (int axis = 0; axis < 3; ++axis)
        for (float side : {-1.0f, 1.0f}) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            const auto first = static_cast<std::uint16_t>(box.positions.size() / 3);
            for (float cu : {-0.5f, 0.5f})
                for (float cv : {-0.5f, 0.5f}) {
                    float p[3], n[3] = {0, 0, 0};
                    p[axis] = 0.5f * side;
                    p[u] = cu;
                    p[v] = side > 0 ? cv : -cv;  // counter-clockwise seen from outside
                    n[axis] = side;
                    box.positions.insert(box.positions.end(), p, p + 3);
                    normals.insert(normals.end(), n, n + 3);
                }
            for (int k : {0, 1, 3, 0, 3, 2}) indices.push_back(static_cast<std::uint16_t>(first + k));
        }
    const std::size_t count = box.positions.size() / 3;
    std::vector<float> stretch(count * 3, 0.0f), normalValues;
    std::vector<std::uint16_t> frontFace;
    for (std::size_t i = 0; i < count; ++i) {
        const float x = box.positions[i * 3], y = box.positions[i * 3 + 1], z = box.positions[i * 3 + 2];
        if (y > 0) stretch[i * 3 + 1] = 0.5f;
        if (z > 0) {
            box.pinched.push_back(static_cast<std::uint16_t>(i));
            box.pinchValues.insert(box.pinchValues.end(), {-0.4f * x, 0.0f, 0.0f});
        }
        if (normals[i * 3 + 2] > 0.5f) {
            frontFace.push_back(static_cast<std::uint16_t>(i));
            normalValues.insert(normalValues.end(), {0.8f, 0.0f, 0.0f});
        }
    }
    const int position = b.addFloats(box.positions, "VEC3", 3);
    b.doc["accessors"][position]["min"] = {-0.5, -0.5, -0.5};
    b.doc["accessors"][position]["max"] = {0.5, 0.5, 0.5};
    const int normal = b.addFloats(normals, "VEC3", 3);
    const int index = b.addAccessor(b.addView(indices), 5123, indices.size(), "SCALAR");
    box.stretchAccessor = b.addFloats(stretch, "VEC3", 3);
    b.doc["accessors"][box.stretchAccessor]["min"] = {0.0, 0.0, 0.0};
    b.doc["accessors"][box.stretchAccessor]["max"] = {0.0, 0.5, 0.0};
    // Sparse accessors without a bufferView: zeros, with the listed elements substituted.
    auto sparse = [&](const std::vector<std::uint16_t>& which, const std::vector<float>& values) {
        nlohmann::json a = {{"componentType", 5126}, {"count", count}, {"type", "VEC3"}};
        a["sparse"] = {{"count", which.size()},
                       {"indices", {{"bufferView", b.addView(which)}, {"componentType", 5123}}},
                       {"values", {{"bufferView", b.addView(values)}}}};
        b.doc["accessors"].push_back(a);
        return static_cast<int>(b.doc["accessors"].size()) - 1;
    };
    box.pinchAccessor = sparse(box.pinched, box.pinchValues);
    box.pinchNormalAccessor = sparse(frontFace, normalValues);
    nlohmann::json primitive = {{"attributes", {{"POSITION", position}, {"NORMAL", normal}}}, {"indices", index}};
    primitive["targets"] = nlohmann::json::array(
        {nlohmann::json{{"POSITION", box.stretchAccessor}},
         nlohmann::json{{"POSITION", box.pinchAccessor}, {"NORMAL", box.pinchNormalAccessor}}});
    nlohmann::json mesh = {{"name", "morph box"}, {"primitives", nlohmann::json::array({primitive})}};
    mesh["weights"] = {0.0, 0.0};
    mesh["extras"] = {{"targetNames", nlohmann::json::array({"stretch", "pinch"})}};
    b.doc["meshes"] = nlohmann::json::array({mesh});
    const glm::quat q = glm::angleAxis(glm::radians(30.0f), glm::vec3(0, 1, 0)) *
                        glm::angleAxis(glm::radians(20.0f), glm::vec3(1, 0, 0));
    b.doc["nodes"] = nlohmann::json::array({nlohmann::json{{"name", "box"}, {"mesh", 0}, {"rotation", {q.x, q.y, q.z, q.w}}}});
    b.doc["scenes"] = nlohmann::json::array({nlohmann::json{{"nodes", nlohmann::json::array({0})}}});
    b.doc["scene"] = 0;
    const int input = b.addFloats({0.0f, 1.0f}, "SCALAR", 1);
    b.doc["accessors"][input]["min"] = nlohmann::json::array({0.0});
    b.doc["accessors"][input]["max"] = nlohmann::json::array({1.0});
    box.weightsOutput = b.addFloats({0.0f, 0.0f, 1.0f, 1.0f}, "SCALAR", 1);
    nlohmann::json animation = {{"name", "morph"}};
    animation["samplers"] = nlohmann::json::array({nlohmann::json{{"input", input}, {"output", box.weightsOutput}}});
    animation["channels"] = nlohmann::json::array(
        {nlohmann::json{{"sampler", 0}, {"target", {{"node", 0}, {"path", "weights"}}}}});
    b.doc["animations"] = nlohmann::json::array({animation});
    return box;
}

}  // namespace signstim::render::testing
