// `signstim render-gltf`: renders a glTF file (optionally animated) to a PNG, a numbered PNG
// sequence or an MP4.
#include "app/cli_values.hpp"
#include "app/commands.hpp"
#include "app/progress.hpp"

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "renderer/frame.hpp"
#include "renderer/frame_sink.hpp"
#include "renderer/gltf_loader.hpp"
#include "renderer/renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <memory>
#include <sstream>

namespace signstim::app {
namespace {

namespace fs = std::filesystem;

struct RenderGltfSettings {
    std::string file, out, size = "640x480", fps = "30", animation, camera, background, device;
    std::vector<std::string> allowedDirectories;
    std::int64_t frames = 0;  // when framesGiven; else one per frame period over the animation
    bool framesGiven = false;
    std::uint32_t msaa = 4;
    int pngCompression = 1;
    int bitDepth = 8;
    bool quiet = false;
};

// "eye=x,y,z;target=x,y,z;up=x,y,z;fov=deg" — every key optional; unset keys keep `camera`.
render::Camera parseCamera(const std::string& text, render::Camera camera) {
    std::stringstream stream(text);
    for (std::string item; std::getline(stream, item, ';');) {
        if (item.empty()) continue;
        const std::size_t eq = item.find('=');
        const std::string key = item.substr(0, eq), value = eq == std::string::npos ? "" : item.substr(eq + 1);
        if (key == "eye" || key == "target" || key == "up") {
            (key == "eye" ? camera.eye : key == "target" ? camera.target : camera.up) = parseTriple(value, "--camera " + key);
        } else if (key == "fov") {
            const float fov = parseNumber(value, "--camera fov");
            if (fov <= 1.0f || fov >= 179.0f) throw commandLineError("--camera", "fov must be in (1, 179) degrees");
            camera.verticalFovDegrees = fov;
        } else {
            throw commandLineError("--camera", "unknown key '" + key + "' (use eye=x,y,z;target=x,y,z;up=x,y,z;fov=deg)");
        }
    }
    if (glm::length(camera.eye - camera.target) < 1e-6f)
        throw commandLineError("--camera", "eye and target must differ");
    const float distance = glm::length(camera.eye - camera.target);
    camera.farPlane = std::max(camera.farPlane, distance * 4.0f);
    camera.nearPlane = std::min(camera.nearPlane, distance * 0.05f);
    return camera;
}

int chooseAnimation(const render::Scene& scene, const std::string& request, const std::string& file) {
    if (request.empty()) return scene.animations.empty() ? -1 : 0;
    if (const int byName = scene.findAnimation(request); byName >= 0) return byName;
    const bool numeric = std::all_of(request.begin(), request.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (numeric && request.size() < 9 && std::stoul(request) < scene.animations.size()) return std::stoi(request);
    std::string names;
    for (std::size_t i = 0; i < scene.animations.size(); ++i)
        names += (i ? ", " : "") + std::to_string(i) + " '" + scene.animations[i].name + "'";
    throw commandLineError("--animation",
                     "'" + request + "' is not an animation of " + file +
                         (names.empty() ? " (it has none)" : " (it has: " + names + ")"));
}

// A clip longer than this is refused: frame counts stay far from any integer limit, and an
// hour of frames is more than any stimulus; a key at 1e9 s is a broken file, not a request.
constexpr double kLongestClipSeconds = 3600.0;

// Frames of an hour at `fps`, first and last included.
std::int64_t mostFrames(double fps) { return static_cast<std::int64_t>(std::ceil(kLongestClipSeconds * fps - 1e-4)) + 1; }

void renderGltf(const RenderGltfSettings& s) {
    render::RendererOptions options;
    const ImageSize size = parseImageSize(s.size, "--size");
    options.width = size.width;
    options.height = size.height;
    options.msaa = requireSampleCount(s.msaa, "--msaa");
    options.device = s.device;
    if (s.bitDepth != 8 && s.bitDepth != 16) throw commandLineError("--bit-depth", "must be 8 or 16");
    options.format = s.bitDepth == 16 ? render::PixelFormat::Rgba16 : render::PixelFormat::Rgba8;
    if (!s.background.empty()) options.background = parseColour(s.background, "--background");
    if (s.pngCompression < 0 || s.pngCompression > 9) throw commandLineError("--png-compression", "must be 0..9");
    render::VideoOptions video;
    video.frameRate = render::parseFrameRate(s.fps);
    const fs::path out = s.out;
    const render::OutputKind kind = render::outputKind(out);

    const double fps = video.frameRate.value();
    if (s.framesGiven && (s.frames < 1 || s.frames > mostFrames(fps)))
        throw commandLineError("--frames", "must be 1 to " + std::to_string(mostFrames(fps)) + " (one hour at " +
                                               video.frameRate.text() + " fps), got " + std::to_string(s.frames));

    render::GltfLoadOptions loadOptions;
    loadOptions.allowedDirectories.assign(s.allowedDirectories.begin(), s.allowedDirectories.end());
    loadOptions.allowFlag = "--allow-dir";
    const render::Scene scene = render::loadGltf(s.file, loadOptions);
    const int animation = chooseAnimation(scene, s.animation, s.file);
    const render::Animation* clip = animation >= 0 ? &scene.animations[static_cast<std::size_t>(animation)] : nullptr;
    const float duration = clip ? clip->durationSeconds : 0.0f;

    const bool singleImage = kind == render::OutputKind::Image;
    std::int64_t frames = s.frames;
    if (!s.framesGiven && (singleImage || duration <= 0.0f)) {
        frames = 1;
    } else if (!s.framesGiven) {
        // In double, before any integer conversion: a key at 1e9 s is 3e10 frames at 30 fps.
        const double needed = std::ceil(static_cast<double>(duration) * fps - 1e-4) + 1.0;
        if (needed > static_cast<double>(mostFrames(fps))) {
            std::ostringstream count, seconds;
            count.precision(0);
            count << std::fixed << needed;
            seconds << duration;
            throw InputError(s.file, 0, clip->durationSource,
                             "animation '" + clip->name + "' lasts " + seconds.str() + " s: " + count.str() +
                                 " frames at " + video.frameRate.text() +
                                 " fps, more than one hour (" + std::to_string(mostFrames(fps)) +
                                 " frames); refused (--frames N renders N frames spread over it)");
        }
        frames = static_cast<std::int64_t>(needed);
    }
    if (singleImage && frames > 1)
        throw commandLineError("--frames", std::to_string(frames) + " frames need a directory or an .mp4 output, not " +
                                               out.string() + " (a single image)");
    if (kind == render::OutputKind::Video && (options.width % 2 || options.height % 2))
        throw commandLineError("--size", s.size + ": MP4 (H.264, yuv420p) needs an even width and height");
    if (kind == render::OutputKind::Folder) render::checkFrameFolder(out);
    // Frame i shows the animation at duration * i / (frames - 1): first and last key included.
    auto timeOf = [&](std::int64_t i) {
        return frames > 1 ? static_cast<float>(static_cast<double>(duration) * static_cast<double>(i) /
                                               static_cast<double>(frames - 1))
                          : 0.0f;
    };
    auto poseAt = [&](std::int64_t i) {
        render::Pose pose = render::restPose(scene);
        if (animation >= 0) render::applyAnimation(scene, animation, timeOf(i), pose);
        return pose;
    };
    // One fixed camera framing the union of the posed bounds (at most 64 samples).
    render::Bounds bounds;
    const std::int64_t samples = std::min<std::int64_t>(frames, 64);
    for (std::int64_t k = 0; k < samples; ++k) {
        const std::int64_t i = samples > 1 ? k * (frames - 1) / (samples - 1) : 0;
        const render::Bounds b = render::computeBounds(scene, poseAt(i));
        if (!b.empty) {
            bounds.add(b.min);
            bounds.add(b.max);
        }
    }
    const float aspect = static_cast<float>(options.width) / static_cast<float>(options.height);
    render::Camera camera = render::frameBounds(bounds, aspect);
    if (!s.camera.empty()) camera = parseCamera(s.camera, camera);
    // The renderer would blame "<frame>"; name where the camera came from instead.
    if (const std::string problem = render::cameraProblem(camera); !problem.empty()) {
        if (!s.camera.empty()) throw commandLineError("--camera", problem);
        throw InputError(s.file, 0, "", "the scene's bounds cannot be framed by a camera: " + problem +
                                            " (give one with --camera)");
    }

    render::ImageWriteOptions imageOptions;
    imageOptions.pngCompression = s.pngCompression;
    imageOptions.alpha = options.background.a < 1.0f;
    // The renderer first: a device that refuses --msaa, --size or --device stops the command
    // before anything is created on disk.
    render::Renderer renderer(options);
    // Fail on a bad output location now, not after rendering.
    checkOutputWritable(out);
    const int handle = renderer.addScene(scene);
    std::unique_ptr<render::FrameSink> sink = render::makeFrameSink(out, imageOptions, video);

    auto frameAt = [&](std::int64_t i) {
        render::Frame frame;
        frame.views.push_back(render::View{handle, poseAt(i), camera, ""});
        return frame;
    };
    ProgressReporter progress("render-gltf", static_cast<double>(frames), s.quiet);
    const auto report = [&](std::int64_t done, bool final) {
        const std::string what = std::to_string(done) + "/" + std::to_string(frames) + " frames";
        if (final)
            progress.stepDone(static_cast<double>(done), what);
        else
            progress.update(static_cast<double>(done), what);
    };
    // Pipelined: keep the renderer's frames in flight busy while the sink encodes.
    const std::int64_t inFlight = std::max(1u, renderer.framesInFlight());
    std::int64_t submitted = 0, done = 0;
    while (done < frames) {
        while (submitted < frames && submitted - done < inFlight) renderer.submit(frameAt(submitted++));
        render::Image image;
        renderer.retrieve(image);
        sink->push(std::move(image));
        ++done;
        report(done, false);
    }
    const std::vector<std::string> messages = renderer.validationMessages();
    if (!messages.empty()) {
        for (const std::string& m : messages) std::fprintf(stderr, "signstim: validation: %s\n", m.c_str());
        throw std::runtime_error(std::to_string(messages.size()) + " Vulkan validation message(s); output not written");
    }
    sink->finish();
    report(done, true);
    progress.end();
}

}  // namespace

void registerRenderCommands(Commands& commands) {
    auto settings = std::make_shared<RenderGltfSettings>();
    CLI::App* cmd = commands.root.add_subcommand(
        "render-gltf",
        "Render a glTF 2.0 file (.gltf/.glb) to a PNG, a PNG sequence directory or an MP4.\n"
        "Frames sample the chosen animation evenly from its start to its end.");
    cmd->add_option("FILE", settings->file, "glTF file (.gltf with external or embedded buffers, or .glb)")->required();
    cmd->add_option("--out,-o", settings->out,
                    "OUT.png/.exr/.tif (one frame), OUT.mp4 (H.264 video) or a folder (frame_00001.png ...;\n"
                    "a new folder, or one holding only an earlier render's frames, which it replaces whole)")
        ->required();
    cmd->add_option("--size", settings->size, "WIDTHxHEIGHT (default 640x480; even for MP4)");
    CLI::Option* framesOption = cmd->add_option(
        "--frames", settings->frames,
        "number of frames, at least 1 (default: duration x fps + 1 with an animation, else 1; at most one hour)");
    cmd->add_option("--fps", settings->fps, "frame rate: 30, 25, 30000/1001 or 29.97 (default 30)");
    cmd->add_option("--msaa", settings->msaa,
                    "multisampling 1 or 4 (default 4; others where the device has them, see `signstim devices`)");
    cmd->add_option("--animation", settings->animation, "animation name or index (default: the first, if any)");
    cmd->add_option("--camera", settings->camera,
                    "'eye=x,y,z;target=x,y,z;up=x,y,z;fov=deg', any subset (default: frames the scene bounds "
                    "from +Z, 30 degree vertical field of view)");
    cmd->add_option("--background", settings->background,
                    "#rrggbb, r,g,b[,a] (sRGB 0..1) or transparent (PNG with alpha)");
    cmd->add_option("--device", settings->device, "Vulkan device: name substring or index (see `signstim devices`)");
    cmd->add_option("--png-compression", settings->pngCompression, "zlib level 0..9 (default 1: fast)");
    cmd->add_option("--bit-depth", settings->bitDepth, "8 or 16 bits per channel (PNG)");
    cmd->add_option("--allow-dir", settings->allowedDirectories,
                    "a folder outside the model's own from which its images and buffers may be read "
                    "(repeatable; by default a URI that is absolute or leads out with .. is refused)");
    cmd->add_flag("--quiet,-q", settings->quiet, "no progress on stderr");
    cmd->callback([settings, framesOption] {
        settings->framesGiven = framesOption->count() > 0;
        renderGltf(*settings);
    });
}

}  // namespace signstim::app
