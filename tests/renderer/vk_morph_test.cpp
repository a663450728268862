// Morph targets on the GPU (shaders/mesh_vertex.glsl with MORPH), under
// VK_LAYER_KHRONOS_validation like every Vulkan test: golden images of the morph box
// (tests/renderer/morph_test_files.hpp, loaded through the glTF loader: dense and sparse
// targets, a NORMAL target) at weights 0, 0.5 and 1 and its weights animation, and a skinned
// cylinder with a morph target (morph first, then skin).
#include "renderer/gltf_loader.hpp"
#include "renderer/procedural.hpp"
#include "renderer/renderer.hpp"
#include "tests/renderer/morph_test_files.hpp"
#include "tests/renderer/vk_golden.hpp"

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace signstim::render {
namespace {

using testing::compareWithGolden;

class VulkanMorphTest : public ::testing::Test {
protected:
    void SetUp() override {
        RendererOptions options;
        options.width = options.height = 256;
        options.validation = true;
        renderer_ = std::make_unique<Renderer>(options);
    }
    void TearDown() override {
        for (const auto& message : renderer_->validationMessages()) ADD_FAILURE() << "validation: " << message;
    }
    Image render(int handle, const Camera& camera, Pose pose) {
        Frame frame;
        View view;
        view.scene = handle;
        view.camera = camera;
        view.pose = std::move(pose);
        frame.views.push_back(view);
        Image image;
        renderer_->render(frame, image);
        return image;
    }
    std::unique_ptr<Renderer> renderer_;
};

Pose named(float stretch, float pinch) {
    Pose pose;
    pose.morphByName = {{"stretch", stretch}, {"pinch", pinch}};
    return pose;
}

TEST_F(VulkanMorphTest, MorphBoxAtWeightsZeroHalfAndOneMatchesGoldens) {
    testing::MorphBox box = testing::morphBox();
    const Scene scene = loadGltf(box.gltf.write(testing::freshTestDir("vk_morph"), "box.gltf",
                                                testing::Container::Embedded));
    const int handle = renderer_->addScene(scene);
    // One camera, framed on the fully morphed box, so the shape is what changes.
    const Camera camera = frameBounds(computeBounds(scene, named(1, 1)), 1.0f);
    const Image zero = render(handle, camera, Pose{});
    const Image half = render(handle, camera, named(0.5f, 0.5f));
    Pose byIndex;
    byIndex.morphWeights = {{1.0f, 1.0f}};
    const Image one = render(handle, camera, byIndex);
    EXPECT_EQ(compareWithGolden(zero, "morph_box_w0"), "");
    EXPECT_EQ(compareWithGolden(half, "morph_box_w05"), "");
    EXPECT_EQ(compareWithGolden(one, "morph_box_w1"), "");
    EXPECT_NE(zero.bytes, half.bytes);
    EXPECT_NE(half.bytes, one.bytes);
    // A name the mesh lacks changes nothing; a weight beyond the range is clamped to it.
    Pose unknown;
    unknown.morphByName = {{"browInnerUp", 1.0f}};
    EXPECT_EQ(render(handle, camera, unknown).bytes, zero.bytes);
    EXPECT_EQ(render(handle, camera, named(7.0f, 3.0f)).bytes, one.bytes);
}

TEST_F(VulkanMorphTest, WeightsAnimationSampledAtTwoTimesMatchesGoldenAndStaticWeights) {
    testing::MorphBox box = testing::morphBox();
    const Scene scene = loadGltf(box.gltf.write(testing::freshTestDir("vk_morph"), "box.gltf",
                                                testing::Container::Embedded));
    const int handle = renderer_->addScene(scene);
    const Camera camera = frameBounds(computeBounds(scene, named(1, 1)), 1.0f);
    auto at = [&](float t) {
        Pose pose = restPose(scene);
        applyAnimation(scene, scene.findAnimation("morph"), t, pose);
        return render(handle, camera, pose);
    };
    const Image quarter = at(0.25f);
    EXPECT_EQ(compareWithGolden(quarter, "morph_box_anim_t025"), "");
    // The channel is LINEAR from 0 to 1 over 1 s: at 0.5 s it is the box at weights 0.5.
    EXPECT_EQ(at(0.5f).bytes, render(handle, camera, named(0.5f, 0.5f)).bytes);
    EXPECT_NE(quarter.bytes, at(0.5f).bytes);
}

// procedural::skinnedCylinder with one target "bulge": the upper segment's middle (bind
// space y 1.3..1.9 m) swells by up to 8 cm. glTF morphs before skinning, so when "upper"
// bends 90 degrees the bulge bends with it.
Scene bulgingCylinder() {
    Scene scene = procedural::skinnedCylinder();
    for (Primitive& primitive : scene.meshes[0].primitives) {
        MorphTarget bulge;
        for (const Vertex& v : primitive.vertices) {
            const float s = std::clamp((v.position.y - 1.3f) / 0.6f, 0.0f, 1.0f);
            const float amount = 0.08f * std::sin(glm::pi<float>() * s);
            bulge.position.push_back(glm::vec3(v.normal.x, 0.0f, v.normal.z) * amount);
        }
        primitive.targets = {bulge};
    }
    scene.meshes[0].weights = {0.0f};
    scene.meshes[0].targetNames = {"bulge"};
    return scene;
}

TEST_F(VulkanMorphTest, SkinnedAndMorphedCylinderBendsWithItsBulge) {
    const Scene scene = bulgingCylinder();
    const int handle = renderer_->addScene(scene);
    Pose bent = restPose(scene);
    applyAnimation(scene, scene.findAnimation("bend"), 1.0f, bent);
    const Camera camera = frameBounds(computeBounds(scene, restPose(scene)), 1.0f);
    Pose bulging = bent;
    bulging.morphByName = {{"bulge", 1.0f}};
    const Image image = render(handle, camera, bulging);
    EXPECT_EQ(compareWithGolden(image, "morph_skinned_cylinder"), "");
    // Weight 0 draws without the morph pipeline: the plain skinned cylinder's golden.
    EXPECT_EQ(compareWithGolden(render(handle, camera, bent), "skinned_cylinder_t1"), "");
    EXPECT_NE(image.bytes, render(handle, camera, bent).bytes);
}

}  // namespace
}  // namespace signstim::render
