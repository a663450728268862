#include "signer/avatar_render.hpp"


#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

#include <vector>

namespace signstim::signer {

render::RendererOptions signerRendererOptions(std::uint32_t width, std::uint32_t height, std::uint32_t msaa,
                                              const std::string& device) {
    render::RendererOptions options;
    options.width = width;
    options.height = height;
    options.msaa = msaa;
    options.device = device;
    options.background = kSignerBackground;
    return options;
}

render::Camera waistUpCamera(const glm::vec3& chestWorld, float aspect) {
    render::Camera camera;
    camera.verticalFovDegrees = 30.0f;
    // [D] Visible height at least 1.15 m, from below the waist to above a hand raised at the
    // forehead, and at least 1.75 m wide (issue 21: both hands, fingertips included, in the
    // frame for every aspect; tests/signer/story_in_frame_test.cpp, sign_in_frame_test.cpp and
    // the verb grid's MotionLimits.EveryVerbInstanceKeepsBothHandsInsideTheWaistUpFrame):
    // - height: a sign whose citation form stands the fingers up at the forehead (FATHER,
    //   UNCLE, GRANDFATHER, PARENTS, MAD; FORGET's move in from IX) lifts the fingertips about
    //   0.1 m above the top of the head; at 1.05 m those left a 16:9 view through its top (5
    //   signs alone, 99 frames; story-01 in every version), and the moves in and out of BUSY,
    //   LATE, BABY, LOVE, TABLE and ENGLISH the bottom (14 frames); at 1.10 m 62 frames were
    //   left, at 1.15 m none (measured 2026-11-27, 30 fps).
    // - width: a point or vector verb at the signing arc's end (|position| 0.9-1) stretches the
    //   arm out to the side; the point model carries a long sweep past the locus (SEND point
    //   s=-1 o=1 ends with the wrist 579 mm right of the chest, fingers pointing out), fingertips
    //   about 0.85 m from the midline. At 1.40 m (4:3 at 1.05 m high) the default stories' verbs
    //   left the frame in 9 of their 48 clips, at 1.55 m in 2, at 1.65 m none but 6 SEND point
    //   instances of the grid (s -0.7..-1, o 0.9..1), at 1.70 m one, at 1.72 m none.
    // A 16:9 view is 1.15 m high (2.04 m wide), a 4:3 view 1.31 m high, a square one 1.75 m. A
    // portrait view keeps its 0.84 m of width (the arc cannot fit it).
    constexpr float kMinimumHeightM = 1.15f, kMinimumWidthM = 1.75f;
    const float height = aspect >= 1.0f ? std::max(kMinimumHeightM, kMinimumWidthM / aspect) : 1.05f / aspect * 0.8f;
    const float distance = 0.5f * height / std::tan(0.5f * camera.verticalFovDegrees * 3.14159265f / 180.0f);
    camera.target = chestWorld + glm::vec3(0.0f, 0.06f, 0.0f);
    camera.eye = camera.target + glm::vec3(0.0f, 0.03f, distance);
    return camera;
}

render::Camera faceCloseUpCamera(const glm::vec3& eyesWorld, float aspect) {
    render::Camera camera;
    camera.verticalFovDegrees = 30.0f;
    // Visible height ≈ 0.36 m: from above the hair to the collarbones, so that a nod, a tilt
    // and a shrug stay in the frame (narrow frames: the same width).
    const float height = aspect >= 1.0f ? 0.36f : 0.36f / aspect * 0.8f;
    const float distance = 0.5f * height / std::tan(0.5f * camera.verticalFovDegrees * 3.14159265f / 180.0f);
    camera.target = eyesWorld + glm::vec3(0.0f, -0.07f, 0.0f);
    camera.eye = camera.target + glm::vec3(0.0f, 0.0f, distance);
    camera.nearPlane = std::min(camera.nearPlane, 0.05f);
    return camera;
}

std::optional<CameraFraming> parseCameraFraming(const std::string& name) {
    if (name == "waist-up") return CameraFraming::WaistUp;
    if (name == "face") return CameraFraming::Face;
    return std::nullopt;
}

render::Frame galleryFrame(const SignerRig& rig, int sceneHandle,
                           const stimuli::HandshapeLibrary& library, std::uint32_t columns,
                           const GalleryView& galleryView) {
    render::Frame frame;
    frame.columns = std::max(1u, columns);
    frame.rows = static_cast<std::uint32_t>((library.shapes.size() + frame.columns - 1) / frame.columns);
    // One viewpoint for every shape, around the presented right hand: aimed 90 mm (scaled with
    // the avatar's hand) up the palm from the wrist, in the hand model's palm frame, so that an
    // avatar's own bone axes do not matter.
    SignerPosture posture;
    posture.rightWrist = rig.presentingTarget(hand::Side::Right);
    PoseReport report;
    rig.pose(posture, &report);
    const float scale = rig.handScale();
    const glm::vec3 center =
        rig.worldFromBodyMm(report.right.wristMm + report.right.hand * glm::vec3(0.0f, 0.0f, 90.0f * scale));
    const float distance = 0.55f * scale;
    render::Camera camera;
    camera.verticalFovDegrees = 28.0f;
    camera.target = center;
    // Straight at the palm (+z, the signer's forward) unless the view orbits elsewhere; the
    // presented palm's thumb points to +x. Whatever lies nearer the camera than the hand's
    // reach (the signer's own body, seen from behind) is clipped away by the near plane.
    const float azimuth = glm::radians(galleryView.azimuthDeg), elevation = glm::radians(galleryView.elevationDeg);
    camera.eye = center + distance * glm::vec3(std::sin(azimuth) * std::cos(elevation), std::sin(elevation),
                                               std::cos(azimuth) * std::cos(elevation));
    camera.nearPlane = distance - 0.2f * scale;
    for (const stimuli::Handshape& shape : library.shapes) {
        posture.rightHand = shape.controls;
        render::View view;
        view.scene = sceneHandle;
        view.pose = rig.pose(posture);
        view.camera = camera;
        view.label = shape.name;
        frame.views.push_back(std::move(view));
    }
    return frame;
}

render::Frame postureFrame(const render::Scene& avatar, const SignerRig& rig, int sceneHandle,
                           const SignerPosture& posture, float aspect, PoseReport* report, CameraFraming framing) {
    render::View view;
    view.scene = sceneHandle;
    view.pose = rig.pose(posture, report);
    std::vector<glm::mat4> world;
    render::computeWorldTransforms(avatar, view.pose, world);
    const glm::vec3 left = world[avatar.findNode("leftUpperArm")][3], right = world[avatar.findNode("rightUpperArm")][3];
    const glm::vec3 chest = 0.5f * (left + right) - glm::vec3(0.0f, 0.13f, 0.0f);
    if (framing == CameraFraming::Face) {
        // Between the eyes: the gaze model's eyes (the eye bones where the avatar has them).
        view.camera = faceCloseUpCamera(rig.worldFromBodyMm(rig.gaze().eyesMm), aspect);
    } else {
        view.camera = waistUpCamera(chest, aspect);
    }
    render::Frame frame;
    frame.views.push_back(std::move(view));
    return frame;
}

std::filesystem::path defaultAvatarPath(const std::filesystem::path& scenesDir) {
    return scenesDir / "avatar" / "signer.glb";
}

}  // namespace signstim::signer
