#pragma once
// MP4 output (SPEC §5): H.264 (libx264), yuv420p, even width and height, constant frame rate,
// +faststart. Raw RGBA frames are piped to an `ffmpeg` child process (posix_spawn, no shell);
// ffmpeg writes a temporary file beside the target that is renamed only when it succeeded,
// so a failure never leaves a half-written .mp4.
#include "common/atomic_file.hpp"
#include "renderer/image.hpp"

#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

namespace signstim::render {

struct FrameRate {
    std::uint32_t numerator = 30;  // SPEC §5: default 30 fps
    std::uint32_t denominator = 1;
    double value() const { return static_cast<double>(numerator) / denominator; }
    std::string text() const;  // "30" or "30000/1001"
};

// Accepts "30", "25", "30000/1001", "29.97" (decimal: converted to NTSC-style rationals when
// close, else to a /1000 rational). Throws InputError(source, 0, field, ...) when invalid.
FrameRate parseFrameRate(std::string_view text, const std::string& source = "<command line>",
                         const std::string& field = "--fps");

struct VideoOptions {
    FrameRate frameRate;
    int crf = 18;                  // x264 quality (0 lossless .. 51); 18 is visually lossless
    std::string preset = "fast";   // x264 speed/size trade-off
    std::string ffmpeg = "ffmpeg"; // program name (PATH lookup) or path
    // Added to ffmpeg's CPU niceness once it has started (0: as this thread). Frame sinks use
    // a positive value so that, where rendering runs on the same CPUs (lavapipe), the
    // encoder takes the cores' idle time rather than preempting the renderer.
    int niceness = 0;
};

class VideoEncoder {
public:
    // Starts ffmpeg. Odd width or height is refused (InputError naming the size: yuv420p
    // subsamples chroma 2x2); ffmpeg not found -> EnvironmentError with install advice.
    VideoEncoder(std::filesystem::path output, std::uint32_t width, std::uint32_t height,
                 PixelFormat format, const VideoOptions& options = {});
    ~VideoEncoder();  // without finish(): stops ffmpeg and removes the temporary file
    VideoEncoder(const VideoEncoder&) = delete;
    VideoEncoder& operator=(const VideoEncoder&) = delete;

    // Frame size and format must match the constructor's. Throws when ffmpeg has failed
    // (EnvironmentError with the tail of its stderr).
    void write(const Image& frame);
    // Closes the pipe, waits for ffmpeg, renames the temporary onto the output.
    void finish();

    std::uint64_t framesWritten() const { return frames_; }
    const std::filesystem::path& output() const { return output_; }

private:
    void abandon() noexcept;
    [[noreturn]] void fail(const std::string& what);

    std::filesystem::path output_;
    // The MP4 being written (ffmpeg's output) and ffmpeg's stderr; both removed unless the
    // video is committed.
    std::unique_ptr<TemporaryFile> temporary_, stderrLog_;
    std::uint32_t width_ = 0, height_ = 0;
    PixelFormat format_ = PixelFormat::Rgba8;
    pid_t child_ = -1;
    int pipe_ = -1;
    std::uint64_t frames_ = 0;
    bool finished_ = false;
};

}  // namespace signstim::render
