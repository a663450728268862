// Head/eye gaze: direction accuracy, split between head and eyes, limits.
#include "hand/gaze.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>

using namespace signstim::hand;

namespace {
glm::vec3 achieved(const GazePose& p) { return p.head * (p.eyes * glm::vec3(0, 0, 1)); }
}  // namespace

TEST(Gaze, StraightAheadNeedsNoRotation) {
    const GazeModel model;
    const GazePose p = solveGaze(model, model.eyesMm + glm::vec3(0, 0, 800));
    EXPECT_NEAR(p.headYawDeg, 0.0f, 1e-4f);
    EXPECT_NEAR(p.eyeYawDeg, 0.0f, 1e-4f);
    EXPECT_NEAR(p.errorDeg, 0.0f, 1e-2f);
}

TEST(Gaze, PointsInFrontAreLookedAtSharedBetweenHeadAndEyes) {
    const GazeModel model;
    for (float x = -600; x <= 600; x += 150)
        for (float y = -260; y <= 300; y += 140) {
            const glm::vec3 target{x, y, 500};
            const GazePose p = solveGaze(model, target);
            EXPECT_TRUE(p.reachable) << x << "," << y;
            EXPECT_GT(glm::dot(achieved(p), glm::normalize(target - model.eyesMm)), 0.9999f);
            EXPECT_TRUE(model.headYaw.contains(p.headYawDeg));
            EXPECT_TRUE(model.eyeYaw.contains(p.eyeYawDeg));
            EXPECT_TRUE(model.headPitch.contains(p.headPitchDeg));
            EXPECT_TRUE(model.eyePitch.contains(p.eyePitchDeg));
            if (std::fabs(x) >= 300) {  // a clear turn: the head takes part, in the same direction
                EXPECT_GT(p.headYawDeg * x, 0.0f);
                EXPECT_GT(p.eyeYawDeg * x, 0.0f);
            }
        }
}

TEST(Gaze, TargetBehindIsApproachedWithinLimitsAndReported) {
    const GazeModel model;
    const GazePose p = solveGaze(model, model.eyesMm + glm::vec3(100, 0, -800));
    EXPECT_FALSE(p.reachable);
    EXPECT_GT(p.errorDeg, 30.0f);
    EXPECT_NEAR(p.headYawDeg, model.headYaw.maxDeg, 1e-3f);
    EXPECT_NEAR(p.eyeYawDeg, model.eyeYaw.maxDeg, 1e-3f);
}

TEST(Gaze, NeckTakesItsShareOfTheHead) {
    const GazeModel model;
    const GazePose p = solveGaze(model, model.eyesMm + glm::vec3(500, 0, 500));
    const float headAngle = 2.0f * std::acos(std::fabs(p.head.w));
    const float neckAngle = 2.0f * std::acos(std::fabs(p.neck.w));
    EXPECT_NEAR(neckAngle, model.neckShare * headAngle, 1e-3f);
}
