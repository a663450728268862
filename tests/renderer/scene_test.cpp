// CPU scene maths: TRS order, hierarchy, joint matrices, skinned bounds, camera framing.
#include "renderer/frame.hpp"
#include "renderer/scene.hpp"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

using namespace signstim::render;

namespace {

void expectNear(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

// Two-node chain: root translated by (1,0,0) and rotated 90° about Z, child at (0,2,0).
Scene chainScene() {
    Scene scene;
    scene.nodes.resize(2);
    scene.nodes[0].name = "root";
    scene.nodes[0].children = {1};
    scene.nodes[0].rest.translation = {1, 0, 0};
    scene.nodes[0].rest.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
    scene.nodes[1].name = "tip";
    scene.nodes[1].parent = 0;
    scene.nodes[1].rest.translation = {0, 2, 0};
    scene.roots = {0};
    return scene;
}

}  // namespace

TEST(Scene, TrsAppliesScaleThenRotationThenTranslation) {
    Trs trs;
    trs.translation = {1, 2, 3};
    trs.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
    trs.scale = {2, 1, 1};
    // (1,0,0) scaled -> (2,0,0), rotated -> (0,2,0), translated -> (1,4,3).
    expectNear(glm::vec3(trs.matrix() * glm::vec4(1, 0, 0, 1)), {1, 4, 3});
}

TEST(Scene, FindsNodesAndAnimationsByName) {
    Scene scene = chainScene();
    scene.animations.resize(2);
    scene.animations[1].name = "wave";
    EXPECT_EQ(scene.findNode("tip"), 1);
    EXPECT_EQ(scene.findNode("nope"), -1);
    EXPECT_EQ(scene.findAnimation("wave"), 1);
    EXPECT_EQ(scene.findAnimation("nope"), -1);
}

TEST(Scene, ChildWorldTransformComposesParent) {
    const Scene scene = chainScene();
    std::vector<glm::mat4> world;
    computeWorldTransforms(scene, restPose(scene), world);
    ASSERT_EQ(world.size(), 2u);
    // Child origin: parent rotates (0,2,0) to (-2,0,0), then adds (1,0,0).
    expectNear(glm::vec3(world[1][3]), {-1, 0, 0});
}

TEST(Scene, RestMatrixIsKeptUnlessPoseOverridesIt) {
    Scene scene = chainScene();
    scene.nodes[1].restMatrix = glm::translate(glm::mat4(1.0f), glm::vec3(0, 5, 0));
    Pose pose = restPose(scene);
    ASSERT_TRUE(pose.useRestMatrix[1]);
    std::vector<glm::mat4> world;
    computeWorldTransforms(scene, pose, world);
    expectNear(glm::vec3(world[1][3]), {-4, 0, 0});
    pose.useRestMatrix[1] = false;
    computeWorldTransforms(scene, pose, world);
    expectNear(glm::vec3(world[1][3]), {-1, 0, 0});
}

TEST(Scene, EmptyPoseMeansRestPose) {
    const Scene scene = chainScene();
    std::vector<glm::mat4> world;
    computeWorldTransforms(scene, Pose{}, world);
    expectNear(glm::vec3(world[1][3]), {-1, 0, 0});
}

TEST(Scene, JointMatrixIsWorldTimesInverseBind) {
    Scene scene = chainScene();
    Skin skin;
    skin.joints = {0, 1};
    skin.inverseBindMatrices = {glm::mat4(1.0f), glm::translate(glm::mat4(1.0f), glm::vec3(0, -2, 0))};
    scene.skins.push_back(skin);
    std::vector<glm::mat4> world, joints;
    computeWorldTransforms(scene, restPose(scene), world);
    computeJointMatrices(scene, 0, world, joints);
    ASSERT_EQ(joints.size(), 2u);
    // A vertex bound at (0,2,0) to joint 1 sits at the tip's world origin.
    expectNear(glm::vec3(joints[1] * glm::vec4(0, 2, 0, 1)), {-1, 0, 0});
    computeJointMatrices(scene, 7, world, joints);
    EXPECT_TRUE(joints.empty());
}

TEST(Scene, BoundsFollowSkinnedVertices) {
    Scene scene;
    scene.nodes.resize(3);
    scene.nodes[0].children = {1};
    scene.nodes[1].parent = 0;
    scene.nodes[2].mesh = 0;
    scene.nodes[2].skin = 0;
    scene.nodes[2].rest.translation = {100, 0, 0};  // ignored for skinned meshes (glTF)
    scene.roots = {0, 2};
    Skin skin;
    skin.joints = {0, 1};
    skin.inverseBindMatrices = {glm::mat4(1.0f), glm::mat4(1.0f)};
    scene.skins.push_back(skin);
    Primitive primitive;
    primitive.skinned = true;
    Vertex a, b;
    a.position = {0, 0, 0};
    a.joints = {0, 0, 0, 0};
    b.position = {0, 1, 0};
    b.joints = {1, 0, 0, 0};
    primitive.vertices = {a, b};
    scene.meshes.push_back(Mesh{"m", {primitive}});

    Pose pose = restPose(scene);
    pose.local[1].translation = {3, 0, 0};
    const Bounds bounds = computeBounds(scene, pose);
    ASSERT_FALSE(bounds.empty);
    expectNear(bounds.min, {0, 0, 0});
    expectNear(bounds.max, {3, 1, 0});
}

TEST(Scene, FramedCameraSeesEveryCornerOfTheBounds) {
    Bounds bounds;
    bounds.add({-0.5f, 0.0f, -0.2f});
    bounds.add({0.5f, 1.8f, 0.3f});
    for (float aspect : {0.5f, 1.0f, 16.0f / 9.0f}) {
        const Camera camera = frameBounds(bounds, aspect, 30.0f);
        const glm::mat4 view = glm::lookAt(camera.eye, camera.target, camera.up);
        const glm::mat4 projection = glm::perspective(glm::radians(camera.verticalFovDegrees),
                                                      aspect, camera.nearPlane, camera.farPlane);
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 c((corner & 1) ? bounds.max.x : bounds.min.x,
                              (corner & 2) ? bounds.max.y : bounds.min.y,
                              (corner & 4) ? bounds.max.z : bounds.min.z);
            const glm::vec4 clip = projection * view * glm::vec4(c, 1.0f);
            ASSERT_GT(clip.w, 0.0f);
            const glm::vec3 ndc = glm::vec3(clip) / clip.w;
            EXPECT_LE(std::abs(ndc.x), 1.0f);
            EXPECT_LE(std::abs(ndc.y), 1.0f);
            EXPECT_GE(ndc.z, 0.0f);
            EXPECT_LE(ndc.z, 1.0f);
        }
        EXPECT_LT(camera.eye.z, 10.0f);  // not absurdly far: the box fills the view
    }
}
