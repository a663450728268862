#include "renderer/contact_sheet.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace signstim::render {

ContactSheetSink::ContactSheetSink(double fps, double fromSeconds, double toSeconds, std::vector<double> markedSeconds)
    : fps_(fps), from_(fromSeconds), to_(toSeconds), marked_(std::move(markedSeconds)) {}

void ContactSheetSink::push(Image&& frame) {
    const double t = static_cast<double>(pushed_++) / fps_;
    if (t < from_ - 1e-9 || t > to_ + 1e-9) return;
    const std::uint32_t x0 = frame.width / 5;
    const std::uint32_t w = (frame.width * 3 / 5) / 2, h = (frame.height * 4 / 5) / 2;
    Image tile;
    tile.width = w;
    tile.height = h;
    tile.bytes.assign(static_cast<std::size_t>(w) * h * 4, 0);
    const std::size_t bpp = frame.bytesPerPixel();
    // 8-bit RGBA, or the high byte of 16-bit little-endian RGBA.
    const auto channel = [&](std::uint32_t x, std::uint32_t y, int c) -> unsigned {
        const std::size_t at = (static_cast<std::size_t>(y) * frame.width + x + x0) * bpp;
        return bpp == 4 ? frame.bytes[at + static_cast<std::size_t>(c)] : frame.bytes[at + 2 * static_cast<std::size_t>(c) + 1];
    };
    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x)
            for (int c = 0; c < 4; ++c)
                tile.bytes[(static_cast<std::size_t>(y) * w + x) * 4 + static_cast<std::size_t>(c)] = static_cast<std::uint8_t>(
                    (channel(2 * x, 2 * y, c) + channel(2 * x + 1, 2 * y, c) + channel(2 * x, 2 * y + 1, c) +
                     channel(2 * x + 1, 2 * y + 1, c) + 2) / 4);
    const bool marked = std::any_of(marked_.begin(), marked_.end(), [&](double m) { return std::abs(m - t) <= 0.5 / fps_; });
    const std::uint8_t bar[4] = {static_cast<std::uint8_t>(marked ? 220 : 150), static_cast<std::uint8_t>(marked ? 30 : 150),
                                 static_cast<std::uint8_t>(marked ? 30 : 150), 255};
    for (std::uint32_t y = 0; y < std::min<std::uint32_t>(h, marked ? 10 : 3); ++y)
        for (std::uint32_t x = 0; x < w; ++x)
            std::copy_n(bar, 4, tile.bytes.begin() + static_cast<std::ptrdiff_t>((static_cast<std::size_t>(y) * w + x) * 4));
    tiles_.push_back(std::move(tile));
}

Image ContactSheetSink::sheet(int columns) const {
    Image out;
    if (tiles_.empty() || columns < 1) return out;
    const std::uint32_t w = tiles_.front().width, h = tiles_.front().height, gap = 4;
    const auto cols = static_cast<std::uint32_t>(std::min<std::size_t>(static_cast<std::size_t>(columns), tiles_.size()));
    const auto rows = static_cast<std::uint32_t>((tiles_.size() + cols - 1) / cols);
    out.width = cols * (w + gap) - gap;
    out.height = rows * (h + gap) - gap;
    out.bytes.assign(static_cast<std::size_t>(out.width) * out.height * 4, 255);
    for (std::size_t i = 0; i < tiles_.size(); ++i) {
        const std::uint32_t ox = static_cast<std::uint32_t>(i % cols) * (w + gap), oy = static_cast<std::uint32_t>(i / cols) * (h + gap);
        for (std::uint32_t y = 0; y < h; ++y)
            std::copy_n(tiles_[i].bytes.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(y) * w * 4), w * 4,
                        out.bytes.begin() + static_cast<std::ptrdiff_t>((static_cast<std::size_t>(oy + y) * out.width + ox) * 4));
    }
    return out;
}

}  // namespace signstim::render
