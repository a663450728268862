#pragma once
// MP4 output (SPEC §5): H.264 (libx264), yuv420p, even width and height, constant frame rate,
// +faststart. Raw RGBA frames are piped to an `ffmpeg` child process (posix_spawn, no shell,
// its own process group so a terminal's Ctrl-C reaches only signstim, which ends it); ffmpeg
// writes a temporary file beside the target that is renamed only when it succeeded, so a
// failure never leaves a half-written .mp4.
// "Succeeded" (docs/errors.md): ffmpeg exited 0, said nothing that looks like an error on its
// stderr (read through a pipe, never a file: a full /tmp must not hide "Error writing
// trailer"), and the file it wrote is a complete MP4 (checkMp4: ffmpeg 5 exits 0 after a
// failed trailer write). Other stderr lines are passed on as warnings.
#include "common/atomic_file.hpp"
#include "renderer/image.hpp"

#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <thread>

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
    // x264 threads; 0: ffmpeg's choice (from the machine's cores). x264's bytes depend on
    // its thread count, so outputs that must be identical on every machine (a study) fix it;
    // their parallelism comes from several encoders at once instead.
    int threads = 0;
};

// Empty when `file` is a complete MP4 at its top level: its boxes ([4-byte big-endian size]
// [4-char type], size 1: a 64-bit size follows, 0: to the end of the file) tile the file
// exactly and one of them is 'moov' (the index, written last; +faststart then moves it before
// 'mdat'). Otherwise what is wrong ("no 'moov' box", "'mdat' runs past the end of the file").
std::string checkMp4(const std::filesystem::path& file);

// True for a line of ffmpeg's stderr that reports a failure ("Error writing trailer ...",
// "No space left on device", "Invalid argument", "Conversion failed!"): case-sensitive, so a
// dynamic loader's "ERROR: ld.so: ... cannot be preloaded ...: ignored." is a warning.
bool isFfmpegErrorLine(std::string_view line);

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

    struct Messages;  // what ffmpeg said on stderr, collected by stderrReader_

private:
    void abandon() noexcept;
    void joinStderrReader() noexcept;
    [[noreturn]] void fail(const std::string& what);

    std::filesystem::path output_;
    // The MP4 being written (ffmpeg's output); removed unless the video is committed.
    std::unique_ptr<TemporaryFile> temporary_;
    // ffmpeg's stderr: read to its end by a thread, so ffmpeg never blocks on a full pipe.
    std::shared_ptr<Messages> messages_;
    std::thread stderrReader_;
    std::uint32_t width_ = 0, height_ = 0;
    PixelFormat format_ = PixelFormat::Rgba8;
    pid_t child_ = -1;
    int pipe_ = -1;
    std::uint64_t frames_ = 0;
    bool finished_ = false;
};

}  // namespace signstim::render
