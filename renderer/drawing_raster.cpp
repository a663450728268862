#include "renderer/drawing.hpp"

#include "renderer/label_overlay.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace signstim::render {

namespace {

constexpr int kGlyphAdvance = 6, kGlyphRows = 8, kGlyphBaselineRow = 7;  // the label font's cells

// The largest whole scale whose 8-pixel cell fits in the font size (never larger than the
// vector text, so a layout that fits one fits the other).
long glyphScale(double size, double pixelsPerUnit) {
    return std::max(1L, static_cast<long>(std::floor(size * pixelsPerUnit / kGlyphRows + 1e-9)));
}

class Raster {
public:
    Raster(Image& image, double scale) : image_(image), scale_(scale) {}

    long px(double units) const { return std::lround(units * scale_); }

    void blend(long x, long y, const Colour& c, double coverage = 1.0) {
        if (x < 0 || y < 0 || x >= static_cast<long>(image_.width) || y >= static_cast<long>(image_.height)) return;
        std::uint8_t* p = image_.bytes.data() + (static_cast<std::size_t>(y) * image_.width + static_cast<std::size_t>(x)) * 4;
        const auto mix = [coverage](std::uint8_t under, std::uint8_t over) {
            return static_cast<std::uint8_t>(std::lround(under + (over - under) * coverage));
        };
        p[0] = mix(p[0], c.r);
        p[1] = mix(p[1], c.g);
        p[2] = mix(p[2], c.b);
        p[3] = 255;
    }

    // Pixels [x0, x1) x [y0, y1).
    void fill(long x0, long y0, long x1, long y1, const Colour& c) {
        for (long y = std::max(0L, y0); y < std::min<long>(y1, image_.height); ++y)
            for (long x = std::max(0L, x0); x < std::min<long>(x1, image_.width); ++x) blend(x, y, c);
    }

    // A band `width` units wide centred on `at` (units): pixel range, at least one pixel.
    std::pair<long, long> band(double at, double width) const {
        long a = px(at - width / 2.0), b = px(at + width / 2.0);
        if (b <= a) {  // thinner than a pixel: the pixel the centre falls in
            a = static_cast<long>(std::floor(at * scale_));
            b = a + 1;
        }
        return {a, b};
    }

    void draw(const DrawRect& r) {
        if (r.fill) fill(px(r.x), px(r.y), px(r.x + r.width), px(r.y + r.height), *r.fill);
        if (r.stroke) {
            draw(DrawLine{r.x - r.strokeWidth / 2, r.y, r.x + r.width + r.strokeWidth / 2, r.y, *r.stroke, r.strokeWidth});
            draw(DrawLine{r.x - r.strokeWidth / 2, r.y + r.height, r.x + r.width + r.strokeWidth / 2, r.y + r.height, *r.stroke,
                          r.strokeWidth});
            draw(DrawLine{r.x, r.y, r.x, r.y + r.height, *r.stroke, r.strokeWidth});
            draw(DrawLine{r.x + r.width, r.y, r.x + r.width, r.y + r.height, *r.stroke, r.strokeWidth});
        }
    }

    void draw(const DrawLine& l) {
        if (l.y1 == l.y2) {
            const auto [y0, y1] = band(l.y1, l.width);
            fill(px(std::min(l.x1, l.x2)), y0, std::max(px(std::max(l.x1, l.x2)), px(std::min(l.x1, l.x2)) + 1), y1, l.colour);
        } else if (l.x1 == l.x2) {
            const auto [x0, x1] = band(l.x1, l.width);
            fill(x0, px(std::min(l.y1, l.y2)), x1, std::max(px(std::max(l.y1, l.y2)), px(std::min(l.y1, l.y2)) + 1), l.colour);
        } else {
            throw std::invalid_argument("rasterizeDrawing: lines must be horizontal or vertical");
        }
    }

    // Coverage from 4x4 samples per pixel: smooth edges, the same bytes every time.
    void disc(double cx, double cy, double radius, const Colour& c) {
        const double x = cx * scale_, y = cy * scale_, r = radius * scale_;
        for (long py = static_cast<long>(std::floor(y - r)); py <= static_cast<long>(std::ceil(y + r)); ++py)
            for (long pxl = static_cast<long>(std::floor(x - r)); pxl <= static_cast<long>(std::ceil(x + r)); ++pxl) {
                int inside = 0;
                for (int sy = 0; sy < 4; ++sy)
                    for (int sx = 0; sx < 4; ++sx) {
                        const double dx = pxl + (sx + 0.5) / 4.0 - x, dy = py + (sy + 0.5) / 4.0 - y;
                        inside += dx * dx + dy * dy <= r * r ? 1 : 0;
                    }
                if (inside > 0) blend(pxl, py, c, inside / 16.0);
            }
    }

    void draw(const DrawDisc& d) {
        if (d.stroke) {
            disc(d.cx, d.cy, d.radius + d.strokeWidth / 2, *d.stroke);
            disc(d.cx, d.cy, std::max(0.0, d.radius - d.strokeWidth / 2), d.fill);
        } else {
            disc(d.cx, d.cy, d.radius, d.fill);
        }
    }

    void draw(const DrawText& t) {
        const long g = glyphScale(t.size, scale_);  // whole pixels
        const long length = static_cast<long>(t.text.size()) * kGlyphAdvance * g - g;
        long along = 0;  // offset of the text's start from the anchor, along the text
        if (t.anchor == TextAnchor::Middle) along = -length / 2;
        if (t.anchor == TextAnchor::End) along = -length;
        const long ax = px(t.x), ay = px(t.y);
        for (std::size_t i = 0; i < t.text.size(); ++i) {
            const std::uint8_t* columns = glyphColumns(t.text[i]);
            for (int column = 0; column < kGlyphAdvance - 1; ++column)
                for (int row = 0; row < kGlyphRows; ++row) {
                    if (!((columns[column] >> row) & 1u)) continue;
                    for (int bold = 0; bold <= (t.bold ? 1 : 0); ++bold) {
                        // (u, v): along the text and down from the baseline, in pixels.
                        const long u = along + (static_cast<long>(i) * kGlyphAdvance + column) * g + bold;
                        const long v = (row - kGlyphBaselineRow) * g;
                        for (long dv = 0; dv < g; ++dv)
                            for (long du = 0; du < g; ++du) {
                                if (t.vertical)
                                    blend(ax + v + dv, ay - (u + du) - 1, t.colour);
                                else
                                    blend(ax + u + du, ay + v + dv, t.colour);
                            }
                    }
                }
        }
    }

private:
    Image& image_;
    double scale_;
};

}  // namespace

double drawingTextWidth(const std::string& text, double size, double pixelsPerUnit) {
    const double g = static_cast<double>(glyphScale(size, pixelsPerUnit));
    return text.empty() ? 0.0 : (static_cast<double>(text.size()) * kGlyphAdvance * g - g) / pixelsPerUnit;
}

Image rasterizeDrawing(const Drawing& drawing, double pixelsPerUnit) {
    const long width = std::lround(drawing.width * pixelsPerUnit), height = std::lround(drawing.height * pixelsPerUnit);
    if (!(pixelsPerUnit > 0.0) || width <= 0 || height <= 0 || width > 16384 || height > 16384)
        throw std::invalid_argument("rasterizeDrawing: the image would be empty or larger than 16384 pixels a side");
    Image image;
    image.width = static_cast<std::uint32_t>(width);
    image.height = static_cast<std::uint32_t>(height);
    image.format = PixelFormat::Rgba8;
    image.bytes.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    for (std::size_t i = 0; i < image.bytes.size(); i += 4) {
        image.bytes[i] = drawing.background.r;
        image.bytes[i + 1] = drawing.background.g;
        image.bytes[i + 2] = drawing.background.b;
        image.bytes[i + 3] = 255;
    }
    Raster raster(image, pixelsPerUnit);
    for (const DrawItem& item : drawing.items) std::visit([&](const auto& shape) { raster.draw(shape); }, item);
    return image;
}

}  // namespace signstim::render
