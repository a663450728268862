// Contact analysis (SPEC §2.6) on constructed cases: touching, missing by 0.1 mm, edges,
// corners, and the segment/capsule queries used for fingers and two-handed verbs.
#include "hand/contact.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

namespace signstim::hand {
namespace {

// Box [0,10] × [0,20] × [−30,0] in the paper's vertex order (1–4 at z = 0, 5–8 at z = −30),
// optionally rotated and moved.
BoxVertices makeBox(const glm::quat& rotation = glm::quat(1, 0, 0, 0), const glm::vec3& offset = glm::vec3(0)) {
    const BoxVertices local = {glm::vec3(10, 0, 0), glm::vec3(10, 20, 0), glm::vec3(0, 20, 0), glm::vec3(0, 0, 0),
                               glm::vec3(10, 0, -30), glm::vec3(10, 20, -30), glm::vec3(0, 20, -30), glm::vec3(0, 0, -30)};
    BoxVertices box{};
    for (int i = 0; i < 8; ++i) box[i] = rotation * local[i] + offset;
    return box;
}

const glm::quat kTilt = glm::normalize(glm::angleAxis(0.7f, glm::normalize(glm::vec3(1, 2, 3))));
const glm::vec3 kShift(40, -25, 12);

glm::vec3 moved(const glm::vec3& p) { return kTilt * p + kShift; }

TEST(ContactTest, SphereTouchingAFaceIsFoundByBothTests) {
    for (bool transformed : {false, true}) {
        const BoxVertices box = transformed ? makeBox(kTilt, kShift) : makeBox();
        auto at = [&](glm::vec3 p) { return transformed ? moved(p) : p; };
        const glm::vec3 touching = at({5, 10, 4.0f});  // 4 mm above the z = 0 face, radius 4
        EXPECT_TRUE(sphereTouchesBoxPaper(box, touching, 4.0f));
        EXPECT_TRUE(sphereTouchesBox(box, touching, 4.0f));
        EXPECT_NEAR(signedDistanceToBox(box, touching), 4.0f, 1e-3f);
        const glm::vec3 missing = at({5, 10, 4.1f});  // misses by 0.1 mm
        EXPECT_FALSE(sphereTouchesBoxPaper(box, missing, 4.0f));
        EXPECT_FALSE(sphereTouchesBox(box, missing, 4.0f));
        // Side faces too (x = 10 face): 0.1 mm short and 0.1 mm too far.
        EXPECT_TRUE(sphereTouchesBoxPaper(box, at({16.9f, 10, -15}), 7.0f));
        EXPECT_FALSE(sphereTouchesBoxPaper(box, at({17.1f, 10, -15}), 7.0f));
    }
}

TEST(ContactTest, EdgeAndCornerContactsNeedTheExactDistance) {
    const BoxVertices box = makeBox(kTilt, kShift);
    // Beyond the edge x = 10, z = 0, diagonally: distance 3·√2 ≈ 4.243 mm.
    const glm::vec3 nearEdge = moved({13, 10, 3});
    EXPECT_NEAR(signedDistanceToBox(box, nearEdge), 3.0f * std::sqrt(2.0f), 1e-3f);
    EXPECT_TRUE(sphereTouchesBox(box, nearEdge, 4.3f));
    EXPECT_FALSE(sphereTouchesBox(box, nearEdge, 4.1f));
    // The paper's face test misses it: the projection falls outside every face.
    EXPECT_FALSE(sphereTouchesBoxPaper(box, nearEdge, 4.3f));
    // Beyond the corner (10, 20, 0): distance √(4+4+4) ≈ 3.464 mm.
    const glm::vec3 nearCorner = moved({12, 22, 2});
    EXPECT_NEAR(signedDistanceToBox(box, nearCorner), std::sqrt(12.0f), 1e-3f);
    EXPECT_TRUE(sphereTouchesBox(box, nearCorner, 3.5f));
    EXPECT_FALSE(sphereTouchesBox(box, nearCorner, 3.4f));
    EXPECT_FALSE(sphereTouchesBoxPaper(box, nearCorner, 3.5f));
}

TEST(ContactTest, CentreInsideTheBoxHasNegativeDistance) {
    const BoxVertices box = makeBox(kTilt, kShift);
    EXPECT_NEAR(signedDistanceToBox(box, moved({5, 10, -15})), -5.0f, 1e-3f);
    EXPECT_NEAR(signedDistanceToBox(box, moved({9, 10, -15})), -1.0f, 1e-3f);
    EXPECT_TRUE(sphereTouchesBox(box, moved({5, 10, -15}), 0.5f));
}

TEST(ContactTest, EveryFaceOfTheBoxIsTested) {
    const BoxVertices box = makeBox();
    const glm::vec3 centre(5, 10, -15);
    const glm::vec3 outward[6] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
    const float halfSize[6] = {15, 15, 5, 5, 10, 10};
    // SPEC face order 1234, 5678, 1265, 4378, 2376, 1485 = top, bottom, x=10, x=0, y=20, y=0.
    for (int face = 0; face < 6; ++face) {
        const glm::vec3 p = centre + outward[face] * (halfSize[face] + 2.0f);
        EXPECT_TRUE(sphereTouchesFacePaper(box, face, p, 2.0f)) << face;
        EXPECT_FALSE(sphereTouchesFacePaper(box, face, p, 1.9f)) << face;
        for (int other = 0; other < 6; ++other) {
            if (other == face) continue;
            EXPECT_FALSE(sphereTouchesFacePaper(box, other, p, 2.0f)) << face << " " << other;
        }
    }
}

TEST(ContactTest, SegmentClosestPointsCoverCrossingParallelAndDegenerateCases) {
    // Skew segments crossing at x = y = 0, 5 mm apart in z.
    SegmentClosestPoints r = closestPointsOnSegments({-10, 0, 0}, {10, 0, 0}, {0, -10, 5}, {0, 10, 5});
    EXPECT_NEAR(r.distance, 5.0f, 1e-5f);
    EXPECT_NEAR(r.s, 0.5f, 1e-5f);
    EXPECT_NEAR(r.t, 0.5f, 1e-5f);
    // Parallel, overlapping.
    r = closestPointsOnSegments({0, 0, 0}, {10, 0, 0}, {5, 3, 0}, {15, 3, 0});
    EXPECT_NEAR(r.distance, 3.0f, 1e-5f);
    // End to end: the closest points are the endpoints.
    r = closestPointsOnSegments({0, 0, 0}, {10, 0, 0}, {13, 4, 0}, {20, 4, 0});
    EXPECT_NEAR(r.distance, 5.0f, 1e-5f);
    EXPECT_EQ(r.s, 1.0f);
    EXPECT_EQ(r.t, 0.0f);
    // Degenerate (points).
    EXPECT_NEAR(closestPointsOnSegments({1, 1, 1}, {1, 1, 1}, {1, 1, 4}, {1, 1, 4}).distance, 3.0f, 1e-6f);
    EXPECT_NEAR(distancePointSegment({5, 2, 0}, {0, 0, 0}, {10, 0, 0}), 2.0f, 1e-6f);
}

TEST(ContactTest, CapsulesTouchingOrMissingByATenthOfAMillimetre) {
    const Capsule a{{0, 0, 0}, {0, 0, 40}, 8.0f};
    const Capsule touching{{16, 0, 10}, {16, 0, 50}, 8.0f};
    const Capsule missing{{16.1f, 0, 10}, {16.1f, 0, 50}, 8.0f};
    EXPECT_NEAR(capsuleGap(a, touching), 0.0f, 1e-5f);
    EXPECT_NEAR(capsuleGap(a, missing), 0.1f, 1e-5f);
    EXPECT_LT(capsuleGap(a, {{10, 0, 0}, {10, 0, 40}, 8.0f}), 0.0f);
}

TEST(ContactTest, ForcedOverlapOfTwoFingersIsReported) {
    const HandModel model = buildHandModel();
    HandControls flat;
    flat.thumb = {5.0f, 70.0f, 0.0f, 0.0f};
    const BoneGap open = closestInterDigitGap(boneCapsules(model, forwardKinematics(model, flat, Side::Right)));
    EXPECT_GT(open.gapMm, 0.0f);
    HandControls crossed = flat;
    crossed.fingers[0].spreadDeg = 30.0f;   // index toward the little finger
    crossed.fingers[1].spreadDeg = -25.0f;  // middle toward the thumb
    const BoneGap overlap = closestInterDigitGap(boneCapsules(model, forwardKinematics(model, crossed, Side::Right)));
    EXPECT_LT(overlap.gapMm, -5.0f);
    EXPECT_EQ((static_cast<int>(overlap.first) - 1) / 3, 1) << "the index is involved";
    EXPECT_EQ((static_cast<int>(overlap.second) - 1) / 3, 2) << "the middle finger is involved";
    // Ignoring that pair, the worst remaining overlap is elsewhere and much smaller.
    const BoneGap rest = closestInterDigitGap(boneCapsules(model, forwardKinematics(model, crossed, Side::Right)),
                                              digitPairBit(Digit::Index, Digit::Middle));
    EXPECT_GT(rest.gapMm, overlap.gapMm + 3.0f);
    EXPECT_FALSE((static_cast<int>(rest.first) - 1) / 3 == 1 && (static_cast<int>(rest.second) - 1) / 3 == 2);
}

TEST(ContactTest, PalmClearanceMeasuresFromThePalmarSurface) {
    const HandModel model = buildHandModel();
    const float zMid = 0.5f * (model.dimensions.palmWristZMm + palmKnuckleZMm(model));
    const float surface = palmarSurfaceXMm(model, zMid);
    // The slab tapers: thicker at the wrist than at the knuckles.
    EXPECT_GT(palmarSurfaceXMm(model, model.dimensions.palmWristZMm), palmarSurfaceXMm(model, palmKnuckleZMm(model)));
    // A capsule lying across the palm 5 mm above its surface.
    const Capsule across{{surface + 13.0f, 15.0f, zMid}, {surface + 13.0f, -30.0f, zMid}, 8.0f};
    EXPECT_NEAR(palmClearanceMm(model, across, Side::Right), 5.0f, 1e-3f);
    // Pushed 4 mm into the palm: negative.
    const Capsule sunk{{surface + 4.0f, 15.0f, zMid}, {surface + 4.0f, -30.0f, zMid}, 8.0f};
    EXPECT_NEAR(palmClearanceMm(model, sunk, Side::Right), -4.0f, 1e-3f);
    // Only the part over the palm counts: a bone sloping down beyond the knuckles is measured
    // where its axis crosses the knuckle line.
    const float zKnuckles = palmKnuckleZMm(model);
    const Capsule beyond{{surface + 20.0f, 0.0f, zKnuckles - 10.0f}, {0.0f, 0.0f, zKnuckles + 30.0f}, 5.0f};
    const float atKnuckles = 0.75f * (surface + 20.0f);  // x where the axis crosses the knuckle line
    EXPECT_NEAR(palmClearanceMm(model, beyond, Side::Right), atKnuckles - palmarSurfaceXMm(model, zKnuckles) - 5.0f, 1e-3f);
    // Entirely past the knuckles or beside the hand: nothing to measure.
    EXPECT_TRUE(std::isinf(palmClearanceMm(model, {{0, 0, zKnuckles + 5}, {0, 0, zKnuckles + 40}, 5.0f}, Side::Right)));
    // Beside the index edge (the thumb along the index in G): against the palm's side, not in it.
    const float indexEdge = model.mcpPositionMm[0].y + 0.5f * model.dimensions.pipWidthMm[0];
    EXPECT_TRUE(std::isinf(palmClearanceMm(
        model, {{surface - 5.0f, indexEdge + 4.0f, zMid - 20.0f}, {surface - 5.0f, indexEdge + 4.0f, zMid + 20.0f}, 8.0f},
        Side::Right)));
    // Behind the back of the hand: not in the palm.
    const float back = 2.0f * model.dimensions.palmCentreXMm - surface;
    EXPECT_TRUE(std::isinf(palmClearanceMm(model, {{back - 6.0f, 15.0f, zMid}, {back - 6.0f, -30.0f, zMid}, 5.0f}, Side::Right)));
    EXPECT_TRUE(std::isinf(palmClearanceMm(model, {{0, 80, zMid}, {0, 90, zMid}, 5.0f}, Side::Right)));
    // The left hand's palm spans -y: the mirrored capsule gives the same clearance.
    const Capsule mirrored{{across.start.x, -across.start.y, across.start.z}, {across.end.x, -across.end.y, across.end.z}, 8.0f};
    EXPECT_NEAR(palmClearanceMm(model, mirrored, Side::Left), 5.0f, 1e-3f);
}

}  // namespace
}  // namespace signstim::hand
