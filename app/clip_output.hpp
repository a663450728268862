#pragma once
// One clip of the signer (a verb, a story) to the output a user named with --out: FILE.mp4,
// FILE.png/.exr/.tif (one still) or a folder of frames. Shared by `verb --out` and
// `story --out`, so both check the same things in the same order:
//   1. the output's kind, --size (even for MP4), --fps, an existing frame folder, --msaa
//      (checkClipOutput, before anything is loaded);
//   2. the device accepts the settings, then the output's place is writable
//      (renderClipToOutput, before the first frame).
#include "app/cli_values.hpp"
#include "renderer/frame_sink.hpp"
#include "renderer/video_encoder.hpp"
#include "renderer/renderer.hpp"
#include "signer/avatar_render.hpp"
#include "signer/clip.hpp"
#include "signer/signer.hpp"

#include <cstdint>
#include <filesystem>
#include <string>

namespace signstim::app {

struct ClipOutput {
    std::filesystem::path out;
    render::OutputKind kind = render::OutputKind::Video;
    ImageSize size;
    render::FrameRate frameRate;
    std::uint32_t msaa = 4;
    std::string device;
    bool quiet = false;
    signer::CameraFraming framing = signer::CameraFraming::WaistUp;  // --camera
};

// Step 1: throws InputError naming the flag (exit 1) or the folder (exit 2).
ClipOutput checkClipOutput(const std::string& out, const std::string& size, const std::string& fps, std::uint32_t msaa,
                           const std::string& device, bool quiet);

// Step 2 and the render: progress on stderr unless quiet; a still output keeps the frame at
// `stillSeconds`. Returns the number of frames written (1 for a still).
std::uint64_t renderClipToOutput(const ClipOutput& output, const signer::Signer& signer, const signer::Clip& clip,
                                 double stillSeconds);

// With validation on (SIGNSTIM_VALIDATION=1), any message of the layer fails the command
// before its output is committed: each is printed, then std::runtime_error (exit 4).
void failOnValidationMessages(const render::Renderer& renderer);

}  // namespace signstim::app
