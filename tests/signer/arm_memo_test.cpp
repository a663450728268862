// The rig's memory of arm solutions (signer/arm_memo.hpp) answers what the solver gives, to
// the bit, for every input it is keyed by: a remembered answer never stands in for another.
#include "signer/arm_memo.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

using namespace signstim;

namespace {

bool sameBits(const hand::ArmPose& a, const hand::ArmPose& b) {
    const auto same = [](const auto& x, const auto& y) { return std::memcmp(&x, &y, sizeof x) == 0; };
    return same(a.shoulderMm, b.shoulderMm) && same(a.elbowMm, b.elbowMm) && same(a.wristMm, b.wristMm) &&
           same(a.upperArm, b.upperArm) && same(a.forearm, b.forearm) && same(a.hand, b.hand) &&
           same(a.elbowDirection, b.elbowDirection) && same(a.swivelDeg, b.swivelDeg) &&
           same(a.elbowFlexionDeg, b.elbowFlexionDeg) && same(a.shoulderElevationDeg, b.shoulderElevationDeg) &&
           same(a.shoulderPlaneDeg, b.shoulderPlaneDeg) && same(a.supinationDeg, b.supinationDeg) &&
           same(a.wristFlexionDeg, b.wristFlexionDeg) && same(a.wristUlnarDeviationDeg, b.wristUlnarDeviationDeg) &&
           same(a.reachErrorMm, b.reachErrorMm) && same(a.orientationErrorDeg, b.orientationErrorDeg) &&
           a.reachable == b.reachable && a.wristLimited == b.wristLimited && a.shoulderLimited == b.shoulderLimited;
}

}  // namespace

TEST(ArmMemo, KeysEveryInputOfTheSolver) {
    // False when a field was added to hand::ArmModel, ArmTarget or ArmSolveOptions: list it in
    // ArmMemo::solve's key and its size in kKnownSizes (until then every call solves afresh).
    EXPECT_TRUE(signer::ArmMemo::keyComplete());
}

TEST(ArmMemo, RemembersExactlyWhatTheSolverGivesForEachInput) {
    signer::ArmMemo memo;
    // Inputs that differ in one field at a time: the target, the elbow hint, an option, the
    // arm (a raised shoulder), the side.
    struct Input {
        hand::ArmModel arm;
        hand::ArmTarget target;
        hand::ArmSolveOptions options;
    };
    std::vector<Input> inputs;
    for (const hand::Side side : {hand::Side::Right, hand::Side::Left}) {
        const float mirror = side == hand::Side::Right ? 1.0f : -1.0f;
        Input base{hand::defaultArmModel(side), {{mirror * -150.0f, -20.0f, 300.0f}, glm::quat(0.9f, 0.1f, 0.3f, -0.2f)}, {}};
        base.target.handRotation = glm::normalize(base.target.handRotation);
        inputs.push_back(base);
        Input moved = base;
        moved.target.wristMm.y += 0.001f;
        inputs.push_back(moved);
        Input hinted = base;
        hinted.options.previousElbowDirection = glm::normalize(glm::vec3(mirror * -0.6f, -0.8f, 0.2f));
        inputs.push_back(hinted);
        Input windowed = hinted;
        windowed.options.maxSwivelStepDeg = 5.0f;
        inputs.push_back(windowed);
        Input weighted = base;
        weighted.options.wristComfortWeight = 3.0f;
        inputs.push_back(weighted);
        Input raised = base;
        raised.arm.shoulderMm.y += 20.0f;
        inputs.push_back(raised);
        Input far = base;
        far.target.wristMm.z += 600.0f;  // beyond reach
        inputs.push_back(far);
    }
    for (int pass = 0; pass < 2; ++pass)  // the first solves, the second answers from memory
        for (std::size_t i = 0; i < inputs.size(); ++i) {
            const Input& in = inputs[i];
            EXPECT_TRUE(sameBits(memo.solve(in.arm, in.target, in.options), hand::solveArm(in.arm, in.target, in.options)))
                << "input " << i << " pass " << pass;
        }
    // The inputs are told apart: each differs from the base's answer somewhere.
    const hand::ArmPose right = hand::solveArm(inputs[0].arm, inputs[0].target, inputs[0].options);
    for (std::size_t i = 1; i < 7; ++i)
        EXPECT_FALSE(sameBits(memo.solve(inputs[i].arm, inputs[i].target, inputs[i].options), right)) << "input " << i;
}
