#pragma once
// Graphics pipelines for dynamic rendering (no render pass objects). Viewport and scissor
// are dynamic so one pipeline serves every view; cull mode can be (dynamicCullMode) but the
// renderer bakes it into its pipeline variants.
#include "renderer/vk_handle.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace signstim::render::vk {

UniqueShaderModule createShaderModule(VkDevice device, const std::uint32_t* words,
                                      std::size_t byteSize);

struct PipelineDesc {
    VkShaderModule vertex = VK_NULL_HANDLE, fragment = VK_NULL_HANDLE;
    std::vector<VkVertexInputBindingDescription> bindings;
    std::vector<VkVertexInputAttributeDescription> attributes;
    VkFormat colorFormat = VK_FORMAT_UNDEFINED;
    VkFormat depthFormat = VK_FORMAT_UNDEFINED;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    bool depthWrite = true;
    bool blend = false;  // straight alpha "over"
    bool dynamicCullMode = true;
    VkCullModeFlags cullMode = VK_CULL_MODE_BACK_BIT;  // when not dynamic
    const VkSpecializationInfo* vertexSpecialization = nullptr;
    const VkSpecializationInfo* fragmentSpecialization = nullptr;
};

UniquePipeline createGraphicsPipeline(VkDevice device, VkPipelineLayout layout,
                                      const PipelineDesc& desc);

UniquePipelineLayout createPipelineLayout(VkDevice device,
                                          const std::vector<VkDescriptorSetLayout>& sets,
                                          const std::vector<VkPushConstantRange>& pushConstants);

}  // namespace signstim::render::vk
