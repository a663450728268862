// Vulkan renderer tests. Every Renderer here runs with VK_LAYER_KHRONOS_validation and the
// fixture fails the test on any validation message. Golden images: see vk_golden.hpp.
#include "common/error.hpp"
#include "renderer/label_overlay.hpp"
#include "renderer/procedural.hpp"
#include "renderer/renderer.hpp"
#include "tests/renderer/vk_golden.hpp"

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <set>

namespace signstim::render {
namespace {

constexpr std::uint32_t kSize = 256;

RendererOptions testOptions(std::uint32_t msaa = 1, PixelFormat format = PixelFormat::Rgba8) {
    RendererOptions options;
    options.width = options.height = kSize;
    options.msaa = msaa;
    options.format = format;
    options.validation = true;
    return options;
}

// A view of `scene` framed by its bounds in `pose` (rest pose when empty).
View framedView(const Scene& scene, int handle, Pose pose, float aspect = 1.0f,
                std::string label = {}) {
    View view;
    view.scene = handle;
    const Pose& bounded = pose.local.empty() ? restPose(scene) : pose;
    view.camera = frameBounds(computeBounds(scene, bounded), aspect);
    view.pose = std::move(pose);
    view.label = std::move(label);
    return view;
}

// The cylinder's "bend" animation (0..90 deg about Z over 1 s) sampled at `timeSeconds`.
Pose bentCylinderPose(const Scene& cylinder, float timeSeconds) {
    Pose pose = restPose(cylinder);
    applyAnimation(cylinder, cylinder.findAnimation("bend"), timeSeconds, pose);
    return pose;
}

Frame singleView(View view) {
    Frame frame;
    frame.views.push_back(std::move(view));
    return frame;
}

const std::uint8_t* pixel(const Image& image, std::uint32_t x, std::uint32_t y) {
    return &image.bytes[(std::size_t(y) * image.width + x) * 4];
}

class VulkanRendererTest : public ::testing::Test {
protected:
    void TearDown() override {
        for (auto& renderer : renderers_) {
            const auto messages = renderer->validationMessages();
            for (const auto& message : messages) ADD_FAILURE() << "validation: " << message;
        }
        renderers_.clear();
    }
    Renderer& make(const RendererOptions& options) {
        renderers_.push_back(std::make_unique<Renderer>(options));
        EXPECT_TRUE(renderers_.back()->validationEnabled());
        return *renderers_.back();
    }
    Image renderOne(Renderer& renderer, const Scene& scene, Pose pose = {}) {
        const int handle = renderer.addScene(scene);
        Image image;
        renderer.render(singleView(framedView(scene, handle, std::move(pose))), image);
        return image;
    }
    std::vector<std::unique_ptr<Renderer>> renderers_;
};

TEST_F(VulkanRendererTest, LitCubeMatchesGolden) {
    Renderer& renderer = make(testOptions());
    Image image = renderOne(renderer, procedural::litCube());
    ASSERT_EQ(image.width, kSize);
    ASSERT_EQ(image.bytes.size(), std::size_t(kSize) * kSize * 4);
    EXPECT_EQ(testing::compareWithGolden(image, "lit_cube"), "");
}

TEST_F(VulkanRendererTest, TexturedQuadMatchesGolden) {
    Renderer& renderer = make(testOptions());
    Image image = renderOne(renderer, procedural::texturedQuad());
    EXPECT_EQ(testing::compareWithGolden(image, "textured_quad"), "");
}

TEST_F(VulkanRendererTest, SkinnedCylinderAtTwoAnimationTimesMatchesGolden) {
    Renderer& renderer = make(testOptions());
    const Scene cylinder = procedural::skinnedCylinder();
    const int handle = renderer.addScene(cylinder);
    // One fixed camera for both times so the bend itself is what changes.
    const Camera camera = frameBounds(computeBounds(cylinder, bentCylinderPose(cylinder, 0.0f)), 1.0f);
    Image rest, bent;
    for (auto [time, image] : {std::pair{0.0f, &rest}, std::pair{1.0f, &bent}}) {
        View view;
        view.scene = handle;
        view.pose = bentCylinderPose(cylinder, time);
        view.camera = camera;
        renderer.render(singleView(view), *image);
    }
    EXPECT_EQ(testing::compareWithGolden(rest, "skinned_cylinder_t0"), "");
    EXPECT_EQ(testing::compareWithGolden(bent, "skinned_cylinder_t1"), "");
    EXPECT_NE(rest.bytes, bent.bytes);
}

TEST_F(VulkanRendererTest, TwoByTwoFrameWithLabelsMatchesGolden) {
    Renderer& renderer = make(testOptions());
    const Scene scenes[4] = {procedural::litCube(), procedural::texturedQuad(),
                             procedural::skinnedCylinder(), procedural::uvSphere(2000)};
    Frame frame;
    frame.columns = frame.rows = 2;
    const char* labels[4] = {"A", "B", "C", "D"};
    for (int i = 0; i < 4; ++i) {
        const int handle = renderer.addScene(scenes[i]);
        Pose pose = i == 2 ? bentCylinderPose(scenes[i], 0.5f) : Pose{};
        frame.views.push_back(framedView(scenes[i], handle, pose, 1.0f, labels[i]));
    }
    Image image;
    renderer.render(frame, image);
    EXPECT_EQ(testing::compareWithGolden(image, "multiview_2x2_labels"), "");
}

TEST_F(VulkanRendererTest, Msaa4DiffersAtEdgesButMatchesInFlatAreas) {
    const Scene cube = procedural::litCube();
    Image single = renderOne(make(testOptions(1)), cube);
    Image multi = renderOne(make(testOptions(4)), cube);
    ASSERT_EQ(single.bytes.size(), multi.bytes.size());
    std::size_t edgeDifferences = 0, flatPixels = 0, flatDifferences = 0;
    for (std::uint32_t y = 1; y + 1 < kSize; ++y) {
        for (std::uint32_t x = 1; x + 1 < kSize; ++x) {
            // Flat: the 3x3 neighbourhood of the 1x image varies by at most 2 per channel.
            bool flat = true;
            for (int dy = -1; dy <= 1 && flat; ++dy)
                for (int dx = -1; dx <= 1 && flat; ++dx)
                    for (int c = 0; c < 4; ++c)
                        if (std::abs(int(pixel(single, x + dx, y + dy)[c]) -
                                     int(pixel(single, x, y)[c])) > 2)
                            flat = false;
            int maxDelta = 0;
            for (int c = 0; c < 4; ++c)
                maxDelta = std::max(maxDelta, std::abs(int(pixel(single, x, y)[c]) -
                                                       int(pixel(multi, x, y)[c])));
            if (flat) {
                ++flatPixels;
                if (maxDelta > 1) ++flatDifferences;
            } else if (maxDelta > 8) {
                ++edgeDifferences;
            }
        }
    }
    EXPECT_GT(flatPixels, std::size_t(kSize) * kSize / 2);
    EXPECT_EQ(flatDifferences, 0u);
    EXPECT_GT(edgeDifferences, 100u);  // the cube's silhouette is antialiased
}

TEST_F(VulkanRendererTest, UnsupportedMsaaIsRefusedNamingSupportedCounts) {
    for (std::uint32_t msaa : {3u, 64u}) {
        RendererOptions options = testOptions(msaa);
        try {
            Renderer renderer(options);
            ADD_FAILURE() << "--msaa " << msaa << " was accepted";
        } catch (const InputError& error) {
            const std::string text = error.what();
            EXPECT_NE(text.find("--msaa " + std::to_string(msaa) + ": device '"), std::string::npos)
                << text;
            EXPECT_NE(text.find("supports 1"), std::string::npos) << text;
        }
    }
}

TEST_F(VulkanRendererTest, TransparentBackgroundLeavesZeroAlphaOutsideTheObject) {
    RendererOptions options = testOptions();
    options.background = {0.0f, 0.0f, 0.0f, 0.0f};
    Image image = renderOne(make(options), procedural::litCube());
    EXPECT_EQ(pixel(image, 0, 0)[3], 0);
    EXPECT_EQ(pixel(image, kSize - 1, kSize - 1)[3], 0);
    EXPECT_EQ(pixel(image, kSize / 2, kSize / 2)[3], 255);
    std::size_t transparent = 0;
    for (std::size_t i = 3; i < image.bytes.size(); i += 4) transparent += image.bytes[i] == 0;
    EXPECT_GT(transparent, image.bytes.size() / 4 / 4);
}

TEST_F(VulkanRendererTest, Rgba16ReadbackAgreesWithRgba8) {
    const Scene sphere = procedural::uvSphere(2000);  // smooth shading: many distinct levels
    Image eight = renderOne(make(testOptions(1, PixelFormat::Rgba8)), sphere);
    Image sixteen = renderOne(make(testOptions(1, PixelFormat::Rgba16)), sphere);
    ASSERT_EQ(sixteen.format, PixelFormat::Rgba16);
    ASSERT_EQ(sixteen.bytes.size(), eight.bytes.size() * 2);
    const auto* wide = reinterpret_cast<const std::uint16_t*>(sixteen.bytes.data());
    int maxDelta = 0;
    std::set<std::uint16_t> lowBits;
    for (std::size_t i = 0; i < eight.bytes.size(); ++i) {
        maxDelta = std::max(maxDelta, std::abs(int(std::lround(wide[i] / 257.0)) - int(eight.bytes[i])));
        lowBits.insert(static_cast<std::uint16_t>(wide[i] % 257));
    }
    EXPECT_LE(maxDelta, 2);
    EXPECT_GT(lowBits.size(), 16u);  // real 16-bit precision, not 8-bit values widened
    EXPECT_EQ(wide[3], 65535);       // opaque background
}

TEST_F(VulkanRendererTest, BlendedMaterialMixesWithTheBackground) {
    RendererOptions options = testOptions();
    options.background = {0.0f, 0.0f, 0.0f, 1.0f};
    Scene quad = procedural::texturedQuad();
    quad.materials[0].baseColorTexture = -1;
    quad.materials[0].baseColorFactor = {1.0f, 1.0f, 1.0f, 1.0f};
    Renderer& renderer = make(options);
    Image opaque = renderOne(renderer, quad);
    quad.materials[0].alphaMode = AlphaMode::Blend;
    quad.materials[0].baseColorFactor.a = 0.5f;
    Image blended = renderOne(renderer, quad);
    const std::uint8_t* full = pixel(opaque, kSize / 2, kSize / 2);
    const std::uint8_t* half = pixel(blended, kSize / 2, kSize / 2);
    ASSERT_GT(full[0], 100);
    // Half coverage over black in linear light: about 0.5 linear, i.e. ~186/255 in sRGB of 1.0.
    EXPECT_LT(half[0], full[0]);
    EXPECT_GT(half[0], full[0] / 2);
    EXPECT_EQ(pixel(blended, 0, 0)[0], pixel(opaque, 0, 0)[0]);  // background untouched
}

TEST_F(VulkanRendererTest, MaskedMaterialCutsOutBelowTheCutoff) {
    RendererOptions options = testOptions();
    options.background = {0.0f, 0.0f, 0.0f, 0.0f};
    Scene quad = procedural::texturedQuad();
    // Dark checker squares become fully transparent texels.
    for (std::size_t i = 0; i < quad.images[0].rgba.size(); i += 4)
        quad.images[0].rgba[i + 3] = quad.images[0].rgba[i] < 128 ? 0 : 255;
    quad.textures[0].magFilter = quad.textures[0].minFilter = Filter::Nearest;
    quad.materials[0].alphaMode = AlphaMode::Mask;
    Image image = renderOne(make(options), quad);
    std::size_t cut = 0, kept = 0;
    // Inside the quad (its middle half), pixels are either background or opaque surface.
    for (std::uint32_t y = kSize / 4; y < 3 * kSize / 4; ++y)
        for (std::uint32_t x = kSize / 4; x < 3 * kSize / 4; ++x) {
            const std::uint8_t alpha = pixel(image, x, y)[3];
            cut += alpha == 0;
            kept += alpha == 255;
        }
    const std::size_t total = std::size_t(kSize / 2) * (kSize / 2);
    EXPECT_EQ(cut + kept, total);
    EXPECT_GT(cut, total / 3);
    EXPECT_GT(kept, total / 3);
}

TEST_F(VulkanRendererTest, EnvironmentVariableTurnsValidationOn) {
    RendererOptions options = testOptions();
    options.validation = false;
    ::setenv("SIGNSTIM_VALIDATION", "1", 1);
    renderers_.push_back(std::make_unique<Renderer>(options));
    ::unsetenv("SIGNSTIM_VALIDATION");
    EXPECT_TRUE(renderers_.back()->validationEnabled());
    options.validation = false;
    Renderer plain(options);
    EXPECT_FALSE(plain.validationEnabled());
}

TEST_F(VulkanRendererTest, PipelinedFramesComeBackInOrderAndMatchSynchronousOnes) {
    Renderer& renderer = make(testOptions());
    ASSERT_GE(renderer.framesInFlight(), 2u);
    const Scene cylinder = procedural::skinnedCylinder();
    const int handle = renderer.addScene(cylinder);
    const Camera camera = frameBounds(computeBounds(cylinder, restPose(cylinder)), 1.0f);
    std::vector<Frame> frames;
    for (int i = 0; i < 5; ++i) {
        View view;
        view.scene = handle;
        view.camera = camera;
        view.pose = bentCylinderPose(cylinder, 0.25f * float(i));
        frames.push_back(singleView(view));
    }
    std::vector<Image> synchronous(frames.size()), pipelined;
    for (std::size_t i = 0; i < frames.size(); ++i) renderer.render(frames[i], synchronous[i]);
    std::size_t next = 0;
    while (pipelined.size() < frames.size()) {
        while (next < frames.size() && renderer.framesPending() < renderer.framesInFlight())
            renderer.submit(frames[next++]);
        pipelined.emplace_back();
        renderer.retrieve(pipelined.back());
    }
    for (std::size_t i = 0; i < frames.size(); ++i)
        EXPECT_EQ(pipelined[i].bytes, synchronous[i].bytes) << "frame " << i;
    EXPECT_NE(synchronous[0].bytes, synchronous[4].bytes);
    EXPECT_THROW(renderer.retrieve(pipelined[0]), std::logic_error);
}

TEST_F(VulkanRendererTest, InvalidFramesAreRefusedWithInputError) {
    Renderer& renderer = make(testOptions());
    const Scene cube = procedural::litCube();
    const int handle = renderer.addScene(cube);
    Image image;
    View view = framedView(cube, handle, {});
    view.scene = 7;
    EXPECT_THROW(renderer.render(singleView(view), image), InputError);
    view = framedView(cube, handle, {});
    view.pose.local.resize(5);
    EXPECT_THROW(renderer.render(singleView(view), image), InputError);
    view = framedView(cube, handle, {});
    view.camera.target = view.camera.eye;
    EXPECT_THROW(renderer.render(singleView(view), image), InputError);
    Frame crowded = singleView(framedView(cube, handle, {}));
    crowded.views.push_back(crowded.views[0]);
    EXPECT_THROW(renderer.render(crowded, image), InputError);
    // The renderer is still usable afterwards.
    renderer.render(singleView(framedView(cube, handle, {})), image);
    EXPECT_EQ(image.width, kSize);
}

TEST_F(VulkanRendererTest, UnknownDeviceIsRefusedListingDevices) {
    RendererOptions options = testOptions();
    options.device = "no-such-gpu";
    try {
        Renderer renderer(options);
        ADD_FAILURE() << "unknown device accepted";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("devices: 0 '"), std::string::npos) << error.what();
    }
}

TEST(VulkanDevices, AtLeastOneUsableDeviceSupportsSingleSampling) {
    const auto devices = Renderer::listDevices();
    ASSERT_FALSE(devices.empty());
    bool usable = false;
    for (const auto& device : devices) {
        usable = usable || device.usable;
        EXPECT_FALSE(device.name.empty());
        EXPECT_NE(std::find(device.sampleCounts.begin(), device.sampleCounts.end(), 1u),
                  device.sampleCounts.end());
    }
    EXPECT_TRUE(usable);
}

TEST(LabelOverlay, EveryPrintableGlyphIsDistinct) {
    std::set<std::vector<std::uint8_t>> seen;
    for (char c = 33; c < 127; ++c) {
        const std::uint8_t* columns = glyphColumns(c);
        std::vector<std::uint8_t> glyph(columns, columns + 5);
        EXPECT_TRUE(seen.insert(glyph).second) << "glyph '" << c << "' duplicates another";
        EXPECT_NE(std::count(glyph.begin(), glyph.end(), 0), 5) << "glyph '" << c << "' is empty";
    }
}

TEST(LabelOverlay, LabelIsDrawnInsideItsCellAndScalesWithIt) {
    Image image;
    image.width = 256;
    image.height = 256;
    image.bytes.assign(256 * 256 * 4, 128);
    drawLabel(image, {128, 128, 128, 128}, "D");
    std::size_t ink = 0, outside = 0;
    for (std::uint32_t y = 0; y < 256; ++y)
        for (std::uint32_t x = 0; x < 256; ++x) {
            const bool changed = pixel(image, x, y)[0] != 128;
            if (changed && (x < 128 || y < 128)) ++outside;
            ink += pixel(image, x, y)[0] == 255;
        }
    EXPECT_EQ(outside, 0u);
    EXPECT_EQ(labelScale(128), 2u);
    EXPECT_GT(ink, 4u * 14u);  // 'D' has 14 lit cells at scale 2 (4 pixels each)
}

}  // namespace
}  // namespace signstim::render
