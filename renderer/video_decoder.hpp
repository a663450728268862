#pragma once
// Reading video files a user supplies (a lab's recordings, issue 24 §2): probing them and
// decoding them into frames of a given size and rate. Like the encoder (video_encoder.hpp) this
// runs the ffmpeg tools as child processes (posix_spawn, no shell, ended on a signal): ffprobe
// to probe, ffmpeg to decode to raw RGBA on a pipe. Knows nothing of what the video shows.
//
// Normalised decoding [D]: ffmpeg's `fps` filter with round=up gives output frame n the input
// frame showing at n/rate (sample and hold, as the animations are sampled at n/rate), for
// every n/rate before the recording's end (timestamps only: deterministic); `scale` fits the picture inside
// the target keeping its display aspect, `pad` centres it on black (letterbox or pillarbox).
// swscale runs with bitexact+accurate_rnd, so the same file and ffmpeg give the same pixels on
// every machine (as x264 with a fixed thread count gives the same bytes, video_encoder.hpp).
#include "renderer/frame_sink.hpp"
#include "renderer/image.hpp"
#include "renderer/label_overlay.hpp"
#include "renderer/video_encoder.hpp"

#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

namespace signstim::render {

struct VideoProbe {
    std::string problem;        // empty: a decodable video; else what is wrong, for the user
    std::string container;      // "mov,mp4,m4a,3gp,3g2,mj2"
    std::string codec;          // "h264"
    std::uint32_t width = 0, height = 0;
    std::string frameRate;      // as ffprobe says it: "25/1", "30000/1001"
    double durationSeconds = 0.0;
    std::uint64_t frames = 0;   // decoded frames (every frame is decoded: a broken one is found)
};

// Probes `file`'s first video stream, decoding every frame. Problems (no such file, not a
// video, no video stream, nothing decodable, zero duration, a single still frame, a size
// outside 16x16 .. 7680x4320, longer than 10 minutes) are returned in `problem`; a missing
// ffprobe throws EnvironmentError (exit 3).
VideoProbe probeVideo(const std::filesystem::path& file, const std::string& ffprobe = "ffprobe");

// Decodes `file`'s first video stream into RGBA8 frames of width x height at `rate`,
// letterboxed (see above). Frames come in order from next(); false at the end.
class VideoFrameReader {
public:
    VideoFrameReader(const std::filesystem::path& file, std::uint32_t width, std::uint32_t height, const FrameRate& rate,
                     const std::string& ffmpeg = "ffmpeg");
    ~VideoFrameReader();  // ends ffmpeg if it still runs
    VideoFrameReader(const VideoFrameReader&) = delete;
    VideoFrameReader& operator=(const VideoFrameReader&) = delete;

    // The next frame into `frame` (its buffer reused); false after the last. Throws
    // EnvironmentError when ffmpeg fails (with what it said), or its output ends mid-frame.
    bool next(Image& frame);
    std::uint64_t framesRead() const { return frames_; }
    std::uint32_t width() const { return width_; }
    std::uint32_t height() const { return height_; }

private:
    void stop() noexcept;
    [[noreturn]] void fail(const std::string& what);

    std::filesystem::path file_;
    std::uint32_t width_, height_;
    pid_t child_ = -1;
    int pipe_ = -1, errors_ = -1;
    std::uint64_t frames_ = 0;
    bool ended_ = false;
};

// The cell of view `index` in a columns x rows grid of a width x height image (row-major), as
// the renderer lays out its views (renderer.cpp).
LabelRect gridCell(std::uint32_t width, std::uint32_t height, std::uint32_t columns, std::uint32_t rows, std::size_t index);

// Puts a video into one cell of every frame going to `next`: each pushed frame gets the
// reader's next frame (the reader's size must be the cell's) drawn over `cell`, captioned
// `label` like the renderer's views; after the reader's last frame the cell holds it. When the
// video is longer than the frames pushed, finish() first appends frames (the last pushed frame
// with the video's next frames in the cell) until it ends, so nothing of the video is cut.
class VideoCellSink final : public FrameSink {
public:
    VideoCellSink(FrameSink& next, std::unique_ptr<VideoFrameReader> reader, const LabelRect& cell, std::string label);
    void push(Image&& frame) override;
    void finish() override;
    std::uint64_t framesPushed() const override { return count_; }

private:
    bool advance();                    // the video's next frame into video_; false at its end
    void paint(Image& frame) const;    // video_ into the cell, with the label

    FrameSink& next_;
    std::unique_ptr<VideoFrameReader> reader_;
    LabelRect cell_;
    std::string label_;
    Image video_;        // the video's current frame (held after its last)
    Image last_;         // the last frame pushed, for frames appended at finish()
    bool videoEnded_ = false, finished_ = false;
    std::uint64_t count_ = 0;
};

}  // namespace signstim::render
