#include "renderer/vk_raw_baseline.hpp"

#include "common/error.hpp"
#include "renderer/vk_check.hpp"
#include "renderer/vk_commands.hpp"
#include "renderer/vk_descriptors.hpp"
#include "renderer/vk_device.hpp"
#include "renderer/vk_instance.hpp"
#include "renderer/vk_pipelines.hpp"
#include "renderer/vk_readback.hpp"
#include "renderer/vk_scene.hpp"
#include "renderer/vk_targets.hpp"

#include "shaders/bench_raw.frag.spv.h"
#include "shaders/bench_raw.vert.spv.h"
#include "shaders/mesh.frag.spv.h"
#include "shaders/mesh.vert.spv.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <vector>

namespace signstim::render {

namespace {

using vk::check;
using vk::make;

std::uint32_t memoryType(VkPhysicalDevice physical, std::uint32_t bits, VkMemoryPropertyFlags flags) {
    VkPhysicalDeviceMemoryProperties memory;
    vkGetPhysicalDeviceMemoryProperties(physical, &memory);
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((bits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & flags) == flags) return i;
    throw EnvironmentError("raw baseline: no suitable memory type");
}

// Everything the loop creates, destroyed in reverse order at scope exit.
struct Objects {
    VkDevice device = VK_NULL_HANDLE;
    std::vector<VkBuffer> buffers;
    std::vector<VkImage> images;
    std::vector<VkImageView> views;
    std::vector<VkDeviceMemory> memories;
    VkShaderModule modules[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkCommandPool pool = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;
    ~Objects() {
        if (device == VK_NULL_HANDLE) return;
        vkDeviceWaitIdle(device);
        vkDestroyFence(device, fence, nullptr);
        vkDestroyCommandPool(device, pool, nullptr);
        vkDestroyPipeline(device, pipeline, nullptr);
        vkDestroyPipelineLayout(device, layout, nullptr);
        for (auto m : modules) vkDestroyShaderModule(device, m, nullptr);
        for (auto v : views) vkDestroyImageView(device, v, nullptr);
        for (auto i : images) vkDestroyImage(device, i, nullptr);
        for (auto b : buffers) vkDestroyBuffer(device, b, nullptr);
        for (auto m : memories) vkFreeMemory(device, m, nullptr);
    }
};

// Lit shading: the Renderer's shader modules, set layouts, push constants and per-material
// pipelines (vk::meshPipelineDesc / vk::createMeshPipeline), its material descriptor sets
// (vk::GpuScene: textures, or the white defaults) and one storage buffer holding the mesh
// node's world and normal matrices. Created once; the loop itself is the same as OneLine.
struct LitObjects {
    // Matches `Push` in shaders/mesh.vert (and renderer.cpp's PushConstants).
    struct Push {
        glm::mat4 viewProjection;
        glm::vec4 cameraPosition;
        std::uint32_t matrixBase = 0;
        std::uint32_t jointCount = 0;  // 0: rigid
        std::uint32_t padding[2] = {0, 0};
    };
    struct Range {
        std::uint32_t firstIndex, indexCount;
        VkPipeline pipeline;
        VkDescriptorSet materialSet;
        bool blend;
    };
    std::unique_ptr<vk::CommandPool> commands;
    vk::UniqueDescriptorSetLayout frameLayout, materialLayout;
    vk::UniquePipelineLayout layout;
    vk::UniqueShaderModule vertex, fragment;
    std::unique_ptr<vk::GpuScene> scene;
    vk::UniqueDescriptorPool pool;
    VkDescriptorSet frameSet = VK_NULL_HANDLE;
    std::vector<vk::UniquePipeline> pipelines;
    std::vector<Range> ranges;
};

}  // namespace

struct RawBaseline::Impl {
    std::unique_ptr<vk::Instance> instance;
    std::unique_ptr<vk::Device> device;
    Objects objects;
    LitObjects lit;  // destroyed before `objects` (after ~RawBaseline waited for the device)
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    void* readbackData = nullptr;
    std::vector<std::uint8_t> host;

    void frame() {
        auto cmdSubmit = make<VkCommandBufferSubmitInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO);
        cmdSubmit.commandBuffer = cmd;
        auto submit = make<VkSubmitInfo2>(VK_STRUCTURE_TYPE_SUBMIT_INFO_2);
        submit.commandBufferInfoCount = 1;
        submit.pCommandBufferInfos = &cmdSubmit;
        VkDevice dev = device->get();
        check(vkQueueSubmit2(device->queue(), 1, &submit, objects.fence), "vkQueueSubmit2");
        check(vkWaitForFences(dev, 1, &objects.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
        check(vkResetFences(dev, 1, &objects.fence), "vkResetFences");
        std::memcpy(host.data(), readbackData, host.size());
    }
};

RawBaseline::~RawBaseline() {
    if (impl_ && impl_->device) vkDeviceWaitIdle(impl_->device->get());
}

void RawBaseline::run(std::uint32_t frames) {
    for (std::uint32_t i = 0; i < frames; ++i) impl_->frame();
}

double RawBaseline::measure(std::uint32_t frames) {
    impl_->frame();  // warm-up
    const auto start = std::chrono::steady_clock::now();
    for (std::uint32_t i = 0; i < frames; ++i) impl_->frame();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return seconds > 0 ? frames / seconds : 0.0;
}

const std::vector<std::uint8_t>& RawBaseline::pixels() const { return impl_->host; }

bool RawBaseline::validationEnabled() const { return impl_->instance->validation(); }

std::vector<std::string> RawBaseline::validationMessages() const {
    return impl_->instance->messages();
}

std::uint64_t RawBaseline::checksum() const {
    std::uint64_t sum = 0;
    for (std::uint8_t byte : impl_->host) sum += byte;
    return sum;
}

RawBaseline::RawBaseline(const Scene& mesh, const RawBaselineSettings& settings)
    : impl_(std::make_unique<Impl>()) {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    std::vector<std::uint32_t> primitiveFirstIndex;  // Lit: one draw per primitive (material)
    if (!mesh.meshes.empty()) {
        for (const auto& primitive : mesh.meshes[0].primitives) {
            const auto base = static_cast<std::uint32_t>(vertices.size());
            primitiveFirstIndex.push_back(static_cast<std::uint32_t>(indices.size()));
            vertices.insert(vertices.end(), primitive.vertices.begin(), primitive.vertices.end());
            for (auto index : primitive.indices) indices.push_back(base + index);
        }
    }
    if (indices.empty()) throw InputError("raw baseline: the scene has no triangles");

    impl_->instance = std::make_unique<vk::Instance>(vk::validationWanted(settings.validation));
    const auto physicalDevices = vk::enumeratePhysicalDevices(impl_->instance->get());
    const vk::PhysicalDevice& physical = vk::selectPhysicalDevice(physicalDevices, settings.device);
    impl_->device = std::make_unique<vk::Device>(physical);
    vk::Device& device = *impl_->device;
    VkDevice dev = device.get();
    Objects& objects = impl_->objects;
    objects.device = dev;
    const auto samples = static_cast<VkSampleCountFlagBits>(settings.msaa);
    // The Renderer's formats for PixelFormat::Rgba8 (R8G8B8A8_SRGB, D32_SFLOAT on lavapipe).
    const VkFormat colorFormat = vk::colorFormatFor(PixelFormat::Rgba8);
    const VkFormat depthFormat = vk::chooseDepthFormat(device);
    const bool lit = settings.shading == RawShading::Lit;
    const VkExtent2D extent{settings.width, settings.height};

    auto allocate = [&](VkMemoryRequirements requirements, VkMemoryPropertyFlags flags) {
        auto info = make<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
        info.allocationSize = requirements.size;
        info.memoryTypeIndex = memoryType(physical.handle, requirements.memoryTypeBits, flags);
        VkDeviceMemory memory;
        check(vkAllocateMemory(dev, &info, nullptr, &memory), "vkAllocateMemory");
        objects.memories.push_back(memory);
        return memory;
    };
    // Host-visible buffers: the baseline skips staging uploads (it measures the loop).
    auto buffer = [&](VkDeviceSize size, VkBufferUsageFlags usage, void** mapped) {
        auto info = make<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
        info.size = size;
        info.usage = usage;
        VkBuffer handle;
        check(vkCreateBuffer(dev, &info, nullptr, &handle), "vkCreateBuffer");
        objects.buffers.push_back(handle);
        VkMemoryRequirements requirements;
        vkGetBufferMemoryRequirements(dev, handle, &requirements);
        VkDeviceMemory memory = allocate(requirements, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                           VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        check(vkBindBufferMemory(dev, handle, memory, 0), "vkBindBufferMemory");
        check(vkMapMemory(dev, memory, 0, VK_WHOLE_SIZE, 0, mapped), "vkMapMemory");
        return handle;
    };
    auto image = [&](VkFormat format, VkSampleCountFlagBits count, VkImageUsageFlags usage,
                     VkImageAspectFlags aspect, VkImageView* view) {
        auto info = make<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
        info.imageType = VK_IMAGE_TYPE_2D;
        info.format = format;
        info.extent = {extent.width, extent.height, 1};
        info.mipLevels = info.arrayLayers = 1;
        info.samples = count;
        info.usage = usage;
        VkImage handle;
        check(vkCreateImage(dev, &info, nullptr, &handle), "vkCreateImage");
        objects.images.push_back(handle);
        VkMemoryRequirements requirements;
        vkGetImageMemoryRequirements(dev, handle, &requirements);
        check(vkBindImageMemory(dev, handle, allocate(requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT), 0),
              "vkBindImageMemory");
        auto viewInfo = make<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
        viewInfo.image = handle;
        viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
        viewInfo.format = format;
        viewInfo.subresourceRange = {aspect, 0, 1, 0, 1};
        check(vkCreateImageView(dev, &viewInfo, nullptr, view), "vkCreateImageView");
        objects.views.push_back(*view);
        return handle;
    };

    void* vertexData = nullptr;
    void* indexData = nullptr;
    void*& readbackData = impl_->readbackData;
    VkBuffer vertexBuffer = buffer(vertices.size() * sizeof(Vertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, &vertexData);
    VkBuffer indexBuffer = buffer(indices.size() * 4, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, &indexData);
    const VkDeviceSize frameBytes = VkDeviceSize(extent.width) * extent.height * 4;
    VkBuffer readback = buffer(frameBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, &readbackData);
    std::memcpy(vertexData, vertices.data(), vertices.size() * sizeof(Vertex));
    std::memcpy(indexData, indices.data(), indices.size() * 4);

    const bool multisampled = settings.msaa > 1;
    VkImageView colorView, resolveView = VK_NULL_HANDLE, depthView;
    VkImage color = image(colorFormat, samples,
                          VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                              (multisampled ? 0 : VK_IMAGE_USAGE_TRANSFER_SRC_BIT),
                          VK_IMAGE_ASPECT_COLOR_BIT, &colorView);
    VkImage resolve = multisampled ? image(colorFormat, VK_SAMPLE_COUNT_1_BIT,
                                           VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                           VK_IMAGE_ASPECT_COLOR_BIT, &resolveView)
                                   : color;
    VkImage depth = image(depthFormat, samples, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                          VK_IMAGE_ASPECT_DEPTH_BIT, &depthView);

    VkViewport viewport{0, float(extent.height), float(extent.width), -float(extent.height), 0, 1};
    VkRect2D scissor{{0, 0}, extent};
    LitObjects& litObjects = impl_->lit;
    if (lit) {
        // As Renderer::Impl::createPipelineLayout and pipelineFor.
        litObjects.commands = std::make_unique<vk::CommandPool>(device);
        litObjects.frameLayout = vk::createSetLayout(
            dev, {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT}});
        litObjects.materialLayout = vk::createSetLayout(
            dev, {{1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT},
                  {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT}});
        litObjects.layout = vk::createPipelineLayout(
            dev, {litObjects.frameLayout.get(), litObjects.materialLayout.get()},
            {{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(LitObjects::Push)}});
        litObjects.vertex = vk::createShaderModule(dev, mesh_vert_spv, sizeof(mesh_vert_spv));
        litObjects.fragment = vk::createShaderModule(dev, mesh_frag_spv, sizeof(mesh_frag_spv));
        // Materials only (descriptor sets, constants); the loop draws from the buffers above.
        litObjects.scene = std::make_unique<vk::GpuScene>(device, *litObjects.commands, mesh,
                                                          litObjects.materialLayout.get());
        const vk::PipelineDesc desc = vk::meshPipelineDesc(
            litObjects.vertex.get(), litObjects.fragment.get(), colorFormat, depthFormat, settings.msaa);
        const auto& primitives = litObjects.scene->primitives(0);
        for (std::size_t p = 0; p < primitives.size(); ++p) {
            if (primitives[p].indexCount == 0) continue;
            const vk::GpuMaterial& material = litObjects.scene->material(primitives[p].material);
            vk::FragmentConstants constants = material.constants;
            vk::setLighting(settings.lighting, constants);
            litObjects.pipelines.push_back(vk::createMeshPipeline(dev, litObjects.layout.get(), desc,
                                                                  material, constants, false));
            litObjects.ranges.push_back({primitiveFirstIndex[p], primitives[p].indexCount,
                                         litObjects.pipelines.back().get(), material.set,
                                         material.alphaMode == AlphaMode::Blend});
        }
        // Opaque first, then blended (the renderer's order; one mesh at one distance).
        std::stable_partition(litObjects.ranges.begin(), litObjects.ranges.end(),
                              [](const LitObjects::Range& range) { return !range.blend; });
        // World and normal matrix of the node holding the mesh, as the renderer computes them.
        std::vector<glm::mat4> world;
        computeWorldTransforms(mesh, restPose(mesh), world);
        glm::mat4 model(1.0f);
        for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
            if (mesh.nodes[n].mesh == 0) {
                model = world[n];
                break;
            }
        const glm::mat4 matrices[2] = {model, glm::mat4(glm::transpose(glm::inverse(glm::mat3(model))))};
        void* matrixData = nullptr;
        VkBuffer matrixBuffer = buffer(sizeof matrices, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, &matrixData);
        std::memcpy(matrixData, matrices, sizeof matrices);
        litObjects.pool = vk::createDescriptorPool(dev, 1, {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}});
        litObjects.frameSet = vk::allocateSet(dev, litObjects.pool.get(), litObjects.frameLayout.get());
        vk::DescriptorWriter()
            .buffer(0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, matrixBuffer, sizeof matrices)
            .update(dev, litObjects.frameSet);
    } else {
        // Pipeline: position + normal from the same 64-byte vertices the renderer uses.
        auto moduleInfo = make<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
        moduleInfo.codeSize = sizeof(bench_raw_vert_spv);
        moduleInfo.pCode = bench_raw_vert_spv;
        check(vkCreateShaderModule(dev, &moduleInfo, nullptr, &objects.modules[0]), "vkCreateShaderModule");
        moduleInfo.codeSize = sizeof(bench_raw_frag_spv);
        moduleInfo.pCode = bench_raw_frag_spv;
        check(vkCreateShaderModule(dev, &moduleInfo, nullptr, &objects.modules[1]), "vkCreateShaderModule");
        VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4)};
        auto layoutInfo = make<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
        layoutInfo.pushConstantRangeCount = 1;
        layoutInfo.pPushConstantRanges = &push;
        check(vkCreatePipelineLayout(dev, &layoutInfo, nullptr, &objects.layout), "vkCreatePipelineLayout");

        VkPipelineShaderStageCreateInfo stages[2];
        for (int i = 0; i < 2; ++i) {
            stages[i] = make<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
            stages[i].stage = i == 0 ? VK_SHADER_STAGE_VERTEX_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
            stages[i].module = objects.modules[i];
            stages[i].pName = "main";
        }
        VkVertexInputBindingDescription binding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
        VkVertexInputAttributeDescription attributes[2] = {
            {0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0},
            {1, 0, VK_FORMAT_R32G32B32_SFLOAT, static_cast<std::uint32_t>(offsetof(Vertex, normal))}};
        auto vertexInput = make<VkPipelineVertexInputStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO);
        vertexInput.vertexBindingDescriptionCount = 1;
        vertexInput.pVertexBindingDescriptions = &binding;
        vertexInput.vertexAttributeDescriptionCount = 2;
        vertexInput.pVertexAttributeDescriptions = attributes;
        auto assembly = make<VkPipelineInputAssemblyStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO);
        assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
        auto viewportState = make<VkPipelineViewportStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO);
        viewportState.viewportCount = viewportState.scissorCount = 1;
        viewportState.pViewports = &viewport;
        viewportState.pScissors = &scissor;
        auto raster = make<VkPipelineRasterizationStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO);
        raster.cullMode = VK_CULL_MODE_BACK_BIT;
        raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
        raster.lineWidth = 1.0f;
        auto multisample = make<VkPipelineMultisampleStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO);
        multisample.rasterizationSamples = samples;
        auto depthState = make<VkPipelineDepthStencilStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO);
        depthState.depthTestEnable = depthState.depthWriteEnable = VK_TRUE;
        depthState.depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
        VkPipelineColorBlendAttachmentState blendAttachment{};
        blendAttachment.colorWriteMask = 0xf;
        auto blend = make<VkPipelineColorBlendStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO);
        blend.attachmentCount = 1;
        blend.pAttachments = &blendAttachment;
        auto rendering = make<VkPipelineRenderingCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO);
        rendering.colorAttachmentCount = 1;
        rendering.pColorAttachmentFormats = &colorFormat;
        rendering.depthAttachmentFormat = depthFormat;
        auto pipelineInfo = make<VkGraphicsPipelineCreateInfo>(VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO, &rendering);
        pipelineInfo.stageCount = 2;
        pipelineInfo.pStages = stages;
        pipelineInfo.pVertexInputState = &vertexInput;
        pipelineInfo.pInputAssemblyState = &assembly;
        pipelineInfo.pViewportState = &viewportState;
        pipelineInfo.pRasterizationState = &raster;
        pipelineInfo.pMultisampleState = &multisample;
        pipelineInfo.pDepthStencilState = &depthState;
        pipelineInfo.pColorBlendState = &blend;
        pipelineInfo.layout = objects.layout;
        check(vkCreateGraphicsPipelines(dev, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr, &objects.pipeline),
              "vkCreateGraphicsPipelines");
    }

    auto poolInfo = make<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
    poolInfo.queueFamilyIndex = device.queueFamily();
    check(vkCreateCommandPool(dev, &poolInfo, nullptr, &objects.pool), "vkCreateCommandPool");
    auto cmdInfo = make<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
    cmdInfo.commandPool = objects.pool;
    cmdInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    cmdInfo.commandBufferCount = 1;
    VkCommandBuffer& cmd = impl_->cmd;
    check(vkAllocateCommandBuffers(dev, &cmdInfo, &cmd), "vkAllocateCommandBuffers");
    auto fenceInfo = make<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
    check(vkCreateFence(dev, &fenceInfo, nullptr, &objects.fence), "vkCreateFence");

    // Recorded once, replayed every frame: the cheapest possible loop.
    auto begin = make<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
    check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
    auto barrier = [&](VkImage target, VkImageLayout from, VkImageLayout to, VkPipelineStageFlags2 srcStage,
                       VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess,
                       VkImageAspectFlags aspect) {
        auto b = make<VkImageMemoryBarrier2>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2);
        b.srcStageMask = srcStage;
        b.srcAccessMask = srcAccess;
        b.dstStageMask = dstStage;
        b.dstAccessMask = dstAccess;
        b.oldLayout = from;
        b.newLayout = to;
        b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.image = target;
        b.subresourceRange = {aspect, 0, 1, 0, 1};
        auto dependency = make<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
        dependency.imageMemoryBarrierCount = 1;
        dependency.pImageMemoryBarriers = &b;
        vkCmdPipelineBarrier2(cmd, &dependency);
    };
    const auto attachmentStage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
    barrier(color, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            attachmentStage | VK_PIPELINE_STAGE_2_COPY_BIT, 0, attachmentStage,
            VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
    if (multisampled)
        barrier(resolve, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                attachmentStage | VK_PIPELINE_STAGE_2_COPY_BIT, 0, attachmentStage,
                VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
    const auto depthStages = VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    barrier(depth, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, depthStages, 0,
            depthStages, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_IMAGE_ASPECT_DEPTH_BIT);
    auto colorAttachment = make<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    colorAttachment.imageView = colorView;
    colorAttachment.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    colorAttachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    colorAttachment.storeOp = multisampled ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
    colorAttachment.clearValue.color = {{0.16f, 0.17f, 0.19f, 1.0f}};
    if (multisampled) {
        colorAttachment.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
        colorAttachment.resolveImageView = resolveView;
        colorAttachment.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    }
    auto depthAttachment = make<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    depthAttachment.imageView = depthView;
    depthAttachment.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depthAttachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depthAttachment.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    depthAttachment.clearValue.depthStencil = {1.0f, 0};
    auto renderingInfo = make<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
    renderingInfo.renderArea = {{0, 0}, extent};
    renderingInfo.layerCount = 1;
    renderingInfo.colorAttachmentCount = 1;
    renderingInfo.pColorAttachments = &colorAttachment;
    renderingInfo.pDepthAttachment = &depthAttachment;
    vkCmdBeginRendering(cmd, &renderingInfo);
    const float aspect = float(extent.width) / float(extent.height);
    const glm::vec3 eye(0, 0, 2.2f);
    const glm::mat4 viewProjection = glm::perspective(glm::radians(30.0f), aspect, 0.1f, 10.0f) *
                                     glm::lookAt(eye, glm::vec3(0), glm::vec3(0, 1, 0));
    VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &vertexBuffer, &offset);
    vkCmdBindIndexBuffer(cmd, indexBuffer, 0, VK_INDEX_TYPE_UINT32);
    if (lit) {
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        VkPipelineLayout layout = litObjects.layout.get();
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1,
                                &litObjects.frameSet, 0, nullptr);
        LitObjects::Push push;
        push.viewProjection = viewProjection;
        push.cameraPosition = glm::vec4(eye, 1.0f);
        vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT,
                           0, sizeof push, &push);
        for (const auto& range : litObjects.ranges) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, range.pipeline);
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 1, 1,
                                    &range.materialSet, 0, nullptr);
            vkCmdDrawIndexed(cmd, range.indexCount, 1, range.firstIndex, 0, 0);
        }
    } else {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, objects.pipeline);
        vkCmdPushConstants(cmd, objects.layout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4),
                           &viewProjection);
        vkCmdDrawIndexed(cmd, static_cast<std::uint32_t>(indices.size()), 1, 0, 0, 0);
    }
    vkCmdEndRendering(cmd);
    barrier(resolve, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
            attachmentStage, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
            VK_ACCESS_2_TRANSFER_READ_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent.width, extent.height, 1};
    vkCmdCopyImageToBuffer(cmd, resolve, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback, 1, &region);
    auto toHost = make<VkMemoryBarrier2>(VK_STRUCTURE_TYPE_MEMORY_BARRIER_2);
    toHost.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    toHost.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    toHost.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
    toHost.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
    auto dependency = make<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
    dependency.memoryBarrierCount = 1;
    dependency.pMemoryBarriers = &toHost;
    vkCmdPipelineBarrier2(cmd, &dependency);
    check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");

    impl_->host.resize(frameBytes);
}

}  // namespace signstim::render
