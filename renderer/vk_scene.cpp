#include "renderer/vk_scene.hpp"

#include "common/error.hpp"
#include "renderer/vk_check.hpp"
#include "renderer/vk_descriptors.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

namespace signstim::render::vk {

namespace {

static_assert(sizeof(Vertex) == 64, "shaders/mesh.vert expects the 64-byte render::Vertex");


GpuImage uploadImage(const Device& device, const CommandPool& commands, std::uint32_t width,
                  std::uint32_t height, const std::uint8_t* rgba, bool srgb, bool mipmaps) {
    VkFormat format = srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
    const auto features = device.formatProperties(format).optimalTilingFeatures;
    const bool canBlit = (features & VK_FORMAT_FEATURE_BLIT_SRC_BIT) &&
                         (features & VK_FORMAT_FEATURE_BLIT_DST_BIT) &&
                         (features & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT);
    ImageDesc desc;
    desc.extent = {width, height};
    desc.format = format;
    desc.mipLevels = mipmaps && canBlit ? std::bit_width(std::max(width, height)) : 1;
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                 (desc.mipLevels > 1 ? VK_IMAGE_USAGE_TRANSFER_SRC_BIT : 0);
    GpuImage image = createImage(device, desc);

    VkDeviceSize size = VkDeviceSize(width) * height * 4;
    Buffer staging = createBuffer(device, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Upload);
    std::memcpy(staging.mapped, rgba, size);
    VkImage handle = image.image.get();
    commands.submitAndWait([&](VkCommandBuffer cmd) {
        transitionImages(cmd, {{handle, VK_IMAGE_LAYOUT_UNDEFINED,
                                VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE,
                                VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                                VK_ACCESS_2_TRANSFER_WRITE_BIT}});
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {width, height, 1};
        vkCmdCopyBufferToImage(cmd, staging.buffer.get(), handle,
                               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        // Each level is blitted from the one above, which is first made a transfer source.
        std::int32_t w = static_cast<std::int32_t>(width), h = static_cast<std::int32_t>(height);
        for (std::uint32_t level = 1; level < desc.mipLevels; ++level) {
            ImageTransition toSource{handle,
                                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                     VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                     VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                                     VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                     VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                                     VK_ACCESS_2_TRANSFER_READ_BIT};
            toSource.baseMip = level - 1;
            toSource.mipCount = 1;
            transitionImages(cmd, {toSource});
            std::int32_t nextW = std::max(1, w / 2), nextH = std::max(1, h / 2);
            VkImageBlit blit{};
            blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, 1};
            blit.srcOffsets[1] = {w, h, 1};
            blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
            blit.dstOffsets[1] = {nextW, nextH, 1};
            vkCmdBlitImage(cmd, handle, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, handle,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
            w = nextW;
            h = nextH;
        }
        // Levels above the last are TRANSFER_SRC, the last is TRANSFER_DST.
        std::vector<VkImageMemoryBarrier2> barriers;
        if (desc.mipLevels > 1) {
            ImageTransition upper{handle,
                                  VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                  VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                  VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                                  VK_ACCESS_2_TRANSFER_READ_BIT,
                                  VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                                  VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
            upper.baseMip = 0;
            upper.mipCount = desc.mipLevels - 1;
            barriers.push_back(imageBarrier(upper));
        }
        ImageTransition last{handle,
                             VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                             VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                             VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                             VK_ACCESS_2_TRANSFER_WRITE_BIT,
                             VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                             VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
        last.baseMip = desc.mipLevels - 1;
        last.mipCount = 1;
        barriers.push_back(imageBarrier(last));
        auto dependency = make<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
        dependency.imageMemoryBarrierCount = static_cast<std::uint32_t>(barriers.size());
        dependency.pImageMemoryBarriers = barriers.data();
        vkCmdPipelineBarrier2(cmd, &dependency);
    });
    return image;
}

VkSamplerAddressMode addressMode(Wrap wrap) {
    switch (wrap) {
    case Wrap::ClampToEdge: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    case Wrap::MirroredRepeat: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    default: return VK_SAMPLER_ADDRESS_MODE_REPEAT;
    }
}

UniqueSampler makeSampler(const Device& device, const Texture& texture) {
    auto info = make<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
    info.magFilter = texture.magFilter == Filter::Nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
    info.minFilter = texture.minFilter == Filter::Nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
    info.mipmapMode = texture.minFilter == Filter::Nearest ? VK_SAMPLER_MIPMAP_MODE_NEAREST
                                                           : VK_SAMPLER_MIPMAP_MODE_LINEAR;
    info.addressModeU = addressMode(texture.wrapS);
    info.addressModeV = addressMode(texture.wrapT);
    info.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    info.maxLod = texture.mipmaps ? VK_LOD_CLAMP_NONE : 0.0f;
    VkSampler sampler = VK_NULL_HANDLE;
    check(vkCreateSampler(device.get(), &info, nullptr, &sampler), "vkCreateSampler");
    return UniqueSampler(device.get(), sampler);
}

}  // namespace

Buffer uploadBuffer(const Device& device, const CommandPool& commands, const void* data,
                    VkDeviceSize size, VkBufferUsageFlags usage) {
    size = std::max<VkDeviceSize>(size, 4);
    Buffer staging = createBuffer(device, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Upload);
    if (data != nullptr) std::memcpy(staging.mapped, data, size);
    Buffer target = createBuffer(device, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                 MemoryUse::DeviceLocal);
    commands.submitAndWait([&](VkCommandBuffer cmd) {
        VkBufferCopy region{0, 0, size};
        vkCmdCopyBuffer(cmd, staging.buffer.get(), target.buffer.get(), 1, &region);
    });
    return target;
}

FragmentConstants materialConstants(const Material& material, bool baseTexture, bool mrTexture) {
    FragmentConstants constants;
    constants.hasBaseColorTexture = baseTexture ? VK_TRUE : VK_FALSE;
    constants.hasMetallicRoughnessTexture = mrTexture ? VK_TRUE : VK_FALSE;
    constants.alphaMask = material.alphaMode == AlphaMode::Mask ? VK_TRUE : VK_FALSE;
    constants.alphaBlend = material.alphaMode == AlphaMode::Blend ? VK_TRUE : VK_FALSE;
    for (int c = 0; c < 4; ++c) constants.baseColor[c] = material.baseColorFactor[c];
    for (int c = 0; c < 3; ++c) constants.emissive[c] = material.emissiveFactor[c];
    constants.metallic = material.metallicFactor;
    constants.roughness = material.roughnessFactor;
    constants.alphaCutoff = material.alphaCutoff;
    // Same formulas and order as the textured path of shaders/mesh.frag.
    constexpr float kPi = 3.14159265f;
    const glm::vec3 base(material.baseColorFactor);
    const float metallic = std::clamp(material.metallicFactor, 0.0f, 1.0f);
    const float roughness = std::clamp(material.roughnessFactor, 0.04f, 1.0f);
    const glm::vec3 diffuse = base * (1.0f - metallic);
    const glm::vec3 f0 = glm::mix(glm::vec3(0.04f), base, metallic);
    const float alpha = roughness * roughness;
    const float shininess = std::clamp(2.0f / (alpha * alpha) - 2.0f, 1.0f, 2048.0f);
    const glm::vec3 diffuseOverPi = diffuse / kPi;
    const glm::vec3 specular = f0 * ((shininess + 8.0f) / (8.0f * kPi));
    const glm::vec3 ambientColor = diffuse + f0 * 0.5f;
    for (int c = 0; c < 3; ++c) {
        constants.diffuseOverPi[c] = diffuseOverPi[c];
        constants.specular[c] = specular[c];
        constants.ambientColor[c] = ambientColor[c];
    }
    constants.exponent = shininess * 1.4427f;
    return constants;
}

const GpuImage& GpuScene::textureImage(const Device& device, const CommandPool& commands, int index,
                                    bool srgb) {
    auto key = std::make_pair(index, srgb);
    auto found = images_.find(key);
    if (found != images_.end()) return found->second;
    const ImageData& data = cpu_.images.at(static_cast<std::size_t>(index));
    if (data.width == 0 || data.height == 0 ||
        data.rgba.size() != std::size_t(data.width) * data.height * 4)
        throw InputError(cpu_.sourceName, 0, "/images/" + std::to_string(index),
                         "image '" + data.name + "' has no decoded RGBA pixels");
    GpuImage image = uploadImage(device, commands, data.width, data.height, data.rgba.data(), srgb,
                              true);
    return images_.emplace(key, std::move(image)).first->second;
}

VkSampler GpuScene::sampler(const Device& device, const Texture& texture) {
    samplers_.push_back(makeSampler(device, texture));
    return samplers_.back().get();
}

GpuScene::GpuScene(const Device& device, const CommandPool& commands, Scene scene,
                   VkDescriptorSetLayout materialLayout)
    : cpu_(std::move(scene)) {
    // Geometry: everything in one vertex and one index buffer.
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    meshes_.resize(cpu_.meshes.size());
    const auto defaultMaterial = static_cast<std::uint32_t>(cpu_.materials.size());
    for (std::size_t m = 0; m < cpu_.meshes.size(); ++m) {
        for (const auto& primitive : cpu_.meshes[m].primitives) {
            GpuPrimitive gpu;
            gpu.firstIndex = static_cast<std::uint32_t>(indices.size());
            gpu.indexCount = static_cast<std::uint32_t>(primitive.indices.size());
            gpu.vertexOffset = static_cast<std::int32_t>(vertices.size());
            gpu.material = primitive.material >= 0 &&
                                   primitive.material < static_cast<int>(cpu_.materials.size())
                               ? static_cast<std::uint32_t>(primitive.material)
                               : defaultMaterial;
            gpu.skinned = primitive.skinned;
            gpu.morphed = !primitive.targets.empty();
            for (std::uint32_t index : primitive.indices) {
                if (index >= primitive.vertices.size())
                    throw InputError(cpu_.sourceName, 0, "/meshes/" + std::to_string(m),
                                     "index " + std::to_string(index) + " out of range");
            }
            vertices.insert(vertices.end(), primitive.vertices.begin(), primitive.vertices.end());
            indices.insert(indices.end(), primitive.indices.begin(), primitive.indices.end());
            triangles_ += primitive.indices.size() / 3;
            meshes_[m].push_back(gpu);
        }
    }
    vertices_ = uploadBuffer(device, commands, vertices.empty() ? nullptr : vertices.data(),
                             vertices.size() * sizeof(Vertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    indices_ = uploadBuffer(device, commands, indices.empty() ? nullptr : indices.data(),
                            indices.size() * sizeof(std::uint32_t),
                            VK_BUFFER_USAGE_INDEX_BUFFER_BIT);

    // Default textures (white) stand in for absent ones so every set is complete.
    const std::uint8_t white[4] = {255, 255, 255, 255};
    whiteSrgb_ = uploadImage(device, commands, 1, 1, white, true, false);
    whiteLinear_ = uploadImage(device, commands, 1, 1, white, false, false);
    defaultSampler_ = makeSampler(device, Texture{});

    std::vector<Material> materials = cpu_.materials;
    Material fallback;  // glTF default material: white, fully rough, dielectric
    fallback.metallicFactor = 0.0f;
    materials.push_back(fallback);

    descriptorPool_ = createDescriptorPool(
        device.get(), static_cast<std::uint32_t>(materials.size()),
        {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2}});
    for (std::size_t i = 0; i < materials.size(); ++i) {
        const Material& material = materials[i];
        auto textureOf = [&](int index) -> const Texture* {
            if (index < 0 || index >= static_cast<int>(cpu_.textures.size())) return nullptr;
            const Texture& texture = cpu_.textures[static_cast<std::size_t>(index)];
            if (texture.image < 0 || texture.image >= static_cast<int>(cpu_.images.size()))
                return nullptr;
            return &texture;
        };
        const Texture* baseTexture = textureOf(material.baseColorTexture);
        const Texture* mrTexture = textureOf(material.metallicRoughnessTexture);


        VkImageView baseView = whiteSrgb_.view.get(), mrView = whiteLinear_.view.get();
        VkSampler baseSampler = defaultSampler_.get(), mrSampler = defaultSampler_.get();
        if (baseTexture) {
            baseView = textureImage(device, commands, baseTexture->image, true).view.get();
            baseSampler = sampler(device, *baseTexture);
        }
        if (mrTexture) {
            mrView = textureImage(device, commands, mrTexture->image, false).view.get();
            mrSampler = sampler(device, *mrTexture);
        }
        GpuMaterial gpu;
        gpu.alphaMode = material.alphaMode;
        gpu.doubleSided = material.doubleSided;
        gpu.hasBaseColorTexture = baseTexture != nullptr;
        gpu.hasMetallicRoughnessTexture = mrTexture != nullptr;
        gpu.constants = materialConstants(material, baseTexture != nullptr, mrTexture != nullptr);
        gpu.set = allocateSet(device.get(), descriptorPool_.get(), materialLayout);
        DescriptorWriter()
            .image(1, baseView, baseSampler)
            .image(2, mrView, mrSampler)
            .update(device.get(), gpu.set);
        materials_.push_back(gpu);
    }
}

}  // namespace signstim::render::vk
