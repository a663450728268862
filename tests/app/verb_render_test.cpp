// From verb performances to signer frames: the hands go where the verb data say, palms and
// fingers pointing the way they say, and clips start at rest.
#include "app/avatar_builder.hpp"
#include "app/signer_pose.hpp"
#include "app/verb_render.hpp"
#include "stimuli/handshapes.hpp"
#include "stimuli/verbs.hpp"
#include "stimuli/verb_models.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

using namespace signstim;

namespace {
const std::filesystem::path kScenes = std::filesystem::path(SIGNSTIM_SOURCE_DIR) / "scenes";

struct Fixture {
    render::Scene avatar = app::buildDefaultAvatar();
    app::SignerRig rig{avatar};
    stimuli::HandshapeLibrary shapes = stimuli::loadHandshapes(kScenes / "handshapes.json", rig.handModel());
    stimuli::VerbLibrary verbs = stimuli::loadVerbLibrary(kScenes / "verbs.json");
    stimuli::TrainedVerbModels models = stimuli::loadVerbModels(kScenes / "models" / "verb_models.json", verbs);
};
const Fixture& fixture() {
    static const Fixture f;
    return f;
}

glm::vec3 nodePosition(const render::Scene& s, const std::vector<glm::mat4>& world, const std::string& name) {
    return glm::vec3(world[s.findNode(name)][3]);
}

// The physical palm normal and finger direction of a posed hand in world (glTF) axes, from
// its joints: for either hand the palm faces (index MCP − little MCP) × fingers for a right
// hand, and the opposite cross product for a left hand (the mirror image).
void palmAndFingers(const render::Scene& s, const std::vector<glm::mat4>& world, const std::string& side,
                    glm::vec3& palm, glm::vec3& fingers) {
    const glm::vec3 index = nodePosition(s, world, side + "IndexProximal");
    const glm::vec3 little = nodePosition(s, world, side + "LittleProximal");
    const glm::vec3 wrist = nodePosition(s, world, side + "Hand");
    fingers = glm::normalize(0.5f * (index + little) - wrist);
    const glm::vec3 across = glm::normalize(index - little);  // toward the thumb side
    palm = glm::normalize(side == "right" ? glm::cross(across, fingers) : glm::cross(fingers, across));
}
}  // namespace

TEST(VerbRender, HandsFaceTheWayTheVerbDataSay) {
    // MEET's citation form (scenes/verbs.json): both index fingers up, palms facing each
    // other across the midline. In glTF world axes the signer faces +Z and the signer's
    // left is +X.
    const Fixture& f = fixture();
    const stimuli::VerbSources sources{&f.verbs, &f.models, kScenes / "animator"};
    const app::VerbClip clip(f.rig, f.shapes,
                             stimuli::synthesizeVerb(sources, "MEET", stimuli::VerbVersion::Uninflected, 0.9, -0.6));
    const render::Pose pose = f.rig.pose(clip.postureAt(app::ClipTiming{}.leadInSeconds));
    std::vector<glm::mat4> world;
    render::computeWorldTransforms(f.avatar, pose, world);
    glm::vec3 palm, fingers;
    palmAndFingers(f.avatar, world, "right", palm, fingers);
    EXPECT_GT(fingers.y, 0.8f) << "right fingers should point up";
    EXPECT_GT(palm.x, 0.7f) << "right palm should face the signer's left (+X)";
    palmAndFingers(f.avatar, world, "left", palm, fingers);
    EXPECT_GT(fingers.y, 0.8f) << "left fingers should point up";
    EXPECT_LT(palm.x, -0.7f) << "left palm should face the signer's right (-X)";
}

TEST(VerbRender, ClipRisesFromRestAndReachesTheFirstKeyframeAfterTheLeadIn) {
    const Fixture& f = fixture();
    const stimuli::VerbSources sources{&f.verbs, &f.models, kScenes / "animator"};
    stimuli::VerbPerformance performance =
        stimuli::synthesizeVerb(sources, "GIVE", stimuli::VerbVersion::Point, 0.9, -0.6);
    const glm::vec3 first = app::armTargetFromSigningSpace(performance.hands[0].keyframes.front().pose).wristMm;
    const glm::vec3 last = app::armTargetFromSigningSpace(performance.hands[0].keyframes.back().pose).wristMm;
    const app::ClipTiming timing;
    const app::VerbClip clip(f.rig, f.shapes, std::move(performance), timing);
    EXPECT_LT(glm::distance(clip.postureAt(0.0).rightWrist->wristMm,
                            f.rig.restingTarget(hand::Side::Right).wristMm), 1e-3f);
    EXPECT_LT(glm::distance(clip.postureAt(timing.leadInSeconds).rightWrist->wristMm, first), 1e-3f);
    EXPECT_LT(glm::distance(clip.postureAt(clip.durationSeconds()).rightWrist->wristMm, last), 1e-3f);
}

TEST(VerbRender, OneHandedVerbsLeaveTheOtherHandAtRest) {
    const Fixture& f = fixture();
    const stimuli::VerbSources sources{&f.verbs, &f.models, kScenes / "animator"};
    const app::VerbClip clip(f.rig, f.shapes,
                             stimuli::synthesizeVerb(sources, "ASK", stimuli::VerbVersion::Point, 0.9, -0.6));
    for (double t : {0.0, 0.5, 0.8, clip.durationSeconds()}) {
        const app::SignerPosture posture = clip.postureAt(t);
        EXPECT_TRUE(posture.rightWrist.has_value());
        EXPECT_FALSE(posture.leftWrist.has_value());
    }
}
