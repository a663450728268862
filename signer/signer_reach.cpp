#include "signer/signer_reach.hpp"

#include "signer/hand_capsules.hpp"

#include <cmath>

namespace signstim::signer {

stimuli::SignerReach signerReach(const SignerRig& rig) {
    const auto armOf = [&rig](hand::Side side) {
        const hand::ArmModel& arm = rig.arm(side);
        stimuli::ArmReach reach;
        reach.shoulderMm = glm::dvec3(bodyFromSigningSpace(arm.shoulderMm));  // the mirror is its own inverse
        const double a = arm.upperArmLengthMm, b = arm.forearmLengthMm;
        reach.lengthMm = a + b;
        // The elbow at its flexion limit (hand/arm_ik.cpp, reachOf: d = sqrt(a² + b² + 2ab·cos flexion)).
        const double flexion = static_cast<double>(arm.limits.elbowFlexion.maxDeg) * 3.14159265358979323846 / 180.0;
        reach.foldedMm = std::sqrt(a * a + b * b + 2.0 * a * b * std::cos(flexion));
        return reach;
    };
    stimuli::SignerReach reach;
    reach.right = armOf(hand::Side::Right);
    reach.left = armOf(hand::Side::Left);
    // The torso the clearance check sees (bodyCapsules' sections; the chest is both frames'
    // origin and the sections are symmetric, so the mirror leaves them as they are), and the
    // hand as drawn (the palm's heel behind the wrist, the extended fingers ahead of it).
    for (const TorsoSectionM& s : torsoSections())
        reach.torso.sections.push_back({(static_cast<double>(s.y) - static_cast<double>(kTorsoChestM)) * 1000.0,
                                        static_cast<double>(s.halfWidth) * 1000.0, static_cast<double>(s.halfDepth) * 1000.0,
                                        static_cast<double>(s.z) * 1000.0});
    const hand::HandDimensions& d = rig.handModel().dimensions;
    const double scale = rig.handScale();
    reach.torso.hand.backMm = -static_cast<double>(d.palmWristZMm) * scale;
    reach.torso.hand.lengthMm = static_cast<double>(d.handLengthMm) * scale;
    reach.torso.hand.halfWidthMm = 0.5 * static_cast<double>(d.handBreadthMm) * scale;
    reach.torso.hand.halfThicknessMm = static_cast<double>(d.palmHalfThicknessWristMm) * scale;
    return reach;
}

}  // namespace signstim::signer
