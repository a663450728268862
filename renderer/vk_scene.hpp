#pragma once
// GPU copy of a render::Scene: one vertex and one index buffer for all primitives, textures
// (sRGB base colour, linear metallic-roughness) with mipmaps, samplers from the glTF
// settings, and one descriptor set per material. The CPU scene is kept for posing.
#include "renderer/scene.hpp"
#include "renderer/vk_commands.hpp"
#include "renderer/vk_memory.hpp"

#include <map>
#include <utility>
#include <vector>

namespace signstim::render::vk {

// std140 layout of the material uniform block (set 1, binding 0) in shaders/mesh.frag.
struct MaterialUniform {
    glm::vec4 baseColorFactor;
    glm::vec4 emissive;     // xyz
    glm::vec4 parameters;   // metallic, roughness, alpha cutoff, alpha mode (0/1/2)
    glm::vec4 textureFlags; // x: has base colour texture, y: has metallic-roughness texture
};

struct GpuPrimitive {
    std::uint32_t firstIndex = 0, indexCount = 0;
    std::int32_t vertexOffset = 0;
    std::uint32_t material = 0;  // index into GpuScene::materials (last = default)
    bool skinned = false;
};

struct GpuMaterial {
    AlphaMode alphaMode = AlphaMode::Opaque;
    bool doubleSided = false;
    bool hasBaseColorTexture = false, hasMetallicRoughnessTexture = false;
    VkDescriptorSet set = VK_NULL_HANDLE;
};

class GpuScene {
public:
    GpuScene(const Device& device, const CommandPool& commands, Scene scene,
             VkDescriptorSetLayout materialLayout);

    const Scene& cpu() const { return cpu_; }
    VkBuffer vertexBuffer() const { return vertices_.buffer.get(); }
    VkBuffer indexBuffer() const { return indices_.buffer.get(); }
    const std::vector<GpuPrimitive>& primitives(int mesh) const {
        return meshes_[static_cast<std::size_t>(mesh)];
    }
    const GpuMaterial& material(std::uint32_t index) const { return materials_[index]; }
    const std::vector<GpuMaterial>& materials() const { return materials_; }
    std::size_t triangleCount() const { return triangles_; }

private:
    const GpuImage& textureImage(const Device& device, const CommandPool& commands, int image,
                              bool srgb);
    VkSampler sampler(const Device& device, const Texture& texture);

    Scene cpu_;
    Buffer vertices_, indices_;
    std::vector<std::vector<GpuPrimitive>> meshes_;
    std::map<std::pair<int, bool>, GpuImage> images_;  // (image index, sRGB) -> GPU image
    std::vector<UniqueSampler> samplers_;
    GpuImage whiteSrgb_, whiteLinear_;
    UniqueSampler defaultSampler_;
    std::vector<Buffer> materialUniforms_;
    UniqueDescriptorPool descriptorPool_;
    std::vector<GpuMaterial> materials_;
    std::size_t triangles_ = 0;
};

}  // namespace signstim::render::vk
