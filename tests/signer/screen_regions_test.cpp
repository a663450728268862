// Eye-tracking regions (signer/screen_regions.hpp) against rendered pixels (lavapipe): a
// region's box holds every pixel of what it names, and is not much larger. What a hand (or the
// head) covers is found by rendering the same pose twice, once with that bone scaled to nothing:
// every pixel that differs is the hand's (or what it hid), so it must lie in the hand's box.
// Set SIGNSTIM_REGIONS_PNG=FILE to write the 2×2 frame with its boxes drawn (for a person to look at).
#include "signer/avatar_builder.hpp"
#include "signer/avatar_render.hpp"
#include "signer/screen_regions.hpp"
#include "renderer/image_io.hpp"
#include "renderer/renderer.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>

using namespace signstim;

namespace {

struct PixelBox {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;  // [x0, x1) × [y0, y1)
    int count = 0;
    void add(int x, int y) {
        x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x + 1), y1 = std::max(y1, y + 1);
        ++count;
    }
    long long area() const { return count == 0 ? 0 : static_cast<long long>(x1 - x0) * (y1 - y0); }
};

PixelBox differingPixels(const render::Image& a, const render::Image& b) {
    PixelBox box;
    for (std::uint32_t y = 0; y < a.height; ++y)
        for (std::uint32_t x = 0; x < a.width; ++x) {
            const std::size_t i = (static_cast<std::size_t>(y) * a.width + x) * 4;
            int d = 0;
            for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.bytes[i + c]) - int(b.bytes[i + c])));
            if (d > 2) box.add(static_cast<int>(x), static_cast<int>(y));  // > 2: beyond rounding
        }
    return box;
}

bool inside(const PixelBox& pixels, const signer::ScreenBox& box) {
    return box.visible && pixels.x0 >= box.x0 && pixels.y0 >= box.y0 && pixels.x1 <= box.x1 && pixels.y1 <= box.y1;
}

long long area(const signer::ScreenBox& b) { return static_cast<long long>(b.x1 - b.x0) * (b.y1 - b.y0); }

void drawBox(render::Image& image, const signer::ScreenBox& b, std::uint8_t r, std::uint8_t g, std::uint8_t bl) {
    if (!b.visible) return;
    const auto put = [&](int x, int y) {
        const std::size_t i = (static_cast<std::size_t>(y) * image.width + static_cast<std::size_t>(x)) * 4;
        image.bytes[i] = r, image.bytes[i + 1] = g, image.bytes[i + 2] = bl;
    };
    for (int x = b.x0; x < b.x1; ++x) put(x, b.y0), put(x, b.y1 - 1);
    for (int y = b.y0; y < b.y1; ++y) put(b.x0, y), put(b.x1 - 1, y);
}

class ScreenRegions : public ::testing::Test {
protected:
    render::Scene avatar = signer::buildDefaultAvatar();
    signer::SignerRig rig{avatar};
    signer::ScreenRegionModel model{avatar, rig};

    // The right hand beside the shoulder, fingers open; the left at rest.
    signer::SignerPosture presenting() const {
        signer::SignerPosture p;
        p.rightWrist = rig.presentingTarget(hand::Side::Right);
        p.leftWrist = rig.restingTarget(hand::Side::Left);
        p.leftHand = signer::relaxedHand();
        return p;
    }
    // `pose` with the bone (and so everything it carries) scaled to nothing.
    render::Pose without(render::Pose pose, const std::string& bone) const {
        pose.local[static_cast<std::size_t>(rig.boneNode(bone))].scale = glm::vec3(1e-4f);
        return pose;
    }
};

}  // namespace

TEST_F(ScreenRegions, RightHandBoxHoldsEveryPixelOfTheHandInOneView) {
    const std::uint32_t w = 320, h = 240;
    render::Renderer renderer(signer::signerRendererOptions(w, h, 1, ""));
    const int handle = renderer.addScene(avatar);
    const render::Camera camera = signer::clipCamera(avatar, rig, w, h, 1, 1);
    const render::Pose pose = rig.pose(presenting());
    render::Frame frame;
    frame.views.push_back({handle, pose, camera, ""});
    render::Image with, withoutHand;
    renderer.render(frame, with);
    frame.views[0].pose = without(pose, "rightHand");
    renderer.render(frame, withoutHand);

    const auto boxes = model.boxes(pose, camera, render::viewCell(w, h, 1, 1, 0));
    const signer::ScreenBox& right = boxes[1];
    const PixelBox hand = differingPixels(with, withoutHand);
    ASSERT_GT(hand.count, 30) << "the hand should cover pixels";
    EXPECT_TRUE(inside(hand, right)) << "hand pixels [" << hand.x0 << "," << hand.y0 << ")-[" << hand.x1 << ","
                                     << hand.y1 << ") box [" << right.x0 << "," << right.y0 << ")-[" << right.x1
                                     << "," << right.y1 << ")";
    // Not absurdly large: the margin (10 mm) and the bones' boxes add at most a little.
    EXPECT_LT(area(right), 3 * hand.area());
    // The signer's right hand is on the viewer's left, beside the face, not on it.
    EXPECT_LT(right.x1, boxes[0].x1);
    // The signing space holds both hands and the face.
    for (std::size_t r = 0; r < 3; ++r) {
        EXPECT_LE(boxes[3].x0, boxes[r].x0);
        EXPECT_GE(boxes[3].x1, boxes[r].x1);
    }
}

TEST_F(ScreenRegions, BoxesOfAPanelOfATwoByTwoFrameHoldTheirPixels) {
    const std::uint32_t w = 320, h = 240;
    render::Renderer renderer(signer::signerRendererOptions(w, h, 1, ""));
    const int handle = renderer.addScene(avatar);
    const render::Camera camera = signer::clipCamera(avatar, rig, w, h, 2, 2);
    const render::Pose rest = rig.pose(signer::SignerPosture{});
    const render::Pose pose = rig.pose(presenting());
    render::Frame frame;
    frame.columns = frame.rows = 2;
    for (const char* label : {"A", "B", "C", "D"}) frame.views.push_back({handle, rest, camera, label});
    frame.views[3].pose = pose;  // panel D shows the hand raised
    render::Image with, withoutHand, withoutHead;
    renderer.render(frame, with);
    frame.views[3].pose = without(pose, "rightHand");
    renderer.render(frame, withoutHand);
    frame.views[3].pose = without(pose, "head");
    renderer.render(frame, withoutHead);

    const render::ViewCell cell = render::viewCell(w, h, 2, 2, 3);
    const auto boxes = model.boxes(pose, camera, cell);
    const PixelBox hand = differingPixels(with, withoutHand), head = differingPixels(with, withoutHead);
    ASSERT_GT(hand.count, 10);
    ASSERT_GT(head.count, 10);
    EXPECT_TRUE(inside(hand, boxes[1]));
    EXPECT_TRUE(inside(head, boxes[0]));
    EXPECT_LT(area(boxes[1]), 3 * hand.area());
    EXPECT_LT(area(boxes[0]), 3 * head.area());
    for (const signer::ScreenBox& b : boxes) {  // within panel D's cell
        EXPECT_GE(b.x0, static_cast<int>(cell.x));
        EXPECT_GE(b.y0, static_cast<int>(cell.y));
        EXPECT_LE(b.x1, static_cast<int>(cell.x + cell.width));
        EXPECT_LE(b.y1, static_cast<int>(cell.y + cell.height));
    }

    if (const char* png = std::getenv("SIGNSTIM_REGIONS_PNG")) {
        for (std::size_t k = 0; k < 4; ++k) {
            const auto b = model.boxes(k == 3 ? pose : rest, camera, render::viewCell(w, h, 2, 2, k));
            drawBox(with, b[0], 255, 255, 0);
            drawBox(with, b[1], 255, 0, 0);
            drawBox(with, b[2], 0, 255, 0);
            drawBox(with, b[3], 255, 255, 255);
        }
        render::writeImage(with, png);
    }
}

TEST_F(ScreenRegions, CsvHasOneRowPerFramePanelAndRegionInsideItsPanel) {
    // A clip that holds the presenting posture for half a second (synthetic).
    struct Still final : signer::Clip {
        signer::SignerPosture posture;
        double durationSeconds() const override { return 0.5; }
        signer::SignerPosture postureAt(double) const override { return posture; }
    } still;
    still.posture = presenting();
    const std::string csv =
        signer::screenRegionsCsv(avatar, rig, model, {&still, &still}, {"A", "B"}, 10.0, 640, 240, 2, 1);
    std::istringstream in(csv);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "frame,time_ms,panel,region,x0,y0,x1,y1,visible");
    int rows = 0;
    while (std::getline(in, line)) {
        ++rows;
        std::istringstream fields(line);
        std::string frame, ms, panel, region, x0, y0, x1, y1, visible;
        std::getline(fields, frame, ',');
        std::getline(fields, ms, ',');
        std::getline(fields, panel, ',');
        std::getline(fields, region, ',');
        std::getline(fields, x0, ',');
        std::getline(fields, y0, ',');
        std::getline(fields, x1, ',');
        std::getline(fields, y1, ',');
        std::getline(fields, visible, ',');
        EXPECT_EQ(std::stoi(ms), std::stoi(frame) * 100);
        ASSERT_EQ(visible, "1") << line;
        const int left = panel == "A" ? 0 : 320;
        EXPECT_GE(std::stoi(x0), left) << line;
        EXPECT_LE(std::stoi(x1), left + 320) << line;
        EXPECT_LT(std::stoi(y0), std::stoi(y1)) << line;
    }
    EXPECT_EQ(rows, 6 * 2 * 4);  // frames 0..5 (0.5 s at 10 fps, both ends), 2 panels, 4 regions
}
