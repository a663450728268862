#pragma once
// The signer's hands and body as capsules, and how close two sets of them come: the geometry
// behind the clearance check (signer/clearance.hpp) and the routing of a story's transitions
// (signer/timeline_clip.hpp).
//
// Geometry [D]. Each hand is capsules in the body frame of hand/arm_ik.hpp (mm): its 15 digit
// bones as hand::boneCapsules gives them (radii from the finger and thumb widths, SPEC §1.2)
// and 4 palm capsules from the heel of the palm to the finger knuckles, as thick as the palm
// slab at the knuckles (HandDimensions::palm*). They are placed at a wrist and hand frame —
// for a posed frame the arm solution's (PoseReport: what the skeleton is posed with) — and
// scaled to the avatar's hand (SignerRig::handScale), so they follow the drawn hand (tested
// against the posed skeleton). The body is capsules fitted to the default signer's torso,
// neck and head (signer/avatar_builder.cpp): horizontal capsules through the torso's
// cross-sections, a vertical one each for the neck and the head. They stand still: the head
// turns with the gaze about an axis close to its capsule's, and the torso is not posed.
#include "hand/contact.hpp"
#include "signer/signer_pose.hpp"

#include <array>
#include <limits>
#include <vector>

namespace signstim::signer {

// The default signer's torso sections (signer/avatar_builder.cpp, world metres with the chest
// bone at kTorsoChestM), from the bottom up: height, half width, half depth, centre z.
struct TorsoSectionM {
    float y, halfWidth, halfDepth, z;
};
inline constexpr float kTorsoChestM = 1.30f;
const std::array<TorsoSectionM, 11>& torsoSections();

// The default signer's torso, neck and head, body frame (mm).
const std::vector<hand::Capsule>& bodyCapsules();

// One hand's capsules (the `side` hand in `controls`) with its wrist at `wristMm` and its
// palm frame turned by `handRotation` (body frame), into `out`.
void handCapsules(const SignerRig& rig, hand::Side side, const hand::HandControls& controls, const glm::vec3& wristMm,
                  const glm::quat& handRotation, std::vector<hand::Capsule>& out);

// The closest approach of two sets of capsules: the smallest surface gap (mm; negative: they
// interpenetrate that deep) and the two axis points it is measured between.
struct Approach {
    float gapMm = std::numeric_limits<float>::infinity();
    glm::vec3 onFirst{0.0f}, onSecond{0.0f};
};
Approach closestApproach(const std::vector<hand::Capsule>& first, const std::vector<hand::Capsule>& second);

struct SignerCapsules {
    std::vector<hand::Capsule> right, left;  // palm and digits
};
// The hands as posed: the posture's hand controls where the arm solution `report` put the
// wrists and turned the hands.
SignerCapsules signerCapsules(const SignerRig& rig, const SignerPosture& posture, const PoseReport& report);

struct Clearance {
    Approach hands;  // right hand (first) to left hand (second)
    Approach body;   // the hand closest to the body (first) to the body (second)
    hand::Side closestToBody = hand::Side::Right;
};
Clearance clearance(const SignerCapsules& capsules);

}  // namespace signstim::signer
