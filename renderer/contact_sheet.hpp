#pragma once
// A contact sheet of a clip: the frames of a time window, each cropped to the middle 60 % across
// and the top 80 % (a signer's upper body and the space of the hands), halved, and laid out in
// rows. Frames at marked instants get a red bar along their top, the others a thin grey one.
#include "renderer/frame_sink.hpp"
#include "renderer/image.hpp"

#include <cstdint>
#include <vector>

namespace signstim::render {

class ContactSheetSink final : public FrameSink {
public:
    // Frames from `fromSeconds` to `toSeconds` (clip time, frame n at n / fps) are kept; a frame
    // within half a frame of one of `markedSeconds` is marked.
    ContactSheetSink(double fps, double fromSeconds, double toSeconds, std::vector<double> markedSeconds);

    void push(Image&& frame) override;
    void finish() override {}
    std::uint64_t framesPushed() const override { return pushed_; }

    std::size_t kept() const { return tiles_.size(); }
    // The kept frames, `columns` a row, 4 px apart on white; empty when none was kept.
    Image sheet(int columns) const;

private:
    double fps_, from_, to_;
    std::vector<double> marked_;
    std::uint64_t pushed_ = 0;
    std::vector<Image> tiles_;
};

}  // namespace signstim::render
