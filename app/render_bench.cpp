// `signstim devices` and `signstim bench render` (Vulkan side).
//
// bench render: frames per second of the Renderer (render + readback, pipelined with
// framesInFlight() frames) beside two raw baselines — minimal draw-and-readback loops written
// directly against Vulkan on the same device and mesh (renderer/vk_raw_baseline.hpp): raw-lit
// with the Renderer's own shaders and constants (same image, checked per row), so renderer /
// raw-lit is the renderer's overhead, and raw 1-line with one dot product of shading, so
// renderer / raw 1-line is the cost of lighting plus overhead; CPU time per frame beside each figure
// (on a CPU device such as lavapipe it is the work, and it is less sensitive than wall time
// to other load). With frame sinks (PNG sequence, MP4) a second table gives each stage
// alone and end to end, beside the slower stage, the serial sum and the shared-CPU bound.
// A last row measures morph targets: the default signer with its face targets animated, and without them.
#include "app/commands.hpp"
#include "common/atomic_file.hpp"
#include "common/cleanup.hpp"
#include "common/error.hpp"
#include "renderer/frame_sink.hpp"
#include "renderer/procedural.hpp"
#include "renderer/renderer.hpp"
#include "renderer/vk_raw_baseline.hpp"
#include "signer/avatar_builder.hpp"

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>
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
    bool morphOnly = false;
};

// The mesh framed as the raw baseline frames it (sphere of radius 0.5 at the origin).
// `shift` moves camera and target sideways (the sink measurements vary their frames so the
// MP4 encoder sees motion, as it would in a real clip; rendering cost is unchanged).
render::Frame benchFrame(int handle, float shift = 0.0f) {
    render::Frame frame;
    render::View view;
    view.scene = handle;
    view.camera.eye = {shift, 0.0f, 2.2f};
    view.camera.target = {shift, 0.0f, 0.0f};
    view.camera.verticalFovDegrees = 30.0f;
    view.camera.nearPlane = 0.1f;
    view.camera.farPlane = 10.0f;
    frame.views.push_back(view);
    return frame;
}

float sinkShift(std::uint32_t index) { return 0.01f * static_cast<float>(index % 30) - 0.15f; }

// Wall-clock frames per second and CPU milliseconds per frame (this process and its reaped
// children, i.e. ffmpeg once the MP4 sink has finished; all threads, so up to cores x wall).
struct Figure {
    double fps = 0;
    double cpuMs = 0;
};

double cpuSeconds() {
    double total = 0;
    for (int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
        rusage usage{};
        getrusage(who, &usage);
        total += double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                 1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
    }
    return total;
}

template <typename Work>
Figure measure(std::uint32_t frames, Work&& work) {
    const double cpu0 = cpuSeconds();
    const auto start = std::chrono::steady_clock::now();
    work();
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpu = cpuSeconds() - cpu0;
    return {wall > 0 ? frames / wall : 0.0, 1000.0 * cpu / frames};
}

// Keeps the best (highest fps, lowest CPU) of interleaved rounds: other load on the machine
// hits every variant alike and only ever slows it down.
void keepBest(Figure& best, const Figure& round) {
    best.fps = std::max(best.fps, round.fps);
    best.cpuMs = best.cpuMs == 0 ? round.cpuMs : std::min(best.cpuMs, round.cpuMs);
}

// Synchronous: render() one frame at a time.
Figure measureSynchronous(render::Renderer& renderer, const render::Frame& frame,
                          std::uint32_t frames) {
    render::Image image;
    renderer.render(frame, image);  // warm-up
    return measure(frames, [&] {
        for (std::uint32_t i = 0; i < frames; ++i) renderer.render(frame, image);
    });
}

// Pipelined: keep framesInFlight() frames submitted. Without a sink every frame is read
// back into one reused Image (as the raw loop reuses its host buffer); with one, each frame
// goes to the sink and is read back into a buffer the sink has finished with, when it has
// one (FrameSink::recycle).
Figure measurePipelined(render::Renderer& renderer, const std::vector<render::Frame>& sequence,
                        std::uint32_t frames, render::FrameSink* sink) {
    render::Image image;
    renderer.render(sequence[0], image);  // warm-up
    return measure(frames, [&] {
        std::uint32_t submitted = 0, retrieved = 0;
        while (retrieved < frames) {
            while (submitted < frames && renderer.framesPending() < renderer.framesInFlight()) {
                renderer.submit(sequence[submitted % sequence.size()]);
                ++submitted;
            }
            if (sink) sink->recycle(image);
            renderer.retrieve(image);
            ++retrieved;
            if (sink) sink->push(std::exchange(image, render::Image{}));
        }
        if (sink) sink->finish();
    });
}

// The sink alone: `frames` already rendered images pushed as fast as it takes them.
Figure measureSinkAlone(render::FrameSink& sink, std::vector<render::Image> images) {
    const auto frames = static_cast<std::uint32_t>(images.size());
    return measure(frames, [&] {
        for (auto& image : images) sink.push(std::move(image));
        sink.finish();
    });
}

struct SinkFigures {
    Figure alone, endToEnd;
    bool available = false;
};

// Overlap judged on a shared CPU: "min" is the slower stage's rate (perfect overlap, free
// cores), "sum" the rate if the stages ran one after the other, "cpu" the rate at which the
// cores could do both stages' CPU work (the bound when, as with lavapipe, rendering and
// encoding compete for the same cores).
// Largest and mean absolute difference of two RGBA8 images' bytes (255 if sizes differ).
std::pair<int, double> imageDifference(const std::vector<std::uint8_t>& a,
                                       const std::vector<std::uint8_t>& b) {
    if (a.size() != b.size() || a.empty()) return {255, 255.0};
    int largest = 0;
    double sum = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const int d = a[i] > b[i] ? a[i] - b[i] : b[i] - a[i];
        largest = std::max(largest, d);
        sum += d;
    }
    return {largest, sum / double(a.size())};
}

std::string sinkColumns(const Figure& render, const SinkFigures& sink, unsigned cores) {
    if (!sink.available) return "   n/a |   n/a |   n/a |   n/a |   n/a |";
    const double slowest = std::min(render.fps, sink.alone.fps);
    const double serial = 1.0 / (1.0 / render.fps + 1.0 / sink.alone.fps);
    const double cpuBound = cores * 1000.0 / (render.cpuMs + sink.alone.cpuMs);
    char text[96];
    std::snprintf(text, sizeof text, " %5.0f | %5.0f | %5.0f | %5.0f | %5.0f |", sink.alone.fps,
                  sink.endToEnd.fps, slowest, serial, cpuBound);
    return text;
}

// The default signer without its face targets: the same meshes, every morph target removed,
// the baseline a face costs against.
render::Scene withoutTargets(render::Scene scene) {
    for (render::Mesh& mesh : scene.meshes) {
        for (render::Primitive& primitive : mesh.primitives) primitive.targets.clear();
        mesh.weights.clear();
        mesh.targetNames.clear();
    }
    return scene;
}

// The morph row (issue 23 §1: "52 targets on the signer cost <= 10 % of its frames/s"): the
// default signer with its own face targets (signer/avatar_face.hpp), all weights non-zero and
// different in every frame (set by name, as the signer sets them), against the same signer with
// the targets removed ("plain").
void runMorphBench(const BenchSettings& settings, std::uint32_t frames) {
    const render::Scene face = signer::buildDefaultAvatar();
    const render::Scene plain = withoutTargets(face);
    std::vector<std::string> names;
    std::size_t vertices = 0, morphed = 0;
    for (const render::Mesh& mesh : face.meshes) {
        names.insert(names.end(), mesh.targetNames.begin(), mesh.targetNames.end());
        for (const render::Primitive& primitive : mesh.primitives) {
            vertices += primitive.vertices.size();
            for (std::size_t v = 0; v < primitive.vertices.size(); ++v)
                morphed += std::any_of(primitive.targets.begin(), primitive.targets.end(), [&](const render::MorphTarget& t) {
                    return v < t.position.size() && t.position[v] != glm::vec3(0.0f);
                });
        }
    }
    render::RendererOptions options;
    options.device = settings.device;
    options.width = 640;
    options.height = 480;
    render::Renderer renderer(options);
    const int plainHandle = renderer.addScene(plain);
    const int faceHandle = renderer.addScene(face);
    render::View view;
    view.camera = render::frameBounds(render::computeBounds(plain, render::restPose(plain)), 640.0f / 480.0f);
    std::vector<render::Frame> plainFrames, faceFrames;
    for (std::uint32_t i = 0; i < 16; ++i) {
        render::Frame frame;
        view.scene = plainHandle;
        view.pose = render::Pose{};
        frame.views = {view};
        plainFrames.push_back(frame);
        view.scene = faceHandle;
        for (std::size_t t = 0; t < names.size(); ++t)
            view.pose.morphByName[names[t]] = 0.5f + 0.45f * std::sin(0.4f * float(i) + float(t));
        frame.views = {view};
        faceFrames.push_back(frame);
    }
    Figure plainBest, morphBest;
    for (std::uint32_t round = 0; round < settings.rounds; ++round) {
        keepBest(plainBest, measurePipelined(renderer, plainFrames, frames, nullptr));
        keepBest(morphBest, measurePipelined(renderer, faceFrames, frames, nullptr));
    }
    const double ratio = morphBest.fps / plainBest.fps;
    std::printf(
        "\nMorph targets: the default signer (%zu vertices) with its %zu face targets (%zu vertices moved by "
        "them; all weights non-zero, new every frame) against the same signer without targets (plain); "
        "640x480, MSAA 1x, renderer pipelined. Goal: morph fps >= 0.90 x plain fps\n\n",
        vertices, names.size(), morphed);
    // CPU time per frame is the work on a CPU device (lavapipe) and less sensitive than wall
    // time to other load, so its ratio is printed beside (plain cpu / morph cpu: the fps ratio
    // the work alone would give).
    std::printf("| signer | targets | plain fps | morph fps | morph/plain | plain cpu | morph cpu | cpu plain/morph | goal |\n");
    std::printf("|--------|---------|-----------|-----------|-------------|-----------|-----------|-----------------|------|\n");
    std::printf("| default | %7zu | %9.0f | %9.0f | %11.3f | %9.2f | %9.2f | %15.3f | %s |\n", names.size(),
                plainBest.fps, morphBest.fps, ratio, plainBest.cpuMs, morphBest.cpuMs,
                plainBest.cpuMs / morphBest.cpuMs, ratio >= 0.90 ? "met" : "MISSED");
    std::fflush(stdout);
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
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());

    {
        render::RendererOptions probe;
        probe.device = settings.device;
        probe.width = probe.height = 16;
        render::Renderer renderer(probe);  // selects (or refuses) the device once
        std::printf("device: %s (%s, %s), %u frames per measurement, %u in flight, %u cores\n",
                    renderer.device().name.c_str(), renderer.device().type.c_str(),
                    renderer.device().driver.c_str(), frames, renderer.framesInFlight(), cores);
        for (std::uint32_t msaa : std::vector<std::uint32_t>(msaaCounts)) {
            const auto& counts = renderer.device().sampleCounts;
            if (std::find(counts.begin(), counts.end(), msaa) == counts.end())
                std::erase(msaaCounts, msaa);
        }
    }
    // The sinks' scratch folder, in the system's temporary folder ($TMPDIR): a refused write
    // there is the environment's problem (IoError, exit 3), not a bug.
    std::error_code noTemporaryFolder;
    std::filesystem::path temporaryFolder = std::filesystem::temp_directory_path(noTemporaryFolder);
    if (noTemporaryFolder) temporaryFolder = "/tmp";
    const auto scratch = temporaryFolder / ("signstim-bench-" + std::to_string(::getpid()));
    std::printf(
        "fps = frames per second (best of %u interleaved rounds); cpu = CPU ms per frame, all "
        "threads (lowest of the rounds). raw-lit = minimal loop with the renderer's shaders and "
        "constants (same image: diff = max/mean |renderer - raw-lit| per byte of the bench "
        "frame); raw 1-line = minimal loop with one-line shading. overhead = renderer "
        "pipelined / raw-lit (fps; cpu: raw-lit / renderer); lighting+overhead = renderer "
        "pipelined / raw 1-line\n\n",
        settings.rounds);
    if (!settings.morphOnly) std::printf("| size      | MSAA | triangles | raw 1-line fps | raw-lit fps | renderer sync | renderer pipelined | overhead | lighting+overhead | raw 1-line cpu | raw-lit cpu | renderer cpu | cpu overhead | cpu lighting+overhead | diff max/mean |\n");
    if (!settings.morphOnly) std::printf("|-----------|------|-----------|----------------|-------------|---------------|--------------------|----------|-------------------|----------------|-------------|--------------|--------------|-----------------------|---------------|\n");
    std::vector<std::string> sinkRows;
    if (settings.morphOnly) sizes.clear();
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
                raw.shading = render::RawShading::Lit;  // RendererOptions' default lighting
                render::RawBaseline rawLit(mesh, raw);

                render::RendererOptions options;
                options.device = settings.device;
                options.width = size.width;
                options.height = size.height;
                options.msaa = msaa;
                render::Renderer renderer(options);
                const int handle = renderer.addScene(mesh);
                const std::vector<render::Frame> still = {benchFrame(handle)};
                // Image agreement of raw-lit and the renderer on the bench frame.
                render::Image reference;
                renderer.render(still[0], reference);
                rawLit.run(1);  // also the warm-up
                const auto [diffMax, diffMean] = imageDifference(reference.bytes, rawLit.pixels());
                Figure rawBest, litBest, syncBest, pipelinedBest;
                baseline.run(1);  // warm-up
                for (std::uint32_t round = 0; round < settings.rounds; ++round) {
                    keepBest(rawBest, measure(frames, [&] { baseline.run(frames); }));
                    keepBest(litBest, measure(frames, [&] { rawLit.run(frames); }));
                    keepBest(syncBest, measureSynchronous(renderer, still[0], frames));
                    keepBest(pipelinedBest, measurePipelined(renderer, still, frames, nullptr));
                }
                const auto shown = static_cast<unsigned>(mesh.meshes[0].primitives[0].indices.size() / 3);
                std::printf("| %4ux%-4u | %ux   | %9u | %14.0f | %11.0f | %13.0f | %18.0f | %7.2fx | %16.2fx | %14.2f | %11.2f | %12.2f | %11.2fx | %20.2fx | %4d / %6.4f |\n",
                            size.width, size.height, msaa, shown, rawBest.fps, litBest.fps,
                            syncBest.fps, pipelinedBest.fps, pipelinedBest.fps / litBest.fps,
                            pipelinedBest.fps / rawBest.fps, rawBest.cpuMs, litBest.cpuMs,
                            pipelinedBest.cpuMs, litBest.cpuMs / pipelinedBest.cpuMs,
                            rawBest.cpuMs / pipelinedBest.cpuMs, diffMax, diffMean);
                std::fflush(stdout);
                if (!settings.sinks) continue;

                // Sinks: render alone (into a sink that drops frames), each encoder alone
                // (on frames rendered beforehand), then both overlapped.
                std::vector<render::Frame> moving;
                std::vector<render::Image> rendered(frames);
                for (std::uint32_t i = 0; i < frames; ++i) {
                    moving.push_back(benchFrame(handle, sinkShift(i)));
                    renderer.render(moving.back(), rendered[i]);
                }
                auto discard = render::makeDiscardSink();
                const Figure renderAlone = measurePipelined(renderer, moving, frames, discard.get());
                {
                    // Registered, so an interrupted bench removes it with the sinks' outputs.
                    CleanupLock lock;
                    if (::mkdir(scratch.c_str(), 0777) != 0 && errno != EEXIST) {
                        const int error = errno;
                        throw IoError(scratch.string(), "cannot write", error);
                    }
                    lock.addTemporary(scratch);
                }
                // Removed on every way out, a failed sink's exception included.
                struct ScratchRemover {
                    const std::filesystem::path& folder;
                    std::error_code error;
                    void remove() {
                        std::filesystem::remove_all(folder, error);
                        CleanupLock{}.removeTemporary(folder);
                    }
                    ~ScratchRemover() {
                        if (std::filesystem::exists(folder, error)) remove();
                    }
                } remover{scratch, {}};
                ensureWritableDirectory(scratch);  // checks that files can be created in it
                SinkFigures png, mp4;
                {
                    auto sink = render::makePngSequenceSink(scratch / "png-alone");
                    png.alone = measureSinkAlone(*sink, rendered);
                    sink = render::makePngSequenceSink(scratch / "png");
                    png.endToEnd = measurePipelined(renderer, moving, frames, sink.get());
                    png.available = true;
                }
                try {
                    auto sink = render::makeVideoSink(scratch / "alone.mp4");
                    mp4.alone = measureSinkAlone(*sink, rendered);
                    sink = render::makeVideoSink(scratch / "bench.mp4");
                    mp4.endToEnd = measurePipelined(renderer, moving, frames, sink.get());
                    mp4.available = true;
                } catch (const EnvironmentError& error) {
                    std::fprintf(stderr, "signstim: +MP4 skipped: %s\n", error.what());
                }
                remover.remove();
                if (remover.error) throw IoError(scratch.string(), "cannot remove", remover.error.message());
                char head[96];
                std::snprintf(head, sizeof head, "| %4ux%-4u | %ux   | %9u | %6.0f | %6.2f |",
                              size.width, size.height, msaa, shown, renderAlone.fps,
                              renderAlone.cpuMs);
                char cpu[64];
                std::snprintf(cpu, sizeof cpu, " %6.2f | %6.2f |", png.alone.cpuMs,
                              mp4.available ? mp4.alone.cpuMs : 0.0);
                sinkRows.push_back(std::string(head) + sinkColumns(renderAlone, png, cores) +
                                   sinkColumns(renderAlone, mp4, cores) + cpu);
            }
        }
    }
    runMorphBench(settings, frames);
    if (sinkRows.empty()) return;
    std::printf(
        "\nSinks (frames move sideways so the encoder sees motion). render = pipelined into a "
        "sink that drops frames; alone = the encoder on frames rendered beforehand; e2e = "
        "both overlapped, finish included; min = the slower stage (perfect overlap on free "
        "cores); sum = the stages one after the other; cpu = %u cores / (render + encoder CPU "
        "ms), the bound when both share the cores\n\n",
        cores);
    std::printf("| size      | MSAA | triangles | render | r. cpu | PNG alone | +PNG e2e | min | sum | cpu | MP4 alone | +MP4 e2e | min | sum | cpu | PNG cpu | MP4 cpu |\n");
    std::printf("|-----------|------|-----------|--------|--------|-------|-------|-------|-------|-------|-------|-------|-------|-------|-------|--------|--------|\n");
    for (const auto& row : sinkRows) std::printf("%s\n", row.c_str());
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
        "~20k/~100k triangles, beside raw Vulkan draw-and-readback baselines (renderer's shading; one-line shading); "
        "then the default signer with its face targets animated against without");
    bench->add_option("--device", settings->device, "Vulkan device name substring or index");
    bench->add_option("--frames", settings->frames, "Frames per measurement")
        ->capture_default_str();
    bench->add_option("--rounds", settings->rounds,
                      "Interleaved rounds per configuration (best of each is printed)")
        ->capture_default_str()
        ->check(CLI::Range(1, 100));
    bench->add_flag("--quick", settings->quick, "640x480, 20k triangles, at most 20 frames");
    bench->add_flag("!--no-sinks", settings->sinks, "Skip the +PNG and +MP4 columns");
    bench->add_flag("--morph-only", settings->morphOnly,
                    "Only the morph-target row (the default signer with its face targets animated, and without)");
    bench->callback([settings] { runRenderBench(*settings); });
}

}  // namespace signstim::app
