#pragma once
// Where rendered frames go: one PNG, a numbered PNG sequence, or an MP4. Encoding runs on
// worker threads so it overlaps with rendering; push() blocks when the bounded queue is full
// (back-pressure) and rethrows the first worker error. Outputs appear atomically, only at
// finish(): an image or MP4 via a temporary file + rename, a PNG sequence as a whole folder
// (written into a temporary sibling folder, then renamed into place). Destroying a sink
// without finish() abandons the work and removes every temporary.
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

// frame_00001.png, frame_00002.png, ... in `directory`, compressed on `threads` workers
// (0: min(hardware threads, 4)). The folder appears, or replaces an earlier render, only at
// finish(). Refused at once (checkFrameFolder, checkOutputWritable) when `directory` holds
// anything but an earlier render's frames, or its parent does not accept new files.
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

// By the output's name (outputKind): *.mp4 -> video, *.png/.exr/.tif(f) -> one image, a name
// without an extension -> a PNG sequence folder.
std::unique_ptr<FrameSink> makeFrameSink(const std::filesystem::path& output,
                                         const ImageWriteOptions& imageOptions = {},
                                         const VideoOptions& videoOptions = {});

enum class OutputKind { Video, Image, Folder };

// What `output` names: .mp4, .png/.exr/.tif/.tiff (case-insensitive), or a folder (no
// extension; a trailing '/' is allowed: "frames/"). Any other extension, or an extension with
// a trailing '/' ("a.mp4/"), is a command-line mistake: InputError naming `flag` (exit 1)
// that says what works. Call it before any work.
OutputKind outputKind(const std::filesystem::path& output, const std::string& flag = "--out");

// A frame folder may be written only where nothing would be lost: `directory` does not exist,
// is empty, or holds only frame_NNNNN.png files (an earlier render, replaced whole). Anything
// else: InputError naming the folder (exit 2) saying to choose a new or empty folder.
void checkFrameFolder(const std::filesystem::path& directory);

// The name the PNG sequence uses for 1-based frame `number` (frame_00001.png).
std::string sequenceFrameName(std::uint64_t number);

}  // namespace signstim::render
