// The contact sheet of `signstim sign --out FILE.png` (renderer/contact_sheet.hpp).
#include "renderer/contact_sheet.hpp"

#include <gtest/gtest.h>

using namespace signstim::render;

namespace {

// An RGBA8 frame of one colour.
Image frameOf(std::uint32_t width, std::uint32_t height, std::uint8_t value) {
    Image image;
    image.width = width;
    image.height = height;
    image.bytes.assign(static_cast<std::size_t>(width) * height * 4, value);
    return image;
}

}  // namespace

TEST(ContactSheet, KeepsTheWindowsFramesHalvedInRowsAndMarksTheMarkedOnes) {
    // 10 frames at 10 fps (0.0 .. 0.9 s); the window 0.2 .. 0.6 s keeps frames 2..6; 0.4 s is marked.
    ContactSheetSink sink(10.0, 0.2, 0.6, {0.4});
    for (int i = 0; i < 10; ++i) sink.push(frameOf(100, 50, static_cast<std::uint8_t>(10 * i)));
    EXPECT_EQ(sink.framesPushed(), 10u);
    ASSERT_EQ(sink.kept(), 5u);
    // Tiles: 60 % of 100 across, 80 % of 50 down, halved: 30 x 20; 3 a row, 4 px apart.
    const Image sheet = sink.sheet(3);
    EXPECT_EQ(sheet.width, 3u * 30 + 2 * 4);
    EXPECT_EQ(sheet.height, 2u * 20 + 4);
    const auto pixel = [&](std::uint32_t x, std::uint32_t y, int c) {
        return sheet.bytes[(static_cast<std::size_t>(y) * sheet.width + x) * 4 + static_cast<std::size_t>(c)];
    };
    // Below the bars, each tile shows its own frame (frame 2 first, frame 3 next).
    EXPECT_EQ(pixel(5, 15, 0), 20);
    EXPECT_EQ(pixel(34 + 5, 15, 0), 30);
    // Frame 4 (0.4 s, the third tile) carries the red bar, 10 px deep; frame 2 a grey one of 3.
    EXPECT_EQ(pixel(68 + 5, 5, 0), 220);
    EXPECT_EQ(pixel(68 + 5, 5, 1), 30);
    EXPECT_EQ(pixel(5, 1, 0), 150);
    EXPECT_EQ(pixel(5, 5, 0), 20);
    // The gap between tiles is white.
    EXPECT_EQ(pixel(31, 15, 0), 255);
}

TEST(ContactSheet, NoFrameInTheWindowGivesAnEmptySheet) {
    ContactSheetSink sink(30.0, 5.0, 6.0, {});
    sink.push(frameOf(40, 40, 0));
    EXPECT_EQ(sink.kept(), 0u);
    EXPECT_TRUE(sink.sheet(8).bytes.empty());
}
