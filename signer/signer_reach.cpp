#include "signer/signer_reach.hpp"

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
    return reach;
}

}  // namespace signstim::signer
