#pragma once
// Frame sinks that pass frames on to other sinks (renderer/frame_sink.hpp): a still captured on
// the way, and one stream written to two places.
#include "renderer/frame_sink.hpp"

#include <cstdint>

namespace signstim::render {

// Forwards every frame to `next` and keeps a copy of frame `keep` (0-based): the still of a clip.
class StillCapturingSink final : public FrameSink {
public:
    StillCapturingSink(FrameSink& next, std::uint64_t keep) : next_(next), keep_(keep) {}
    void push(Image&& frame) override;
    void finish() override { next_.finish(); }
    std::uint64_t framesPushed() const override { return count_; }
    bool recycle(Image& out) override { return next_.recycle(out); }
    const Image& still() const { return still_; }

private:
    FrameSink& next_;
    std::uint64_t keep_;
    std::uint64_t count_ = 0;
    Image still_;
};

// Every frame to both sinks (an MP4 and its PNG frames, say).
class TeeSink final : public FrameSink {
public:
    TeeSink(FrameSink& first, FrameSink& second) : first_(first), second_(second) {}
    void push(Image&& frame) override;
    void finish() override;
    std::uint64_t framesPushed() const override { return count_; }
    // The second sink's buffers: the first receives a copy of each frame, the second the frame.
    bool recycle(Image& out) override { return second_.recycle(out); }

private:
    FrameSink& first_;
    FrameSink& second_;
    std::uint64_t count_ = 0;
};

}  // namespace signstim::render
