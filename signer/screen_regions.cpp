#include "signer/screen_regions.hpp"

#include "signer/avatar_render.hpp"
#include "stimuli/verbs/signing_space.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

namespace signstim::signer {

std::string toString(ScreenRegion region) {
    switch (region) {
        case ScreenRegion::Face: return "face";
        case ScreenRegion::RightHand: return "right_hand";
        case ScreenRegion::LeftHand: return "left_hand";
        case ScreenRegion::SigningSpace: return "signing_space";
    }
    return "face";
}

namespace {

// The region a node's vertices belong to: the first of head, rightHand, leftHand found among
// the node and its ancestors.
std::optional<ScreenRegion> regionOfNode(const render::Scene& scene, int node, int head, int rightHand, int leftHand) {
    for (int n = node; n >= 0; n = scene.nodes[static_cast<std::size_t>(n)].parent) {
        if (n == head) return ScreenRegion::Face;
        if (n == rightHand) return ScreenRegion::RightHand;
        if (n == leftHand) return ScreenRegion::LeftHand;
    }
    return std::nullopt;
}

std::array<glm::vec3, 8> corners(const glm::vec3& lo, const glm::vec3& hi) {
    std::array<glm::vec3, 8> c;
    for (int i = 0; i < 8; ++i) c[i] = {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
    return c;
}

// Pixel bounds of projected points, accumulated.
struct PixelBounds {
    double minX = std::numeric_limits<double>::max(), minY = std::numeric_limits<double>::max();
    double maxX = std::numeric_limits<double>::lowest(), maxY = std::numeric_limits<double>::lowest();
    bool any = false;
    void add(const glm::mat4& viewProjection, const render::ViewCell& cell, const glm::vec3& world) {
        const glm::vec4 clip = viewProjection * glm::vec4(world, 1.0f);
        if (clip.w <= 1e-6f) return;  // behind the camera: not on the screen
        // The renderer's viewport (renderer.cpp): negative height, so clip-space +Y is up.
        const double x = cell.x + 0.5 * (static_cast<double>(clip.x / clip.w) + 1.0) * cell.width;
        const double y = cell.y + 0.5 * (1.0 - static_cast<double>(clip.y / clip.w)) * cell.height;
        minX = std::min(minX, x), maxX = std::max(maxX, x);
        minY = std::min(minY, y), maxY = std::max(maxY, y);
        any = true;
    }
    ScreenBox box(const render::ViewCell& cell) const {
        ScreenBox b;
        if (!any) return b;
        const double cx0 = cell.x, cy0 = cell.y, cx1 = cell.x + cell.width, cy1 = cell.y + cell.height;
        const double x0 = std::clamp(std::floor(minX), cx0, cx1), x1 = std::clamp(std::ceil(maxX), cx0, cx1);
        const double y0 = std::clamp(std::floor(minY), cy0, cy1), y1 = std::clamp(std::ceil(maxY), cy0, cy1);
        if (x0 >= x1 || y0 >= y1) return b;
        b.visible = true;
        b.x0 = static_cast<int>(x0), b.x1 = static_cast<int>(x1);
        b.y0 = static_cast<int>(y0), b.y1 = static_cast<int>(y1);
        return b;
    }
};

}  // namespace

ScreenRegionModel::ScreenRegionModel(const render::Scene& avatar, const SignerRig& rig) : avatar_(&avatar) {
    const int head = rig.boneNode("head"), rightHand = rig.boneNode("rightHand"), leftHand = rig.boneNode("leftHand");
    std::vector<glm::mat4> restWorld;
    render::computeWorldTransforms(avatar, render::Pose{}, restWorld);

    std::map<int, Part> parts;  // by node: ordered, so the model is the same on every run
    const auto addPoint = [&](int node, const glm::vec3& local) {
        const std::optional<ScreenRegion> region = regionOfNode(avatar, node, head, rightHand, leftHand);
        if (!region) return;
        auto [it, fresh] = parts.try_emplace(node);
        Part& part = it->second;
        if (fresh) {
            part.node = node;
            part.region = *region;
            part.min = part.max = local;
        }
        part.min = glm::min(part.min, local);
        part.max = glm::max(part.max, local);
    };
    for (std::size_t n = 0; n < avatar.nodes.size(); ++n) {
        const render::Node& node = avatar.nodes[n];
        if (node.mesh < 0) continue;
        const render::Mesh& mesh = avatar.meshes[static_cast<std::size_t>(node.mesh)];
        const render::Skin* skin = node.skin >= 0 ? &avatar.skins[static_cast<std::size_t>(node.skin)] : nullptr;
        for (const render::Primitive& primitive : mesh.primitives) {
            for (std::size_t v = 0; v < primitive.vertices.size(); ++v) {
                const render::Vertex& vertex = primitive.vertices[v];
                const auto add = [&](int bone, const glm::mat4& toBone) {
                    addPoint(bone, glm::vec3(toBone * glm::vec4(vertex.position, 1.0f)));
                    // A morph target (a face's jaw, brows) moves the vertex up to its displacement.
                    for (const render::MorphTarget& target : primitive.targets)
                        if (v < target.position.size())
                            addPoint(bone, glm::vec3(toBone * glm::vec4(vertex.position + target.position[v], 1.0f)));
                };
                if (!skin || !primitive.skinned) {
                    add(static_cast<int>(n), glm::mat4(1.0f));
                    continue;
                }
                // Every bone that moves the vertex at all: the skin between the hand and the
                // forearm (the wrist) is the hand's too, as it moves with it.
                for (int k = 0; k < 4; ++k) {
                    const std::size_t joint = vertex.joints[k];
                    if (vertex.weights[k] <= 0.0f || joint >= skin->joints.size()) continue;
                    add(skin->joints[joint],
                        joint < skin->inverseBindMatrices.size() ? skin->inverseBindMatrices[joint] : glm::mat4(1.0f));
                }
            }
        }
    }
    float headTop = std::numeric_limits<float>::lowest();
    for (auto& [node, part] : parts) {
        // The margin in the bone's own units (an avatar may scale its armature).
        const float scale = std::max(1e-6f, glm::length(glm::vec3(restWorld[static_cast<std::size_t>(node)][0])));
        const glm::vec3 grow(kScreenRegionMarginMm * 0.001f / scale);
        part.min -= grow;
        part.max += grow;
        if (part.region == ScreenRegion::Face)
            for (const glm::vec3& c : corners(part.min, part.max))
                headTop = std::max(headTop, (restWorld[static_cast<std::size_t>(node)] * glm::vec4(c, 1.0f)).y);
        parts_.push_back(part);
    }

    // SPEC §3.1: the signing space is the arc of radius r around the chest; from the resting
    // hands' height to the top of the head.
    const float r = static_cast<float>(stimuli::SigningSpace{}.arcRadiusMm);
    const float bottom = rig.restingTarget(hand::Side::Right).wristMm.y;
    const float top = headTop > std::numeric_limits<float>::lowest()
                          ? (headTop - rig.worldFromBodyMm(glm::vec3(0.0f)).y) * 1000.0f
                          : 2.0f * r;  // an avatar without a head mesh: up to arm's reach
    // The rectangle at the chest's depth, where the arc's ends are (ψ = ±90°: x = ±r, z = 0).
    signingSpace_ = corners(rig.worldFromBodyMm({-r, bottom, 0.0f}), rig.worldFromBodyMm({r, top, 0.0f}));
}

std::array<ScreenBox, 4> ScreenRegionModel::boxes(const render::Pose& pose, const render::Camera& camera,
                                                  const render::ViewCell& cell) const {
    std::vector<glm::mat4> world;
    render::computeWorldTransforms(*avatar_, pose, world);
    const glm::mat4 viewProjection =
        render::viewProjection(camera, static_cast<float>(cell.width) / static_cast<float>(cell.height));
    std::array<PixelBounds, 4> bounds;
    for (const Part& part : parts_) {
        const glm::mat4& m = world[static_cast<std::size_t>(part.node)];
        for (const glm::vec3& c : corners(part.min, part.max))
            bounds[static_cast<std::size_t>(part.region)].add(viewProjection, cell, glm::vec3(m * glm::vec4(c, 1.0f)));
    }
    for (const glm::vec3& c : signingSpace_)
        bounds[static_cast<std::size_t>(ScreenRegion::SigningSpace)].add(viewProjection, cell, c);
    std::array<ScreenBox, 4> out;
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = bounds[i].box(cell);
    return out;
}

render::Camera clipCamera(const render::Scene& avatar, const SignerRig& rig, std::uint32_t width, std::uint32_t height,
                          std::uint32_t columns, std::uint32_t rows) {
    // As renderClips (signer/clip_render.cpp) places it.
    const float aspect = (static_cast<float>(width) / static_cast<float>(columns)) /
                         (static_cast<float>(height) / static_cast<float>(rows));
    return postureFrame(avatar, rig, 0, SignerPosture{}, aspect).views.front().camera;
}

std::string screenRegionsCsv(const render::Scene& avatar, const SignerRig& rig, const ScreenRegionModel& model,
                             const std::vector<const Clip*>& clips, const std::vector<std::string>& labels,
                             double framesPerSecond, std::uint32_t width, std::uint32_t height, std::uint32_t columns,
                             std::uint32_t rows) {
    std::string csv = "frame,time_ms,panel,region,x0,y0,x1,y1,visible\n";
    if (clips.empty()) return csv;
    double duration = 0.0;
    // A null panel is one no signer is drawn in (a lab's recording, a human-video version): no rows.
    for (const Clip* clip : clips)
        if (clip) duration = std::max(duration, clip->durationSeconds());
    // renderClips' frames: one per 1/fps from 0 to the longest clip's end inclusive.
    const std::uint64_t total = static_cast<std::uint64_t>(std::floor(duration * framesPerSecond + 1e-9)) + 1;
    const render::Camera camera = clipCamera(avatar, rig, width, height, columns, rows);
    std::vector<std::optional<ClipPoser>> posers;
    for (const Clip* clip : clips) posers.push_back(clip ? std::optional<ClipPoser>(ClipPoser(rig, *clip)) : std::nullopt);
    csv.reserve(static_cast<std::size_t>(total) * clips.size() * 4 * 40);
    for (std::uint64_t f = 0; f < total; ++f) {
        const double t = static_cast<double>(f) / framesPerSecond;
        const std::string head = std::to_string(f) + "," + std::to_string(std::llround(t * 1000.0)) + ",";
        for (std::size_t k = 0; k < clips.size(); ++k) {
            if (!posers[k]) continue;
            const render::ViewCell cell = render::viewCell(width, height, columns, rows, k);
            const std::array<ScreenBox, 4> boxes = model.boxes(posers[k]->next(t), camera, cell);
            const std::string panel = k < labels.size() ? labels[k] : "";
            for (std::size_t r = 0; r < boxes.size(); ++r) {
                const ScreenBox& b = boxes[r];
                csv += head + panel + "," + toString(kScreenRegions[r]) + ",";
                if (b.visible)
                    csv += std::to_string(b.x0) + "," + std::to_string(b.y0) + "," + std::to_string(b.x1) + "," +
                           std::to_string(b.y1) + ",1\n";
                else
                    csv += ",,,,0\n";
            }
        }
    }
    return csv;
}

}  // namespace signstim::signer
