// Renderer: ties the Vulkan pieces together. Per frame: pose every view on the CPU (world
// and joint matrices into one storage buffer), record one command buffer that clears the
// target, draws each view into its grid cell, resolves and copies to a staging buffer.
// Frame slots (target + command buffer + fence + matrices) are used round robin so the
// readback of one frame overlaps the drawing of the next.
#include "renderer/renderer.hpp"

#include "common/error.hpp"
#include "renderer/label_overlay.hpp"
#include "renderer/vk_check.hpp"
#include "renderer/vk_commands.hpp"
#include "renderer/vk_descriptors.hpp"
#include "renderer/vk_device.hpp"
#include "renderer/vk_instance.hpp"
#include "renderer/vk_morph.hpp"
#include "renderer/vk_pipelines.hpp"
#include "renderer/vk_readback.hpp"
#include "renderer/vk_scene.hpp"
#include "renderer/vk_targets.hpp"

#include "shaders/mesh.frag.spv.h"
#include "shaders/mesh_morph.vert.spv.h"
#include "shaders/mesh.vert.spv.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstring>
#include <deque>
#include <map>
#include <stdexcept>

namespace signstim::render {

namespace {

constexpr std::uint32_t kFramesInFlight = 2;

// Matches `Push` in shaders/mesh.vert and mesh.frag.
struct PushConstants {
    glm::mat4 viewProjection;
    glm::vec4 cameraPosition;
    std::uint32_t matrixBase = 0;
    std::uint32_t jointCount = 0;  // 0: rigid
    std::uint32_t morphBase = 0;   // the draw's first morphed vec4 (vk_morph.hpp)
    std::uint32_t morphCount = 0;  // 1: morphed (mesh_morph.vert), 0: not
};

std::string joinCounts(const std::vector<std::uint32_t>& counts) {
    std::string text;
    for (auto c : counts) text += (text.empty() ? "" : ", ") + std::to_string(c);
    return text;
}

LabelRect cellOf(std::uint32_t width, std::uint32_t height, std::uint32_t columns,
                 std::uint32_t rows, std::size_t index) {
    const ViewCell c = viewCell(width, height, columns, rows, index);  // renderer/view_geometry.cpp
    return LabelRect{c.x, c.y, c.width, c.height};
}

struct Draw {
    const vk::GpuPrimitive* primitive;
    std::uint32_t matrixBase, jointCount;  // jointCount 0: rigid
    float distance;
    std::uint32_t morphBase = 0, morphCount = 0;  // morphCount 1: morphed, 0: not
};

}  // namespace


struct Renderer::Impl {
    struct Slot {
        std::unique_ptr<vk::OffscreenTarget> target;
        VkCommandBuffer cmd = VK_NULL_HANDLE;
        vk::UniqueFence fence;
        vk::Buffer matrices, morphed;
        VkDescriptorSet set = VK_NULL_HANDLE;
        std::vector<std::pair<LabelRect, std::string>> labels;
    };

    RendererOptions options;
    DeviceInfo info;
    std::unique_ptr<vk::Instance> instance;
    std::unique_ptr<vk::Device> device;
    std::unique_ptr<vk::CommandPool> commands;
    vk::UniqueDescriptorSetLayout frameLayout, materialLayout, morphLayout;
    vk::UniquePipelineLayout pipelineLayout;
    vk::UniqueShaderModule vertexShader, morphVertexShader, fragmentShader;
    vk::PipelineDesc pipelineDesc;
    // One pipeline per distinct (specialisation constants, skinned, double-sided): materials
    // with equal factors share one, across scenes too.
    std::map<std::vector<std::uint32_t>, vk::UniquePipeline> pipelines;
    std::map<std::tuple<const vk::GpuMaterial*, bool, bool>, VkPipeline> materialPipelines;  // cache
    vk::UniqueDescriptorPool framePool;
    std::vector<Slot> slots;
    std::deque<std::size_t> pending;
    std::size_t nextSlot = 0;
    std::vector<std::unique_ptr<vk::GpuScene>> scenes;
    std::vector<std::unique_ptr<vk::GpuMorphs>> morphs;  // per scene; null: no morph targets

    // Scratch reused across frames.
    std::vector<glm::mat4> matrices, world, joints;
    std::vector<glm::vec4> morphed;            // the frame's morphed (position, normal) pairs
    std::vector<std::uint32_t> morphBases;     // per primitive of the node being recorded
    std::vector<Draw> opaqueDraws, blendDraws;

    ~Impl() {
        if (device) vkDeviceWaitIdle(device->get());
    }

    void checkOptions(const vk::PhysicalDevice& physical);
    void createPipelineLayout(VkFormat colorFormat, VkFormat depthFormat);
    VkPipeline pipelineFor(const vk::GpuMaterial& material, bool skinned, bool morphed = false);
    void validateFrame(const Frame& frame) const;
    void recordFrame(Slot& slot, const Frame& frame);
    void ensureMatrixCapacity(Slot& slot, std::size_t count);
    void ensureMorphCapacity(Slot& slot, std::size_t count);
};

void Renderer::Impl::checkOptions(const vk::PhysicalDevice& physical) {
    const auto& limits = device->properties().limits;
    // The mesh pipeline layout: 3 sets (frame, material, morph targets), 3 storage buffers
    // in the vertex stage, the push constants. Vulkan's guaranteed minimums (4, 4, 128 bytes)
    // cover them; a device below them is refused here rather than failing at draw time.
    if (limits.maxBoundDescriptorSets < 3 || limits.maxPerStageDescriptorStorageBuffers < 3 ||
        limits.maxPushConstantsSize < sizeof(PushConstants))
        throw EnvironmentError("device '" + info.name + "' is below Vulkan's minimum limits (descriptor sets, "
                               "storage buffers per stage, push constant size)");
    if (options.width == 0 || options.height == 0 ||
        options.width > limits.maxImageDimension2D || options.height > limits.maxImageDimension2D)
        throw InputError("<command line>", 0, "--size",
                         std::to_string(options.width) + "x" + std::to_string(options.height) +
                             ": width and height must be 1.." +
                             std::to_string(limits.maxImageDimension2D) + " on device '" +
                             info.name + "'");
    VkFormat colorFormat = vk::colorFormatFor(options.format);
    const VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT |
                                        VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT |
                                        VK_FORMAT_FEATURE_TRANSFER_SRC_BIT;
    if ((device->formatProperties(colorFormat).optimalTilingFeatures & needed) != needed)
        throw InputError("<command line>", 0, "--format",
                         std::string(options.format == PixelFormat::Rgba8 ? "rgba8" : "rgba16") +
                             ": device '" + info.name + "' cannot render this format");
    // Sample counts: framebuffer limits and what the colour format allows.
    VkImageFormatProperties formatProperties{};
    vkGetPhysicalDeviceImageFormatProperties(
        physical.handle, colorFormat, VK_IMAGE_TYPE_2D, VK_IMAGE_TILING_OPTIMAL,
        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT, 0,
        &formatProperties);
    std::vector<std::uint32_t> supported;
    for (std::uint32_t count : info.sampleCounts)
        if (formatProperties.sampleCounts & count) supported.push_back(count);
    if (std::find(supported.begin(), supported.end(), options.msaa) == supported.end())
        throw InputError("<command line>", 0, "--msaa",
                         "--msaa " + std::to_string(options.msaa) + ": device '" + info.name +
                             "' supports " + joinCounts(supported));
}

void Renderer::Impl::createPipelineLayout(VkFormat colorFormat, VkFormat depthFormat) {
    VkDevice dev = device->get();
    // Lighting and material factors are specialisation constants (see mesh.frag), so the
    // sets hold only the per-frame matrices and the material textures.
    frameLayout = vk::createSetLayout(
        dev, {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT},
              {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT}});  // morphed vertices
    materialLayout = vk::createSetLayout(
        dev, {{1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT},
              {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT}});
    morphLayout = vk::createMorphSetLayout(dev);
    pipelineLayout = vk::createPipelineLayout(
        dev, {frameLayout.get(), materialLayout.get(), morphLayout.get()},
        {{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(PushConstants)}});

    vertexShader = vk::createShaderModule(dev, mesh_vert_spv, sizeof(mesh_vert_spv));
    morphVertexShader = vk::createShaderModule(dev, mesh_morph_vert_spv, sizeof(mesh_morph_vert_spv));
    fragmentShader = vk::createShaderModule(dev, mesh_frag_spv, sizeof(mesh_frag_spv));
    pipelineDesc = vk::meshPipelineDesc(vertexShader.get(), fragmentShader.get(), colorFormat,
                                        depthFormat, options.msaa);
}

VkPipeline Renderer::Impl::pipelineFor(const vk::GpuMaterial& material, bool skinned, bool morphed) {
    const auto cacheKey = std::make_tuple(&material, skinned, morphed);
    auto cached = materialPipelines.find(cacheKey);
    if (cached != materialPipelines.end()) return cached->second;
    vk::FragmentConstants constants = material.constants;
    vk::setLighting(options.lighting, constants);
    std::vector<std::uint32_t> key(vk::kFragmentConstantCount + 1);
    std::memcpy(key.data(), &constants, sizeof(constants));
    key.back() = (skinned ? 1u : 0u) | (material.doubleSided ? 2u : 0u) | (morphed ? 4u : 0u);
    auto found = pipelines.find(key);
    if (found != pipelines.end()) return materialPipelines[cacheKey] = found->second.get();

    vk::PipelineDesc desc = pipelineDesc;
    if (morphed) desc.vertex = morphVertexShader.get();  // mesh_morph.vert
    auto pipeline = vk::createMeshPipeline(device->get(), pipelineLayout.get(), desc,
                                           material, constants, skinned);
    VkPipeline handle = pipelines.emplace(std::move(key), std::move(pipeline)).first->second.get();
    return materialPipelines[cacheKey] = handle;
}

void Renderer::Impl::ensureMatrixCapacity(Slot& slot, std::size_t count) {
    const VkDeviceSize needed = std::max<std::size_t>(count, 1) * sizeof(glm::mat4);
    if (slot.matrices.size >= needed) return;
    VkDeviceSize size = std::max<VkDeviceSize>(needed, 2 * slot.matrices.size);
    size = std::max<VkDeviceSize>(size, 256 * sizeof(glm::mat4));
    slot.matrices = vk::createBuffer(*device, size, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                     vk::MemoryUse::Upload);
    vk::DescriptorWriter()
        .buffer(0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, slot.matrices.buffer.get(), size)
        .update(device->get(), slot.set);
}

void Renderer::Impl::ensureMorphCapacity(Slot& slot, std::size_t count) {
    const VkDeviceSize needed = std::max<std::size_t>(count, 1) * sizeof(glm::vec4);
    if (slot.morphed.size >= needed) return;
    VkDeviceSize size = std::max<VkDeviceSize>(needed, 2 * slot.morphed.size);
    size = std::max<VkDeviceSize>(size, 256 * sizeof(glm::vec4));
    slot.morphed = vk::createBuffer(*device, size, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                    vk::MemoryUse::Upload);
    vk::DescriptorWriter()
        .buffer(1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, slot.morphed.buffer.get(), size)
        .update(device->get(), slot.set);
}

void Renderer::Impl::validateFrame(const Frame& frame) const {
    if (frame.columns == 0 || frame.rows == 0)
        throw InputError("<frame>", 0, "columns/rows", "the view grid must be at least 1x1");
    if (frame.views.size() > std::size_t(frame.columns) * frame.rows)
        throw InputError("<frame>", 0, "views",
                         std::to_string(frame.views.size()) + " views do not fit a " +
                             std::to_string(frame.columns) + "x" + std::to_string(frame.rows) +
                             " grid");
    if (frame.columns > options.width || frame.rows > options.height)
        throw InputError("<frame>", 0, "columns/rows", "more grid cells than pixels");
    for (std::size_t i = 0; i < frame.views.size(); ++i) {
        const View& view = frame.views[i];
        const std::string field = "views[" + std::to_string(i) + "]";
        if (view.scene < 0 || static_cast<std::size_t>(view.scene) >= scenes.size())
            throw InputError("<frame>", 0, field + ".scene",
                             "no scene with handle " + std::to_string(view.scene) +
                                 " (addScene returned " + std::to_string(scenes.size()) +
                                 " so far)");
        const Scene& scene = scenes[static_cast<std::size_t>(view.scene)]->cpu();
        if (!view.pose.local.empty() && view.pose.local.size() != scene.nodes.size())
            throw InputError("<frame>", 0, field + ".pose",
                             "pose has " + std::to_string(view.pose.local.size()) +
                                 " transforms, scene '" + scene.sourceName + "' has " +
                                 std::to_string(scene.nodes.size()) + " nodes");
        if (const std::string problem = cameraProblem(view.camera); !problem.empty())
            throw InputError("<frame>", 0, field + ".camera", problem);
        if (const std::string problem = morphProblem(scene, view.pose); !problem.empty())
            throw InputError("<frame>", 0, field + ".pose", problem);
    }
}

void Renderer::Impl::recordFrame(Slot& slot, const Frame& frame) {
    // CPU pass: matrices of every view into one array, and the draw list of each view.
    struct ViewDraws {
        LabelRect cell;
        PushConstants push;
        const vk::GpuScene* scene;
        const vk::GpuMorphs* morphs;
        std::size_t opaqueBegin, opaqueEnd, blendBegin, blendEnd;
    };
    std::vector<ViewDraws> views;
    matrices.clear();
    morphed.clear();
    opaqueDraws.clear();
    blendDraws.clear();
    slot.labels.clear();
    for (std::size_t v = 0; v < frame.views.size(); ++v) {
        const View& view = frame.views[v];
        const vk::GpuScene& gpu = *scenes[static_cast<std::size_t>(view.scene)];
        const Scene& scene = gpu.cpu();
        ViewDraws draws{};
        draws.cell = cellOf(options.width, options.height, frame.columns, frame.rows, v);
        draws.scene = &gpu;
        draws.morphs = morphs[static_cast<std::size_t>(view.scene)].get();
        if (!view.label.empty()) slot.labels.emplace_back(draws.cell, view.label);

        const Camera& camera = view.camera;
        const float aspect = float(draws.cell.width) / float(draws.cell.height);
        draws.push.viewProjection = viewProjection(camera, aspect);  // renderer/view_geometry.cpp
        draws.push.cameraPosition = glm::vec4(camera.eye, 1.0f);

        if (view.pose.local.empty())
            computeWorldTransforms(scene, restPose(scene), world);
        else
            computeWorldTransforms(scene, view.pose, world);

        draws.opaqueBegin = opaqueDraws.size();
        draws.blendBegin = blendDraws.size();
        for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
            const Node& node = scene.nodes[n];
            if (node.mesh < 0 || node.mesh >= static_cast<int>(scene.meshes.size())) continue;
            // Rigid draws: world matrix and its normal matrix (mesh.vert).
            const auto rigidBase = static_cast<std::uint32_t>(matrices.size());
            matrices.push_back(world[n]);
            matrices.push_back(glm::mat4(glm::transpose(glm::inverse(glm::mat3(world[n])))));
            std::uint32_t skinBase = 0, jointCount = 0;
            if (node.skin >= 0 && node.skin < static_cast<int>(scene.skins.size())) {
                computeJointMatrices(scene, node.skin, world, joints);
                if (!joints.empty()) {
                    skinBase = static_cast<std::uint32_t>(matrices.size());
                    jointCount = static_cast<std::uint32_t>(joints.size());
                    matrices.insert(matrices.end(), joints.begin(), joints.end());
                }
            }
            const float distance = glm::length(glm::vec3(world[n][3]) - camera.eye);
            // Morph targets: the node's morphed vertices (none, or all weights zero: the draws
            // skip mesh_morph.vert).
            morphBases.clear();
            if (draws.morphs && scene.meshes[static_cast<std::size_t>(node.mesh)].targetCount() > 0)
                draws.morphs->appendMorphed(node.mesh, resolveMorphWeights(scene, view.pose, static_cast<int>(n)),
                                            morphed, morphBases);
            const auto& primitives = gpu.primitives(node.mesh);
            for (std::size_t p = 0; p < primitives.size(); ++p) {
                const vk::GpuPrimitive& primitive = primitives[p];
                if (primitive.indexCount == 0) continue;
                const bool skinned = primitive.skinned && jointCount > 0;
                const std::uint32_t morphBase = p < morphBases.size() ? morphBases[p] : vk::kNoMorph;
                Draw draw{&primitive, skinned ? skinBase : rigidBase, skinned ? jointCount : 0u,
                          distance, morphBase == vk::kNoMorph ? 0u : morphBase, morphBase == vk::kNoMorph ? 0u : 1u};
                if (gpu.material(primitive.material).alphaMode == AlphaMode::Blend)
                    blendDraws.push_back(draw);
                else
                    opaqueDraws.push_back(draw);
            }
        }
        draws.opaqueEnd = opaqueDraws.size();
        draws.blendEnd = blendDraws.size();
        // Blended surfaces back to front.
        std::stable_sort(blendDraws.begin() + static_cast<std::ptrdiff_t>(draws.blendBegin),
                         blendDraws.end(),
                         [](const Draw& a, const Draw& b) { return a.distance > b.distance; });
        views.push_back(draws);
    }
    ensureMatrixCapacity(slot, matrices.size());
    if (!matrices.empty())
        std::memcpy(slot.matrices.mapped, matrices.data(), matrices.size() * sizeof(glm::mat4));
    ensureMorphCapacity(slot, morphed.size());
    if (!morphed.empty())
        std::memcpy(slot.morphed.mapped, morphed.data(), morphed.size() * sizeof(glm::vec4));

    // GPU pass.
    VkCommandBuffer cmd = slot.cmd;
    vk::check(vkResetCommandBuffer(cmd, 0), "vkResetCommandBuffer");
    auto begin = vk::make<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vk::check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
    const glm::vec4& bg = options.background;
    slot.target->beginRendering(cmd, VkClearColorValue{{bg.r, bg.g, bg.b, bg.a}});
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout.get(), 0, 1,
                            &slot.set, 0, nullptr);
    for (const ViewDraws& view : views) {
        // Negative height: clip-space +Y up (OpenGL/glTF convention), windings preserved.
        VkViewport viewport{float(view.cell.x), float(view.cell.y + view.cell.height),
                            float(view.cell.width), -float(view.cell.height), 0.0f, 1.0f};
        VkRect2D scissor{{static_cast<std::int32_t>(view.cell.x),
                          static_cast<std::int32_t>(view.cell.y)},
                         {view.cell.width, view.cell.height}};
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        if (view.opaqueBegin == view.opaqueEnd && view.blendBegin == view.blendEnd) continue;
        VkBuffer vertexBuffer = view.scene->vertexBuffer();
        VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &vertexBuffer, &offset);
        vkCmdBindIndexBuffer(cmd, view.scene->indexBuffer(), 0, VK_INDEX_TYPE_UINT32);
        if (const vk::GpuMorphs* morph = view.morphs) {
            VkDescriptorSet morphSet = morph->set();
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout.get(), 2, 1,
                                    &morphSet, 0, nullptr);
        }

        auto drawRange = [&](const std::vector<Draw>& draws, std::size_t from, std::size_t to) {
            PushConstants push = view.push;
            VkPipeline bound = VK_NULL_HANDLE;
            VkDescriptorSet boundSet = VK_NULL_HANDLE;
            for (std::size_t i = from; i < to; ++i) {
                const Draw& draw = draws[i];
                const vk::GpuMaterial& material = view.scene->material(draw.primitive->material);
                VkPipeline pipeline = pipelineFor(material, draw.jointCount > 0, draw.morphCount > 0);
                if (pipeline != bound) {
                    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
                    bound = pipeline;
                }
                if (material.set != boundSet) {
                    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                                            pipelineLayout.get(), 1, 1, &material.set, 0, nullptr);
                    boundSet = material.set;
                }
                push.matrixBase = draw.matrixBase;
                push.jointCount = draw.jointCount;
                push.morphBase = draw.morphBase;
                push.morphCount = draw.morphCount;
                vkCmdPushConstants(cmd, pipelineLayout.get(),
                                   VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                   sizeof(PushConstants), &push);
                vkCmdDrawIndexed(cmd, draw.primitive->indexCount, 1, draw.primitive->firstIndex,
                                 draw.primitive->vertexOffset, 0);
            }
        };
        drawRange(opaqueDraws, view.opaqueBegin, view.opaqueEnd);
        drawRange(blendDraws, view.blendBegin, view.blendEnd);
    }
    slot.target->endRenderingAndCopy(cmd);
    vk::check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
}

std::vector<DeviceInfo> Renderer::listDevices() {
    vk::Instance instance(false);
    const auto devices = vk::enumeratePhysicalDevices(instance.get());
    const int automatic = vk::automaticChoice(devices);
    std::vector<DeviceInfo> result;
    for (const auto& device : devices) result.push_back(device.info);
    if (automatic >= 0) result[static_cast<std::size_t>(automatic)].automatic = true;
    return result;
}

Renderer::Renderer(const RendererOptions& options) : impl_(std::make_unique<Impl>()) {
    Impl& r = *impl_;
    r.options = options;
    r.instance = std::make_unique<vk::Instance>(vk::validationWanted(options.validation));
    const auto physicalDevices = vk::enumeratePhysicalDevices(r.instance->get());
    const vk::PhysicalDevice& physical = vk::selectPhysicalDevice(physicalDevices, options.device);
    r.info = physical.info;
    r.info.automatic = vk::automaticChoice(physicalDevices) ==
                       static_cast<int>(&physical - physicalDevices.data());
    r.device = std::make_unique<vk::Device>(physical);
    r.checkOptions(physical);

    r.commands = std::make_unique<vk::CommandPool>(*r.device);
    const VkFormat colorFormat = vk::colorFormatFor(options.format);
    const VkFormat depthFormat = vk::chooseDepthFormat(*r.device);
    r.createPipelineLayout(colorFormat, depthFormat);

    r.framePool = vk::createDescriptorPool(
        r.device->get(), kFramesInFlight,
        {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2}});
    vk::TargetFormats formats{colorFormat, depthFormat,
                              static_cast<VkSampleCountFlagBits>(options.msaa)};
    r.slots.resize(kFramesInFlight);
    for (auto& slot : r.slots) {
        slot.target = std::make_unique<vk::OffscreenTarget>(
            *r.device, VkExtent2D{options.width, options.height}, formats);
        slot.cmd = r.commands->allocate();
        slot.fence = vk::createFence(*r.device, false);
        slot.set = vk::allocateSet(r.device->get(), r.framePool.get(), r.frameLayout.get());
        r.ensureMatrixCapacity(slot, 256);
        r.ensureMorphCapacity(slot, 256);
    }
}

Renderer::~Renderer() = default;

const DeviceInfo& Renderer::device() const { return impl_->info; }
const RendererOptions& Renderer::options() const { return impl_->options; }

int Renderer::addScene(const Scene& scene) {
    // Joint indices beyond a skin are clamped in the shader; report them here instead of
    // drawing garbage.
    for (const Node& node : scene.nodes) {
        if (node.mesh < 0 || node.mesh >= static_cast<int>(scene.meshes.size())) continue;
        if (node.skin < 0 || node.skin >= static_cast<int>(scene.skins.size())) continue;
        const std::size_t jointCount = scene.skins[static_cast<std::size_t>(node.skin)].joints.size();
        for (const auto& primitive : scene.meshes[static_cast<std::size_t>(node.mesh)].primitives) {
            if (!primitive.skinned) continue;
            for (const Vertex& vertex : primitive.vertices)
                for (int k = 0; k < 4; ++k)
                    if (vertex.weights[k] != 0.0f && vertex.joints[k] >= jointCount)
                        throw InputError(scene.sourceName, 0,
                                         "meshes[" + std::to_string(node.mesh) + "]",
                                         "vertex joint index " + std::to_string(vertex.joints[k]) +
                                             " exceeds skin '" + node.name + "' joint count " +
                                             std::to_string(jointCount));
        }
    }
    impl_->scenes.push_back(std::make_unique<vk::GpuScene>(*impl_->device, *impl_->commands, scene,
                                                           impl_->materialLayout.get()));
    // Compile the scene's pipeline variants now rather than on the first frame: every
    // material rigid, and skinned where a skinned primitive on a skinned node uses it.
    const vk::GpuScene& gpu = *impl_->scenes.back();
    bool hasTargets = false;
    for (const Mesh& mesh : scene.meshes) hasTargets = hasTargets || mesh.targetCount() > 0;
    impl_->morphs.push_back(hasTargets ? std::make_unique<vk::GpuMorphs>(*impl_->device, *impl_->commands, gpu,
                                                                         impl_->morphLayout.get())
                                       : nullptr);
    for (const auto& material : gpu.materials()) impl_->pipelineFor(material, false);
    // The same for morphed primitives (mesh_morph.vert), skinned or not.
    for (const Node& node : scene.nodes) {
        if (node.mesh < 0 || node.mesh >= static_cast<int>(scene.meshes.size())) continue;
        const bool hasSkin = node.skin >= 0 && node.skin < static_cast<int>(scene.skins.size());
        for (const auto& primitive : gpu.primitives(node.mesh)) {
            const bool skinned = hasSkin && primitive.skinned;
            if (skinned) impl_->pipelineFor(gpu.material(primitive.material), true);
            if (primitive.morphed) impl_->pipelineFor(gpu.material(primitive.material), skinned, true);
        }
    }
    return static_cast<int>(impl_->scenes.size() - 1);
}

void Renderer::render(const Frame& frame, Image& out) {
    if (!impl_->pending.empty())
        throw std::logic_error("Renderer::render while frames are in flight; retrieve() them");
    submit(frame);
    retrieve(out);
}

void Renderer::submit(const Frame& frame) {
    Impl& r = *impl_;
    if (r.pending.size() >= r.slots.size())
        throw std::logic_error("Renderer::submit: " + std::to_string(r.slots.size()) +
                               " frames already in flight; call retrieve() first");
    r.validateFrame(frame);
    const std::size_t index = r.nextSlot;
    Impl::Slot& slot = r.slots[index];
    r.recordFrame(slot, frame);

    VkFence fence = slot.fence.get();
    vk::check(vkResetFences(r.device->get(), 1, &fence), "vkResetFences");
    auto cmdInfo = vk::make<VkCommandBufferSubmitInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO);
    cmdInfo.commandBuffer = slot.cmd;
    auto submitInfo = vk::make<VkSubmitInfo2>(VK_STRUCTURE_TYPE_SUBMIT_INFO_2);
    submitInfo.commandBufferInfoCount = 1;
    submitInfo.pCommandBufferInfos = &cmdInfo;
    vk::check(vkQueueSubmit2(r.device->queue(), 1, &submitInfo, fence), "vkQueueSubmit2");
    r.pending.push_back(index);
    r.nextSlot = (index + 1) % r.slots.size();
}

void Renderer::retrieve(Image& out) {
    Impl& r = *impl_;
    if (r.pending.empty()) throw std::logic_error("Renderer::retrieve: no frame in flight");
    const std::size_t index = r.pending.front();
    Impl::Slot& slot = r.slots[index];
    VkFence fence = slot.fence.get();
    vk::check(vkWaitForFences(r.device->get(), 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    r.pending.pop_front();
    vk::convertReadback(slot.target->readback(), slot.target->extent(), r.options.format, out);
    for (const auto& [cell, text] : slot.labels) drawLabel(out, cell, text);
}

std::uint32_t Renderer::framesInFlight() const {
    return static_cast<std::uint32_t>(impl_->slots.size());
}

std::uint32_t Renderer::framesPending() const {
    return static_cast<std::uint32_t>(impl_->pending.size());
}

bool Renderer::validationEnabled() const { return impl_->instance->validation(); }

std::vector<std::string> Renderer::validationMessages() const {
    return impl_->instance->messages();
}

}  // namespace signstim::render
