#pragma once
// Where rendered frames go: one PNG, a numbered PNG sequence, or an MP4. Encoding runs on
// worker threads so it overlaps with rendering; push() blocks when the bounded queue is full
// (back-pressure) and rethrows the first worker error. Outputs appear atomically: each PNG
// via a temporary + rename, the MP4 only at finish(). Destroying a sink without finish()
// abandons the work and removes temporaries (files of a PNG sequence already committed stay).
#include "renderer/image.hpp"
#include "renderer/image_io.hpp"
#include "renderer/video_encoder.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>

namespace signstim::render {

class FrameSink {
public:
    virtual ~FrameSink() = default;
    virtual void push(Image&& frame) = 0;
    // Waits for every pushed frame to be written; throws the first error.
    virtual void finish() = 0;
    virtual std::uint64_t framesPushed() const = 0;
    // Hands back the buffer of a frame the sink has finished with, so the producer can read
    // the next frame into it instead of allocating (a fresh multi-megabyte buffer costs page
    // faults and zero-filling every frame). False when none is free; `out` is then untouched.
    virtual bool recycle(Image& out) {
        (void)out;
        return false;
    }
};

// Exactly one frame into `file` (.png/.exr/.tif). A second push throws InputError.
std::unique_ptr<FrameSink> makeImageFileSink(const std::filesystem::path& file,
                                             const ImageWriteOptions& options = {});

// frame_00001.png, frame_00002.png, ... in `directory` (created if missing), compressed on
// `threads` workers (0: min(hardware threads, 4)).
std::unique_ptr<FrameSink> makePngSequenceSink(const std::filesystem::path& directory,
                                               const ImageWriteOptions& options = {},
                                               unsigned threads = 0);

// MP4 via VideoEncoder on its own thread; width/height/format fixed by the first frame.
// `queueFrames` bounds the frames waiting for the encoder.
std::unique_ptr<FrameSink> makeVideoSink(const std::filesystem::path& file,
                                         const VideoOptions& options = {},
                                         unsigned queueFrames = 4);

// Drops frames (benchmarks of rendering alone).
std::unique_ptr<FrameSink> makeDiscardSink();

// By the output's name: *.mp4 -> video, *.png/.exr/.tif(f) -> one image, anything else -> a
// PNG sequence directory.
std::unique_ptr<FrameSink> makeFrameSink(const std::filesystem::path& output,
                                         const ImageWriteOptions& imageOptions = {},
                                         const VideoOptions& videoOptions = {});

// The name the PNG sequence uses for 1-based frame `number` (frame_00001.png).
std::string sequenceFrameName(std::uint64_t number);

}  // namespace signstim::render
