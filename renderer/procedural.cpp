#include "renderer/procedural.hpp"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace signstim::render::procedural {

namespace {

Scene singleMeshScene(std::string sourceName, std::string nodeName, Primitive primitive,
                      Material material, Trs rest = {}) {
    Scene scene;
    scene.sourceName = std::move(sourceName);
    primitive.material = 0;
    scene.materials.push_back(std::move(material));
    Mesh mesh;
    mesh.name = nodeName;
    mesh.primitives.push_back(std::move(primitive));
    scene.meshes.push_back(std::move(mesh));
    Node node;
    node.name = std::move(nodeName);
    node.mesh = 0;
    node.rest = rest;
    scene.nodes.push_back(std::move(node));
    scene.roots.push_back(0);
    return scene;
}

}  // namespace

Scene litCube() {
    Primitive primitive;
    // Each face: normal n, and two in-plane axes u, v with u x v = n (counter-clockwise).
    const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                  {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const glm::vec3& n : normals) {
        glm::vec3 u = std::abs(n.y) > 0.5f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
        u = glm::cross(u, n);  // perpendicular to n
        glm::vec3 v = glm::cross(n, u);
        const auto base = static_cast<std::uint32_t>(primitive.vertices.size());
        const glm::vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (const glm::vec2& c : corners) {
            Vertex vertex;
            vertex.position = 0.5f * (n + c.x * u + c.y * v);
            vertex.normal = n;
            vertex.uv = c * 0.5f + 0.5f;
            primitive.vertices.push_back(vertex);
        }
        for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) primitive.indices.push_back(base + i);
    }
    Material material;
    material.name = "orange";
    material.baseColorFactor = {0.85f, 0.35f, 0.08f, 1.0f};
    material.metallicFactor = 0.0f;
    material.roughnessFactor = 0.5f;
    Trs rest;
    rest.rotation = glm::angleAxis(glm::radians(20.0f), glm::vec3(1, 0, 0)) *
                    glm::angleAxis(glm::radians(-30.0f), glm::vec3(0, 1, 0));
    return singleMeshScene("procedural:cube", "cube", std::move(primitive), material, rest);
}

ImageData checkerImage(std::uint32_t size, std::uint32_t squares) {
    ImageData image;
    image.name = "checker";
    image.width = image.height = size;
    image.rgba.resize(std::size_t(size) * size * 4);
    const std::uint32_t cell = std::max<std::uint32_t>(1, size / squares);
    for (std::uint32_t y = 0; y < size; ++y) {
        for (std::uint32_t x = 0; x < size; ++x) {
            const bool light = ((x / cell) + (y / cell)) % 2 == 0;
            std::uint8_t* p = &image.rgba[(std::size_t(y) * size + x) * 4];
            p[0] = light ? 235 : 30;
            p[1] = light ? 230 : 60;
            p[2] = light ? 220 : 140;
            p[3] = 255;
        }
    }
    return image;
}

Scene texturedQuad() {
    Primitive primitive;
    const glm::vec2 corners[4] = {{-0.5f, -0.5f}, {0.5f, -0.5f}, {0.5f, 0.5f}, {-0.5f, 0.5f}};
    for (const glm::vec2& c : corners) {
        Vertex vertex;
        vertex.position = {c.x, c.y, 0.0f};
        vertex.normal = {0, 0, 1};
        vertex.uv = {c.x + 0.5f, 0.5f - c.y};  // glTF: v grows downwards in the image
        primitive.vertices.push_back(vertex);
    }
    primitive.indices = {0, 1, 2, 0, 2, 3};
    Material material;
    material.name = "checker";
    material.baseColorTexture = 0;
    material.metallicFactor = 0.0f;
    material.roughnessFactor = 0.8f;
    material.doubleSided = true;
    Scene scene = singleMeshScene("procedural:quad", "quad", std::move(primitive), material);
    scene.images.push_back(checkerImage(64, 8));
    Texture texture;
    texture.image = 0;
    scene.textures.push_back(texture);
    return scene;
}

Scene skinnedCylinder() {
    constexpr int kSegments = 32, kRings = 40;
    constexpr float kRadius = 0.15f, kLength = 2.0f, kJoint = 1.0f, kBlend = 0.3f;
    Primitive primitive;
    primitive.skinned = true;
    for (int ring = 0; ring <= kRings; ++ring) {
        const float y = kLength * float(ring) / kRings;
        // Smoothstep from the lower to the upper joint around the joint height.
        float t = std::clamp((y - (kJoint - kBlend)) / (2 * kBlend), 0.0f, 1.0f);
        t = t * t * (3 - 2 * t);
        for (int s = 0; s <= kSegments; ++s) {
            const float angle = glm::two_pi<float>() * float(s) / kSegments;
            Vertex vertex;
            vertex.normal = {std::cos(angle), 0.0f, -std::sin(angle)};
            vertex.position = glm::vec3(kRadius * vertex.normal.x, y, kRadius * vertex.normal.z);
            vertex.uv = {float(s) / kSegments, float(ring) / kRings};
            vertex.joints = {0, 1, 0, 0};
            vertex.weights = {1.0f - t, t, 0.0f, 0.0f};
            primitive.vertices.push_back(vertex);
        }
    }
    for (int ring = 0; ring < kRings; ++ring) {
        for (int s = 0; s < kSegments; ++s) {
            const auto a = static_cast<std::uint32_t>(ring * (kSegments + 1) + s);
            const auto b = a + kSegments + 1;
            // Counter-clockwise seen from outside.
            for (std::uint32_t i : {a, a + 1, b + 1, a, b + 1, b}) primitive.indices.push_back(i);
        }
    }
    Material material;
    material.name = "skin-tone";
    material.baseColorFactor = {0.80f, 0.55f, 0.42f, 1.0f};
    material.metallicFactor = 0.0f;
    material.roughnessFactor = 0.6f;
    Scene scene = singleMeshScene("procedural:skinned-cylinder", "cylinder", std::move(primitive),
                                  material);
    scene.nodes[0].skin = 0;

    Node lower;
    lower.name = "lower";
    lower.children = {2};
    Node upper;
    upper.name = "upper";
    upper.parent = 1;
    upper.rest.translation = {0.0f, kJoint, 0.0f};
    scene.nodes.push_back(lower);
    scene.nodes.push_back(upper);
    scene.roots.push_back(1);

    Skin skin;
    skin.name = "two-bone";
    skin.joints = {1, 2};
    skin.inverseBindMatrices = {glm::mat4(1.0f),
                                glm::translate(glm::mat4(1.0f), glm::vec3(0, -kJoint, 0))};
    skin.skeleton = 1;
    scene.skins.push_back(skin);

    Animation animation;
    animation.name = "bend";
    AnimationSampler sampler;
    sampler.times = {0.0f, 1.0f};
    const glm::quat bent = glm::angleAxis(glm::half_pi<float>(), glm::vec3(0, 0, 1));
    sampler.values = {glm::vec4(0, 0, 0, 1), glm::vec4(bent.x, bent.y, bent.z, bent.w)};
    animation.samplers.push_back(sampler);
    animation.channels.push_back({2, AnimationPath::Rotation, 0});
    animation.durationSeconds = 1.0f;
    scene.animations.push_back(animation);
    return scene;
}

Scene uvSphere(std::uint32_t triangles) {
    // 2 * rings * segments triangles with segments = 2 * rings (poles included as quads
    // with a degenerate edge keep the count exact and the code short).
    const auto rings = std::max<std::uint32_t>(
        2, static_cast<std::uint32_t>(std::lround(std::sqrt(triangles / 4.0))));
    const std::uint32_t segments = 2 * rings;
    Primitive primitive;
    for (std::uint32_t r = 0; r <= rings; ++r) {
        const float theta = glm::pi<float>() * float(r) / rings;
        for (std::uint32_t s = 0; s <= segments; ++s) {
            const float phi = glm::two_pi<float>() * float(s) / segments;
            Vertex vertex;
            vertex.normal = {std::sin(theta) * std::cos(phi), std::cos(theta),
                             -std::sin(theta) * std::sin(phi)};
            vertex.position = 0.5f * vertex.normal;
            vertex.uv = {float(s) / segments, float(r) / rings};
            primitive.vertices.push_back(vertex);
        }
    }
    for (std::uint32_t r = 0; r < rings; ++r) {
        for (std::uint32_t s = 0; s < segments; ++s) {
            const std::uint32_t a = r * (segments + 1) + s, b = a + segments + 1;
            for (std::uint32_t i : {a, b, b + 1, a, b + 1, a + 1}) primitive.indices.push_back(i);
        }
    }
    Material material;
    material.name = "grey";
    material.baseColorFactor = {0.7f, 0.7f, 0.72f, 1.0f};
    material.metallicFactor = 0.0f;
    material.roughnessFactor = 0.5f;
    return singleMeshScene("procedural:uv-sphere", "sphere", std::move(primitive), material);
}

}  // namespace signstim::render::procedural
