// The committed default signer is the output of `signstim avatar build`; golden images of the
// handshape gallery and a posed signer, rendered with Vulkan validation on (any message
// fails the test). Golden comparison: tests/renderer/vk_golden.hpp (exact, then tolerance;
// SIGNSTIM_UPDATE_GOLDEN=1 rewrites tests/signer/golden/*.png).
#include "signer/avatar_builder.hpp"
#include "signer/avatar_render.hpp"
#include "signer/signer_pose.hpp"
#include "common/error.hpp"
#include "renderer/gltf_loader.hpp"
#include "renderer/gltf_writer.hpp"
#include "renderer/renderer.hpp"
#include "app/cli_values.hpp"
#include "stimuli/story/handshapes.hpp"
#include "tests/signer/avatar_variants.hpp"
#include "tests/renderer/vk_golden.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

using namespace signstim;

namespace {

const std::string kScenes = std::string(SIGNSTIM_SOURCE_DIR) + "/scenes";

std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

render::RendererOptions options(std::uint32_t width, std::uint32_t height) {
    render::RendererOptions o;
    o.width = width;
    o.height = height;
    o.msaa = 4;
    o.background = signer::kSignerBackground;
    o.validation = true;
    return o;
}

void expectNoValidationMessages(const render::Renderer& renderer) {
    for (const std::string& message : renderer.validationMessages()) ADD_FAILURE() << "validation: " << message;
}

}  // namespace

TEST(AvatarFile, CommittedAvatarIsTheBuildersOutputByteForByte) {
    const std::string committed = readBytes(kScenes + "/avatar/signer.glb");
    ASSERT_FALSE(committed.empty()) << "scenes/avatar/signer.glb missing";
    const std::string built = render::encodeGltf(signer::buildDefaultAvatar(), true);
    EXPECT_TRUE(built == committed)
        << "scenes/avatar/signer.glb is stale: run `signstim avatar build --out scenes/avatar/signer.glb`";
    EXPECT_LT(committed.size(), 2u * 1024u * 1024u);
}

TEST(AvatarFile, CommittedAvatarLoadsAndIsAcceptedAsASigner) {
    const render::Scene scene = render::loadGltf(kScenes + "/avatar/signer.glb");
    EXPECT_NO_THROW(signer::SignerRig rig(scene));
    for (const std::string& bone : signer::requiredAvatarBones()) EXPECT_GE(scene.findNode(bone), 0) << bone;
}

TEST(AvatarGolden, HandshapeGallery) {
    const render::Scene scene = render::loadGltf(kScenes + "/avatar/signer.glb");
    const signer::SignerRig rig(scene);
    const stimuli::HandshapeLibrary library = stimuli::loadHandshapes(kScenes + "/handshapes.json", rig.handModel());
    const std::uint32_t columns = 7, cell = 64;
    const auto rows = static_cast<std::uint32_t>((library.shapes.size() + columns - 1) / columns);
    render::Renderer renderer(options(columns * cell, rows * cell));
    const int handle = renderer.addScene(scene);
    render::Image image;
    renderer.render(signer::galleryFrame(rig, handle, library, columns), image);
    expectNoValidationMessages(renderer);
    const std::string problem = render::testing::compareWithGolden(image, "../../signer/golden/handshape_gallery");
    EXPECT_TRUE(problem.empty()) << problem;
}

TEST(AvatarGallery, ViewsOrbitTheHandAtTheSameDistance) {
    const render::Scene scene = render::loadGltf(kScenes + "/avatar/signer.glb");
    const signer::SignerRig rig(scene);
    const stimuli::HandshapeLibrary library = stimuli::loadHandshapes(kScenes + "/handshapes.json", rig.handModel());
    const auto offset = [&](const std::string& view) {
        const render::Frame frame = signer::galleryFrame(rig, 0, library, 7, app::parseGalleryView(view));
        return frame.views.at(0).camera.eye - frame.views.at(0).camera.target;
    };
    const glm::vec3 palm = offset("palm"), thumb = offset("thumb"), back = offset("back"), top = offset("top");
    EXPECT_NEAR(glm::length(palm - glm::vec3(0.0f, 0.0f, 0.55f)), 0.0f, 1e-6f) << "the default view is unchanged";
    EXPECT_NEAR(glm::length(thumb - glm::vec3(0.55f, 0.0f, 0.0f)), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(back - glm::vec3(0.0f, 0.0f, -0.55f)), 0.0f, 1e-5f);
    EXPECT_GT(top.y, 0.4f);
    EXPECT_NEAR(glm::length(top), 0.55f, 1e-5f);
    EXPECT_NEAR(glm::length(offset("-45,20") - glm::vec3(0.55f * std::sin(glm::radians(-45.0f)) * std::cos(glm::radians(20.0f)),
                                                           0.55f * std::sin(glm::radians(20.0f)),
                                                           0.55f * std::cos(glm::radians(-45.0f)) * std::cos(glm::radians(20.0f)))),
                0.0f, 1e-5f);
    for (const char* bad : {"side", "10", "1,2,3", "0,95", "abc,def"}) {
        EXPECT_THROW(app::parseGalleryView(bad), InputError) << bad;
    }
}

TEST(AvatarGallery, TheHandIsInSightFromEveryNamedView) {
    // From behind, the signer's own body lies between the camera and the hand: the near plane
    // must clip it. Skin (red over green over blue, not dark) must fill a good part of the cell.
    const render::Scene scene = render::loadGltf(kScenes + "/avatar/signer.glb");
    const signer::SignerRig rig(scene);
    stimuli::HandshapeLibrary library = stimuli::loadHandshapes(kScenes + "/handshapes.json", rig.handModel());
    library.shapes = {library.at("5")};
    render::Renderer renderer(options(96, 96));
    const int handle = renderer.addScene(scene);
    std::map<std::string, std::size_t> skin;
    for (const char* view : {"palm", "thumb", "little", "back", "top"}) {
        render::Image image;
        renderer.render(signer::galleryFrame(rig, handle, library, 1, app::parseGalleryView(view)), image);
        for (std::size_t i = 0; i < image.bytes.size(); i += 4) {
            const int r = image.bytes[i], g = image.bytes[i + 1], b = image.bytes[i + 2];
            if (r > 90 && r > g + 15 && g > b) ++skin[view];
        }
        EXPECT_GT(skin[view], image.bytes.size() / 4 / 20) << view << ": " << skin[view] << " skin pixels";
    }
    // The back of the open hand shows about as much as its palm (the body clipped: 60 %; with
    // the torso in the way, 7 %); edge-on views show less.
    EXPECT_GT(skin["back"], skin["palm"] * 2 / 5) << skin["back"] << " vs " << skin["palm"];
    EXPECT_GT(skin["top"], skin["palm"] / 4) << skin["top"] << " vs " << skin["palm"];
    expectNoValidationMessages(renderer);
}

TEST(AvatarGallery, AnAvatarInAnotherRestPoseAndFacingRendersTheSameSigning) {
    // The default signer written out in an A-pose with a palm turned down and curled fingers,
    // facing -Z (as VRM 0.x avatars do), then loaded as a user's avatar: the same posture must
    // render as it does on the default signer (same skin, so the same image up to rounding).
    render::Scene changed = render::loadGltf(kScenes + "/avatar/signer.glb");
    test::useAnotherRestPose(changed);
    test::turnRoots(changed, glm::angleAxis(glm::radians(180.0f), glm::vec3(0, 1, 0)));
    const std::filesystem::path file = std::filesystem::temp_directory_path() / "signstim_turned_signer.glb";
    render::writeGltf(changed, file);
    const render::Scene user = signer::loadSignerAvatar(file);
    std::filesystem::remove(file);
    const render::Scene standard = render::loadGltf(kScenes + "/avatar/signer.glb");
    const signer::SignerRig userRig(user), standardRig(standard);
    const stimuli::HandshapeLibrary library = stimuli::loadHandshapes(kScenes + "/handshapes.json", standardRig.handModel());
    signer::SignerPosture posture;
    posture.rightHand = library.at("B").controls;
    posture.leftHand = library.at("5").controls;
    posture.rightWrist = standardRig.presentingTarget(hand::Side::Right);
    posture.leftWrist = hand::ArmTarget{{160, -40, 260}, glm::angleAxis(glm::radians(30.0f), glm::vec3(0, 1, 0))};
    std::array<render::Image, 2> images;
    for (int i = 0; i < 2; ++i) {
        const render::Scene& scene = i == 0 ? user : standard;
        const signer::SignerRig& rig = i == 0 ? userRig : standardRig;
        render::Renderer renderer(options(160, 160));
        const int handle = renderer.addScene(scene);
        renderer.render(signer::postureFrame(scene, rig, handle, posture, 1.0f), images[i]);
        expectNoValidationMessages(renderer);
    }
    ASSERT_EQ(images[0].bytes.size(), images[1].bytes.size());
    std::size_t differing = 0;
    int largest = 0;
    for (std::size_t i = 0; i < images[0].bytes.size(); ++i) {
        const int d = std::abs(int(images[0].bytes[i]) - int(images[1].bytes[i]));
        largest = std::max(largest, d);
        if (d > 2) ++differing;
    }
    EXPECT_LT(differing, images[0].bytes.size() / 1000) << "largest channel difference " << largest << ", " << differing << " channels differ";

}

TEST(AvatarGolden, PosedSigner) {
    const render::Scene scene = render::loadGltf(kScenes + "/avatar/signer.glb");
    const signer::SignerRig rig(scene);
    const stimuli::HandshapeLibrary library = stimuli::loadHandshapes(kScenes + "/handshapes.json", rig.handModel());
    signer::SignerPosture posture;
    posture.rightHand = library.at("A").controls;
    posture.rightWrist = rig.presentingTarget(hand::Side::Right);
    posture.leftHand = library.at("5").controls;
    posture.leftWrist = hand::ArmTarget{signer::bodyFromSigningSpace({-150.0f, -80.0f, 300.0f}),
                                        rig.presentingTarget(hand::Side::Left).handRotation};
    posture.gazeMm = signer::bodyFromSigningSpace({300.0f, 0.0f, 500.0f});
    render::Renderer renderer(options(256, 256));
    const int handle = renderer.addScene(scene);
    signer::PoseReport report;
    render::Image image;
    renderer.render(signer::postureFrame(scene, rig, handle, posture, 1.0f, &report), image);
    expectNoValidationMessages(renderer);
    EXPECT_TRUE(report.right.reachable);
    EXPECT_TRUE(report.left.reachable);
    const std::string problem = render::testing::compareWithGolden(image, "../../signer/golden/posed_signer");
    EXPECT_TRUE(problem.empty()) << problem;
}
