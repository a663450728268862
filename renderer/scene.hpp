#pragma once
// CPU-side scene: what a glTF 2.0 file (or a procedural builder) describes, decoded and
// validated, independent of Vulkan. The renderer uploads it once; per frame it takes a Pose
// (one local transform per node). The renderer knows nothing of ASL: it draws posed
// skeletons. Units are glTF's (metres, radians, +Y up, right-handed).
//
// Contract shared by the glTF side (loader/writer/animation: renderer/gltf_*.cpp,
// renderer/animation.cpp, renderer/scene.cpp) and the Vulkan side (renderer/renderer.cpp).
// Fields may be added; do not change the meaning of existing ones.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace signstim::render {

struct Trs {
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // (w, x, y, z)
    glm::vec3 scale{1.0f};
    glm::mat4 matrix() const;
};

struct Vertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec2 uv{0.0f};
    glm::uvec4 joints{0u};                      // indices into the skin's joint list
    glm::vec4 weights{1.0f, 0.0f, 0.0f, 0.0f};  // sum 1 when skinned
};

// glTF 2.0 §3.7.2.2 morph target: per-vertex displacements added to the base attributes,
// weighted (p = p0 + sum w_i dp_i), before skinning. Dense, indexed like
// Primitive::vertices (sparse accessors are expanded when loaded); empty: no such target
// attribute (zero displacement).
struct MorphTarget {
    std::vector<glm::vec3> position{};
    std::vector<glm::vec3> normal{};
};

struct Primitive {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;  // triangle list (non-indexed input is expanded)
    int material = -1;                   // -1: default material (white, rough, dielectric)
    bool skinned = false;                // JOINTS_0/WEIGHTS_0 were present
    std::vector<MorphTarget> targets{};  // every primitive of a mesh has the same count
};

struct Mesh {
    std::string name;
    std::vector<Primitive> primitives;
    // Morph targets: default weights (glTF mesh.weights; zeros when the file has none) and
    // the targets' names (mesh.extras.targetNames, the common exporter convention; empty
    // when the file names none). Both have the primitives' target count, or are empty.
    std::vector<float> weights{};
    std::vector<std::string> targetNames{};
    std::size_t targetCount() const { return primitives.empty() ? 0 : primitives.front().targets.size(); }
};

struct ImageData {  // decoded, 8-bit RGBA
    std::string name;
    std::uint32_t width = 0, height = 0;
    std::vector<std::uint8_t> rgba;
};

enum class Filter { Nearest, Linear };
enum class Wrap { Repeat, ClampToEdge, MirroredRepeat };

struct Texture {
    int image = -1;
    Filter magFilter = Filter::Linear, minFilter = Filter::Linear;
    bool mipmaps = true;
    Wrap wrapS = Wrap::Repeat, wrapT = Wrap::Repeat;
};

enum class AlphaMode { Opaque, Mask, Blend };

struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};  // linear RGBA
    int baseColorTexture = -1;        // index into Scene::textures (sRGB)
    float metallicFactor = 1.0f;
    float roughnessFactor = 1.0f;
    int metallicRoughnessTexture = -1;  // B = metallic, G = roughness (linear)
    glm::vec3 emissiveFactor{0.0f};
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
};

struct Node {
    std::string name;
    int parent = -1;
    std::vector<int> children;
    Trs rest;                                // local transform from the file
    std::optional<glm::mat4> restMatrix;     // glTF `matrix` (not animatable) when given
    int mesh = -1;
    int skin = -1;
    std::vector<float> weights{};  // glTF node.weights (overrides the mesh's); usually empty
};

struct Skin {
    std::string name;
    std::vector<int> joints;                 // node indices
    std::vector<glm::mat4> inverseBindMatrices;  // identity when the file has none
    int skeleton = -1;
};

enum class Interpolation { Linear, Step, CubicSpline };
enum class AnimationPath { Translation, Rotation, Scale, Weights };

struct AnimationSampler {
    std::vector<float> times;       // seconds, strictly increasing
    std::vector<glm::vec4> values;  // vec3 in xyz, or quaternion as (x, y, z, w);
                                    // CubicSpline: 3 per key (in-tangent, value, out-tangent)
    Interpolation interpolation = Interpolation::Linear;
    // Morph-target weights (a SCALAR output): `weightCount` values per key, key after key
    // (CubicSpline: in-tangents, values, out-tangents, each weightCount long, per key).
    std::vector<float> weights{};
    std::size_t weightCount = 0;
};

struct AnimationChannel {
    int node = -1;
    AnimationPath path = AnimationPath::Translation;
    int sampler = -1;
};

struct Animation {
    std::string name;
    std::vector<AnimationSampler> samplers;
    std::vector<AnimationChannel> channels;
    float durationSeconds = 0.0f;  // max over samplers' last time
    // Where durationSeconds comes from, for messages about it: the glTF input accessor
    // holding the last key ("/accessors/4"); empty for animations not loaded from a file.
    std::string durationSource;
};

struct Scene {
    std::string sourceName;  // file the scene came from (for messages)
    std::vector<Node> nodes;
    std::vector<int> roots;  // root nodes of the displayed glTF scene
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<ImageData> images;
    std::vector<Skin> skins;
    std::vector<Animation> animations;

    int findNode(std::string_view name) const;          // -1 if absent
    int findAnimation(std::string_view name) const;     // -1 if absent
};

// Morph weights set by name apply to every mesh target of that name; they are clamped to
// [kMorphWeightMin, kMorphWeightMax]. glTF itself allows any finite weight; [0, 1] is the
// range in which a named target (ARKit's blend shapes, e.g. "jawOpen") means anything.
constexpr float kMorphWeightMin = 0.0f, kMorphWeightMax = 1.0f;

// One local transform per node (indexed like Scene::nodes). This is the per-frame data.
struct Pose {
    std::vector<Trs> local;
    std::vector<bool> useRestMatrix;  // node keeps its glTF `matrix` (no TRS override)
    // Morph weights per node (indexed like Scene::nodes; an inner vector has the node's mesh
    // target count). Empty (or an empty inner vector): the node's default weights
    // (node.weights, else mesh.weights). Animations with "weights" channels fill it.
    std::vector<std::vector<float>> morphWeights{};
    // Morph weights by target name (mesh.extras.targetNames), applied after morphWeights to
    // every mesh that has a target of that name, clamped to [kMorphWeightMin, kMorphWeightMax];
    // a name no mesh has is ignored. The seam for whoever drives a face by name.
    std::map<std::string, float, std::less<>> morphByName{};
};

struct Bounds {
    glm::vec3 min{0.0f}, max{0.0f};
    bool empty = true;
    glm::vec3 center() const { return (min + max) * 0.5f; }
    void add(const glm::vec3& p);
};

Pose restPose(const Scene& scene);

// Samples `animation` at `timeSeconds` (clamped to [0, duration]) into `pose`, leaving
// channels the animation does not drive untouched.
void applyAnimation(const Scene& scene, int animation, float timeSeconds, Pose& pose);

// World matrices of every node for `pose` (parents before children).
void computeWorldTransforms(const Scene& scene, const Pose& pose, std::vector<glm::mat4>& world);

// Joint matrices of `skin` for the given world transforms: world[joint] * inverseBind.
void computeJointMatrices(const Scene& scene, int skin, const std::vector<glm::mat4>& world,
                          std::vector<glm::mat4>& jointMatrices);

// The morph weights of node `node` for `pose` (empty when its mesh has no targets): the
// pose's per-node weights, else node.weights, else mesh.weights, else zeros; then the
// pose's named weights (clamped). Non-finite weights count as 0.
std::vector<float> resolveMorphWeights(const Scene& scene, const Pose& pose, int node);

// The position and normal of vertex `v` of `primitive` with morph `weights` applied
// (glTF: before skinning). The normal is not renormalised.
void morphVertex(const Primitive& primitive, std::size_t v, const std::vector<float>& weights,
                 glm::vec3& position, glm::vec3& normal);

// Empty when `pose`'s morph weights fit `scene` (morphWeights empty or one entry per node,
// each empty or of its mesh's target count; named weights finite); otherwise what is wrong.
std::string morphProblem(const Scene& scene, const Pose& pose);

// Axis-aligned bounds of every mesh vertex in world space for `pose` (morphs and skinning applied).
Bounds computeBounds(const Scene& scene, const Pose& pose);

}  // namespace signstim::render
