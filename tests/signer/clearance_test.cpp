// The hands keep clear of each other and of the body (signer/clearance.hpp): the capsules
// follow the drawn hands, transitions are routed around the hands, and every frame of the
// twelve default stories in the four versions keeps the rules — the hands touch, each other
// or the body, only inside signs whose citation form touches, and a transition never takes
// them deeper than the items at its ends.
#include "signer/clearance.hpp"
#include "signer/timeline_clip.hpp"
#include "signer/clip.hpp"
#include "signer/hand_capsules.hpp"
#include "signer/signer.hpp"
#include "signer/signer_reach.hpp"
#include "stimuli/story/lexicon.hpp"
#include "stimuli/verbs/sora.hpp"
#include "stimuli/story/story.hpp"
#include "stimuli/story/timeline_builder.hpp"
#include "stimuli/verbs/verb_models.hpp"
#include "tests/test_breadth.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

using namespace signstim;

namespace {

const std::filesystem::path kScenes = std::filesystem::path(SIGNSTIM_SOURCE_DIR) / "scenes";
const std::vector<stimuli::VerbVersion> kVersions{stimuli::VerbVersion::Point, stimuli::VerbVersion::Vector,
                                                  stimuli::VerbVersion::Animator, stimuli::VerbVersion::Uninflected};

// What `signstim story` builds a story from: the default signer (scenes/avatar/signer.glb),
// the handshapes, verbs, trained models and lexicon of scenes/.
struct World {
    signer::Signer signer{kScenes};
    stimuli::HandshapeLibrary shapes = stimuli::loadHandshapes(kScenes / "handshapes.json", signer.rig().handModel());
    stimuli::VerbLibrary verbs = stimuli::loadVerbLibrary(kScenes / "verbs.json");
    stimuli::TrainedVerbModels models = stimuli::loadVerbModels(kScenes / "models" / "verb_models.json", verbs);
    stimuli::Lexicon lexicon = stimuli::loadLexicon(kScenes / "lexicon", shapes, signer.rig().handModel());
    // As `signstim story` and `study` build timelines: transitions paced by the signer's path.
    stimuli::TransitionPacer pacer = signer::transitionPacer(signer.rig());

    stimuli::TimelineSources sources() const {
        stimuli::TimelineSources s;
        s.lexicon = &lexicon;
        s.shapes = &shapes;
        s.verbs = [this](const std::string& verb, stimuli::VerbVersion version, double subject, double object, int, int) {
            return stimuli::synthesizeVerb(stimuli::VerbSources{&verbs, &models, kScenes / "animator", &shapes},
                                           verb, version, subject, object);
        };
        s.transitions = pacer;
        s.reach = signer::signerReach(signer.rig());  // issue 21: verbs within the comfortable reach
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

stimuli::TimelineKey key(double t, const glm::dvec3& positionMm, const glm::dvec3& fingers, const glm::dvec3& palm,
                         const std::string& shape) {
    stimuli::TimelineKey k;
    k.timeSeconds = t;
    k.pose.positionMm = positionMm;
    k.pose.orientation = stimuli::orientationFromFingersPalm(fingers, palm);
    k.handshape = shape;
    k.controls = world().shapes.at(shape).controls;
    return k;
}

}  // namespace

TEST(Clearance, HandCapsulesFollowThePosedSkeleton) {
    // Bent fingers and a turned hand on the right, the relaxed hand on the left: each bone's
    // capsule starts where the posed avatar has that bone's joint.
    const World& w = world();
    const signer::SignerRig& rig = w.signer.rig();
    const render::Scene& scene = w.signer.avatar();
    signer::SignerPosture posture;
    posture.rightHand = w.shapes.at("X").controls;
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

TEST(Clearance, ATouchMayDentButNotSinkIn) {
    // One sign that touches the body, one that does not, each 0.2 s at 10 fps: in the first a
    // hand may sink in up to kContactDepthToleranceMm (and no deeper), in the second only
    // kClearanceToleranceMm; the touching sign's violation says it is a contact.
    stimuli::Timeline timeline;
    timeline.spans = {{stimuli::SpanKind::Sign, 0.0, 0.2, "MY", 0, 0, 0.0, 0.2, {}},
                      {stimuli::SpanKind::Sign, 0.3, 0.5, "WHO", 0, 1, 0.3, 0.5, {}}};
    timeline.spans[0].contact.body = true;
    const auto framesWith = [](float touching, float clear) {
        std::vector<signer::ClearanceFrame> frames;
        for (int f = 0; f <= 5; ++f) {
            signer::ClearanceFrame frame;
            frame.seconds = f / 10.0;
            frame.span = f <= 2 ? 0 : f == 3 ? -1 : 1;
            frame.clearance.hands.gapMm = 100.0f;
            frame.clearance.body.gapMm = f <= 2 ? touching : f == 3 ? 50.0f : clear;
            frames.push_back(frame);
        }
        return frames;
    };
    const float depth = signer::kContactDepthToleranceMm;
    EXPECT_TRUE(signer::checkClearance(timeline, framesWith(-depth + 0.5f, 0.0f)).violations.empty());
    const signer::ClearanceSummary sunk = signer::checkClearance(timeline, framesWith(-depth - 0.5f, 0.0f));
    ASSERT_EQ(sunk.violations.size(), 1u);
    EXPECT_TRUE(sunk.violations[0].contact);
    EXPECT_FALSE(sunk.violations[0].hands);
    EXPECT_FLOAT_EQ(sunk.violations[0].allowedMm, -depth);
    EXPECT_FLOAT_EQ(sunk.bodyInContactSigns.gapMm, -depth - 0.5f);
    const signer::ClearanceSummary inBody = signer::checkClearance(timeline, framesWith(0.0f, -5.0f));
    ASSERT_EQ(inBody.violations.size(), 1u);
    EXPECT_FALSE(inBody.violations[0].contact);
    EXPECT_EQ(inBody.violations[0].before, 1);
}

TEST(Clearance, TransitionsDetourAroundTheOtherHandAndKeepTheirKeys) {
    // The right hand crosses from the signer's left to the right while the left hand holds
    // still across its straight path: the transition goes around the left hand, and the
    // keys, and the stops at them, stay as they are.
    const World& w = world();
    const signer::SignerRig& rig = w.signer.rig();
    stimuli::Timeline timeline;
    timeline.story = "crossing";
    timeline.version = "test";
    timeline.durationSeconds = 1.4;
    const glm::dvec3 forward(0, 0, 1), down(0, -1, 0), right(1, 0, 0);
    const auto rightAt = [&](double t, double x) { return key(t, {x, -40, 300}, forward, down, "B"); };
    timeline.right = {rightAt(0.0, -170), rightAt(0.4, -170), rightAt(1.0, 170), rightAt(1.4, 170)};
    for (double t : {0.0, 0.4, 1.0, 1.4}) timeline.left.push_back(key(t, {-10, -40, 330}, forward, right, "1"));
    timeline.spans = {{stimuli::SpanKind::Sign, 0.0, 0.4, "A", 0, 0, 0.0, 0.4, {}},
                      {stimuli::SpanKind::Sign, 0.4, 1.4, "B", 0, 1, 1.0, 1.4, {}}};
    timeline.gaze = {{0.0, std::nullopt}, {1.4, std::nullopt}};
    const signer::TimelineClip clip(rig, timeline);

    // The straight blend would go through the left hand.
    signer::SignerPosture straight = clip.postureAt(0.7);
    straight.rightWrist = signer::blendTargets(signer::armTargetFromSigningSpace(timeline.right[1].pose),
                                               signer::armTargetFromSigningSpace(timeline.right[2].pose),
                                               static_cast<float>(stimuli::minimumJerk(0.5)));
    std::vector<hand::Capsule> rightHand, leftHand;
    signer::handCapsules(rig, hand::Side::Right, straight.rightHand, straight.rightWrist->wristMm,
                         straight.rightWrist->handRotation, rightHand);
    signer::handCapsules(rig, hand::Side::Left, straight.leftHand, straight.leftWrist->wristMm,
                         straight.leftWrist->handRotation, leftHand);
    ASSERT_LT(signer::closestApproach(rightHand, leftHand).gapMm, -20.0f);

    // The routed one does not.
    for (const signer::ClearanceFrame& frame : signer::clearanceFrames(rig, clip))
        EXPECT_GE(frame.clearance.hands.gapMm, signer::kTransitionClearanceMm - signer::kClearanceToleranceMm)
            << "at " << frame.seconds << " s";
    const float detourMm = glm::distance(clip.postureAt(0.7).rightWrist->wristMm, straight.rightWrist->wristMm);
    EXPECT_GT(detourMm, 20.0f);
    // The keys hold, and the hand leaves and reaches them at rest: 5 ms after the key it has
    // moved only as far as the minimum-jerk profile takes it (10u³ of the way).
    for (double t : {0.4, 1.0}) {
        const glm::vec3 atKey = signer::armTargetFromSigningSpace(t < 0.5 ? timeline.right[1].pose : timeline.right[2].pose).wristMm;
        EXPECT_LT(glm::distance(clip.postureAt(t).rightWrist->wristMm, atKey), 1e-3f) << t;
        const double near = t < 0.5 ? t + 0.005 : t - 0.005;
        EXPECT_LT(glm::distance(clip.postureAt(near).rightWrist->wristMm, atKey), 0.5f) << near;
    }
}

TEST(Clearance, TransitionsClearBetweenTheirRoutingInstants) {
    // Synthetic: the right hand crosses the held left hand in a quick transition (0.1 s), so
    // fast that at the routing grid's instants (30 a second from the transition's start) the
    // straight path is clear on either side of the left hand and meets it only between them.
    // The route is judged between its instants: at 480 frames a second no frame of the
    // transition has the hands in each other.
    const World& w = world();
    const signer::SignerRig& rig = w.signer.rig();
    stimuli::Timeline timeline;
    timeline.durationSeconds = 0.7;
    const glm::dvec3 forward(0, 0, 1), down(0, -1, 0), right(1, 0, 0);
    const double leftX = -27.0, leftY = -70.0;
    const auto rightAt = [&](double t, double x) { return key(t, {x, -40, 300}, forward, down, "B"); };
    timeline.right = {rightAt(0.0, -200), rightAt(0.3, -200), rightAt(0.4, 200), rightAt(0.7, 200)};
    for (double t : {0.0, 0.3, 0.4, 0.7}) timeline.left.push_back(key(t, {leftX, leftY, 330}, forward, right, "1"));
    timeline.spans = {{stimuli::SpanKind::Sign, 0.0, 0.3, "A", 0, 0, 0.0, 0.3, {}},
                      {stimuli::SpanKind::Sign, 0.3, 0.7, "B", 0, 1, 0.4, 0.7, {}}};
    timeline.gaze = {{0.0, std::nullopt}, {0.7, std::nullopt}};
    const signer::TimelineClip clip(rig, timeline);

    // The straight blend at instant t: clear at the grid's instants, through the left hand
    // between them.
    const auto straightGap = [&](double t) {
        signer::SignerPosture p = clip.postureAt(t);
        p.rightWrist = signer::blendTargets(signer::armTargetFromSigningSpace(timeline.right[1].pose),
                                            signer::armTargetFromSigningSpace(timeline.right[2].pose),
                                            static_cast<float>(stimuli::minimumJerk((t - 0.3) / 0.1)));
        std::vector<hand::Capsule> rightHand, leftHand;
        signer::handCapsules(rig, hand::Side::Right, p.rightHand, p.rightWrist->wristMm, p.rightWrist->handRotation, rightHand);
        signer::handCapsules(rig, hand::Side::Left, p.leftHand, p.leftWrist->wristMm, p.leftWrist->handRotation, leftHand);
        return signer::closestApproach(rightHand, leftHand).gapMm;
    };
    float deepestBetween = std::numeric_limits<float>::infinity();
    for (int f = 1; f <= 3; ++f) {
        const double t = 0.3 + f / signer::kRoutingFramesPerSecond;
        ASSERT_GT(straightGap(t), signer::kTransitionClearanceMm) << "grid instant " << t;
        for (int k = 1; k < 16; ++k) deepestBetween = std::min(deepestBetween, straightGap(t - k / (16.0 * signer::kRoutingFramesPerSecond)));
    }
    ASSERT_LT(deepestBetween, -10.0f);

    int judged = 0;
    for (const signer::ClearanceFrame& frame : signer::clearanceFrames(rig, clip, 480.0)) {
        if (frame.span >= 0) continue;
        ++judged;
        EXPECT_GE(frame.clearance.hands.gapMm, signer::kTransitionClearanceMm - signer::kClearanceToleranceMm)
            << "at " << frame.seconds << " s";
    }
    EXPECT_GT(judged, 40);
}

TEST(Clearance, TransitionsAreJudgedAtTheItemsOwnKeysNotTheNearestFrame) {
    // An item's keys end between two 30 fps frames (0.41 s): the check poses the signer there
    // too, and a transition that leaves a touch (at the key, -15 mm) is allowed that deep,
    // though the frame before it (0.4 s, mid-lift) was clear.
    const World& w = world();
    stimuli::Timeline timeline;
    timeline.durationSeconds = 1.0;
    const glm::dvec3 forward(0, 0, 1), down(0, -1, 0);
    for (double t : {0.0, 0.41, 1.0}) {
        timeline.right.push_back(key(t, {100, -40, 300}, forward, down, "B"));
        timeline.left.push_back(key(t, {-100, -40, 300}, forward, down, "B"));
    }
    timeline.spans = {{stimuli::SpanKind::Sign, 0.0, 0.41, "A", 0, 0, 0.0, 0.41, {}},
                      {stimuli::SpanKind::Sign, 0.41, 1.0, "B", 0, 1, 0.9, 1.0, {}}};
    timeline.gaze = {{0.0, std::nullopt}, {1.0, std::nullopt}};
    const signer::TimelineClip clip(w.signer.rig(), timeline);
    const std::vector<signer::ClearanceFrame> frames = signer::clearanceFrames(w.signer.rig(), clip);
    bool atKey = false;
    for (const signer::ClearanceFrame& f : frames) atKey = atKey || (std::abs(f.seconds - 0.41) < 1e-12 && f.span == 0);
    EXPECT_TRUE(atKey);
    EXPECT_TRUE(std::is_sorted(frames.begin(), frames.end(),
                               [](const signer::ClearanceFrame& a, const signer::ClearanceFrame& b) { return a.seconds < b.seconds; }));
    // The rule on such frames: clear at 0.4 s, touching at the key, the transition no deeper.
    std::vector<signer::ClearanceFrame> judged(4);
    const double times[] = {0.4, 0.41, 0.5, 0.9};
    const int spans[] = {0, 0, -1, 1};
    const float gaps[] = {20.0f, -15.0f, -16.0f, 40.0f};
    for (std::size_t i = 0; i < judged.size(); ++i) {
        judged[i].seconds = times[i];
        judged[i].span = spans[i];
        judged[i].clearance.hands.gapMm = gaps[i];
        judged[i].clearance.body.gapMm = 50.0f;
    }
    timeline.spans[0].contact.hands = true;
    const signer::ClearanceSummary leaving = signer::checkClearance(timeline, judged);
    for (const signer::ClearanceViolation& v : leaving.violations) EXPECT_FALSE(v.transition) << v.gapMm;
    // Without the key's frame the same transition would be judged against the clear frame.
    judged.erase(judged.begin() + 1);
    const signer::ClearanceSummary nearest = signer::checkClearance(timeline, judged);
    ASSERT_FALSE(nearest.violations.empty());
    EXPECT_TRUE(nearest.violations[0].transition);
}

TEST(Clearance, APacedTransitionIntoATouchIsRememberedOnlyForTheSameHandsInThatTouch) {
    // The rig remembers the pacer's answers (SignerRig::pacerMemo). A touch settles on the hands
    // as their controls shape them, so a query that differs only in the controls of the touch
    // it goes into must be paced afresh, never answered from the memory of the other.
    const World& w = world();
    std::vector<stimuli::TransitionQuery> intoTouch;
    stimuli::TimelineSources sources = w.sources();
    sources.transitions = [&](const stimuli::TransitionQuery& q) {
        if (!q.intoTouch[0].empty() || !q.intoTouch[1].empty()) intoTouch.push_back(q);
        return w.pacer(q);
    };
    // Stories whose touches go in with the arms in different poses (EMAIL's touch, the one that
    // differed in stories 01, 03 and 06, is gone: its index no longer touches the C).
    for (const char* file : {"story-01.json", "story-03.json", "story-06.json", "story-08.json", "story-11.json"})
        stimuli::buildTimeline(w.story(kScenes / "stories" / file), stimuli::VerbVersion::Point, sources);
    ASSERT_FALSE(intoTouch.empty());
    int differing = 0;
    for (stimuli::TransitionQuery q : intoTouch) {
        const double remembered = w.pacer(q);  // now in the memory
        for (std::vector<stimuli::TimelineKey>& keys : q.intoTouch)
            for (stimuli::TimelineKey& k : keys) k.controls = w.shapes.at("5").controls;
        const double afresh = signer::pacedTransitionSeconds(w.signer.rig(), q);
        EXPECT_EQ(w.pacer(q), afresh);
        differing += afresh != remembered;
    }
    // The property is only tested where the controls change the answer.
    EXPECT_GT(differing, 0) << intoTouch.size() << " queries into a touch";
}

TEST(Clearance, RoutedFramesOutsideTheVerbSlotsAreTheSameInEveryVersion) {
    // A detour depends only on the keys at its ends and on where the arms are, and the arms
    // are solved afresh after every verb slot: so the frames a study renders once stay shared.
    const World& w = world();
    const stimuli::Story story = w.story(kScenes / "stories" / "story-01.json");
    std::vector<signer::TimelineClip> clips;
    for (stimuli::VerbVersion v : kVersions)
        clips.emplace_back(w.signer.rig(), stimuli::buildTimeline(story, v, w.sources()));
    const stimuli::Timeline& first = clips.front().timeline();
    int compared = 0;
    for (int frame = 0; frame / 30.0 <= first.durationSeconds; ++frame) {
        const double t = frame / 30.0;
        bool inSlot = false;
        for (const stimuli::TimelineSpan& span : first.spans)
            inSlot = inSlot || (span.kind == stimuli::SpanKind::Verb && t > span.startSeconds - 1e-9 && t < span.endSeconds + 1e-9);
        if (inSlot) continue;
        const signer::SignerPosture a = clips.front().postureAt(t);
        for (const signer::TimelineClip& other : clips) {
            const signer::SignerPosture b = other.postureAt(t);
            EXPECT_EQ(a.rightWrist->wristMm, b.rightWrist->wristMm) << other.timeline().version << " at " << t;
            EXPECT_EQ(a.leftWrist->wristMm, b.leftWrist->wristMm) << other.timeline().version << " at " << t;
            EXPECT_EQ(a.rightWrist->handRotation, b.rightWrist->handRotation) << other.timeline().version << " at " << t;
            EXPECT_EQ(a.leftWrist->handRotation, b.leftWrist->handRotation) << other.timeline().version << " at " << t;
        }
        ++compared;
    }
    EXPECT_GT(compared, 300);
}

// Each default story in the four versions, every frame at 30 fps (and each item's first and
// last key) as `signstim story` renders it; with `everyRate`, every frame at each rate a study
// may render (issue 21: 15, 24, 25, 30, 30000/1001 and 60 fps; 60 holds 15's and 30's).
class StoryClearance : public testing::TestWithParam<int> {
protected:
    struct Checked {
        stimuli::Timeline timeline;
        signer::ClearanceSummary summary;
    };
    static std::vector<signer::ClearanceFrame> frames(const signer::TimelineClip& clip, bool everyRate) {
        const signer::SignerRig& rig = world().signer.rig();
        if (!everyRate) return signer::clearanceFrames(rig, clip);
        std::vector<signer::ClearanceFrame> all;
        for (const double fps : {60.0, 24.0, 25.0, 30000.0 / 1001.0}) {
            const std::vector<signer::ClearanceFrame> at = signer::clearanceFrames(rig, clip, fps);
            all.insert(all.end(), at.begin(), at.end());
        }
        std::stable_sort(all.begin(), all.end(),
                         [](const signer::ClearanceFrame& a, const signer::ClearanceFrame& b) { return a.seconds < b.seconds; });
        all.erase(std::unique(all.begin(), all.end(),
                              [](const signer::ClearanceFrame& a, const signer::ClearanceFrame& b) {
                                  return b.seconds - a.seconds < 1e-9;
                              }),
                  all.end());
        return all;
    }
    // Under SIGNSTIM_TEST_BREADTH=sanitizer the motion tests' sample of three stories
    // (test::storySwept, tests/test_breadth.hpp), the same paths of the clearance check; the
    // other nine are skipped there (their CTest entries pass, saying so); the gcc suite checks
    // all 12.
    static bool skippedUnderSanitizer(int story) {
        test::noteSanitizerBreadth("StoryClearance checks 3 of the 12 default stories (story-01, 06, 10)");
        char stem[16];
        std::snprintf(stem, sizeof stem, "story-%02d", story);
        return !test::storySwept(stem);
    }
    // Each (story, rate) checked once per process: the three tests of a story run in one
    // (tests/signer/CMakeLists.txt, ONE_PROCESS StoryClearance.storyNN), and two of them ask
    // for the same 30 fps check, which built the story's four timelines a second time.
    static const std::vector<Checked>& check(int story, bool everyRate = false) {
        static std::map<std::pair<int, bool>, std::vector<Checked>> memo;
        const auto known = memo.find({story, everyRate});
        if (known != memo.end()) return known->second;
        return memo.emplace(std::make_pair(story, everyRate), checkAfresh(story, everyRate)).first->second;
    }
    static std::vector<Checked> checkAfresh(int story, bool everyRate) {
        const World& w = world();
        char name[32];
        std::snprintf(name, sizeof name, "story-%02d.json", story);
        const stimuli::Story parsed = w.story(kScenes / "stories" / name);
        std::vector<Checked> out;
        for (stimuli::VerbVersion v : kVersions) {
            // As `story` and `study` tell it: the story's timing (by default the natural preset).
            const signer::TimelineClip clip(
                w.signer.rig(), stimuli::buildTimeline(parsed, v, w.sources(), stimuli::timelineOptionsFor(parsed.timing, 1.0)));
            const signer::ClearanceSummary summary = signer::checkClearance(clip.timeline(), frames(clip, everyRate));
            // The closest approaches, for the record (ctest -V).
            const auto show = [&](const signer::ClearanceExtreme& e) {
                char text[160];
                std::snprintf(text, sizeof text, "%6.1f mm (%s, %.2f s)", e.gapMm,
                              signer::describeClearancePlace(clip.timeline(), e.before, e.after).c_str(), e.seconds);
                return std::string(text);
            };
            std::printf("%s %-11s hands: at transitions %s, in signs %s, touching %s; hand-body: %s, touching %s\n",
                        name, stimuli::toString(v).c_str(), show(summary.handsAtTransitions).c_str(),
                        show(summary.handsInSigns).c_str(), show(summary.handsInContactSigns).c_str(),
                        show(summary.body).c_str(), show(summary.bodyInContactSigns).c_str());
            out.push_back({clip.timeline(), summary});
        }
        return out;
    }
    // The violations that `select` picks, one line each.
    template <typename Select>
    static std::string violations(const std::vector<Checked>& checked, Select select) {
        std::string text;
        for (const Checked& c : checked)
            for (const signer::ClearanceViolation& v : c.summary.violations) {
                if (!select(v)) continue;
                char line[200];
                std::snprintf(line, sizeof line, "\n  %s %s: %s %.1f mm apart at %.2f s (at least %.1f allowed)",
                              c.timeline.version.c_str(), signer::describeClearancePlace(c.timeline, v.before, v.after).c_str(),
                              v.hands ? "hands" : "hand and body", v.gapMm, v.seconds, v.allowedMm);
                text += line;
            }
        return text;
    }
};

// Whether the arm solver's pose jumps within a millisecond of `seconds`: a hand's capsules
// move farther than 20 m/s (8 times SPEC §6.2's peak) would take them between two instants
// 1/1920 s apart — the solver switching between two solutions of nearly the same target. No
// route goes around such a jump; it is the solver's to remove (issue 21 §1: an elbow chosen by
// a rule of the target; the disabled MotionLimits tests).
namespace {
bool armSolutionJumpsNear(const signer::TimelineClip& clip, double seconds) {
    const signer::SignerRig& rig = world().signer.rig();
    const auto capsulesAt = [&](double t) {
        const signer::SignerPosture posture = clip.postureAt(t);
        signer::PoseReport report;
        report.right = rig.solveArm(hand::Side::Right, posture);
        report.left = rig.solveArm(hand::Side::Left, posture);
        return signer::signerCapsules(rig, posture, report);
    };
    constexpr double kStep = 1.0 / 1920.0;
    signer::SignerCapsules before = capsulesAt(seconds - 2 * kStep);
    for (int k = -1; k <= 2; ++k) {
        const signer::SignerCapsules after = capsulesAt(seconds + k * kStep);
        for (const bool right : {true, false}) {
            const std::vector<hand::Capsule>&a = right ? before.right : before.left, &b = right ? after.right : after.left;
            for (std::size_t i = 0; i < a.size(); ++i)
                if (std::max(glm::distance(a[i].start, b[i].start), glm::distance(a[i].end, b[i].end)) > 20000.0 * kStep)
                    return true;
        }
        before = after;
    }
    return false;
}
}  // namespace

TEST_P(StoryClearance, HandsNeverInterpenetrateAtTransitions) {
    if (skippedUnderSanitizer(GetParam())) GTEST_SKIP() << "not in the sanitizer suite's sample of stories";
    // Neither each other nor the body, deeper than the items at the transition's ends have
    // them (the issue: "no interpenetration of the hands at transitions"), at every frame of
    // every output rate: a transition is routed on instants of its own time and judged between
    // them (signer/transition_route.cpp), so no rate's frames find it in the body. Not counted
    // (but printed): a frame where the arm solver's pose jumps (armSolutionJumpsNear).
    const std::vector<Checked> checked = check(GetParam(), true);
    std::string jumps;
    const std::string found = violations(checked, [&](const signer::ClearanceViolation& v) {
        if (!v.transition) return false;
        for (const Checked& c : checked)
            for (const signer::ClearanceViolation& w : c.summary.violations)
                if (&w == &v && armSolutionJumpsNear(signer::TimelineClip(world().signer.rig(), c.timeline), v.seconds)) {
                    char line[200];
                    std::snprintf(line, sizeof line, "%s %s: %.1f mm at %.4f s, where the arm solver's pose jumps\n",
                                  c.timeline.version.c_str(), signer::describeClearancePlace(c.timeline, v.before, v.after).c_str(),
                                  v.gapMm, v.seconds);
                    jumps += line;
                    return false;
                }
        return true;
    });
    if (!jumps.empty()) std::printf("not counted:\n%s", jumps.c_str());
    EXPECT_TRUE(found.empty()) << found;
}

TEST_P(StoryClearance, HandsTouchOnlyInSignsThatTouch) {
    if (skippedUnderSanitizer(GetParam())) GTEST_SKIP() << "not in the sanitizer suite's sample of stories";
    // Inside an item's own keys the hands touch each other, or a hand the body, only where
    // the lexicon or verbs.json says the citation form does ("contact").
    const std::string found =
        violations(check(GetParam()), [](const signer::ClearanceViolation& v) { return !v.transition && !v.contact; });
    EXPECT_TRUE(found.empty()) << found;
}

// Signs whose touch still goes deeper than kContactDepthToleranceMm, each held at its depth
// (mm, to 0.5 mm); a sign not listed, or one going deeper, fails; remove a line when its sign
// is fixed. Touches settle on the surface (signer/timeline_clip.hpp, settleTouches), which
// took the hand-to-hand signs from 12-23 mm deep to about kTouchDepthMm. None is left: EMAIL
// (-21 mm, its bent-B hand through the left C's cavity) left on 2026-11-27, when it became
// ASL-LEX 2.0's 1 hand whose index slides into the C without contact (scenes/verbs.json; the
// strict clearance rules hold it now); LOSE (now -1.8 mm) and BROTHER (the body -6.3 mm) on
// 2026-11-26.
struct KnownTooDeep {
    const char* sign;
    bool hands;
    float deepestMm;
};
const std::vector<KnownTooDeep> kKnownTooDeep{};  // none now; add {sign, hands, deepestMm} with a reason

TEST_P(StoryClearance, ContactSignsTouchWithoutSinkingIn) {
    if (skippedUnderSanitizer(GetParam())) GTEST_SKIP() << "not in the sanitizer suite's sample of stories";
    // Where a sign touches on purpose, the hand comes to the surface, of the body or of the
    // other hand, and goes no deeper than kContactDepthToleranceMm into it (but for the signs
    // of kKnownTooDeep, no deeper than they went).
    const std::vector<Checked> checked = check(GetParam());
    std::string found;
    for (const Checked& c : checked)
        for (const signer::ClearanceViolation& v : c.summary.violations) {
            if (!v.contact) continue;
            const std::string& sign = c.timeline.spans[static_cast<std::size_t>(v.after)].label;
            bool known = false;
            for (const KnownTooDeep& k : kKnownTooDeep)
                known = known || (sign == k.sign && v.hands == k.hands && v.gapMm >= k.deepestMm - 0.5f);
            if (known) continue;
            char line[200];
            std::snprintf(line, sizeof line, "\n  %s %s: %s %.1f mm apart at %.2f s (at least %.1f allowed)",
                          c.timeline.version.c_str(), signer::describeClearancePlace(c.timeline, v.before, v.after).c_str(),
                          v.hands ? "hands" : "hand and body", v.gapMm, v.seconds, v.allowedMm);
            found += line;
        }
    EXPECT_TRUE(found.empty()) << found;
}

INSTANTIATE_TEST_SUITE_P(DefaultStories, StoryClearance, testing::Range(1, 13),
                         [](const testing::TestParamInfo<int>& info) {
                             char name[16];
                             std::snprintf(name, sizeof name, "story%02d", info.param);
                             return std::string(name);
                         });
