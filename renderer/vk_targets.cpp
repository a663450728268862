#include "renderer/vk_targets.hpp"

#include "common/error.hpp"
#include "renderer/vk_check.hpp"
#include "renderer/vk_commands.hpp"

namespace signstim::render::vk {

std::uint32_t bytesPerPixel(VkFormat colorFormat) {
    switch (colorFormat) {
    case VK_FORMAT_R16G16B16A16_SFLOAT:
    case VK_FORMAT_R16G16B16A16_UNORM: return 8;
    default: return 4;
    }
}

VkFormat chooseDepthFormat(const Device& device) {
    for (VkFormat format : {VK_FORMAT_D32_SFLOAT, VK_FORMAT_D32_SFLOAT_S8_UINT,
                            VK_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_D16_UNORM}) {
        if (device.formatProperties(format).optimalTilingFeatures &
            VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT)
            return format;
    }
    throw EnvironmentError("Vulkan: the device offers no depth attachment format");
}

OffscreenTarget::OffscreenTarget(const Device& device, VkExtent2D extent,
                                 const TargetFormats& formats)
    : extent_(extent), formats_(formats) {
    const bool multisampled = formats.samples != VK_SAMPLE_COUNT_1_BIT;
    ImageDesc color;
    color.extent = extent;
    color.format = formats.color;
    color.samples = formats.samples;
    color.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                  (multisampled ? VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT
                                : VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    color_ = createImage(device, color);
    if (multisampled) {
        ImageDesc resolve = color;
        resolve.samples = VK_SAMPLE_COUNT_1_BIT;
        resolve.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        resolve_ = createImage(device, resolve);
    }
    ImageDesc depth;
    depth.extent = extent;
    depth.format = formats.depth;
    depth.samples = formats.samples;
    depth.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                  VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
    depth.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
    depth_ = createImage(device, depth);

    VkDeviceSize size =
        VkDeviceSize(extent.width) * extent.height * bytesPerPixel(formats.color);
    readback_ = createBuffer(device, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Readback);
}

void OffscreenTarget::beginRendering(VkCommandBuffer cmd, const VkClearColorValue& clear) const {
    const bool multisampled = static_cast<bool>(resolve_.image);
    // Attachments start UNDEFINED every frame (their old content is never needed); the
    // source stages order the writes after the previous frame's copy of the same images.
    ImageTransition colorTransition{color_.image.get(),
                                    VK_IMAGE_LAYOUT_UNDEFINED,
                                    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                    VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT |
                                        VK_PIPELINE_STAGE_2_COPY_BIT,
                                    VK_ACCESS_2_NONE,
                                    VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                    VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT |
                                        VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT};
    ImageTransition resolveTransition = colorTransition;
    resolveTransition.image = resolve_.image.get();
    ImageTransition depthTransition{
        depth_.image.get(),
        VK_IMAGE_LAYOUT_UNDEFINED,
        VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
        VK_ACCESS_2_NONE,
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
        VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
            VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
        VK_IMAGE_ASPECT_DEPTH_BIT};
    if (multisampled)
        transitionImages(cmd, {colorTransition, resolveTransition, depthTransition});
    else
        transitionImages(cmd, {colorTransition, depthTransition});

    auto colorAttachment = make<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    colorAttachment.imageView = color_.view.get();
    colorAttachment.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    colorAttachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    colorAttachment.storeOp =
        multisampled ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
    colorAttachment.clearValue.color = clear;
    if (multisampled) {
        colorAttachment.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
        colorAttachment.resolveImageView = resolve_.view.get();
        colorAttachment.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    }
    auto depthAttachment = make<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    depthAttachment.imageView = depth_.view.get();
    depthAttachment.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depthAttachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depthAttachment.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    depthAttachment.clearValue.depthStencil = {1.0f, 0};

    auto rendering = make<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
    rendering.renderArea = {{0, 0}, extent_};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &colorAttachment;
    rendering.pDepthAttachment = &depthAttachment;
    vkCmdBeginRendering(cmd, &rendering);
}

void OffscreenTarget::endRenderingAndCopy(VkCommandBuffer cmd) const {
    vkCmdEndRendering(cmd);
    VkImage source = resolve_.image ? resolve_.image.get() : color_.image.get();
    transitionImages(cmd, {{source, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                            VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                            VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                            VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                            VK_ACCESS_2_TRANSFER_READ_BIT}});
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent_.width, extent_.height, 1};
    vkCmdCopyImageToBuffer(cmd, source, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           readback_.buffer.get(), 1, &region);

    auto toHost = make<VkBufferMemoryBarrier2>(VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2);
    toHost.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    toHost.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    toHost.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
    toHost.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
    toHost.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.buffer = readback_.buffer.get();
    toHost.size = VK_WHOLE_SIZE;
    auto dependency = make<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
    dependency.bufferMemoryBarrierCount = 1;
    dependency.pBufferMemoryBarriers = &toHost;
    vkCmdPipelineBarrier2(cmd, &dependency);
}

}  // namespace signstim::render::vk
