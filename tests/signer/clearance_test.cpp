// The hands keep clear of each other and of the body (signer/clearance.hpp): the capsules
// follow the drawn hands and measure the gaps between their surfaces.
#include "signer/clearance.hpp"
#include "signer/timeline_clip.hpp"
#include "signer/verb_render.hpp"
#include "stimuli/lexicon.hpp"
#include "stimuli/sora.hpp"
#include "stimuli/story.hpp"
#include "stimuli/timeline.hpp"
#include "stimuli/verb_models.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cstdio>
#include <string>
#include <vector>

using namespace signstim;

namespace {

const std::filesystem::path kScenes = std::filesystem::path(SIGNSTIM_SOURCE_DIR) / "scenes";

// What `signstim story` builds a story from: the default signer (scenes/avatar/signer.glb),
// the handshapes, verbs, trained models and lexicon of scenes/.
struct World {
    signer::Signer signer{kScenes};
    stimuli::VerbLibrary verbs = stimuli::loadVerbLibrary(kScenes / "verbs.json");
    stimuli::TrainedVerbModels models = stimuli::loadVerbModels(kScenes / "models" / "verb_models.json", verbs);
    stimuli::Lexicon lexicon = stimuli::loadLexicon(kScenes / "lexicon", signer.shapes(), signer.rig().handModel());

    stimuli::TimelineSources sources() const {
        stimuli::TimelineSources s;
        s.lexicon = &lexicon;
        s.shapes = &signer.shapes();
        s.verbs = [this](const std::string& verb, stimuli::VerbVersion version, double subject, double object, int, int) {
            return stimuli::synthesizeVerb(stimuli::VerbSources{&verbs, &models, kScenes / "animator", &signer.shapes()},
                                           verb, version, subject, object);
        };
        return s;
    }
    stimuli::Story story(const std::filesystem::path& file) const {
        stimuli::StoryVocabulary vocabulary;
        vocabulary.verbs = &verbs;
        vocabulary.signs = lexicon.glosses();
        return stimuli::loadStory(file, vocabulary);
    }
};
const World& world() {
    static const World w;
    return w;
}

}  // namespace

TEST(Clearance, HandCapsulesFollowThePosedSkeleton) {
    // Bent fingers and a turned hand on the right, the relaxed hand on the left: each bone's
    // capsule starts where the posed avatar has that bone's joint.
    const World& w = world();
    const signer::SignerRig& rig = w.signer.rig();
    const render::Scene& scene = w.signer.avatar();
    signer::SignerPosture posture;
    posture.rightHand = w.signer.shapes().at("X").controls;
    posture.leftHand = signer::relaxedHand();
    posture.rightWrist = hand::ArmTarget{{-60.0f, -50.0f, 300.0f}, glm::angleAxis(0.7f, glm::normalize(glm::vec3(1, 2, 3)))};
    posture.leftWrist = hand::ArmTarget{{120.0f, -80.0f, 260.0f}, glm::angleAxis(-1.1f, glm::normalize(glm::vec3(2, -1, 1)))};
    signer::PoseReport report;
    const render::Pose pose = rig.pose(posture, &report);
    std::vector<glm::mat4> world;
    render::computeWorldTransforms(scene, pose, world);
    const signer::SignerCapsules capsules = signer::signerCapsules(rig, posture, report);
    for (const hand::Side side : {hand::Side::Right, hand::Side::Left}) {
        const std::vector<hand::Capsule>& hand = side == hand::Side::Right ? capsules.right : capsules.left;
        ASSERT_EQ(hand.size(), 19u);  // 15 digit bones, 4 palm capsules
        const auto bones = hand::handBones(side);
        for (int body = 1; body < hand::kBodyCount; ++body) {
            const glm::vec3 joint = glm::vec3(world[static_cast<std::size_t>(scene.findNode(std::string(bones[body].name)))][3]);
            const glm::vec3 capsuleStart = rig.worldFromBodyMm(hand[static_cast<std::size_t>(body - 1)].start);
            EXPECT_LT(glm::distance(joint, capsuleStart) * 1000.0f, 0.5f) << bones[body].name;
        }
    }
}

TEST(Clearance, ClosestApproachIsTheSmallestSurfaceGap) {
    // Two parallel finger capsules 30 mm apart (radii 10 and 8) touch at 12 mm; a far capsule
    // in the same set does not hide the near one.
    const std::vector<hand::Capsule> first{{{0, 0, 0}, {0, 0, 50}, 10.0f}};
    const std::vector<hand::Capsule> second{{{500, 0, 0}, {500, 0, 50}, 8.0f}, {{30, 0, 10}, {30, 0, 60}, 8.0f}};
    const signer::Approach a = signer::closestApproach(first, second);
    EXPECT_NEAR(a.gapMm, 12.0f, 1e-4f);
    EXPECT_NEAR(a.onFirst.x, 0.0f, 1e-4f);
    EXPECT_NEAR(a.onSecond.x, 30.0f, 1e-4f);
    // Crossing capsules interpenetrate by the sum of their radii.
    const std::vector<hand::Capsule> crossing{{{-40, 0, 25}, {40, 0, 25}, 8.0f}};
    EXPECT_NEAR(signer::closestApproach(first, crossing).gapMm, -18.0f, 1e-4f);
}
