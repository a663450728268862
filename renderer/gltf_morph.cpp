// glTF 2.0 morph targets (§3.7.2.2, §3.11 "weights" channels): conversion and the checks that
// go with it (gltf_morph.hpp).
#include "renderer/gltf_morph.hpp"

#include <tiny_gltf.h>

#include <cmath>

namespace signstim::render::gltf_morph {
namespace {
using gltf_detail::at;

std::string meshPointer(std::size_t mesh) { return at("meshes", mesh); }

// A weights array (mesh.weights, node.weights): `count` finite numbers.
std::vector<float> checkedWeights(const ValidatedGltf& gltf, const std::vector<double>& weights,
                                  std::size_t count, const std::string& field) {
    if (weights.size() != count)
        gltf.fail(field, "has " + std::to_string(weights.size()) + " weights but the mesh has " +
                             std::to_string(count) + " morph targets (glTF 2.0 §3.7.2.2: one weight per target)");
    std::vector<float> out;
    out.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        if (!std::isfinite(weights[i]) || std::abs(weights[i]) > 3.4e38)
            gltf.fail(at(field, i), "weight is not a finite number");
        out.push_back(static_cast<float>(weights[i]));
    }
    return out;
}

// One POSITION or NORMAL target attribute: VEC3 FLOAT with the base's count, inside its
// declared min/max (when given), read with sparse substitution.
std::vector<glm::vec3> readTargetAttribute(const ValidatedGltf& gltf, int accessor, std::size_t vertexCount,
                                           const std::string& field) {
    const tinygltf::Accessor& a = gltf.model().accessors[static_cast<std::size_t>(accessor)];
    const std::vector<double> values =
        gltf.readAccessor(accessor, {TINYGLTF_TYPE_VEC3}, {TINYGLTF_COMPONENT_TYPE_FLOAT}, field);
    if (a.count != vertexCount)
        gltf.fail(field, "has " + std::to_string(a.count) + " elements but the base POSITION has " +
                             std::to_string(vertexCount) + " (a target displaces every vertex)");
    const std::string f = at("accessors", static_cast<std::size_t>(accessor));
    // Declared bounds are a promise about the values (glTF 2.0 §3.6.2.5): a file that breaks
    // it is broken, as the Khronos validator reports (ACCESSOR_MIN_MISMATCH/MAX_MISMATCH).
    for (const auto* bound : {&a.minValues, &a.maxValues}) {
        if (bound->empty()) continue;
        const bool isMin = bound == &a.minValues;
        const std::string bf = f + (isMin ? "/min" : "/max");
        if (bound->size() != 3) gltf.fail(bf, "must have 3 numbers (VEC3)");
        for (std::size_t v = 0; v < vertexCount; ++v)
            for (std::size_t c = 0; c < 3; ++c) {
                const double value = values[v * 3 + c], limit = (*bound)[c];
                const double slack = 1e-6 * std::max(1.0, std::abs(limit));  // float rounding
                if (isMin ? value < limit - slack : value > limit + slack)
                    gltf.fail(bf, "element " + std::to_string(v) + " of " + field + " lies outside the declared " +
                                      (isMin ? "minimum" : "maximum") + " (component " + std::to_string(c) + ")");
            }
    }
    std::vector<glm::vec3> out(vertexCount);
    for (std::size_t v = 0; v < vertexCount; ++v)
        out[v] = glm::vec3(values[v * 3], values[v * 3 + 1], values[v * 3 + 2]);
    return out;
}

}  // namespace

void convertMeshMorphs(const ValidatedGltf& gltf, std::size_t mesh, Mesh& out) {
    const tinygltf::Mesh& m = gltf.model().meshes[mesh];
    const std::string f = meshPointer(mesh);
    const std::size_t count = m.primitives.empty() ? 0 : m.primitives.front().targets.size();
    // glTF 2.0 §3.7.2.2: all primitives have the same number of targets, in the same order.
    for (std::size_t p = 0; p < m.primitives.size(); ++p)
        if (m.primitives[p].targets.size() != count)
            gltf.fail(at(f + "/primitives", p) + "/targets",
                      "has " + std::to_string(m.primitives[p].targets.size()) + " morph targets but " +
                          at(f + "/primitives", 0) + " has " + std::to_string(count) +
                          " (every primitive of a mesh has the same targets)");
    if (count > kMaxMorphTargets)
        gltf.fail(at(f + "/primitives", 0) + "/targets", std::to_string(count) + " morph targets; at most " +
                                                            std::to_string(kMaxMorphTargets) + " are supported");
    if (!m.weights.empty() || count > 0)
        out.weights = m.weights.empty() ? std::vector<float>(count, 0.0f)
                                        : checkedWeights(gltf, m.weights, count, f + "/weights");
    // mesh.extras.targetNames: the convention of Blender's and three.js' exporters.
    if (m.extras.IsObject() && m.extras.Has("targetNames")) {
        const tinygltf::Value& names = m.extras.Get("targetNames");
        const std::string nf = f + "/extras/targetNames";
        if (!names.IsArray() || names.ArrayLen() != count)
            gltf.fail(nf, "must be an array of " + std::to_string(count) + " names, one per morph target");
        for (std::size_t t = 0; t < count; ++t) {
            const tinygltf::Value& name = names.Get(static_cast<int>(t));
            if (!name.IsString()) gltf.fail(at(nf, t), "must be a string");
            out.targetNames.push_back(name.Get<std::string>());
        }
    }
}

void convertPrimitiveTargets(const ValidatedGltf& gltf, std::size_t mesh, std::size_t primitive, Primitive& out,
                             std::vector<std::string>* warnings) {
    const tinygltf::Primitive& prim = gltf.model().meshes[mesh].primitives[primitive];
    if (prim.targets.empty()) return;
    const std::string f = at(at("meshes", mesh) + "/primitives", primitive);
    const std::size_t vertexCount = out.vertices.size();
    if (vertexCount > 0 && prim.targets.size() > kMaxMorphElements / vertexCount)
        gltf.fail(f + "/targets", std::to_string(prim.targets.size()) + " targets of " + std::to_string(vertexCount) +
                                      " vertices exceed the supported " + std::to_string(kMaxMorphElements) +
                                      " vertex-target pairs");
    bool warned = false;
    out.targets.resize(prim.targets.size());
    for (std::size_t t = 0; t < prim.targets.size(); ++t) {
        const std::string tf = at(f + "/targets", t);
        for (const auto& [name, accessor] : prim.targets[t]) {
            const std::string af = tf + "/" + name;
            // Khronos validator MESH_PRIMITIVE_MORPH_TARGET_NO_BASE_ACCESSOR: a displaced
            // attribute must exist in the base primitive.
            if (prim.attributes.find(name) == prim.attributes.end())
                gltf.fail(af, "the base primitive has no " + name + " attribute to displace");
            if (name == "POSITION") {
                out.targets[t].position = readTargetAttribute(gltf, accessor, vertexCount, af);
            } else if (name == "NORMAL") {
                out.targets[t].normal = readTargetAttribute(gltf, accessor, vertexCount, af);
            } else if (!warned && warnings) {
                warnings->push_back(gltf.fileName() + ": " + af + ": morph target attribute ignored (only POSITION and NORMAL are applied)");
                warned = true;
            }
        }
    }
}

void convertNodeWeights(const ValidatedGltf& gltf, Scene& scene) {
    const auto& nodes = gltf.model().nodes;
    for (std::size_t i = 0; i < nodes.size() && i < scene.nodes.size(); ++i) {
        if (nodes[i].weights.empty()) continue;
        const int mesh = nodes[i].mesh;
        const std::size_t count = mesh >= 0 && static_cast<std::size_t>(mesh) < scene.meshes.size()
                                      ? gltf.model().meshes[static_cast<std::size_t>(mesh)].primitives.front().targets.size()
                                      : 0;
        if (count == 0) gltf.fail(at("nodes", i) + "/weights", "the node has no mesh with morph targets");
        scene.nodes[i].weights = checkedWeights(gltf, nodes[i].weights, count, at("nodes", i) + "/weights");
    }
}

void convertWeightsChannel(const ValidatedGltf& gltf, const Scene& scene, std::size_t animation,
                           std::size_t channel, AnimationSampler& sampler) {
    const tinygltf::Animation& a = gltf.model().animations[animation];
    const tinygltf::AnimationChannel& c = a.channels[channel];
    const std::string cf = at(at("animations", animation) + "/channels", channel);
    const int node = c.target_node;
    const int mesh = scene.nodes[static_cast<std::size_t>(node)].mesh;
    const std::size_t count = mesh >= 0 ? gltf.model().meshes[static_cast<std::size_t>(mesh)].primitives.front().targets.size() : 0;
    if (count == 0) gltf.fail(cf + "/target/node", "animates weights of a node without morph targets");
    const std::string sf = at(at("animations", animation) + "/samplers", static_cast<std::size_t>(c.sampler));
    const tinygltf::Accessor& output =
        gltf.model().accessors[static_cast<std::size_t>(a.samplers[static_cast<std::size_t>(c.sampler)].output)];
    // glTF 2.0 §3.11: weights outputs are FLOAT or normalized (unsigned) byte/short.
    const bool normalizedInteger = output.normalized && output.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT &&
                                   output.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    if (output.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !normalizedInteger)
        gltf.fail(sf + "/output", "weights must be FLOAT or normalized byte/short values");
    const std::size_t perKey = sampler.interpolation == Interpolation::CubicSpline ? 3 : 1;
    const std::size_t expected = sampler.times.size() * perKey * count;
    if (sampler.weights.size() != expected)
        gltf.fail(sf + "/output", "has " + std::to_string(sampler.weights.size()) + " values; " +
                                      std::to_string(sampler.times.size()) + " keys x " + std::to_string(count) +
                                      " morph targets" + (perKey == 3 ? " x 3 (CUBICSPLINE)" : "") + " need " +
                                      std::to_string(expected));
    sampler.weightCount = count;
}

}  // namespace signstim::render::gltf_morph
