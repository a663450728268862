#pragma once
// Caption labels drawn into a read-back frame with a small embedded bitmap font (5x8 cells,
// printable ASCII; other bytes draw as '?'). Text is white on an opaque dark box in the
// view's top-left corner, scaled by whole pixels so it stays crisp and readable from 128 px
// cells (256x256 2x2 grids) up to 720p frames.
#include "renderer/image.hpp"

#include <cstdint>
#include <string>

namespace signstim::render {

struct LabelRect {
    std::uint32_t x = 0, y = 0, width = 0, height = 0;  // the view's cell in the image
};

// Integer glyph scale for a cell of `cellHeight` pixels (2 at 128 px, 3 from 193 px up);
// drawLabel lowers it further when the caption would not fit the cell's width.
std::uint32_t labelScale(std::uint32_t cellHeight);

// Draws `text` into `image` inside `cell` (clipped to the cell).
void drawLabel(Image& image, const LabelRect& cell, const std::string& text);

// The 5 column bytes of a glyph (bit 0 = top row); exposed for tests.
const std::uint8_t* glyphColumns(char c);

}  // namespace signstim::render
