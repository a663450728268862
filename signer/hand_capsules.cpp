#include "signer/hand_capsules.hpp"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace signstim::signer {
namespace {

// [D] The heel of the palm is narrower than the knuckle line: the palm capsules start at
// this fraction of their knuckle's distance from the palm's middle.
constexpr float kPalmHeelSpread = 0.6f;

}  // namespace

const std::array<TorsoSectionM, 11>& torsoSections() {
    static const std::array<TorsoSectionM, 11> sections{{{0.86f, 0.165f, 0.105f, 0.0f},
                                                         {0.96f, 0.160f, 0.100f, 0.0f},
                                                         {1.06f, 0.148f, 0.092f, 0.0f},
                                                         {1.16f, 0.150f, 0.097f, 0.004f},
                                                         {1.24f, 0.160f, 0.105f, 0.008f},
                                                         {1.32f, 0.170f, 0.108f, 0.008f},
                                                         {1.38f, 0.182f, 0.100f, 0.002f},
                                                         {1.42f, 0.184f, 0.090f, -0.004f},
                                                         {1.455f, 0.170f, 0.075f, -0.008f},
                                                         {1.475f, 0.130f, 0.058f, -0.010f},
                                                         {1.487f, 0.080f, 0.045f, -0.010f}}};
    return sections;
}

const std::vector<hand::Capsule>& bodyCapsules() {
    static const std::vector<hand::Capsule> capsules = [] {
        // The torso's sections (torsoSections): each becomes a horizontal capsule whose radius
        // is the half depth; three per interval, as the mesh has rings, so that the capsules'
        // rounded edges leave no dent between them.
        using Section = TorsoSectionM;
        const std::array<Section, 11>& sections = torsoSections();
        constexpr float kChestM = kTorsoChestM, kMm = 1000.0f;
        std::vector<hand::Capsule> out;
        const auto add = [&](const Section& s) {
            const float half = std::max(0.0f, s.halfWidth - s.halfDepth) * kMm;
            const float y = (s.y - kChestM) * kMm, z = s.z * kMm;
            out.push_back({{-half, y, z}, {half, y, z}, s.halfDepth * kMm});
        };
        for (std::size_t i = 0; i + 1 < sections.size(); ++i)
            for (int k = 0; k < 3; ++k) {
                const float t = static_cast<float>(k) / 3.0f;
                const Section& a = sections[i];
                const Section& b = sections[i + 1];
                add({a.y + (b.y - a.y) * t, a.halfWidth + (b.halfWidth - a.halfWidth) * t,
                     a.halfDepth + (b.halfDepth - a.halfDepth) * t, a.z + (b.z - a.z) * t});
            }
        add(sections.back());
        // Neck: 50 mm round from inside the torso up into the head.
        out.push_back({{0.0f, 150.0f, -5.0f}, {0.0f, 250.0f, 0.0f}, 50.0f});
        // Head: the skull's ellipsoid (78 mm wide, 110 high, 95 deep about (0, 340, 12)) as a
        // capsule as wide as it: its front matches the face at the chin and falls 17 mm short
        // of the nose, so a hand that touches it is in the face.
        out.push_back({{0.0f, 308.0f, 12.0f}, {0.0f, 372.0f, 12.0f}, 78.0f});
        return out;
    }();
    return capsules;
}

void handCapsules(const SignerRig& rig, hand::Side side, const hand::HandControls& controls, const glm::vec3& wristMm,
                  const glm::quat& handRotation, std::vector<hand::Capsule>& out) {
    const hand::HandModel& model = rig.handModel();
    const hand::HandPose pose = hand::forwardKinematics(model, controls, side);
    const float scale = rig.handScale();
    const auto place = [&](const glm::vec3& palmMm) { return wristMm + handRotation * (scale * palmMm); };
    out.clear();
    for (const hand::Capsule& bone : hand::boneCapsules(model, pose))
        if (bone.radiusMm > 0.0f) out.push_back({place(bone.start), place(bone.end), scale * bone.radiusMm});
    const hand::HandDimensions& d = model.dimensions;
    for (int f = 0; f < hand::kFingerCount; ++f) {
        glm::vec3 knuckle = model.mcpPositionMm[static_cast<std::size_t>(f)];
        if (side == hand::Side::Left) knuckle = hand::mirrorToLeft(knuckle);
        knuckle.x = d.palmCentreXMm;
        const glm::vec3 heel(d.palmCentreXMm, kPalmHeelSpread * knuckle.y, 0.0f);
        out.push_back({place(heel), place(knuckle), scale * d.palmHalfThicknessKnucklesMm});
    }
}

Approach closestApproach(const std::vector<hand::Capsule>& first, const std::vector<hand::Capsule>& second) {
    Approach best;
    if (first.empty()) return best;
    // A sphere around all of `first`: a capsule of `second` farther from it than the best gap
    // so far cannot come closer (the body's capsules are mostly far from a hand).
    glm::vec3 low = first.front().start, high = low;
    for (const hand::Capsule& a : first)
        for (const glm::vec3& p : {a.start, a.end}) {
            low = glm::min(low, p);
            high = glm::max(high, p);
        }
    const glm::vec3 centre = 0.5f * (low + high);
    float radius = 0.0f;
    for (const hand::Capsule& a : first)
        radius = std::max({radius, glm::distance(centre, a.start) + a.radiusMm, glm::distance(centre, a.end) + a.radiusMm});
    // And a sphere around each capsule of `first`: a pair whose spheres are farther apart than
    // the best gap so far, by more than any rounding (kSkipMarginMm), cannot come closer, and
    // is skipped without its segments' closest points (a pair skipped would not have been
    // taken: the result is the same to the bit).
    constexpr float kSkipMarginMm = 1.0f;
    std::vector<glm::vec4> spheres;  // centre, radius
    spheres.reserve(first.size());
    for (const hand::Capsule& a : first)
        spheres.emplace_back(0.5f * (a.start + a.end), 0.5f * glm::distance(a.start, a.end) + a.radiusMm);
    for (const hand::Capsule& b : second) {
        if (hand::distancePointSegment(centre, b.start, b.end) - radius - b.radiusMm >= best.gapMm) continue;
        const glm::vec3 bCentre = 0.5f * (b.start + b.end);
        const float bRadius = 0.5f * glm::distance(b.start, b.end) + b.radiusMm;
        for (std::size_t i = 0; i < first.size(); ++i) {
            const hand::Capsule& a = first[i];
            if (glm::distance(glm::vec3(spheres[i]), bCentre) - spheres[i].w - bRadius > best.gapMm + kSkipMarginMm) continue;
            const hand::SegmentClosestPoints c = hand::closestPointsOnSegments(a.start, a.end, b.start, b.end);
            const float gap = c.distance - a.radiusMm - b.radiusMm;
            if (gap < best.gapMm) best = {gap, c.onFirst, c.onSecond};
        }
    }
    return best;
}

SignerCapsules signerCapsules(const SignerRig& rig, const SignerPosture& posture, const PoseReport& report) {
    SignerCapsules capsules;
    handCapsules(rig, hand::Side::Right, posture.rightHand, report.right.wristMm, report.right.hand, capsules.right);
    handCapsules(rig, hand::Side::Left, posture.leftHand, report.left.wristMm, report.left.hand, capsules.left);
    return capsules;
}

Clearance clearance(const SignerCapsules& capsules) {
    Clearance c;
    c.hands = closestApproach(capsules.right, capsules.left);
    const Approach right = closestApproach(capsules.right, bodyCapsules());
    const Approach left = closestApproach(capsules.left, bodyCapsules());
    c.closestToBody = left.gapMm < right.gapMm ? hand::Side::Left : hand::Side::Right;
    c.body = left.gapMm < right.gapMm ? left : right;
    return c;
}

}  // namespace signstim::signer
