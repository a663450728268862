// Figure PNGs (analysis/figure_png.hpp): the size in pixels is the drawing's size in inches
// (units of 1/96 inch) times the dpi, the file records that resolution, text is antialiased
// DejaVu Sans placed where the drawing puts it (horizontal and reading upwards), and the same
// drawing gives the same bytes.
#include "analysis/figure_png.hpp"
#include "renderer/image_io.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

namespace {

namespace fs = std::filesystem;
using namespace signstim::analysis;
using namespace signstim::render;

Drawing labelled() {
    Drawing d;
    d.width = 192;  // 2 inches
    d.height = 96;  // 1 inch
    d.items.push_back(DrawRect{10, 10, 20, 20, Colour{0, 114, 178}, std::nullopt, 1});
    d.items.push_back(DrawText{96, 60, "Comprehension", 12, Colour{0, 0, 0}, TextAnchor::Middle, false, false});
    d.items.push_back(DrawText{180, 90, "rating", 10, Colour{0, 0, 0}, TextAnchor::Start, true, true});
    return d;
}

Image decode(const std::vector<std::uint8_t>& png, const std::string& name) {
    const fs::path file = fs::path(SIGNSTIM_BINARY_DIR) / "figure_png_test" / (name + ".png");
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
    return readImage(file);
}

// Grey levels (0 = black) in a rectangle of pixels.
std::set<int> greys(const Image& image, std::uint32_t x0, std::uint32_t y0, std::uint32_t x1, std::uint32_t y1) {
    std::set<int> levels;
    for (std::uint32_t y = y0; y < y1; ++y)
        for (std::uint32_t x = x0; x < x1; ++x) levels.insert(image.bytes[(static_cast<std::size_t>(y) * image.width + x) * 4]);
    return levels;
}

TEST(FigurePng, SizeFollowsTheDpiAndTheFileRecordsIt) {
    for (const double dpi : {150.0, 300.0}) {
        const std::vector<std::uint8_t> png = figurePng(labelled(), dpi);
        const std::string bytes(png.begin(), png.end());
        const Image image = decode(png, "size-" + std::to_string(static_cast<int>(dpi)));
        EXPECT_EQ(image.width, static_cast<std::uint32_t>(2 * dpi));
        EXPECT_EQ(image.height, static_cast<std::uint32_t>(dpi));
        // pHYs: pixels per metre in both directions, unit metre (PNG spec 11.3.5.3).
        const std::size_t at = bytes.find("pHYs");
        ASSERT_NE(at, std::string::npos);
        const auto perMetre = static_cast<std::uint32_t>(std::lround(dpi / 0.0254));
        const std::string expected = {static_cast<char>(perMetre >> 24), static_cast<char>((perMetre >> 16) & 0xff),
                                      static_cast<char>((perMetre >> 8) & 0xff), static_cast<char>(perMetre & 0xff)};
        EXPECT_EQ(bytes.substr(at + 4, 4), expected);
        EXPECT_EQ(bytes.substr(at + 8, 4), expected);
        EXPECT_EQ(bytes[at + 12], '\x01');
    }
}

TEST(FigurePng, TextIsAntialiasedWhereTheDrawingPutsItAndTheBytesRepeat) {
    const std::vector<std::uint8_t> png = figurePng(labelled(), 300);
    EXPECT_EQ(png, figurePng(labelled(), 300));
    const Image image = decode(png, "text");
    const double s = 300.0 / 96.0;
    // "Comprehension", 12 units, centred on x = 96 with its baseline at y = 60: dark pixels and
    // in-between greys (antialiasing) above the baseline, none far to the left or right.
    const auto px = [s](double units) { return static_cast<std::uint32_t>(units * s); };
    const std::set<int> word = greys(image, px(50), px(50), px(142), px(60));
    EXPECT_LT(*word.begin(), 40);
    std::size_t between = 0;
    for (int g : word) between += g > 40 && g < 215 ? 1 : 0;
    EXPECT_GT(between, 20u);  // many levels of coverage, not a 1-bit font
    EXPECT_EQ(greys(image, px(0), px(50), px(30), px(60)), std::set<int>{255});
    EXPECT_EQ(greys(image, px(148), px(50), px(165), px(60)), std::set<int>{255});
    // "rating", bold, reading upwards from (180, 90): ink left of x = 180 (above the baseline
    // turned), above y = 90, none below it.
    EXPECT_LT(*greys(image, px(171), px(60), px(180), px(90)).begin(), 40);
    EXPECT_EQ(greys(image, px(170), px(91), px(192), px(96)), std::set<int>{255});
    // The shape under the text is the rasterizer's: the box's colour inside it.
    EXPECT_EQ(image.bytes[(static_cast<std::size_t>(px(20)) * image.width + px(20)) * 4 + 2], 178);
}

}  // namespace
