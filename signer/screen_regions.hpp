#pragma once
// Eye-tracking regions (issue 24 §3; docs/study.md, "Eye-tracking regions"): where the signer's
// face, right hand, left hand and signing space are on the screen, frame by frame, as boxes in
// the pixels of the rendered clip. Kacorri, Harper & Huenerfauth (ASSETS 2013) measured the
// time viewers of ASL animation spend on the face and the transitions between face and body;
// the renderer knows exactly where those are, so the boxes come from the same posed skeleton
// and the same camera math (renderer/frame.hpp viewCell, viewProjection) as the image.
//
// How a box is made. When the model is built, every vertex of the avatar's meshes is given to
// every bone that moves it (any skin weight above 0, so the wrist's skin is the hand's too; a
// rigid mesh's to its node), in that bone's own frame, morph targets' displacements included;
// a bone under the rig's "head" bone
// counts for the face, under "rightHand"/"leftHand" (every finger bone, so the fingertips are
// in) for that hand. Each bone keeps the box of its vertices, grown by kScreenRegionMarginMm on
// every side. Per frame, the corners of those boxes are carried by the bones' world matrices
// for the pose and projected; a region's box is the pixel bounds of its corners (floor/ceil),
// clipped to the view's cell. The face region is the head seen from the camera (hair and ears
// included). The signing space is where signs are made (SPEC §3.1: the arc of radius r around
// the chest): the rectangle at the chest's depth from r to the signer's left to r to the
// right (the arc's ends), from the resting wrists' height up to the top of the head at rest;
// it does not move. In a waist-up panel it spans 2r = 1.0 m of the view's width (1.75 m at 4:3, 2.04 m at 16:9).
// Boxes are not occlusion-aware: a hand in front of the face is in both boxes.
#include "renderer/frame.hpp"
#include "renderer/scene.hpp"
#include "signer/clip.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace signstim::signer {

enum class ScreenRegion { Face, RightHand, LeftHand, SigningSpace };
inline constexpr std::array<ScreenRegion, 4> kScreenRegions = {ScreenRegion::Face, ScreenRegion::RightHand,
                                                               ScreenRegion::LeftHand, ScreenRegion::SigningSpace};
// "face", "right_hand", "left_hand", "signing_space" (the CSV's `region` column). Right and left
// are the signer's own (the signer's right hand is on the viewer's left).
std::string toString(ScreenRegion region);

// [D] How far each bone's box is grown on every side (mm): covers the skin between bones
// (a vertex blended between two bones leaves either bone's box by less than this) and a
// viewer's fixation error is left to the analysis.
inline constexpr float kScreenRegionMarginMm = 10.0f;

struct ScreenBox {
    bool visible = false;  // some of the region inside the view's cell
    // Pixels of the image (x right, y down, origin at the image's top left), [x0, x1) × [y0, y1),
    // clipped to the view's cell; all 0 when not visible.
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

class ScreenRegionModel {
public:
    // Reads the avatar's meshes once. `rig` must have been made from `avatar`.
    ScreenRegionModel(const render::Scene& avatar, const SignerRig& rig);

    // The regions (in kScreenRegions' order) of `pose` seen by `camera` in `cell` of the image.
    std::array<ScreenBox, 4> boxes(const render::Pose& pose, const render::Camera& camera,
                                   const render::ViewCell& cell) const;

private:
    struct Part {
        int node = -1;
        ScreenRegion region = ScreenRegion::Face;
        glm::vec3 min{0.0f}, max{0.0f};  // in the node's frame (a joint's: bind-inverse · vertex), grown
    };
    const render::Scene* avatar_;
    std::vector<Part> parts_;
    std::array<glm::vec3, 8> signingSpace_{};  // world corners
};

// The regions of every frame of `clips` shown side by side as renderClips draws them
// (signer/clip_render.hpp: the same frame count, times, grid and camera) in a width × height
// image, as CSV (docs/study.md, "Eye-tracking regions"):
//   frame,time_ms,panel,region,x0,y0,x1,y1,visible
// one row per frame, panel (clips[k], named labels[k]; empty when not given) and region; a null
// clips[k] (a panel of a lab's recording) keeps its cell in the grid and has no rows.
// `frame` counts from 0; time_ms is the frame's start, frame · 1000 / fps rounded to the ms;
// x0..y1 are empty when the region is not visible (visible 0).
std::string screenRegionsCsv(const render::Scene& avatar, const SignerRig& rig, const ScreenRegionModel& model,
                             const std::vector<const Clip*>& clips, const std::vector<std::string>& labels,
                             double framesPerSecond, std::uint32_t width, std::uint32_t height, std::uint32_t columns,
                             std::uint32_t rows);

// The camera renderClips uses for a columns × rows grid in a width × height image (waist-up on
// the rest pose).
render::Camera clipCamera(const render::Scene& avatar, const SignerRig& rig, std::uint32_t width, std::uint32_t height,
                          std::uint32_t columns, std::uint32_t rows);

}  // namespace signstim::signer
