#pragma once
// Frames of the signer for the avatar commands and their golden tests: the handshape gallery
// (one hand, close-up, same viewpoint for every shape) and a posed signer (waist-up camera).
#include "signer/signer_pose.hpp"
#include "renderer/frame.hpp"
#include "renderer/renderer.hpp"
#include "stimuli/story/handshapes.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace signstim::signer {

// Sign-language video practice: plain, medium background the dark top and the skin both
// stand out against (linear RGB of sRGB ≈ (0.55, 0.62, 0.68)).
inline constexpr glm::vec4 kSignerBackground{0.26f, 0.34f, 0.42f, 1.0f};

// Renderer options for the signer: the background above, size, multisampling, device.
render::RendererOptions signerRendererOptions(std::uint32_t width, std::uint32_t height, std::uint32_t msaa,
                                              const std::string& device);

// Waist-up view of a signer whose chest is at `chestWorld` (metres), for aspect w/h.
render::Camera waistUpCamera(const glm::vec3& chestWorld, float aspect);
// Face close-up (issue 23 §6): the head, neck and the tops of the shoulders, centred between
// the eyes at `eyesWorld` (metres), for a study of the face (non-manuals, mouthing).
render::Camera faceCloseUpCamera(const glm::vec3& eyesWorld, float aspect);

// The camera presets of the signer's frames (`--camera waist-up|face`).
enum class CameraFraming { WaistUp, Face };
// "waist-up" / "face" -> the preset; empty when the name is none of them.
std::optional<CameraFraming> parseCameraFraming(const std::string& name);

// Where the gallery camera looks from: an orbit around the presented right hand, degrees.
// Azimuth turns about the vertical (+90 = from the thumb side, -90 = from the little-finger
// side, 180 = the back of the hand); elevation raises the camera (+ = from above).
struct GalleryView {
    float azimuthDeg = 0.0f;
    float elevationDeg = 0.0f;
};
// A grid of every handshape in `library` on the right hand, presented palm-forward beside the
// shoulder, each labelled with its name, all seen from `view` (default: straight at the palm).
// `sceneHandle` is the avatar's Renderer handle.
render::Frame galleryFrame(const SignerRig& rig, int sceneHandle,
                           const stimuli::HandshapeLibrary& library, std::uint32_t columns,
                           const GalleryView& view = {});

// The signer in one posture, framed by `framing` on the rest pose (the camera does not follow
// the posture).
render::Frame postureFrame(const render::Scene& avatar, const SignerRig& rig, int sceneHandle,
                           const SignerPosture& posture, float aspect, PoseReport* report = nullptr,
                           CameraFraming framing = CameraFraming::WaistUp);

// The default signer committed in scenes/ (scenes/avatar/signer.glb).
std::filesystem::path defaultAvatarPath(const std::filesystem::path& scenesDir);

}  // namespace signstim::signer
