#include "app/clip_output.hpp"

#include "app/progress.hpp"
#include "common/atomic_file.hpp"
#include "renderer/image_io.hpp"
#include "renderer/relay_sinks.hpp"
#include "renderer/renderer.hpp"
#include "signer/avatar_render.hpp"
#include "signer/clip_render.hpp"

#include <cstdio>
#include <memory>
#include <string>

namespace signstim::app {

ClipOutput checkClipOutput(const std::string& out, const std::string& size, const std::string& fps, std::uint32_t msaa,
                           const std::string& device, bool quiet) {
    ClipOutput output;
    output.out = out;
    output.kind = render::outputKind(output.out);
    // H.264 in yuv420p needs even sides: refused here as the flag's mistake, before rendering.
    output.size = parseImageSize(size, "--size", {.even = output.kind == render::OutputKind::Video});
    output.frameRate = render::parseFrameRate(fps);
    if (output.kind == render::OutputKind::Folder) render::checkFrameFolder(output.out);
    requireSampleCount(msaa, "--msaa");
    output.msaa = msaa;
    output.device = device;
    output.quiet = quiet;
    return output;
}

std::uint64_t renderClipToOutput(const ClipOutput& output, const signer::Signer& signer, const signer::Clip& clip,
                                 double stillSeconds) {
    // The renderer first: a device that refuses --msaa, --size or --device stops the command
    // before anything is created on disk; then the output's place, before any frame.
    render::Renderer renderer(
        signer::signerRendererOptions(output.size.width, output.size.height, output.msaa, output.device));
    checkOutputWritable(output.out);
    const int handle = renderer.addScene(signer.avatar());
    signer::ClipRenderOptions options;
    options.framesPerSecond = output.frameRate.value();
    options.framing = output.framing;
    render::VideoOptions video;
    video.frameRate = output.frameRate;
    const bool still = output.kind == render::OutputKind::Image;
    std::unique_ptr<render::FrameSink> target =
        still ? render::makeDiscardSink() : render::makeFrameSink(output.out, {}, video);
    render::StillCapturingSink sink(*target, static_cast<std::uint64_t>(stillSeconds * options.framesPerSecond));
    std::unique_ptr<ProgressReporter> progress;
    const std::uint64_t frames = signer::renderClips(
        renderer, handle, signer.avatar(), signer.rig(), {&clip}, {}, options, sink,
        [&](std::uint64_t done, std::uint64_t total) {
            if (!progress) progress = std::make_unique<ProgressReporter>("signstim", static_cast<double>(total), output.quiet);
            const std::string what = "frame " + std::to_string(done) + "/" + std::to_string(total);
            if (done == total)
                progress->stepDone(static_cast<double>(done), what);
            else
                progress->update(static_cast<double>(done), what);
        });
    if (progress) progress->end();
    failOnValidationMessages(renderer);
    sink.finish();
    if (!still) return frames;
    render::writeImage(sink.still(), output.out);
    return 1;
}

void failOnValidationMessages(const render::Renderer& renderer) {
    const std::vector<std::string> messages = renderer.validationMessages();
    if (messages.empty()) return;
    for (const std::string& m : messages) std::fprintf(stderr, "signstim: validation: %s\n", m.c_str());
    throw std::runtime_error(std::to_string(messages.size()) + " Vulkan validation message(s); output not written");
}

}  // namespace signstim::app
