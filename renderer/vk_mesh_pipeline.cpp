// The Renderer's mesh pipelines (vk_scene.hpp: setLighting, meshPipelineDesc,
// createMeshPipeline), shared with the raw-lit baseline of `signstim bench render`.
#include "renderer/renderer.hpp"
#include "renderer/vk_scene.hpp"

#include <glm/glm.hpp>

#include <cstddef>
#include <vector>

namespace signstim::render {

namespace vk {

// The lighting part of mesh.frag's specialisation constants: directions towards the lights.
void setLighting(const Lighting& lighting, FragmentConstants& constants) {
    glm::vec3 key = lighting.keyDirection;
    if (glm::length(key) < 1e-6f) key = {-0.3f, -0.5f, -1.0f};
    key = glm::normalize(key);
    // Fill mirrors the key to the other side and comes in nearly level; the rim comes from
    // behind and above.
    glm::vec3 fill = glm::normalize(glm::vec3(-key.x * 2.0f + (key.x == 0.0f ? 0.5f : 0.0f),
                                              key.y * 0.2f, key.z));
    glm::vec3 rim = glm::normalize(glm::vec3(-key.x * 0.5f, -0.6f, -key.z));
    for (int c = 0; c < 3; ++c) {
        constants.toKey[c] = -key[c];
        constants.toFill[c] = -fill[c];
        constants.toRim[c] = -rim[c];
    }
    constants.keyIntensity = lighting.keyIntensity;
    constants.fillIntensity = lighting.fillIntensity;
    constants.rimIntensity = lighting.rimIntensity;
    constants.ambient = lighting.ambient;
}

PipelineDesc meshPipelineDesc(VkShaderModule vertex, VkShaderModule fragment, VkFormat colorFormat,
                              VkFormat depthFormat, std::uint32_t msaa) {
    PipelineDesc desc;
    desc.vertex = vertex;
    desc.fragment = fragment;
    desc.bindings = {{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.attributes = {
        {0, 0, VK_FORMAT_R32G32B32_SFLOAT, static_cast<std::uint32_t>(offsetof(Vertex, position))},
        {1, 0, VK_FORMAT_R32G32B32_SFLOAT, static_cast<std::uint32_t>(offsetof(Vertex, normal))},
        {2, 0, VK_FORMAT_R32G32_SFLOAT, static_cast<std::uint32_t>(offsetof(Vertex, uv))},
        {3, 0, VK_FORMAT_R32G32B32A32_UINT, static_cast<std::uint32_t>(offsetof(Vertex, joints))},
        {4, 0, VK_FORMAT_R32G32B32A32_SFLOAT,
         static_cast<std::uint32_t>(offsetof(Vertex, weights))}};
    desc.colorFormat = colorFormat;
    desc.depthFormat = depthFormat;
    desc.samples = static_cast<VkSampleCountFlagBits>(msaa);
    return desc;
}

UniquePipeline createMeshPipeline(VkDevice device, VkPipelineLayout layout, const PipelineDesc& mesh,
                                  const GpuMaterial& material, const FragmentConstants& constants,
                                  bool skinned) {
    std::vector<VkSpecializationMapEntry> entries(kFragmentConstantCount);
    for (std::uint32_t id = 0; id < kFragmentConstantCount; ++id)
        entries[id] = {id, id * 4u, 4u};  // bools are 32-bit in SPIR-V, like the floats
    const VkSpecializationInfo specialization{kFragmentConstantCount, entries.data(),
                                              sizeof(constants), &constants};
    const VkBool32 vertexConstant = skinned ? VK_TRUE : VK_FALSE;  // SKINNED in mesh.vert
    const VkSpecializationMapEntry vertexEntry{0, 0, sizeof(VkBool32)};
    const VkSpecializationInfo vertexSpecialization{1, &vertexEntry, sizeof(VkBool32),
                                                    &vertexConstant};
    PipelineDesc desc = mesh;
    desc.vertexSpecialization = &vertexSpecialization;
    desc.fragmentSpecialization = &specialization;
    desc.dynamicCullMode = false;
    desc.cullMode = material.doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
    desc.blend = material.alphaMode == AlphaMode::Blend;
    desc.depthWrite = !desc.blend;  // blended surfaces test against, but do not hide, others
    return createGraphicsPipeline(device, layout, desc);
}

}  // namespace vk

}  // namespace signstim::render
