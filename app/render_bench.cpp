// `signstim devices` and `signstim bench render` (Vulkan side).
//
// bench render: frames per second of the Renderer (render + readback, pipelined with
// framesInFlight() frames) beside a raw baseline — a minimal draw-and-readback loop written
// directly against Vulkan on the same device and mesh (renderer/vk_raw_baseline.hpp) — so
// the renderer's overhead is a ratio from one run. With a frame sink (+PNG sequence, +MP4)
// the figure is end to end, sink finish included.
#include "app/commands.hpp"
#include "common/error.hpp"
#include "renderer/frame_sink.hpp"
#include "renderer/procedural.hpp"
#include "renderer/renderer.hpp"
#include "renderer/vk_raw_baseline.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace signstim::app {

namespace {

std::string joinCounts(const std::vector<std::uint32_t>& counts) {
    std::string text;
    for (auto c : counts) text += (text.empty() ? "" : ",") + std::to_string(c);
    return text;
}

void printDevices() {
    const auto devices = render::Renderer::listDevices();
    if (devices.empty()) {
        std::printf("no Vulkan devices (install mesa-vulkan-drivers for the lavapipe CPU device)\n");
        return;
    }
    std::printf("  %-3s %-36s %-10s %-32s %-8s %-8s %s\n", "#", "name", "type", "driver", "api",
                "msaa", "usable");
    for (const auto& device : devices) {
        std::printf("%s %-3u %-36s %-10s %-32s %-8s %-8s %s\n", device.automatic ? "*" : " ",
                    device.index, device.name.c_str(), device.type.c_str(), device.driver.c_str(),
                    device.apiVersion.c_str(), joinCounts(device.sampleCounts).c_str(),
                    device.usable ? "yes" : "no (needs Vulkan 1.3)");
    }
    std::printf("* = chosen automatically (discrete > integrated > virtual > cpu); "
                "pick another with --device NAME|INDEX\n");
}

struct BenchSettings {
    std::string device;
    std::uint32_t frames = 60;
    bool quick = false;
    bool sinks = true;
    std::uint32_t rounds = 3;
};

// The mesh framed as the raw baseline frames it (sphere of radius 0.5 at the origin).
render::Frame benchFrame(int handle) {
    render::Frame frame;
    render::View view;
    view.scene = handle;
    view.camera.eye = {0.0f, 0.0f, 2.2f};
    view.camera.target = {0.0f, 0.0f, 0.0f};
    view.camera.verticalFovDegrees = 30.0f;
    view.camera.nearPlane = 0.1f;
    view.camera.farPlane = 10.0f;
    frame.views.push_back(view);
    return frame;
}

double seconds(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Synchronous: render() one frame at a time.
double measureSynchronous(render::Renderer& renderer, const render::Frame& frame,
                          std::uint32_t frames) {
    render::Image image;
    renderer.render(frame, image);  // warm-up
    const auto start = std::chrono::steady_clock::now();
    for (std::uint32_t i = 0; i < frames; ++i) renderer.render(frame, image);
    return frames / seconds(start);
}

// Pipelined: keep framesInFlight() frames submitted; each retrieved frame goes to `sink`.
double measurePipelined(render::Renderer& renderer, const render::Frame& frame,
                        std::uint32_t frames, render::FrameSink* sink) {
    render::Image warmup;
    renderer.render(frame, warmup);
    const auto start = std::chrono::steady_clock::now();
    std::uint32_t submitted = 0, retrieved = 0;
    render::Image image;  // reused when there is no sink (as the raw loop reuses its buffer)
    while (retrieved < frames) {
        while (submitted < frames && renderer.framesPending() < renderer.framesInFlight()) {
            renderer.submit(frame);
            ++submitted;
        }
        renderer.retrieve(image);
        ++retrieved;
        if (sink) sink->push(std::exchange(image, render::Image{}));
    }
    if (sink) sink->finish();
    return frames / seconds(start);
}

void runRenderBench(const BenchSettings& settings) {
    struct Size {
        std::uint32_t width, height;
    };
    std::vector<Size> sizes = {{640, 480}, {1280, 720}};
    std::vector<std::uint32_t> triangleCounts = {20000, 100000};
    std::vector<std::uint32_t> msaaCounts = {1, 4};
    std::uint32_t frames = settings.frames;
    if (settings.quick) {
        sizes = {{640, 480}};
        triangleCounts = {20000};
        frames = std::min<std::uint32_t>(frames, 20);
    }
    if (frames == 0) throw InputError("<command line>", 0, "--frames", "must be at least 1");

    {
        render::RendererOptions probe;
        probe.device = settings.device;
        probe.width = probe.height = 16;
        render::Renderer renderer(probe);  // selects (or refuses) the device once
        std::printf("device: %s (%s, %s), %u frames per measurement, %u in flight\n",
                    renderer.device().name.c_str(), renderer.device().type.c_str(),
                    renderer.device().driver.c_str(), frames, renderer.framesInFlight());
        for (std::uint32_t msaa : std::vector<std::uint32_t>(msaaCounts)) {
            const auto& counts = renderer.device().sampleCounts;
            if (std::find(counts.begin(), counts.end(), msaa) == counts.end())
                std::erase(msaaCounts, msaa);
        }
    }
    const auto scratch = std::filesystem::temp_directory_path() /
                         ("signstim-bench-" + std::to_string(::getpid()));
    std::printf("fps = frames per second, best of %u interleaved rounds; ratio = renderer "
                "(pipelined) / raw; +PNG/+MP4 end to end (sink on its own threads)\n\n",
                settings.rounds);
    std::printf("| size      | MSAA | triangles | raw   | renderer sync | renderer pipelined | ratio | +PNG  | +MP4  |\n");
    std::printf("|-----------|------|-----------|-------|---------------|--------------------|-------|-------|-------|\n");
    for (const Size& size : sizes) {
        for (std::uint32_t msaa : msaaCounts) {
            for (std::uint32_t triangles : triangleCounts) {
                const render::Scene mesh = render::procedural::uvSphere(triangles);
                render::RawBaselineSettings raw;
                raw.device = settings.device;
                raw.width = size.width;
                raw.height = size.height;
                raw.msaa = msaa;
                render::RawBaseline baseline(mesh, raw);

                render::RendererOptions options;
                options.device = settings.device;
                options.width = size.width;
                options.height = size.height;
                options.msaa = msaa;
                render::Renderer renderer(options);
                const int handle = renderer.addScene(mesh);
                const render::Frame frame = benchFrame(handle);
                // Interleaved rounds, best of each: other load on the machine hits both alike.
                double rawFps = 0, syncFps = 0, pipelinedFps = 0;
                for (std::uint32_t round = 0; round < settings.rounds; ++round) {
                    rawFps = std::max(rawFps, baseline.measure(frames));
                    syncFps = std::max(syncFps, measureSynchronous(renderer, frame, frames));
                    pipelinedFps = std::max(pipelinedFps, measurePipelined(renderer, frame, frames, nullptr));
                }
                std::string png = "-", mp4 = "-";
                if (settings.sinks) {
                    std::filesystem::create_directories(scratch);
                    auto pngSink = render::makePngSequenceSink(scratch / "png");
                    png = std::to_string(
                        static_cast<int>(measurePipelined(renderer, frame, frames, pngSink.get()) + 0.5));
                    try {
                        auto videoSink = render::makeVideoSink(scratch / "bench.mp4");
                        mp4 = std::to_string(static_cast<int>(
                            measurePipelined(renderer, frame, frames, videoSink.get()) + 0.5));
                    } catch (const EnvironmentError& error) {
                        mp4 = "n/a";  // no ffmpeg
                        std::fprintf(stderr, "signstim: +MP4 skipped: %s\n", error.what());
                    }
                    std::filesystem::remove_all(scratch);
                }
                std::printf("| %4ux%-4u | %ux   | %9u | %5.0f | %13.0f | %18.0f | %4.2fx | %5s | %5s |\n",
                            size.width, size.height, msaa,
                            static_cast<unsigned>(mesh.meshes[0].primitives[0].indices.size() / 3),
                            rawFps, syncFps, pipelinedFps, pipelinedFps / rawFps, png.c_str(),
                            mp4.c_str());
                std::fflush(stdout);
            }
        }
    }
}

}  // namespace

void registerRenderBenchCommands(Commands& commands) {
    CLI::App* devices = commands.root.add_subcommand(
        "devices", "List Vulkan devices: type, driver, API version, MSAA counts, usability");
    devices->callback([] { printDevices(); });

    auto settings = std::make_shared<BenchSettings>();
    CLI::App* bench = commands.bench.add_subcommand(
        "render",
        "Renderer frames/s (render + readback, +PNG, +MP4) at 640x480 and 1280x720, MSAA 1x/4x, "
        "~20k/~100k triangles, beside a raw Vulkan draw-and-readback baseline");
    bench->add_option("--device", settings->device, "Vulkan device name substring or index");
    bench->add_option("--frames", settings->frames, "Frames per measurement")
        ->capture_default_str();
    bench->add_option("--rounds", settings->rounds,
                      "Interleaved rounds per configuration (best of each is printed)")
        ->capture_default_str()
        ->check(CLI::Range(1, 100));
    bench->add_flag("--quick", settings->quick, "640x480, 20k triangles, at most 20 frames");
    bench->add_flag("!--no-sinks", settings->sinks, "Skip the +PNG and +MP4 columns");
    bench->callback([settings] { runRenderBench(*settings); });
}

}  // namespace signstim::app
