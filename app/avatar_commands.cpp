// `signstim avatar build`, `signstim handshapes --gallery`, `signstim pose`: the default signer,
// its handshape gallery and one posture of it (docs: signer/avatar_builder.hpp, signer_pose.hpp).
#include "signer/avatar_builder.hpp"
#include "signer/avatar_render.hpp"
#include "app/cli_values.hpp"
#include "app/commands.hpp"
#include "signer/signer_pose.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "renderer/frame_sink.hpp"
#include "renderer/gltf_loader.hpp"
#include "renderer/gltf_writer.hpp"
#include "renderer/image_io.hpp"
#include "renderer/renderer.hpp"
#include "stimuli/story/handshapes.hpp"
#include "stimuli/scenes_path.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>

namespace signstim::app {

// The signer's room (avatar, rig, clips) is this command line's main collaborator.
using namespace signstim::signer;
namespace {

struct AvatarSource {
    std::string scenesDir, avatarFile, boneMapFile;
};

void addAvatarOptions(CLI::App* command, AvatarSource& o) {
    command->add_option("--scenes", o.scenesDir,
                        "Data directory (default: $SIGNSTIM_SCENES, else the scenes/ beside signstim, else the "
                        "source tree's)");
    command->add_option("--avatar", o.avatarFile,
                        "Your own avatar (.glb/.gltf, +Y up) with VRM humanoid bone names; any rest pose (T or "
                        "A) and facing (default: SCENES/avatar/signer.glb)");
    command->add_option("--bone-map", o.boneMapFile,
                        "JSON {\"vrmBoneName\": \"yourNodeName\", ...} for an avatar without VRM names");
}

BoneMapping mappingOf(const AvatarSource& o) { return o.boneMapFile.empty() ? BoneMapping{} : loadBoneMapping(o.boneMapFile); }

render::Scene loadAvatar(const AvatarSource& o) {
    const std::filesystem::path path = o.avatarFile.empty()
                                           ? defaultAvatarPath(stimuli::resolveScenesDir(o.scenesDir))
                                           : std::filesystem::path(o.avatarFile);
    return loadSignerAvatar(path, mappingOf(o));
}

// The handshape `name` given with `flag` (the library's own message names --shape, the flag
// of `hand pose`).
const stimuli::Handshape& shapeFor(const stimuli::HandshapeLibrary& library, const std::string& name,
                                   const std::string& flag) {
    try {
        return library.at(name);
    } catch (const InputError& e) {
        throw commandLineError(flag, e.detail());
    }
}

// An extra hand rotation given as a rotation vector in degrees in the signing-space frame.
glm::quat signingSpaceRotation(const glm::vec3& rotationVectorDeg) {
    const float angle = glm::length(rotationVectorDeg);
    if (angle < 1e-6f) return glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
    return bodyFromSigningSpace(glm::angleAxis(angle * 3.14159265f / 180.0f, rotationVectorDeg / angle));
}

void renderToFile(const render::Scene& scene, const std::function<render::Frame(int)>& makeFrame,
                  std::uint32_t width, std::uint32_t height, const std::string& device, std::uint32_t msaa,
                  const std::string& out) {
    // The renderer first: a device that refuses --msaa or --device stops the command before
    // anything is created on disk; then the output's place, before the frame is drawn.
    render::Renderer renderer(signerRendererOptions(width, height, msaa, device));
    checkOutputWritable(out);
    const int handle = renderer.addScene(scene);
    render::Image image;
    renderer.render(makeFrame(handle), image);
    render::writeImage(image, out);
}

// Before any work: `out` must name an image file the writers handle (exit 1); its place is
// probed once the renderer exists (renderToFile; exit 3).
void checkImageOutput(const std::string& out, const std::string& flag) {
    if (render::outputKind(out, flag) != render::OutputKind::Image)
        throw commandLineError(flag, "'" + out + "': give an image file name ending in .png, .exr, .tif or .tiff");
}

void reportArm(const char* side, const hand::ArmPose& arm) {
    if (!arm.reachable)
        std::fprintf(stderr, "signstim: note: %s wrist target out of reach: placed %.0f mm from it\n", side,
                     arm.reachErrorMm);
    if (arm.orientationErrorDeg > 2.0f)
        std::fprintf(stderr, "signstim: note: %s hand orientation limited by the wrist: %.0f° from the target\n",
                     side, arm.orientationErrorDeg);
}

}  // namespace

void registerAvatarCommands(Commands& commands) {
    // avatar build
    CLI::App* avatar = commands.root.add_subcommand("avatar", "The default signer avatar");
    avatar->require_subcommand(1);
    auto buildOut = std::make_shared<std::string>();
    CLI::App* build = avatar->add_subcommand(
        "build", "Generate the default signer (glTF: .glb or .gltf); scenes/avatar/signer.glb is its output");
    build->add_option("--out", *buildOut, "Output file (.glb or .gltf)")->required();
    build->callback([buildOut] {
        const std::string extension = std::filesystem::path(*buildOut).extension().string();
        if (extension != ".glb" && extension != ".gltf")
            throw commandLineError("--out", "'" + *buildOut + "': give a file name ending in .glb or .gltf");
        checkOutputWritable(*buildOut);
        render::writeGltf(buildDefaultAvatar(), *buildOut);
        std::printf("%s\n", buildOut->c_str());
    });

    // handshapes --gallery
    struct GalleryOptions {
        AvatarSource source;
        std::string gallery, shapesFile, device, view = "palm";
        std::uint32_t columns = 7, cell = 200, msaa = 4;
    };
    auto g = std::make_shared<GalleryOptions>();
    CLI::App* shapes = commands.root.add_subcommand(
        "handshapes", "Render every handshape of the library as a labelled grid (right hand, close-up)");
    shapes->add_option("--gallery", g->gallery, "Output image (.png)")->required();
    shapes->add_option("--shapes", g->shapesFile, "Handshape file (default: SCENES/handshapes.json)");
    shapes->add_option("--columns", g->columns, "Shapes per row")->check(CLI::Range(1u, 64u));
    shapes->add_option("--cell", g->cell, "Size of one cell in pixels")->check(CLI::Range(32u, 1024u));
    shapes->add_option("--view", g->view,
                       "Viewpoint around the hand: palm (default), thumb, little, back, top, or AZIMUTH,ELEVATION in "
                       "degrees (azimuth +90 = thumb side, elevation + = from above)");
    shapes->add_option("--device", g->device, "Vulkan device (name substring or index; see `signstim devices`)");
    shapes->add_option("--msaa", g->msaa, "Multisampling: 1 or 4");
    addAvatarOptions(shapes, g->source);
    shapes->callback([g] {
        const GalleryView view = parseGalleryView(g->view);
        checkImageOutput(g->gallery, "--gallery");
        requireSampleCount(g->msaa, "--msaa");
        const render::Scene scene = loadAvatar(g->source);
        const SignerRig rig(scene, mappingOf(g->source));
        const stimuli::HandshapeLibrary library =
            stimuli::loadHandshapes(stimuli::handshapesFile(g->shapesFile, g->source.scenesDir), rig.handModel());
        const std::uint32_t rows = static_cast<std::uint32_t>((library.shapes.size() + g->columns - 1) / g->columns);
        renderToFile(scene, [&](int handle) { return galleryFrame(rig, handle, library, g->columns, view); },
                     g->columns * g->cell, rows * g->cell, g->device, g->msaa, g->gallery);
        std::printf("%s: %zu handshapes\n", g->gallery.c_str(), library.shapes.size());
    });

    // pose
    struct PoseOptions {
        AvatarSource source;
        std::string right, left, rightWrist, leftWrist, rightRotation, leftRotation, gaze, out, size = "640x480",
                                                                                          shapesFile, device;
        std::string nonManual, camera = "waist-up";
        std::uint32_t msaa = 4;
    };
    auto p = std::make_shared<PoseOptions>();
    CLI::App* pose = commands.root.add_subcommand(
        "pose", "Render the signer in one posture (waist-up). Positions are in the signing-space frame of "
                "SPEC §3.1: millimetres from the chest centre, +x the signer's right, +y up, +z forward");
    pose->add_option("--right", p->right, "Right handshape (see `signstim hand shapes`)")->required();
    pose->add_option("--left", p->left, "Left handshape (default: the left hand rests)");
    pose->add_option("--right-wrist", p->rightWrist, "Right wrist x,y,z in mm (default: beside the right shoulder)");
    pose->add_option("--left-wrist", p->leftWrist, "Left wrist x,y,z in mm (default: beside the left shoulder)");
    pose->add_option("--right-rotation", p->rightRotation,
                     "Extra right-hand rotation: rotation vector in degrees (signing-space axes) applied to the "
                     "default palm-forward, fingers-up orientation");
    pose->add_option("--left-rotation", p->leftRotation, "The same for the left hand");
    pose->add_option("--gaze", p->gaze, "Look at x,y,z in mm (default: straight ahead)");
    pose->add_option("--nonmanual", p->nonManual,
                     "Face, head, torso and shoulders: CHANNEL=VALUE,... with the channels and units of the "
                     "non-manual seam (docs/avatar-face.md): browInnerUp=1,jawOpen=0.5,head.nod=0.2,torso.turn=-0.3");
    pose->add_option("--camera", p->camera, "Camera preset: waist-up or face (close-up)")
        ->check(CLI::IsMember({"waist-up", "face"}))
        ->capture_default_str();
    pose->add_option("--out", p->out, "Output image (.png)")->required();
    pose->add_option("--size", p->size, "Image size WxH");
    pose->add_option("--shapes", p->shapesFile, "Handshape file (default: SCENES/handshapes.json)");
    pose->add_option("--device", p->device, "Vulkan device (name substring or index)");
    pose->add_option("--msaa", p->msaa, "Multisampling: 1 or 4");
    addAvatarOptions(pose, p->source);
    pose->callback([p] {
        const ImageSize size = parseImageSize(p->size, "--size", {.minimum = 16, .maximum = 8192});
        checkImageOutput(p->out, "--out");
        const std::uint32_t width = size.width, height = size.height;
        requireSampleCount(p->msaa, "--msaa");
        const render::Scene scene = loadAvatar(p->source);
        const SignerRig rig(scene, mappingOf(p->source));
        const stimuli::HandshapeLibrary library =
            stimuli::loadHandshapes(stimuli::handshapesFile(p->shapesFile, p->source.scenesDir), rig.handModel());
        SignerPosture posture;
        posture.rightHand = shapeFor(library, p->right, "--right").controls;
        hand::ArmTarget right = rig.presentingTarget(hand::Side::Right);
        if (!p->rightWrist.empty()) right.wristMm = bodyFromSigningSpace(parseTriple(p->rightWrist, "--right-wrist"));
        if (!p->rightRotation.empty())
            right.handRotation = signingSpaceRotation(parseTriple(p->rightRotation, "--right-rotation")) * right.handRotation;
        posture.rightWrist = right;
        if (!p->left.empty() || !p->leftWrist.empty()) {
            if (!p->left.empty()) posture.leftHand = shapeFor(library, p->left, "--left").controls;
            hand::ArmTarget left = rig.presentingTarget(hand::Side::Left);
            if (!p->leftWrist.empty()) left.wristMm = bodyFromSigningSpace(parseTriple(p->leftWrist, "--left-wrist"));
            if (!p->leftRotation.empty())
                left.handRotation = signingSpaceRotation(parseTriple(p->leftRotation, "--left-rotation")) * left.handRotation;
            posture.leftWrist = left;
        }
        if (!p->gaze.empty()) posture.gazeMm = bodyFromSigningSpace(parseTriple(p->gaze, "--gaze"));
        std::stringstream channels(p->nonManual);
        for (std::string item; std::getline(channels, item, ',');) {
            const std::size_t eq = item.find('=');
            if (eq == std::string::npos || eq == 0)
                throw commandLineError("--nonmanual", "'" + item + "' is not CHANNEL=VALUE");
            const float value = parseNumber(item.substr(eq + 1), "--nonmanual " + item.substr(0, eq));
            if (!setNonManualChannel(posture.nonManual, item.substr(0, eq), value))
                throw commandLineError("--nonmanual", "unknown channel '" + item.substr(0, eq) + "'");
        }
        PoseReport report;
        renderToFile(scene,
                     [&](int handle) {
                         return postureFrame(scene, rig, handle, posture,
                                             static_cast<float>(width) / static_cast<float>(height), &report,
                                             *parseCameraFraming(p->camera));
                     },
                     width, height, p->device, p->msaa, p->out);
        reportArm("right", report.right);
        if (posture.leftWrist) reportArm("left", report.left);
        std::printf("%s\n", p->out.c_str());
    });
}

}  // namespace signstim::app
