// Two-handed verbs whose meaning rests on how the hands meet (SPEC §3.5, §2.6): in EMAIL the
// right index finger slides into the left hand's C (without contact); in COPY the hands start in contact. Checked
// on the posed McDonald hands (hand/contact.hpp capsules and segment proximity) for every
// stimulus version at the paper's phase-2 arrangement and its mirror.
#include "hand/contact.hpp"
#include "hand/hand_model.hpp"
#include "stimuli/story/handshapes.hpp"
#include "stimuli/verbs/verb_models.hpp"
#include "stimuli/verbs/verb_synthesis.hpp"
#include "stimuli/verbs/verbs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <limits>

namespace signstim::stimuli {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(SIGNSTIM_SOURCE_DIR) / "scenes";

struct Fixture {
    VerbLibrary verbs = loadVerbLibrary(kScenes / "verbs.json");
    TrainedVerbModels models = loadVerbModels(kScenes / "models" / "verb_models.json", verbs);
    hand::HandModel handModel = hand::buildHandModel();
    HandshapeLibrary shapes = loadHandshapes(kScenes / "handshapes.json", handModel);
};
const Fixture& fixture() {
    static const Fixture f;
    return f;
}

glm::vec3 toWorld(const HandPose& pose, const glm::vec3& local) {
    return glm::vec3(pose.positionMm + pose.orientation * glm::dvec3(local));
}

// Capsules of the finger and thumb bones plus the palm (origin → each MCP and the thumb's
// CMC, radius 12 mm: half a palm's thickness [D]) in the signing-space frame.
std::vector<hand::Capsule> worldCapsules(const HandSample& sample, HandSide side) {
    const Fixture& f = fixture();
    const hand::HandControls controls = hand::interpolate(f.shapes.at(sample.handshapeFrom).controls,
                                                          f.shapes.at(sample.handshapeTo).controls,
                                                          static_cast<float>(sample.handshapeBlend));
    const hand::Side handSide = side == HandSide::Left ? hand::Side::Left : hand::Side::Right;
    const hand::HandPose pose = hand::forwardKinematics(f.handModel, controls, handSide);
    std::vector<hand::Capsule> result;
    for (const hand::Capsule& c : hand::boneCapsules(f.handModel, pose))
        if (c.radiusMm > 0) result.push_back({toWorld(sample.pose, c.start), toWorld(sample.pose, c.end), c.radiusMm});
    for (int b : {1, 4, 7, 10, 13})
        result.push_back({toWorld(sample.pose, glm::vec3(0)), toWorld(sample.pose, pose.bodies[b].position), 12.0f});
    return result;
}

float smallestGap(const std::vector<hand::Capsule>& a, const std::vector<hand::Capsule>& b) {
    float gap = std::numeric_limits<float>::max();
    for (const auto& x : a)
        for (const auto& y : b) gap = std::min(gap, hand::capsuleGap(x, y));
    return gap;
}

const std::vector<std::pair<double, double>> kArrangements{{0.9, -0.6}, {-0.6, 0.9}};
const std::vector<VerbVersion> kVersions{VerbVersion::Point, VerbVersion::Vector, VerbVersion::Animator,
                                         VerbVersion::Uninflected};

TEST(VerbContact, EmailIndexFingerSlidesIntoTheLeftHandsC) {
    // ASL-LEX 2.0 'email': the 1 hand's index finger slides into the C base without touching it
    // (the clearance tests hold the "without"): its tip starts on the near side of the C's hole
    // and reaches through it to the far side.
    const Fixture& f = fixture();
    const VerbSources sources{&f.verbs, &f.models, kScenes / "animator"};
    for (const auto& [s, o] : kArrangements)
        for (VerbVersion version : kVersions) {
            const VerbPerformance p = synthesizeVerb(sources, "EMAIL", version, s, o);
            float closest = std::numeric_limits<float>::max();
            double firstSide = 0.0, farthestSide = -std::numeric_limits<double>::max();
            constexpr int kFrames = 60;
            for (int i = 0; i <= kFrames; ++i) {
                const double t = p.durationSeconds * i / kFrames;
                const HandSample right = sampleHand(p.hands[0], t);
                const HandSample left = sampleHand(p.hands[1], t);
                // The C's hole: 40 mm palmar of the palm, 75 mm along the fingers [D, from the
                // posed C of scenes/handshapes.json]; its axis is the palm frame's y, which runs
                // from the little finger's side (+y of the left hand) to the index's.
                const glm::dvec3 hole = left.pose.positionMm + left.pose.orientation * glm::dvec3(40, 0, 75);
                const glm::dvec3 axis = left.pose.orientation * glm::dvec3(0, -1, 0);
                const glm::vec3 holePoint(hole);
                const auto rightCapsules = worldCapsules(right, HandSide::Right);
                for (int b = 3; b < 6; ++b) {  // the index finger's bones (after the thumb's three)
                    const auto& c = rightCapsules[static_cast<std::size_t>(b)];
                    closest = std::min(closest, hand::distancePointSegment(holePoint, c.start, c.end));
                }
                const double side = glm::dot(glm::dvec3(rightCapsules[5].end) - hole, axis);  // the fingertip
                if (i == 0) firstSide = side;
                farthestSide = std::max(farthestSide, side);
            }
            const std::string what = toString(version) + " s=" + std::to_string(s);
            EXPECT_LT(closest, 35.0f) << what;      // the index passes by the hole's centre
            EXPECT_LT(firstSide, 0.0) << what;      // from the near side of the C
            EXPECT_GT(farthestSide, 0.0) << what;   // into and through its hole
        }
}

TEST(VerbContact, CopyHandsStartInContact) {
    const Fixture& f = fixture();
    const VerbSources sources{&f.verbs, &f.models, kScenes / "animator"};
    for (const auto& [s, o] : kArrangements)
        for (VerbVersion version : kVersions) {
            const VerbPerformance p = synthesizeVerb(sources, "COPY", version, s, o);
            const float startGap = smallestGap(worldCapsules(sampleHand(p.hands[0], 0.0), HandSide::Right),
                                               worldCapsules(sampleHand(p.hands[1], 0.0), HandSide::Left));
            const float endGap = smallestGap(worldCapsules(sampleHand(p.hands[0], p.durationSeconds), HandSide::Right),
                                             worldCapsules(sampleHand(p.hands[1], p.durationSeconds), HandSide::Left));
            const std::string what = toString(version) + " s=" + std::to_string(s);
            EXPECT_LT(startGap, 20.0f) << what;   // touching
            EXPECT_GT(startGap, -12.0f) << what;  // not through each other
            EXPECT_GT(endGap, 60.0f) << what;     // and apart at the end
        }
}

}  // namespace
}  // namespace signstim::stimuli
