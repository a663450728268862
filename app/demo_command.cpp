// `signstim demo`: the verbs at a glance (the main job is `signstim study`, docs/study.md): the
// handshape gallery, and every indicating verb in its four versions side by side (SPEC §4.3
// layout), with a manifest listing every file (common/file_manifest.hpp, the study's writer).
#include "signer/avatar_render.hpp"
#include "app/cli_values.hpp"
#include "app/commands.hpp"
#include "app/progress.hpp"
#include "signer/signer_pose.hpp"
#include "signer/clip_render.hpp"
#include "signer/signer.hpp"
#include "signer/verb_clip.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/file_manifest.hpp"
#include "renderer/frame_sink.hpp"
#include "renderer/image_io.hpp"
#include "renderer/relay_sinks.hpp"
#include "renderer/renderer.hpp"
#include "stimuli/story/handshapes.hpp"
#include "stimuli/scenes_path.hpp"
#include "stimuli/verbs/signing_space.hpp"
#include "stimuli/verbs/verb_models.hpp"
#include "stimuli/verbs/verb_synthesis.hpp"
#include "stimuli/verbs/verbs.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>
#include <vector>


namespace signstim::app {

// The signer's room (avatar, rig, clips) is this command line's main collaborator.
using namespace signstim::signer;
namespace {

namespace fs = std::filesystem;

struct DemoOptions {
    std::string out = "out";
    std::string scenesDir;
    std::string panelSize = "480x360";
    std::string fps = "30";  // "30", "25", "30000/1001"
    std::uint32_t msaa = 4;
    std::string device;
    double subject = 0.9;   // SPEC §4.3: the paper's phase-2 example arrangement
    double object = -0.6;
    std::vector<std::string> verbs;  // empty: all
    bool quiet = false;
};

const std::vector<stimuli::VerbVersion> kVersions = {stimuli::VerbVersion::Point, stimuli::VerbVersion::Vector,
                                                     stimuli::VerbVersion::Animator,
                                                     stimuli::VerbVersion::Uninflected};

// "0.9" / "-0.6": positions as written in file names (SPEC §5 key-value names).
std::string positionText(double p) {
    std::ostringstream s;
    s << p;
    return s.str();
}

nlohmann::json fileEntry(const fs::path& root, const fs::path& file, const std::string& shows,
                         std::uint32_t width, std::uint32_t height, std::uint64_t frames, double fps) {
    nlohmann::json entry = describeFile(root, fs::relative(file, root).generic_string(), frames > 1 ? "video" : "image");
    entry["width"] = width;
    entry["height"] = height;
    entry["frames"] = frames;
    if (frames > 1) entry["fps"] = fps;
    entry["shows"] = shows;
    return entry;
}

// "ASK (3/10)": the verb being drawn, for the progress line.
std::string verbProgress(const stimuli::VerbDefinition& verb, std::size_t v, std::size_t count) {
    return verb.name + " (" + std::to_string(v + 1) + "/" + std::to_string(count) + ")";
}

void runDemo(const DemoOptions& o) {
    const ImageSize panel = parseImageSize(o.panelSize, "--panel-size", {64, 4096, true});
    const std::uint32_t panelWidth = panel.width, panelHeight = panel.height;
    stimuli::checkArcPosition(o.subject, "<command line>", "--subject");
    stimuli::checkArcPosition(o.object, "<command line>", "--object");
    const render::FrameRate frameRate = render::parseFrameRate(o.fps);
    const double fps = frameRate.value();
    requireSampleCount(o.msaa, "--msaa");

    // Inputs first, so that a data problem is reported before anything is rendered or written.
    const fs::path scenes = stimuli::resolveScenesDir(o.scenesDir);
    const Signer signer(scenes);
    const render::Scene& avatar = signer.avatar();
    const SignerRig& rig = signer.rig();
    const stimuli::HandshapeLibrary shapes = stimuli::loadHandshapes(scenes / "handshapes.json", rig.handModel());
    const stimuli::VerbLibrary verbs = stimuli::loadVerbLibrary(scenes / "verbs.json");
    const stimuli::TrainedVerbModels models = stimuli::loadVerbModels(scenes / "models" / "verb_models.json", verbs);
    const stimuli::VerbSources sources{&verbs, &models, scenes / "animator", &shapes};  // unknown handshapes name their file

    std::vector<const stimuli::VerbDefinition*> chosen;
    if (o.verbs.empty())
        for (const auto& v : verbs.verbs) chosen.push_back(&v);
    else
        for (const auto& name : o.verbs) {
            const stimuli::VerbDefinition* verb = &verbs.get(name, "<command line>", 0, "--verbs");
            // Each verb once: a repeat would render the same files twice and list them twice
            // in the manifest.
            if (std::find(chosen.begin(), chosen.end(), verb) != chosen.end())
                throw commandLineError("--verbs", verb->name + " is listed twice");
            chosen.push_back(verb);
        }

    // Every clip is synthesized before rendering starts (missing animator files fail fast).
    std::vector<std::vector<VerbClip>> clips;
    for (const stimuli::VerbDefinition* verb : chosen) {
        std::vector<VerbClip> versions;
        for (stimuli::VerbVersion version : kVersions)
            versions.emplace_back(rig, shapes,
                                  stimuli::synthesizeVerb(sources, verb->name, version, o.subject, o.object));
        clips.push_back(std::move(versions));
    }

    // The verbs' renderer first: a device that refuses --msaa, the panel size or --device stops
    // the demo before anything is created on disk.
    const render::RendererOptions options = signerRendererOptions(2 * panelWidth, 2 * panelHeight, o.msaa, o.device);
    render::Renderer renderer(options);

    const fs::path root(o.out);
    ensureWritableDirectory(root);
    ensureWritableDirectory(root / "verbs");
    // A manifest says "this folder is complete" (docs/errors.md). The files it lists are about
    // to be overwritten, so an earlier one goes before the first of them; the new one is
    // written last. A run that fails from here on leaves no manifest.
    const fs::path manifestFile = root / "manifest.json";
    removeStaleFile(manifestFile);
    nlohmann::json files = nlohmann::json::array();

    // 1. The handshape gallery.
    {
        const std::uint32_t columns = 7, cell = 160;
        const std::uint32_t rows = static_cast<std::uint32_t>((shapes.shapes.size() + columns - 1) / columns);
        render::Renderer renderer(signerRendererOptions(columns * cell, rows * cell, o.msaa, o.device));
        const int handle = renderer.addScene(avatar);
        render::Image image;
        renderer.render(galleryFrame(rig, handle, shapes, columns), image);
        const fs::path file = root / "handshapes.png";
        render::writeImage(image, file);
        files.push_back(fileEntry(root, file, "every handshape of scenes/handshapes.json on the right hand",
                                  image.width, image.height, 1, 0.0));
        if (!o.quiet) std::fprintf(stderr, "signstim: %s\n", file.string().c_str());
    }

    // 2. Each verb: the four versions side by side, in sync (2x2 panels A-D).
    const int handle = renderer.addScene(avatar);
    ClipRenderOptions clipOptions;
    clipOptions.framesPerSecond = fps;
    clipOptions.columns = 2;
    clipOptions.rows = 2;
    std::vector<std::string> labels;
    const char* letters[] = {"A", "B", "C", "D"};
    for (std::size_t i = 0; i < kVersions.size(); ++i)
        labels.push_back(std::string(letters[i]) + " " + stimuli::toString(kVersions[i]));

    ProgressReporter progress("signstim demo", static_cast<double>(chosen.size()), o.quiet);
    render::VideoOptions video;
    video.frameRate = frameRate;
    for (std::size_t v = 0; v < chosen.size(); ++v) {
        const stimuli::VerbDefinition& verb = *chosen[v];
        std::string stem = "verb-" + verb.name;
        if (!verb.objectOnly()) stem += "_subject-" + positionText(o.subject);
        stem += "_object-" + positionText(o.object) + "_panels-PVAU";
        const fs::path movie = root / "verbs" / (stem + ".mp4");
        const fs::path still = root / "verbs" / (stem + ".png");

        std::vector<const Clip*> views;
        for (const VerbClip& clip : clips[v]) views.push_back(&clip);
        const double middle = clips[v].front().middleOfVerbSeconds();
        auto videoSink = render::makeVideoSink(movie, video);
        render::StillCapturingSink sink(*videoSink, static_cast<std::uint64_t>(middle * fps));
        const std::uint64_t frames = renderClips(
            renderer, handle, avatar, rig, views, labels, clipOptions, sink,
            [&](std::uint64_t done, std::uint64_t total) {
                progress.update(static_cast<double>(v) + static_cast<double>(done) / static_cast<double>(total),
                                verbProgress(verb, v, chosen.size()));
            });
        sink.finish();
        render::writeImage(sink.still(), still);
        progress.stepDone(static_cast<double>(v + 1), verbProgress(verb, v, chosen.size()));
        const std::string shows = verb.name + " (" + verb.movement + ") in the four versions, in sync: A point, B "
                                  "vector, C animator, D uninflected; " +
                                  (verb.objectOnly() ? "" : "subject " + positionText(o.subject) + ", ") +
                                  "object " + positionText(o.object);
        files.push_back(fileEntry(root, movie, shows, options.width, options.height, frames, fps));
        files.push_back(fileEntry(root, still, "middle frame of " + movie.filename().string(), options.width,
                                  options.height, 1, 0.0));
    }

    nlohmann::json manifest;
    manifest["tool"] = "signstim";
    manifest["version"] = SIGNSTIM_VERSION;
    manifest["job"] = "demo";
    manifest["device"] = renderer.device().name;
    manifest["note"] = "Point and vector versions come from models trained on the synthetic reference corpus "
                       "(scenes/corpus/reference_corpus.csv), not on motion capture.";
    manifest["files"] = files;
    writeManifest(manifestFile, manifest);
}

}  // namespace

void registerDemoCommand(Commands& commands) {
    auto o = std::make_shared<DemoOptions>();
    CLI::App* demo = commands.root.add_subcommand(
        "demo",
        "Render the demonstration set: the handshape gallery and every verb in its four versions (point, "
        "vector, animator, uninflected) side by side, with a manifest (the main job of ./run.sh)");
    demo->add_option("--out", o->out, "Output directory (created if missing)")->capture_default_str();
    demo->add_option("--scenes", o->scenesDir, "Data directory (default: $SIGNSTIM_SCENES, else scenes/ beside signstim)");
    demo->add_option("--panel-size", o->panelSize, "Size of one of the four panels, WxH (even)")->capture_default_str();
    demo->add_option("--fps", o->fps, "Frame rate: 30, 25, 30000/1001 ...")->capture_default_str();
    demo->add_option("--msaa", o->msaa, "Multisampling: 1 or 4")->capture_default_str();
    demo->add_option("--device", o->device, "Vulkan device: name substring or index (see `signstim devices`)");
    demo->add_option("--subject", o->subject, "Arc position of the subject, in [-1, 1]")->capture_default_str();
    demo->add_option("--object", o->object, "Arc position of the object, in [-1, 1]")->capture_default_str();
    demo->add_option("--verbs", o->verbs, "Only these verbs (e.g. --verbs ASK,GIVE)")->delimiter(',');
    demo->add_flag("--quiet", o->quiet, "No progress on stderr");
    demo->callback([o] {
        runDemo(*o);
        std::printf("signstim: demo written to %s/ (manifest.json lists every file)\n",
                    std::filesystem::absolute(o->out).lexically_normal().string().c_str());
    });
}

}  // namespace signstim::app
