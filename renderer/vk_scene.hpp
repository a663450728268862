#pragma once
// GPU copy of a render::Scene: one vertex and one index buffer for all primitives, textures
// (sRGB base colour, linear metallic-roughness) with mipmaps, samplers from the glTF
// settings, one descriptor set per material (its textures) and its specialisation constants. The CPU scene is kept for posing.
#include "renderer/scene.hpp"
#include "renderer/vk_commands.hpp"
#include "renderer/vk_memory.hpp"
#include "renderer/vk_pipelines.hpp"

#include <map>
#include <utility>
#include <vector>

namespace signstim::render {
struct Lighting;
}

namespace signstim::render::vk {

// Specialisation constants of shaders/mesh.frag: ids 0..36, 4 bytes each, in this order.
// The material part comes from materialConstants(); the Renderer fills in the lighting.
struct FragmentConstants {
    VkBool32 hasBaseColorTexture = VK_FALSE, hasMetallicRoughnessTexture = VK_FALSE;  // 0, 1
    VkBool32 alphaMask = VK_FALSE, alphaBlend = VK_FALSE;                             // 2, 3
    float baseColor[4] = {1, 1, 1, 1};                // 4-7
    float emissive[3] = {0, 0, 0};                    // 8-10
    float metallic = 1, roughness = 1, alphaCutoff = 0.5f;  // 11-13
    // Derived from the factors (used for untextured materials):
    float diffuseOverPi[3] = {0, 0, 0};               // 14-16 base * (1 - metallic) / pi
    float specular[3] = {0, 0, 0};                    // 17-19 f0 * (shininess + 8) / (8 pi)
    float exponent = 1;                               // 20    shininess * log2(e)
    float ambientColor[3] = {0, 0, 0};                // 21-23 diffuse + f0 / 2
    // Lighting (directions towards the lights, unit length):
    float toKey[3] = {0, 0, 1}, keyIntensity = 1;     // 24-27
    float toFill[3] = {0, 0, 1}, fillIntensity = 0;   // 28-31
    float toRim[3] = {0, 0, 1}, rimIntensity = 0;     // 32-35
    float ambient = 0;                                // 36
};
static_assert(sizeof(FragmentConstants) == 37 * 4, "one 4-byte word per constant id");
constexpr std::uint32_t kFragmentConstantCount = 37;

// The lighting part of FragmentConstants (ids 24..36), as the Renderer sets it (defined in
// vk_mesh_pipeline.cpp; also used by the raw-lit baseline of `signstim bench render`).
void setLighting(const Lighting& lighting, FragmentConstants& constants);

// The material part of FragmentConstants (ids 0..23).
FragmentConstants materialConstants(const Material& material, bool baseTexture, bool mrTexture);

// A device-local buffer holding `size` bytes of `data` (zeros when null; at least 4 bytes),
// copied through a staging buffer; waits for the copy.
Buffer uploadBuffer(const Device& device, const CommandPool& commands, const void* data,
                    VkDeviceSize size, VkBufferUsageFlags usage);

struct GpuPrimitive {
    std::uint32_t firstIndex = 0, indexCount = 0;
    std::int32_t vertexOffset = 0;
    std::uint32_t material = 0;  // index into GpuScene::materials (last = default)
    bool skinned = false;
    bool morphed = false;  // has morph targets (drawn with mesh_morph.vert when weights are non-zero)
};

struct GpuMaterial {
    AlphaMode alphaMode = AlphaMode::Opaque;
    bool doubleSided = false;
    bool hasBaseColorTexture = false, hasMetallicRoughnessTexture = false;
    FragmentConstants constants;  // material part; lighting left at its defaults
    VkDescriptorSet set = VK_NULL_HANDLE;  // textures (set 1, bindings 1 and 2)
};

// The Renderer's mesh pipeline (shaders/mesh.vert + mesh.frag, the five vertex attributes of
// render::Vertex) and one material's pipeline from it: `constants` = the material's
// FragmentConstants with the lighting set (setLighting), cull mode and blending from the
// material. Defined in vk_mesh_pipeline.cpp; the raw-lit baseline of `signstim bench render` builds
// its pipeline with the same two functions so both draw the same image.
PipelineDesc meshPipelineDesc(VkShaderModule vertex, VkShaderModule fragment, VkFormat colorFormat,
                              VkFormat depthFormat, std::uint32_t msaa);
UniquePipeline createMeshPipeline(VkDevice device, VkPipelineLayout layout, const PipelineDesc& mesh,
                                  const GpuMaterial& material, const FragmentConstants& constants,
                                  bool skinned);

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
    UniqueDescriptorPool descriptorPool_;
    std::vector<GpuMaterial> materials_;
    std::size_t triangles_ = 0;
};

}  // namespace signstim::render::vk
