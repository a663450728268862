// glTF writer: write -> load gives the same scene; output is byte-identical per scene.
#include "renderer/gltf_loader.hpp"
#include "renderer/gltf_writer.hpp"

#include "common/error.hpp"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <fstream>
#include <sstream>

using namespace signstim;
using namespace signstim::render;
namespace fs = std::filesystem;

namespace {

fs::path testDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path dir = fs::path(SIGNSTIM_BINARY_DIR) / "test-tmp" / "gltf_writer" / info->name();
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// A small skinned, textured, animated scene (synthetic).
Scene richScene() {
    Scene scene;
    scene.nodes.resize(4);
    scene.nodes[0].name = "root";
    scene.nodes[0].children = {1, 3};
    scene.nodes[0].rest.translation = {0.1f, 0.2f, 0.3f};
    scene.nodes[1].name = "bone";
    scene.nodes[1].parent = 0;
    scene.nodes[1].children = {2};
    scene.nodes[1].rest.rotation = glm::angleAxis(0.3f, glm::normalize(glm::vec3(1, 2, 3)));
    scene.nodes[2].name = "tip";
    scene.nodes[2].parent = 1;
    scene.nodes[2].rest.scale = {1, 2, 1};
    scene.nodes[3].name = "body";
    scene.nodes[3].parent = 0;
    scene.nodes[3].mesh = 0;
    scene.nodes[3].skin = 0;
    scene.nodes[3].restMatrix = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 1));
    scene.nodes[3].rest.translation = {0, 0, 1};
    scene.roots = {0};

    Primitive p;
    p.skinned = true;
    p.material = 0;
    for (int i = 0; i < 4; ++i) {
        Vertex v;
        v.position = {float(i % 2), float(i / 2), 0.25f * i};
        v.normal = glm::normalize(glm::vec3(0.1f * i, 0.2f, 1.0f));
        v.uv = {0.5f * i, 1.0f - 0.25f * i};
        v.joints = {0, 1, 2, 0};
        v.weights = {0.5f, 0.25f, 0.25f, 0.0f};
        p.vertices.push_back(v);
    }
    p.indices = {0, 1, 2, 2, 1, 3};
    scene.meshes.push_back(Mesh{"quad", {p}});

    ImageData image;
    image.name = "checker";
    image.width = 2;
    image.height = 2;
    image.rgba = {255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 255, 10, 20, 30, 40};
    scene.images.push_back(image);
    Texture texture;
    texture.image = 0;
    texture.magFilter = Filter::Nearest;
    texture.wrapS = Wrap::ClampToEdge;
    texture.wrapT = Wrap::MirroredRepeat;
    scene.textures.push_back(texture);
    Material material;
    material.name = "skin";
    material.baseColorFactor = {0.8f, 0.6f, 0.5f, 1.0f};
    material.baseColorTexture = 0;
    material.metallicFactor = 0.0f;
    material.roughnessFactor = 0.7f;
    material.alphaMode = AlphaMode::Mask;
    material.alphaCutoff = 0.3f;
    material.doubleSided = true;
    scene.materials.push_back(material);

    Skin skin;
    skin.name = "arm";
    skin.joints = {0, 1, 2};
    skin.inverseBindMatrices = {glm::mat4(1.0f), glm::translate(glm::mat4(1.0f), glm::vec3(0, -1, 0)),
                                glm::scale(glm::mat4(1.0f), glm::vec3(2.0f))};
    skin.skeleton = 0;
    scene.skins.push_back(skin);

    Animation animation;
    animation.name = "wave";
    AnimationSampler linear{{0.0f, 0.5f, 1.0f}, {{0, 0, 0, 0}, {1, 0, 0, 0}, {1, 1, 0, 0}}, Interpolation::Linear};
    AnimationSampler step{{0.0f, 2.0f}, {{1, 1, 1, 0}, {2, 2, 2, 0}}, Interpolation::Step};
    const glm::quat q = glm::angleAxis(1.0f, glm::vec3(0, 0, 1));
    AnimationSampler cubic{{0.0f, 1.5f},
                           {{0, 0, 0, 0}, {0, 0, 0, 1}, {0, 0, 0.1f, 0}, {0, 0, 0.2f, 0}, {q.x, q.y, q.z, q.w}, {0, 0, 0, 0}},
                           Interpolation::CubicSpline};
    animation.samplers = {linear, step, cubic};
    animation.channels = {{1, AnimationPath::Translation, 0}, {2, AnimationPath::Scale, 1}, {1, AnimationPath::Rotation, 2}};
    animation.durationSeconds = 2.0f;
    scene.animations.push_back(animation);
    return scene;
}

void expectVecNear(const glm::vec4& a, const glm::vec4& b, const std::string& what) {
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(a[i], b[i], 1e-6f) << what << "[" << i << "]";
}

void expectSameScene(const Scene& a, const Scene& b) {
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    for (std::size_t i = 0; i < a.nodes.size(); ++i) {
        const Node &x = a.nodes[i], &y = b.nodes[i];
        EXPECT_EQ(x.name, y.name);
        EXPECT_EQ(x.parent, y.parent);
        EXPECT_EQ(x.children, y.children);
        EXPECT_EQ(x.mesh, y.mesh);
        EXPECT_EQ(x.skin, y.skin);
        EXPECT_EQ(x.restMatrix.has_value(), y.restMatrix.has_value());
        expectVecNear(glm::vec4(x.rest.translation, 0), glm::vec4(y.rest.translation, 0), "translation");
        expectVecNear(glm::vec4(x.rest.scale, 0), glm::vec4(y.rest.scale, 0), "scale");
        EXPECT_NEAR(std::abs(glm::dot(x.rest.rotation, y.rest.rotation)), 1.0f, 1e-6f);
    }
    EXPECT_EQ(a.roots, b.roots);
    ASSERT_EQ(a.meshes.size(), b.meshes.size());
    for (std::size_t m = 0; m < a.meshes.size(); ++m) {
        EXPECT_EQ(a.meshes[m].name, b.meshes[m].name);
        ASSERT_EQ(a.meshes[m].primitives.size(), b.meshes[m].primitives.size());
        for (std::size_t p = 0; p < a.meshes[m].primitives.size(); ++p) {
            const Primitive &x = a.meshes[m].primitives[p], &y = b.meshes[m].primitives[p];
            EXPECT_EQ(x.indices, y.indices);
            EXPECT_EQ(x.material, y.material);
            EXPECT_EQ(x.skinned, y.skinned);
            ASSERT_EQ(x.vertices.size(), y.vertices.size());
            for (std::size_t v = 0; v < x.vertices.size(); ++v) {
                expectVecNear(glm::vec4(x.vertices[v].position, 0), glm::vec4(y.vertices[v].position, 0), "position");
                expectVecNear(glm::vec4(x.vertices[v].normal, 0), glm::vec4(y.vertices[v].normal, 0), "normal");
                expectVecNear(glm::vec4(x.vertices[v].uv, 0, 0), glm::vec4(y.vertices[v].uv, 0, 0), "uv");
                EXPECT_EQ(x.vertices[v].joints, y.vertices[v].joints);
                expectVecNear(x.vertices[v].weights, y.vertices[v].weights, "weights");
            }
        }
    }
    ASSERT_EQ(a.images.size(), b.images.size());
    for (std::size_t i = 0; i < a.images.size(); ++i) {
        EXPECT_EQ(a.images[i].name, b.images[i].name);
        EXPECT_EQ(a.images[i].width, b.images[i].width);
        EXPECT_EQ(a.images[i].rgba, b.images[i].rgba);
    }
    ASSERT_EQ(a.textures.size(), b.textures.size());
    for (std::size_t i = 0; i < a.textures.size(); ++i) {
        EXPECT_EQ(a.textures[i].image, b.textures[i].image);
        EXPECT_EQ(a.textures[i].magFilter, b.textures[i].magFilter);
        EXPECT_EQ(a.textures[i].minFilter, b.textures[i].minFilter);
        EXPECT_EQ(a.textures[i].mipmaps, b.textures[i].mipmaps);
        EXPECT_EQ(a.textures[i].wrapS, b.textures[i].wrapS);
        EXPECT_EQ(a.textures[i].wrapT, b.textures[i].wrapT);
    }
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (std::size_t i = 0; i < a.materials.size(); ++i) {
        const Material &x = a.materials[i], &y = b.materials[i];
        EXPECT_EQ(x.name, y.name);
        expectVecNear(x.baseColorFactor, y.baseColorFactor, "baseColorFactor");
        EXPECT_EQ(x.baseColorTexture, y.baseColorTexture);
        EXPECT_FLOAT_EQ(x.metallicFactor, y.metallicFactor);
        EXPECT_FLOAT_EQ(x.roughnessFactor, y.roughnessFactor);
        EXPECT_EQ(x.alphaMode, y.alphaMode);
        EXPECT_FLOAT_EQ(x.alphaCutoff, y.alphaCutoff);
        EXPECT_EQ(x.doubleSided, y.doubleSided);
    }
    ASSERT_EQ(a.skins.size(), b.skins.size());
    for (std::size_t i = 0; i < a.skins.size(); ++i) {
        EXPECT_EQ(a.skins[i].joints, b.skins[i].joints);
        EXPECT_EQ(a.skins[i].skeleton, b.skins[i].skeleton);
        EXPECT_EQ(a.skins[i].inverseBindMatrices, b.skins[i].inverseBindMatrices);
    }
    ASSERT_EQ(a.animations.size(), b.animations.size());
    for (std::size_t i = 0; i < a.animations.size(); ++i) {
        const Animation &x = a.animations[i], &y = b.animations[i];
        EXPECT_EQ(x.name, y.name);
        EXPECT_FLOAT_EQ(x.durationSeconds, y.durationSeconds);
        ASSERT_EQ(x.samplers.size(), y.samplers.size());
        for (std::size_t s = 0; s < x.samplers.size(); ++s) {
            EXPECT_EQ(x.samplers[s].times, y.samplers[s].times);
            EXPECT_EQ(x.samplers[s].interpolation, y.samplers[s].interpolation);
            ASSERT_EQ(x.samplers[s].values.size(), y.samplers[s].values.size());
            for (std::size_t v = 0; v < x.samplers[s].values.size(); ++v)
                expectVecNear(x.samplers[s].values[v], y.samplers[s].values[v], "animation value");
        }
        ASSERT_EQ(x.channels.size(), y.channels.size());
        for (std::size_t c = 0; c < x.channels.size(); ++c) {
            EXPECT_EQ(x.channels[c].node, y.channels[c].node);
            EXPECT_EQ(x.channels[c].path, y.channels[c].path);
            EXPECT_EQ(x.channels[c].sampler, y.channels[c].sampler);
        }
    }
}

}  // namespace

TEST(GltfWriter, EmbeddedGltfRoundTrips) {
    const Scene scene = richScene();
    const fs::path path = testDir() / "rich.gltf";
    writeGltf(scene, path);
    expectSameScene(scene, loadGltf(path));
}

TEST(GltfWriter, GlbRoundTrips) {
    const Scene scene = richScene();
    const fs::path path = testDir() / "rich.glb";
    writeGltf(scene, path);
    expectSameScene(scene, loadGltf(path));
}

TEST(GltfWriter, OutputIsByteIdenticalForTheSameScene) {
    const fs::path dir = testDir();
    for (const char* name : {"a.glb", "b.glb", "a.gltf", "b.gltf"}) writeGltf(richScene(), dir / name);
    EXPECT_TRUE(slurp(dir / "a.glb") == slurp(dir / "b.glb"));
    EXPECT_TRUE(slurp(dir / "a.gltf") == slurp(dir / "b.gltf"));
    // Not a fixed point through the loader: it renormalises normals (1-ulp changes).
}

TEST(GltfWriter, RefusesUnknownExtensionAndLeavesNoTemporary) {
    const fs::path dir = testDir();
    EXPECT_THROW(writeGltf(richScene(), dir / "x.obj"), InputError);
    EXPECT_TRUE(fs::is_empty(dir));
}
