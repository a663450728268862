#pragma once
// Figures as PNG for publication (docs/analysis.md, "Figures"). The drawing's units are CSS
// pixels, 1/96 inch (as in its SVG), so a figure 600 units wide is 6.25 inches: at `dpi` its
// PNG is round(600 * dpi / 96) pixels wide, and the file records that resolution (pHYs), so
// a word processor places it at its size in inches.
//  - Shapes: render::rasterizeDrawing (antialiased discs; lines and boxes on whole pixels).
//  - Text: FreeType, antialiased (8-bit coverage), unhinted outlines placed at sub-pixel
//    positions, in DejaVu Sans (Debian: fonts-dejavu-core), found through fontconfig. The
//    font is pinned, not "any sans-serif": another font would give other pixels, and the
//    figure's layout (measured with wider metrics) is known to fit it.
// Same drawing, dpi, FreeType and font file -> the same bytes.
#include "renderer/drawing.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace signstim::analysis {

// The default: print resolution for journals' line art with text.
inline constexpr double kDefaultFigureDpi = 300.0;
inline constexpr double kMinimumFigureDpi = 72.0, kMaximumFigureDpi = 1200.0;

// The PNG file's bytes. Throws EnvironmentError (exit 3) when DejaVu Sans is not installed,
// saying which package has it.
std::vector<std::uint8_t> figurePng(const render::Drawing& drawing, double dpi);

// The font files used (regular and bold), as fontconfig finds them: for the report.
std::vector<std::string> figureFontFiles();

}  // namespace signstim::analysis
