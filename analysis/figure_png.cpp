#include "analysis/figure_png.hpp"

#include "common/error.hpp"
#include "renderer/image_io.hpp"

#include <fontconfig/fontconfig.h>
#include <ft2build.h>
#include FT_FREETYPE_H
#include <zlib.h>

#include <cmath>
#include <memory>

namespace signstim::analysis {

namespace {

constexpr double kUnitsPerInch = 96.0;  // CSS pixels, the SVG's units

const char* const kFamily = "DejaVu Sans";
const char* const kFontHint =
    "the figures' PNGs need the font DejaVu Sans (Debian/Ubuntu: apt install fonts-dejavu-core fontconfig)";

// The file of DejaVu Sans (bold or not), as fontconfig finds it; EnvironmentError when the
// match is another family (fontconfig always answers with some font).
std::string fontFile(bool bold) {
    if (!FcInit()) throw EnvironmentError(std::string("fontconfig could not start: ") + kFontHint);
    FcPattern* pattern = FcNameParse(reinterpret_cast<const FcChar8*>(kFamily));
    FcPatternAddInteger(pattern, FC_WEIGHT, bold ? FC_WEIGHT_BOLD : FC_WEIGHT_REGULAR);
    FcPatternAddInteger(pattern, FC_SLANT, FC_SLANT_ROMAN);
    FcConfigSubstitute(nullptr, pattern, FcMatchPattern);
    FcDefaultSubstitute(pattern);
    FcResult result = FcResultNoMatch;
    FcPattern* match = FcFontMatch(nullptr, pattern, &result);
    FcPatternDestroy(pattern);
    std::string file, family;
    int weight = 0;
    if (match) {
        FcChar8* value = nullptr;
        if (FcPatternGetString(match, FC_FILE, 0, &value) == FcResultMatch) file = reinterpret_cast<const char*>(value);
        if (FcPatternGetString(match, FC_FAMILY, 0, &value) == FcResultMatch) family = reinterpret_cast<const char*>(value);
        FcPatternGetInteger(match, FC_WEIGHT, 0, &weight);
        FcPatternDestroy(match);
    }
    if (file.empty() || family != kFamily || (bold && weight < FC_WEIGHT_BOLD))
        throw EnvironmentError(std::string(kFontHint) + " (fontconfig offers " + (family.empty() ? "no font" : "'" + family + "'") +
                               " for '" + kFamily + (bold ? " Bold" : "") + "')");
    return file;
}

struct Library {
    FT_Library library = nullptr;
    Library() {
        if (FT_Init_FreeType(&library) != 0) throw EnvironmentError("FreeType could not start");
    }
    ~Library() { FT_Done_FreeType(library); }
};

struct Face {
    FT_Face face = nullptr;
    Face(FT_Library library, const std::string& file) {
        if (FT_New_Face(library, file.c_str(), 0, &face) != 0)
            throw EnvironmentError(file + ": FreeType cannot read this font file; " + kFontHint);
    }
    ~Face() { FT_Done_Face(face); }
};

// Unhinted outlines (the shapes the font designer drew, at any scale and position) with
// 8-bit antialiasing.
constexpr FT_Int32 kLoadFlags = FT_LOAD_NO_HINTING | FT_LOAD_RENDER;

void blend(render::Image& image, long x, long y, const render::Colour& c, unsigned coverage) {
    if (x < 0 || y < 0 || x >= static_cast<long>(image.width) || y >= static_cast<long>(image.height) || coverage == 0) return;
    std::uint8_t* p = image.bytes.data() + (static_cast<std::size_t>(y) * image.width + static_cast<std::size_t>(x)) * 4;
    // Integer arithmetic: the same bytes on every machine.
    const auto mix = [coverage](unsigned under, unsigned over) {
        return static_cast<std::uint8_t>((under * (255 - coverage) + over * coverage + 127) / 255);
    };
    p[0] = mix(p[0], c.r);
    p[1] = mix(p[1], c.g);
    p[2] = mix(p[2], c.b);
}

// Width of `text` in 26.6 pixels at the face's current size, from unhinted advances.
long textAdvance(FT_Face face, const std::string& text) {
    FT_Set_Transform(face, nullptr, nullptr);
    long width = 0;
    for (const char c : text) {
        if (FT_Load_Char(face, static_cast<unsigned char>(c), FT_LOAD_NO_HINTING) != 0) continue;
        width += face->glyph->advance.x;
    }
    return width;
}

void drawText(render::Image& image, FT_Face face, const render::DrawText& t, double pixelsPerUnit) {
    FT_Set_Char_Size(face, 0, static_cast<FT_F26Dot6>(std::lround(t.size * pixelsPerUnit * 64.0)), 72, 72);
    const long width = textAdvance(face, t.text);
    long along = 0;  // 26.6 pixels from the anchor to the text's start, along the text
    if (t.anchor == render::TextAnchor::Middle) along = -width / 2;
    if (t.anchor == render::TextAnchor::End) along = -width;
    // The anchor in pixels: a whole-pixel origin plus a fraction, carried in the pen (26.6,
    // FreeType's y up, the image's y down).
    const double ox = t.x * pixelsPerUnit, oy = t.y * pixelsPerUnit;
    const long bx = static_cast<long>(std::floor(ox)), by = static_cast<long>(std::floor(oy));
    FT_Vector pen;
    pen.x = std::lround((ox - static_cast<double>(bx)) * 64.0);
    pen.y = -std::lround((oy - static_cast<double>(by)) * 64.0);
    FT_Matrix matrix{0x10000, 0, 0, 0x10000};
    if (t.vertical) {
        matrix = FT_Matrix{0, -0x10000, 0x10000, 0};  // 90 degrees counter-clockwise: reads upwards
        pen.y += along;
    } else {
        pen.x += along;
    }
    for (const char c : t.text) {
        FT_Set_Transform(face, &matrix, &pen);
        if (FT_Load_Char(face, static_cast<unsigned char>(c), kLoadFlags) != 0) continue;
        const FT_GlyphSlot g = face->glyph;
        const FT_Bitmap& bitmap = g->bitmap;
        for (unsigned row = 0; row < bitmap.rows; ++row)
            for (unsigned column = 0; column < bitmap.width; ++column)
                blend(image, bx + g->bitmap_left + static_cast<long>(column), by - g->bitmap_top + static_cast<long>(row), t.colour,
                      bitmap.buffer[static_cast<long>(row) * bitmap.pitch + static_cast<long>(column)]);
        pen.x += g->advance.x;  // transformed by the matrix
        pen.y += g->advance.y;
    }
}

void putBigEndian(std::string& out, std::uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8) out += static_cast<char>((value >> shift) & 0xff);
}

// A pHYs chunk (PNG spec §11.3.5.3: pixels per metre, unit 1) right after IHDR, which is
// always the first chunk (8-byte signature + 25-byte chunk).
std::vector<std::uint8_t> withResolution(std::vector<std::uint8_t> png, double dpi) {
    const auto perMetre = static_cast<std::uint32_t>(std::lround(dpi / 0.0254));
    std::string chunk = "pHYs";
    putBigEndian(chunk, perMetre);
    putBigEndian(chunk, perMetre);
    chunk += '\x01';
    const auto crc = static_cast<std::uint32_t>(
        crc32(0L, reinterpret_cast<const Bytef*>(chunk.data()), static_cast<uInt>(chunk.size())));
    std::string bytes;
    putBigEndian(bytes, 9);
    bytes += chunk;
    putBigEndian(bytes, crc);
    constexpr std::size_t kAfterIhdr = 8 + 25;
    if (png.size() < kAfterIhdr) throw std::logic_error("figurePng: not a PNG");
    png.insert(png.begin() + kAfterIhdr, bytes.begin(), bytes.end());
    return png;
}

}  // namespace

std::vector<std::string> figureFontFiles() { return {fontFile(false), fontFile(true)}; }

std::vector<std::uint8_t> figurePng(const render::Drawing& drawing, double dpi) {
    if (!(dpi >= kMinimumFigureDpi && dpi <= kMaximumFigureDpi)) throw std::invalid_argument("figurePng: dpi out of range");
    const double pixelsPerUnit = dpi / kUnitsPerInch;
    render::Drawing shapes = drawing;
    std::erase_if(shapes.items, [](const render::DrawItem& item) { return std::holds_alternative<render::DrawText>(item); });
    render::Image image = render::rasterizeDrawing(shapes, pixelsPerUnit);

    const Library library;
    std::unique_ptr<Face> regular, bold;
    // Text is painted over the shapes in the drawing's order (labels never sit under a shape).
    for (const render::DrawItem& item : drawing.items) {
        const auto* text = std::get_if<render::DrawText>(&item);
        if (!text) continue;
        std::unique_ptr<Face>& face = text->bold ? bold : regular;
        if (!face) face = std::make_unique<Face>(library.library, fontFile(text->bold));
        drawText(image, face->face, *text, pixelsPerUnit);
    }
    render::ImageWriteOptions png;
    png.pngCompression = 6;
    png.alpha = false;
    return withResolution(render::encodePng(image, png), dpi);
}

}  // namespace signstim::analysis
