#pragma once
// A flat 2D drawing (charts: bars, boxes, whiskers, axes, labels) as plain values, and its
// rasterization into an Image. Knows nothing of what the drawing shows. Writers of vector
// formats (analysis/svg.hpp) take the same value, so a PNG and an SVG of one drawing show the
// same shapes at the same places.
//
// Units are abstract ("px" of the vector form); rasterizeDrawing draws `pixelsPerUnit` pixels
// per unit. Lines are horizontal or vertical only (all a chart needs; they rasterize exactly);
// text is printable ASCII drawn with the label font (renderer/label_overlay.hpp, 5x8 cells)
// scaled by whole pixels. Same drawing, same bytes.
#include "renderer/image.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace signstim::render {

struct Colour {
    std::uint8_t r = 0, g = 0, b = 0;  // sRGB
    bool operator==(const Colour&) const = default;
};

struct DrawRect {
    double x = 0, y = 0, width = 0, height = 0;  // top-left corner, y down
    std::optional<Colour> fill;
    std::optional<Colour> stroke;  // centred on the edges
    double strokeWidth = 1.0;
};

struct DrawLine {  // horizontal (y1 == y2) or vertical (x1 == x2)
    double x1 = 0, y1 = 0, x2 = 0, y2 = 0;
    Colour colour;
    double width = 1.0;
};

struct DrawDisc {
    double cx = 0, cy = 0, radius = 0;
    Colour fill;
    std::optional<Colour> stroke;
    double strokeWidth = 1.0;
};

enum class TextAnchor { Start, Middle, End };

struct DrawText {
    double x = 0, y = 0;  // the anchor point on the baseline
    std::string text;     // printable ASCII
    double size = 12.0;   // font size (em) in units
    Colour colour;
    TextAnchor anchor = TextAnchor::Start;
    bool bold = false;
    bool vertical = false;  // turned 90 degrees counter-clockwise about (x, y): reads upwards
};

using DrawItem = std::variant<DrawRect, DrawLine, DrawDisc, DrawText>;

struct Drawing {
    double width = 0, height = 0;
    Colour background{255, 255, 255};
    std::string title;  // what the drawing shows (SVG <title>, alt text)
    std::vector<DrawItem> items;  // painted in order
};

// Width of `text` at font size `size` in units as rasterizeDrawing draws it at `pixelsPerUnit`
// (whole-pixel glyph scales): for layout. Vector fonts of that size are narrower.
double drawingTextWidth(const std::string& text, double size, double pixelsPerUnit);

// The drawing as an Rgba8 image of round(width * pixelsPerUnit) x round(height * pixelsPerUnit)
// pixels, opaque. Throws std::invalid_argument for a slanted line or a size of 0.
Image rasterizeDrawing(const Drawing& drawing, double pixelsPerUnit);

}  // namespace signstim::render
