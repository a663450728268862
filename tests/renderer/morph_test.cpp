// Morph targets on the CPU side: loading (dense and sparse targets, weights, names), the
// hostile-input rules of gltf_morph.hpp, weight sampling (LINEAR, STEP, CUBICSPLINE) and
// weight resolution (per node, by name, clamped).
#include "renderer/gltf_loader.hpp"
#include "renderer/gltf_writer.hpp"
#include "renderer/scene.hpp"

#include "common/error.hpp"
#include "tests/renderer/morph_test_files.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace signstim;
using namespace signstim::render;
using namespace signstim::render::testing;
namespace fs = std::filesystem;

namespace {

Scene load(MorphBox& box, const std::string& name = "box.gltf") {
    return loadGltf(box.gltf.write(freshTestDir("morph"), name, Container::Embedded));
}

// The InputError loading `box` throws; fails the test if none.
InputError refusal(MorphBox& box) {
    try {
        load(box);
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "accepted";
    return InputError("", 0, "", "accepted");
}

nlohmann::json& primitive(MorphBox& box) { return box.gltf.doc["meshes"][0]["primitives"][0]; }

TEST(MorphLoad, DenseAndSparseTargetsDecodeToPerVertexDisplacements) {
    MorphBox box = morphBox();
    const Scene scene = load(box);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& mesh = scene.meshes[0];
    ASSERT_EQ(mesh.targetCount(), 2u);
    EXPECT_EQ(mesh.targetNames, (std::vector<std::string>{"stretch", "pinch"}));
    EXPECT_EQ(mesh.weights, (std::vector<float>{0.0f, 0.0f}));
    const Primitive& p = mesh.primitives[0];
    const std::size_t count = box.positions.size() / 3;
    ASSERT_EQ(p.targets[1].position.size(), count);
    // Sparse: the listed vertices carry their values, every other one is zero.
    std::size_t listed = 0;
    for (std::size_t v = 0; v < count; ++v) {
        glm::vec3 expected(0.0f);
        if (listed < box.pinched.size() && box.pinched[listed] == v) {
            expected = glm::vec3(box.pinchValues[listed * 3], box.pinchValues[listed * 3 + 1], box.pinchValues[listed * 3 + 2]);
            ++listed;
        }
        EXPECT_EQ(p.targets[1].position[v], expected) << "vertex " << v;
        EXPECT_EQ(p.targets[0].position[v].y, box.positions[v * 3 + 1] > 0 ? 0.5f : 0.0f) << "vertex " << v;
    }
    EXPECT_EQ(listed, box.pinched.size());
    EXPECT_TRUE(p.targets[0].normal.empty());
    EXPECT_EQ(p.targets[1].normal.size(), count);
    ASSERT_EQ(scene.animations.size(), 1u);
    EXPECT_EQ(scene.animations[0].channels[0].path, AnimationPath::Weights);
    EXPECT_EQ(scene.animations[0].samplers[0].weightCount, 2u);
}

TEST(MorphLoad, WeightsChannelSamplesLinearlyBetweenKeys) {
    MorphBox box = morphBox();
    const Scene scene = load(box);
    for (float t : {0.0f, 0.25f, 0.5f, 1.0f}) {
        Pose pose = restPose(scene);
        applyAnimation(scene, 0, t, pose);
        const std::vector<float> weights = resolveMorphWeights(scene, pose, 0);
        ASSERT_EQ(weights.size(), 2u);
        EXPECT_FLOAT_EQ(weights[0], t);
        EXPECT_FLOAT_EQ(weights[1], t);
    }
}

// Samples a hand-built sampler of two keys (t = 0 and 2 s) and two weights.
std::vector<float> sampleAt(Interpolation interpolation, const std::vector<float>& data, float t) {
    Scene scene;
    scene.nodes.resize(1);
    scene.nodes[0].mesh = 0;
    Mesh mesh;
    mesh.primitives.resize(1);
    mesh.primitives[0].targets.resize(2);
    scene.meshes.push_back(mesh);
    Animation animation;
    AnimationSampler sampler;
    sampler.times = {0.0f, 2.0f};
    sampler.interpolation = interpolation;
    sampler.weights = data;
    sampler.weightCount = 2;
    animation.samplers.push_back(sampler);
    animation.channels.push_back({0, AnimationPath::Weights, 0});
    animation.durationSeconds = 2.0f;
    scene.animations.push_back(animation);
    Pose pose = restPose(scene);
    applyAnimation(scene, 0, t, pose);
    return resolveMorphWeights(scene, pose, 0);
}

TEST(MorphSampling, StepHoldsTheEarlierKeyUntilTheNext) {
    const std::vector<float> data = {0.2f, 0.9f, 0.6f, 0.1f};
    EXPECT_EQ(sampleAt(Interpolation::Step, data, 1.99f), (std::vector<float>{0.2f, 0.9f}));
    EXPECT_EQ(sampleAt(Interpolation::Step, data, 2.0f), (std::vector<float>{0.6f, 0.1f}));
}

TEST(MorphSampling, LinearMixesEachWeightByTheKeyFraction) {
    const std::vector<float> data = {0.2f, 0.9f, 0.6f, 0.1f};
    const std::vector<float> w = sampleAt(Interpolation::Linear, data, 0.5f);  // a quarter of the way
    EXPECT_FLOAT_EQ(w[0], 0.2f + (0.6f - 0.2f) * 0.25f);
    EXPECT_FLOAT_EQ(w[1], 0.9f + (0.1f - 0.9f) * 0.25f);
}

TEST(MorphSampling, CubicSplineFollowsTheHermiteBasisWithTangents) {
    // Per key: in-tangents (2), values (2), out-tangents (2).
    const std::vector<float> data = {0, 0, 0.2f, 0.9f, 0.5f, -0.3f, 0.7f, 0.1f, 0.6f, 0.1f, 0, 0};
    const float dt = 2.0f, u = 0.25f, u2 = u * u, u3 = u2 * u;
    const float h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
    const std::vector<float> w = sampleAt(Interpolation::CubicSpline, data, 0.5f);
    EXPECT_NEAR(w[0], h00 * 0.2f + h10 * dt * 0.5f + h01 * 0.6f + h11 * dt * 0.7f, 1e-6f);
    EXPECT_NEAR(w[1], h00 * 0.9f + h10 * dt * -0.3f + h01 * 0.1f + h11 * dt * 0.1f, 1e-6f);
    // At a key the spline passes through its value.
    EXPECT_EQ(sampleAt(Interpolation::CubicSpline, data, 2.0f), (std::vector<float>{0.6f, 0.1f}));
}

TEST(MorphWeights, NamedWeightsAreClampedAndUnknownNamesIgnored) {
    MorphBox box = morphBox();
    const Scene scene = load(box);
    Pose pose;
    pose.morphByName = {{"stretch", 5.0f}, {"pinch", -2.0f}, {"browInnerUp", 1.0f}};
    EXPECT_EQ(resolveMorphWeights(scene, pose, 0), (std::vector<float>{kMorphWeightMax, kMorphWeightMin}));
    pose.morphByName = {{"pinch", 0.25f}};
    pose.morphWeights = {{0.5f, 0.75f}};  // by index first, then by name
    EXPECT_EQ(resolveMorphWeights(scene, pose, 0), (std::vector<float>{0.5f, 0.25f}));
}

TEST(MorphWeights, NodeWeightsOverrideTheMeshDefaults) {
    MorphBox box = morphBox();
    box.gltf.doc["meshes"][0]["weights"] = {0.1, 0.2};
    EXPECT_EQ(resolveMorphWeights(load(box), Pose{}, 0), (std::vector<float>{0.1f, 0.2f}));
    box.gltf.doc["nodes"][0]["weights"] = {0.3, 0.4};
    EXPECT_EQ(resolveMorphWeights(load(box), Pose{}, 0), (std::vector<float>{0.3f, 0.4f}));
}

TEST(MorphWeights, BoundsFollowTheMorphedVertices) {
    MorphBox box = morphBox();
    const Scene scene = load(box);
    Pose pose = restPose(scene);
    const Bounds rest = computeBounds(scene, pose);
    pose.morphByName = {{"stretch", 1.0f}};
    const Bounds stretched = computeBounds(scene, pose);
    EXPECT_GT(stretched.max.y, rest.max.y + 0.3f);
    EXPECT_FLOAT_EQ(stretched.min.y, rest.min.y);
}

TEST(MorphLoad, WriterRoundTripKeepsTargetsWeightsNamesAndChannels) {
    MorphBox box = morphBox();
    const Scene scene = load(box);
    const fs::path path = freshTestDir("morph") / "again.glb";
    writeGltf(scene, path);
    const Scene again = loadGltf(path);
    ASSERT_EQ(again.meshes.size(), 1u);
    EXPECT_EQ(again.meshes[0].targetNames, scene.meshes[0].targetNames);
    EXPECT_EQ(again.meshes[0].weights, scene.meshes[0].weights);
    const Primitive &a = scene.meshes[0].primitives[0], &b = again.meshes[0].primitives[0];
    ASSERT_EQ(b.targets.size(), a.targets.size());
    for (std::size_t t = 0; t < a.targets.size(); ++t) {
        EXPECT_EQ(b.targets[t].position, a.targets[t].position) << t;
        EXPECT_EQ(b.targets[t].normal, a.targets[t].normal) << t;
    }
    ASSERT_EQ(again.animations.size(), 1u);
    EXPECT_EQ(again.animations[0].channels[0].path, AnimationPath::Weights);
    EXPECT_EQ(again.animations[0].samplers[0].weights, scene.animations[0].samplers[0].weights);
}

// ---- hostile input: each names the file and the JSON pointer -----------------------------
void expectRefusal(MorphBox& box, const std::string& field, const std::string& words) {
    const InputError e = refusal(box);
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("box.gltf"), std::string::npos) << e.what();
}

TEST(MorphRefusal, SparseIndicesThatDoNotIncreaseStrictly) {
    MorphBox box = morphBox();
    std::swap(box.pinched[0], box.pinched[1]);
    const int view = box.gltf.addView(box.pinched);
    box.gltf.doc["accessors"][box.pinchAccessor]["sparse"]["indices"]["bufferView"] = view;
    expectRefusal(box, "/accessors/" + std::to_string(box.pinchAccessor) + "/sparse/indices", "increase strictly");
}

TEST(MorphRefusal, SparseIndexPastTheCount) {
    MorphBox box = morphBox();
    box.pinched.back() = 24;
    box.gltf.doc["accessors"][box.pinchAccessor]["sparse"]["indices"]["bufferView"] = box.gltf.addView(box.pinched);
    expectRefusal(box, "/accessors/" + std::to_string(box.pinchAccessor) + "/sparse/indices", "out of range");
}

TEST(MorphRefusal, PrimitivesWithDifferentTargetCounts) {
    MorphBox box = morphBox();
    nlohmann::json second = primitive(box);
    second["targets"].erase(1);
    box.gltf.doc["meshes"][0]["primitives"].push_back(second);
    expectRefusal(box, "/meshes/0/primitives/1/targets", "same targets");
}

TEST(MorphRefusal, TargetAccessorOfTheWrongTypeOrCount) {
    MorphBox box = morphBox();
    primitive(box)["targets"][0]["POSITION"] = box.gltf.addFloats({0, 0, 0, 1}, "VEC4", 4);
    expectRefusal(box, "/accessors/" + std::to_string(box.gltf.doc["accessors"].size() - 1) + "/type", "VEC3");
    box = morphBox();
    primitive(box)["targets"][0]["POSITION"] = box.gltf.addFloats({0, 0, 0, 1, 1, 1}, "VEC3", 3);
    expectRefusal(box, "/meshes/0/primitives/0/targets/0/POSITION", "has 2 elements");
}

TEST(MorphRefusal, NonFiniteDisplacement) {
    MorphBox box = morphBox();
    std::vector<float> values = box.pinchValues;
    values[4] = std::nanf("");
    box.gltf.doc["accessors"][box.pinchAccessor]["sparse"]["values"]["bufferView"] = box.gltf.addView(values);
    expectRefusal(box, "/accessors/" + std::to_string(box.pinchAccessor), "not finite");
}

TEST(MorphRefusal, DisplacementOutsideTheDeclaredBounds) {
    MorphBox box = morphBox();
    box.gltf.doc["accessors"][box.stretchAccessor]["max"] = {0.0, 0.25, 0.0};
    expectRefusal(box, "/accessors/" + std::to_string(box.stretchAccessor) + "/max", "outside the declared maximum");
}

TEST(MorphRefusal, TargetAttributeTheBaseLacks) {
    MorphBox box = morphBox();
    primitive(box)["attributes"].erase("NORMAL");
    expectRefusal(box, "/meshes/0/primitives/0/targets/1/NORMAL", "no NORMAL");
}

TEST(MorphRefusal, WeightsNotOnePerTarget) {
    MorphBox box = morphBox();
    box.gltf.doc["meshes"][0]["weights"] = {0.5, 0.5, 0.5};
    expectRefusal(box, "/meshes/0/weights", "one weight per target");
    box = morphBox();
    box.gltf.doc["nodes"][0]["weights"] = nlohmann::json::array({0.5});
    expectRefusal(box, "/nodes/0/weights", "one weight per target");
}

TEST(MorphRefusal, TargetNamesNotOneStringPerTarget) {
    MorphBox box = morphBox();
    box.gltf.doc["meshes"][0]["extras"]["targetNames"] = nlohmann::json::array({"stretch"});
    expectRefusal(box, "/meshes/0/extras/targetNames", "2 names");
    box = morphBox();
    box.gltf.doc["meshes"][0]["extras"]["targetNames"] = {"stretch", 7};
    expectRefusal(box, "/meshes/0/extras/targetNames/1", "string");
}

TEST(MorphRefusal, WeightsChannelWithTheWrongValueCount) {
    MorphBox box = morphBox();
    const int output = box.gltf.addFloats({0, 0, 1}, "SCALAR", 1);
    box.gltf.doc["animations"][0]["samplers"][0]["output"] = output;
    expectRefusal(box, "/animations/0/samplers/0/output", "2 keys x 2 morph targets");
}

TEST(MorphRefusal, WeightsChannelOnANodeWithoutTargets) {
    MorphBox box = morphBox();
    primitive(box).erase("targets");
    box.gltf.doc["meshes"][0].erase("weights");
    box.gltf.doc["meshes"][0].erase("extras");
    expectRefusal(box, "/animations/0/channels/0/target/node", "without morph targets");
}

}  // namespace
