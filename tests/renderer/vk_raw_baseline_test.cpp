// The raw baselines of `signstim bench render` (renderer/vk_raw_baseline.hpp), under
// VK_LAYER_KHRONOS_validation: the raw-lit loop must draw the Renderer's image of the bench
// frame (so renderer / raw-lit is overhead only), and the one-line loop must not (so the
// comparison can tell them apart).
#include "renderer/procedural.hpp"
#include "renderer/renderer.hpp"
#include "renderer/vk_raw_baseline.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

namespace signstim::render {
namespace {

struct Difference {
    int max = 0;
    double mean = 0;
};

Difference compare(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    Difference difference;
    if (a.size() != b.size() || a.empty()) return {255, 255.0};
    double sum = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const int d = std::abs(int(a[i]) - int(b[i]));
        difference.max = std::max(difference.max, d);
        sum += d;
    }
    difference.mean = sum / double(a.size());
    return difference;
}

void expectNoValidationMessages(const std::vector<std::string>& messages, const char* who) {
    for (const auto& message : messages) ADD_FAILURE() << who << " validation: " << message;
}

class RawBaselineTest : public ::testing::TestWithParam<std::uint32_t> {};

TEST_P(RawBaselineTest, RawLitDrawsTheRenderersImageOfTheBenchFrame) {
    const std::uint32_t msaa = GetParam();
    const Scene sphere = procedural::uvSphere(20000);

    RendererOptions options;
    options.width = 160;
    options.height = 120;
    options.msaa = msaa;
    options.validation = true;
    Image rendered;
    std::vector<std::string> rendererMessages;
    {
        Renderer renderer(options);
        ASSERT_TRUE(renderer.validationEnabled());
        Frame frame;  // the bench frame (app/render_bench.cpp benchFrame)
        View view;
        view.scene = renderer.addScene(sphere);
        view.camera.eye = {0.0f, 0.0f, 2.2f};
        view.camera.target = {0.0f, 0.0f, 0.0f};
        view.camera.verticalFovDegrees = 30.0f;
        view.camera.nearPlane = 0.1f;
        view.camera.farPlane = 10.0f;
        frame.views.push_back(view);
        renderer.render(frame, rendered);
        rendererMessages = renderer.validationMessages();
    }
    expectNoValidationMessages(rendererMessages, "renderer");

    auto rawImage = [&](RawShading shading) {
        RawBaselineSettings settings;
        settings.width = options.width;
        settings.height = options.height;
        settings.msaa = msaa;
        settings.shading = shading;
        settings.lighting = options.lighting;
        settings.validation = true;
        RawBaseline raw(sphere, settings);
        EXPECT_TRUE(raw.validationEnabled());
        raw.run(2);
        expectNoValidationMessages(raw.validationMessages(), "raw");
        return raw.pixels();
    };
    const auto lit = rawImage(RawShading::Lit);
    const auto oneLine = rawImage(RawShading::OneLine);

    ASSERT_EQ(rendered.format, PixelFormat::Rgba8);
    ASSERT_EQ(rendered.bytes.size(), lit.size());
    const Difference litDifference = compare(rendered.bytes, lit);
    EXPECT_LE(litDifference.max, 1) << "mean " << litDifference.mean;
    EXPECT_LT(litDifference.mean, 0.01);
    // The sphere covers part of the frame and is shaded: the image is not just background.
    const Difference fromBackground =
        compare(rendered.bytes, std::vector<std::uint8_t>(lit.size(), lit[0]));
    EXPECT_GT(fromBackground.max, 50);
    // One-line shading draws a visibly different image.
    const Difference oneLineDifference = compare(rendered.bytes, oneLine);
    EXPECT_GT(oneLineDifference.max, 20);
}

INSTANTIATE_TEST_SUITE_P(Msaa, RawBaselineTest, ::testing::Values(1u, 4u));

}  // namespace
}  // namespace signstim::render
