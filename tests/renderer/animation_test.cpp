// Animation sampling of hand-written glTF files against hand-computed values.
#include "renderer/gltf_loader.hpp"
#include "renderer/scene.hpp"

#include "gltf_test_files.hpp"

#include <gtest/gtest.h>
#include <glm/gtc/quaternion.hpp>

using namespace signstim::render;
using namespace signstim::render::testing;
namespace fs = std::filesystem;

namespace {

fs::path testDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path dir = fs::path(SIGNSTIM_BINARY_DIR) / "test-tmp" / "animation" / info->name();
    fs::remove_all(dir);
    return dir;
}

// Node 0 animated by one channel; `values` are floats of `type` (VEC3 or VEC4).
Scene animatedScene(const char* path, const char* interpolation, const std::vector<float>& times,
                    const std::vector<float>& values, const char* type, std::size_t width) {
    GltfBuilder b = triangleGltf();
    const int input = b.addFloats(times, "SCALAR", 1);
    const int output = b.addFloats(values, type, width);
    nlohmann::json sampler = {{"input", input}, {"output", output}, {"interpolation", interpolation}};
    nlohmann::json channel = {{"sampler", 0}, {"target", {{"node", 0}, {"path", path}}}};
    nlohmann::json animation = {{"name", "move"}};
    animation["samplers"] = nlohmann::json::array({sampler});
    animation["channels"] = nlohmann::json::array({channel});
    b.doc["animations"] = nlohmann::json::array({animation});
    return loadGltf(b.write(testDir(), "anim.gltf", Container::Embedded));
}

Trs sampleAt(const Scene& scene, float t) {
    Pose pose = restPose(scene);
    applyAnimation(scene, 0, t, pose);
    return pose.local[0];
}

void expectNear(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

}  // namespace

TEST(Animation, LinearTranslationInterpolatesAndClamps) {
    const Scene scene = animatedScene("translation", "LINEAR", {0, 1, 2}, {0, 0, 0, 2, 0, 0, 2, 4, 0}, "VEC3", 3);
    EXPECT_EQ(scene.animations[0].name, "move");
    EXPECT_FLOAT_EQ(scene.animations[0].durationSeconds, 2.0f);
    EXPECT_EQ(scene.findAnimation("move"), 0);
    expectNear(sampleAt(scene, 0.5f).translation, {1, 0, 0});
    expectNear(sampleAt(scene, 1.0f).translation, {2, 0, 0});
    expectNear(sampleAt(scene, 1.25f).translation, {2, 1, 0});
    expectNear(sampleAt(scene, -3.0f).translation, {0, 0, 0});
    expectNear(sampleAt(scene, 9.0f).translation, {2, 4, 0});
}

TEST(Animation, StepHoldsThePreviousKey) {
    const Scene scene = animatedScene("scale", "STEP", {0, 1, 2}, {1, 1, 1, 2, 2, 2, 3, 3, 3}, "VEC3", 3);
    expectNear(sampleAt(scene, 0.99f).scale, {1, 1, 1});
    expectNear(sampleAt(scene, 1.0f).scale, {2, 2, 2});
    expectNear(sampleAt(scene, 1.7f).scale, {2, 2, 2});
    expectNear(sampleAt(scene, 2.0f).scale, {3, 3, 3});
}

TEST(Animation, LinearRotationIsSlerp) {
    // Identity to 90° about Z, written unnormalised (x2) to check the loader normalises keys.
    const float s = std::sqrt(0.5f);
    const Scene scene = animatedScene("rotation", "LINEAR", {0, 1}, {0, 0, 0, 2, 0, 0, 2 * s, 2 * s}, "VEC4", 4);
    const glm::quat q = sampleAt(scene, 0.5f).rotation;
    // Slerp halfway: 45° about Z. A normalised lerp gives the same angle at 0.5, so also
    // check 0.25 where they differ: slerp 22.5°, nlerp ~ 20.6°.
    expectNear(q * glm::vec3(1, 0, 0), {std::cos(glm::radians(45.0f)), std::sin(glm::radians(45.0f)), 0});
    const glm::quat quarter = sampleAt(scene, 0.25f).rotation;
    expectNear(quarter * glm::vec3(1, 0, 0), {std::cos(glm::radians(22.5f)), std::sin(glm::radians(22.5f)), 0});
}

TEST(Animation, LinearRotationTakesTheShortWay) {
    // Second key is the same 90° rotation written as -q: the path must still be 45° at 0.5.
    const float s = std::sqrt(0.5f);
    const Scene scene = animatedScene("rotation", "LINEAR", {0, 1}, {0, 0, 0, 1, 0, 0, -s, -s}, "VEC4", 4);
    const glm::quat q = sampleAt(scene, 0.5f).rotation;
    expectNear(q * glm::vec3(1, 0, 0), {std::cos(glm::radians(45.0f)), std::sin(glm::radians(45.0f)), 0});
}

TEST(Animation, CubicSplineFollowsHermiteBasis) {
    // Keys t=0: v=(0,0,0), out-tangent (3,0,0); t=2: v=(2,0,0), in-tangent (0,0,0).
    // At t=1 (u=0.5, dt=2): h00=0.5, h10=0.125, h01=0.5, h11=-0.125
    //   x = 0.125*2*3 + 0.5*2 = 1.75.  At t=0.5 (u=0.25): h10=0.140625, h01=0.15625
    //   x = 0.140625*2*3 + 0.15625*2 = 1.15625.
    const Scene scene = animatedScene("translation", "CUBICSPLINE", {0, 2},
                                      {9, 9, 9, 0, 0, 0, 3, 0, 0, /**/ 0, 0, 0, 2, 0, 0, 9, 9, 9}, "VEC3", 3);
    EXPECT_NEAR(sampleAt(scene, 1.0f).translation.x, 1.75f, 1e-5f);
    EXPECT_NEAR(sampleAt(scene, 0.5f).translation.x, 1.15625f, 1e-5f);
    expectNear(sampleAt(scene, 0.0f).translation, {0, 0, 0});  // tangents never leak at keys
    expectNear(sampleAt(scene, 2.0f).translation, {2, 0, 0});
}

TEST(Animation, UndrivenChannelsKeepThePose) {
    const Scene scene = animatedScene("translation", "LINEAR", {0, 1}, {0, 0, 0, 1, 0, 0}, "VEC3", 3);
    Pose pose = restPose(scene);
    pose.local[0].scale = glm::vec3(5.0f);
    applyAnimation(scene, 0, 0.5f, pose);
    expectNear(pose.local[0].scale, {5, 5, 5});
    Pose empty;
    applyAnimation(scene, 0, 0.5f, empty);
    ASSERT_EQ(empty.local.size(), scene.nodes.size());
    expectNear(empty.local[0].translation, {0.5f, 0, 0});
}
