// Touches come to the surface (signer/timeline_clip.hpp, settleTouches; issue 22: contact as
// an event the motion reaches; issue 21: the hands never pass through each other): inside an
// item that touches with both hands the hands meet at kTouchDepthMm, not deeper, and still
// meet; a held base hand stays where its keys put it; a touch that reaches the surface on its
// own is left alone; and every sign of the default lexicon that touches with both hands,
// signed alone in citation form, comes to the surface and reaches it.
#include "signer/clearance.hpp"
#include "signer/clip.hpp"
#include "signer/hand_capsules.hpp"
#include "signer/signer.hpp"
#include "signer/timeline_clip.hpp"
#include "stimuli/story/lexicon.hpp"
#include "stimuli/story/story.hpp"
#include "stimuli/story/story_world.hpp"
#include "stimuli/story/timeline_builder.hpp"
#include "stimuli/verbs/sora.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <vector>

using namespace signstim;

namespace {

const std::filesystem::path kScenes = std::filesystem::path(SIGNSTIM_SOURCE_DIR) / "scenes";

// What `signstim sign` signs from: the default signer, and the handshapes, verbs, models and
// lexicon of scenes/ as every command loads them (stimuli::StoryWorld).
struct World {
    signer::Signer signer{kScenes};
    stimuli::StoryWorld story{kScenes.string(), ""};
};
const World& world() {
    static const World w;
    return w;
}

stimuli::TimelineKey key(double t, const glm::dvec3& positionMm, const glm::dvec3& fingers, const glm::dvec3& palm) {
    stimuli::TimelineKey k;
    k.timeSeconds = t;
    k.pose.positionMm = positionMm;
    k.pose.orientation = stimuli::orientationFromFingersPalm(fingers, palm);
    k.handshape = "B";
    k.controls = world().story.shapes.at("B").controls;
    return k;
}

// Synthetic: the B hands facing each other, fingers up, palm frames `apartMm` apart across the
// midline (a clap); the right hand slides 30 mm up along the left's palm in a sign of 0.5 s,
// the left hand holds still.
stimuli::Timeline palmToPalm(double apartMm, bool touches) {
    stimuli::Timeline timeline;
    timeline.durationSeconds = 0.5;
    const glm::dvec3 up(0, 1, 0), toLeft(-1, 0, 0), toRight(1, 0, 0);
    const double x = 0.5 * apartMm;
    timeline.right = {key(0.0, {x, -40, 300}, up, toLeft), key(0.5, {x, -10, 300}, up, toLeft)};
    timeline.left = {key(0.0, {-x, -40, 300}, up, toRight), key(0.5, {-x, -40, 300}, up, toRight)};
    timeline.spans = {{stimuli::SpanKind::Sign, 0.0, 0.5, "CLAP", 0, 0, 0.0, 0.5, {}}};
    timeline.spans[0].contact.hands = touches;
    timeline.gaze = {{0.0, std::nullopt}, {0.5, std::nullopt}};
    return timeline;
}

// The hands' gap as the keys alone put them (no settling), at key k of palmToPalm.
float keyedGap(const stimuli::Timeline& timeline, std::size_t k) {
    const signer::SignerRig& rig = world().signer.rig();
    std::vector<hand::Capsule> right, left;
    const hand::ArmTarget r = signer::armTargetFromSigningSpace(timeline.right[k].pose);
    const hand::ArmTarget l = signer::armTargetFromSigningSpace(timeline.left[k].pose);
    signer::handCapsules(rig, hand::Side::Right, timeline.right[k].controls, r.wristMm, r.handRotation, right);
    signer::handCapsules(rig, hand::Side::Left, timeline.left[k].controls, l.wristMm, l.handRotation, left);
    return signer::closestApproach(right, left).gapMm;
}

// Where the keys alone put the right wrist at t (body frame).
glm::vec3 keyedRightWrist(const stimuli::Timeline& timeline, double t) {
    const stimuli::TimelineSample s = stimuli::sampleTrack(timeline.right, t);
    return signer::blendTargets(signer::armTargetFromSigningSpace(s.from->pose), signer::armTargetFromSigningSpace(s.to->pose),
                                static_cast<float>(s.blend))
        .wristMm;
}

// Whether a sign touches the other arm (a contact event at an `arm:` place, docs/lexicon.md:
// the forearm in SON, DAUGHTER, BABY and TABLE): its touch is measured on the arm too.
bool touchesTheArm(const stimuli::LexiconSign& sign) {
    for (const stimuli::ContactEvent& e : sign.contactEvents)
        if (e.at.rfind("arm:", 0) == 0) return true;
    return false;
}

// The left arm as posed, as capsules: the default avatar's sleeve (signer/avatar_builder.cpp,
// radiusAt: 38 mm at the elbow, 40 mm at 30 % of the forearm, 29 mm at the wrist), its upper
// arm near the elbow and its forearm, each no thicker than the sleeve there (a touch measured
// on them is not deeper than it is).
void leftArmCapsules(const hand::ArmPose& arm, std::vector<hand::Capsule>& out) {
    const glm::vec3 thick = arm.elbowMm + 0.3f * (arm.wristMm - arm.elbowMm);
    out.push_back({arm.elbowMm + 0.3f * (arm.shoulderMm - arm.elbowMm), arm.elbowMm, 38.0f});
    out.push_back({arm.elbowMm, thick, 38.0f});
    out.push_back({thick, arm.wristMm, 29.0f});
}

// A sign whose right arm touches with its forearm (a contact's `by` a point along the forearm:
// BABY, SON, DAUGHTER rest the right forearm on the left).
bool touchesWithTheForearm(const stimuli::LexiconSign& sign) {
    for (const stimuli::ContactEvent& e : sign.contactEvents)
        if (e.by == "forearm" || e.by == "forearm-front" || e.by == "elbow" || e.by == "elbow-front") return true;
    return false;
}

// The right forearm as posed, as capsules: the same sleeve as the left's (leftArmCapsules).
void rightForearmCapsules(const hand::ArmPose& arm, std::vector<hand::Capsule>& out) {
    const glm::vec3 thick = arm.elbowMm + 0.3f * (arm.wristMm - arm.elbowMm);
    out.push_back({arm.elbowMm, thick, 38.0f});
    out.push_back({thick, arm.wristMm, 29.0f});
}

// The closest approach of the right hand (and its forearm, when `forearm`: the sign touches
// with it) to the left hand and arm inside the sign's items that touch with both hands, every
// frame of `frames` (mm).
float handToArmGap(const signer::TimelineClip& clip, const std::vector<signer::ClearanceFrame>& frames, bool forearm) {
    const signer::ClipPoser poser(world().signer.rig(), clip);
    float gap = std::numeric_limits<float>::infinity();
    for (const signer::ClearanceFrame& f : frames) {
        if (f.span < 0 || !clip.timeline().spans[static_cast<std::size_t>(f.span)].contact.hands) continue;
        signer::SignerPosture posture;
        signer::PoseReport report;
        poser.next(f.seconds, &posture, &report);
        signer::SignerCapsules capsules = signer::signerCapsules(world().signer.rig(), posture, report);
        leftArmCapsules(report.left, capsules.left);
        if (forearm) rightForearmCapsules(report.right, capsules.right);
        gap = std::min(gap, signer::closestApproach(capsules.right, capsules.left).gapMm);
    }
    return gap;
}

}  // namespace

TEST(Touch, HandsThatTouchMeetAtTheSurfaceAndTheBaseHandHolds) {
    // The keys put the hands 15-20 mm into each other (synthetic data): settled, they meet at
    // every frame, kTouchDepthMm deep or within kClearanceToleranceMm of it (the offset grows
    // no faster than kTouchRateMmPerSecond); only the moving right hand is moved, away from
    // the left.
    const stimuli::Timeline timeline = palmToPalm(40.0, true);
    ASSERT_LT(keyedGap(timeline, 0), -10.0f);
    ASSERT_LT(keyedGap(timeline, 1), -10.0f);
    const signer::TimelineClip clip(world().signer.rig(), timeline);
    const glm::vec3 leftKey = signer::armTargetFromSigningSpace(timeline.left[0].pose).wristMm;
    for (const signer::ClearanceFrame& f : signer::clearanceFrames(world().signer.rig(), clip)) {
        EXPECT_GE(f.clearance.hands.gapMm, -signer::kTouchDepthMm - 0.5f) << "at " << f.seconds << " s";
        EXPECT_LE(f.clearance.hands.gapMm, signer::kClearanceToleranceMm) << "at " << f.seconds << " s";
        const signer::SignerPosture p = clip.postureAt(f.seconds);
        EXPECT_LT(glm::distance(p.leftWrist->wristMm, leftKey), 1e-3f) << "at " << f.seconds << " s";
        const glm::vec3 keyed = keyedRightWrist(timeline, f.seconds);
        EXPECT_GT(glm::distance(p.rightWrist->wristMm, leftKey), glm::distance(keyed, leftKey) + 5.0f) << "at " << f.seconds << " s";
    }
}

TEST(Touch, ClaspingHandsYieldTheirDigitsAndKeepTheirPlace) {
    // HUSBAND's clasp (its last keys: the right C palm down on the left C palm up, as the
    // lexicon compiles them) held 0.5 s. The two C hands' thumbs and curled fingers cross each
    // other's, 19 mm deep. Settled by the wrists (a touch that is no clasp), the right hand is
    // held off by more than 30 mm and the palms no longer meet; as a clasp (SignContact::clasp)
    // the digits yield, by at most kMostClaspYield of their way to straight, the touch comes to
    // kTouchDepthMm, and the wrists stay where the keys put them.
    const World& w = world();
    const stimuli::LexiconSign* husband = w.story.lexicon.find("HUSBAND");
    ASSERT_NE(husband, nullptr);
    ASSERT_EQ(husband->keyframes.size(), 2u);
    ASSERT_TRUE(husband->contact.clasp);
    const auto held = [&](std::size_t h, double t) {
        const stimuli::VerbKeyframe& v = husband->keyframes[h].back();
        stimuli::TimelineKey k;
        k.timeSeconds = t;
        k.pose = v.pose;
        k.handshape = v.handshape;
        k.controls = w.story.shapes.at(v.handshape).controls;
        return k;
    };
    for (const bool clasp : {false, true}) {
        stimuli::Timeline timeline;
        timeline.durationSeconds = 0.5;
        timeline.right = {held(0, 0.0), held(0, 0.5)};
        timeline.left = {held(1, 0.0), held(1, 0.5)};
        timeline.spans = {{stimuli::SpanKind::Sign, 0.0, 0.5, "HUSBAND", 0, 0, 0.0, 0.5, {true, false, clasp}}};
        timeline.gaze = {{0.0, std::nullopt}, {0.5, std::nullopt}};
        ASSERT_LT(keyedGap(timeline, 0), -10.0f);
        const signer::TimelineClip clip(w.signer.rig(), timeline);
        for (const signer::ClearanceFrame& f : signer::clearanceFrames(w.signer.rig(), clip)) {
            const signer::SignerPosture p = clip.postureAt(f.seconds);
            const float moved = glm::distance(p.rightWrist->wristMm, keyedRightWrist(timeline, f.seconds));
            if (!clasp) {
                EXPECT_GT(moved, 30.0f) << "at " << f.seconds << " s";
                continue;
            }
            EXPECT_LT(moved, 1e-3f) << "at " << f.seconds << " s";
            EXPECT_GE(f.clearance.hands.gapMm, -signer::kTouchDepthMm - 0.5f) << "at " << f.seconds << " s";
            EXPECT_LE(f.clearance.hands.gapMm, signer::kClearanceToleranceMm) << "at " << f.seconds << " s";
            for (const auto& [posed, keyed] : {std::pair{p.rightHand, timeline.right[0].controls}, std::pair{p.leftHand, timeline.left[0].controls}}) {
                const float bend = keyed.fingers[1].bend;
                EXPECT_LT(posed.fingers[1].bend, bend - 0.01f) << "at " << f.seconds << " s";
                EXPECT_GE(posed.fingers[1].bend, (1.0f - signer::kMostClaspYield) * bend - 1e-4f) << "at " << f.seconds << " s";
            }
        }
    }
}

TEST(Touch, ATouchAtTheSurfaceAndASignThatDoesNotTouchAreLeftAlone) {
    // The hands as far apart as makes them just touch (within kTouchDepthMm), and deep in each
    // other in a sign that does not say it touches: the wrists go where the keys say.
    double touching = 40.0;
    while (touching < 150.0 && keyedGap(palmToPalm(touching, true), 0) < -1.0f) touching += 0.5;
    for (const auto& [apart, touches] : {std::pair{touching, true}, std::pair{40.0, false}}) {
        const stimuli::Timeline timeline = palmToPalm(apart, touches);
        ASSERT_GT(keyedGap(timeline, 0), touches ? -1.0f : -50.0f);
        ASSERT_LT(keyedGap(timeline, 0), touches ? 1.0f : -10.0f);
        const signer::TimelineClip clip(world().signer.rig(), timeline);
        for (double t : {0.0, 0.25, 0.5})
            EXPECT_LT(glm::distance(clip.postureAt(t).rightWrist->wristMm, keyedRightWrist(timeline, t)), 1e-3f)
                << apart << " mm apart at " << t << " s";
    }
}

// Signs of the default lexicon that do not yet keep the rule alone in citation form, each held
// at what it does now (mm, to 0.5 mm); remove a line when the sign's data is fixed (LOSE, MORE,
// NICE, MORNING, WHEN, AGAIN, MARRY and TABLE were, 2026-11-26: MORE's flat-O fingertips now
// lead and meet; MARRY's right palm lands over the left fingers, its curled fingers past them;
// TABLE's left forearm rises toward the wrist as the posed one does).
struct KnownSign {
    const char* sign;
    float gapMm;
};
// None now: HOW left on 2026-11-27 (-21.5 mm -> within kContactDepthToleranceMm): its contact
// place, hand:finger-back, lay inside the C's curve (the chord from the knuckle to the middle
// fingertip), and the hands put there passed through each other's curled fingers; the place is
// now on the finger's back surface, and the bent fingers' backs meet on the midline.
const KnownSign kSinksIn[] = {{"", 0.0f}};
// SON, DAUGHTER and BABY left this list on 2026-11-26 (-33.2 mm -> 0.4-0.9 mm): the right forearm
// lay across the left at its crook with both elbows drawn in before the body, where the
// sleeves' capsules overlapped; now each elbow hangs by its own side (as the rig's arm solver
// puts it) and the right forearm lies across the middle of the left (arm:forearm-front), the
// hands' directions those of the forearms as posed.
// Signs that say they touch with both hands and never come within 10 mm (issue 22: contact is
// an event the motion reaches), measured on the left arm (touchesTheArm). None now: SON,
// DAUGHTER and BABY reached the arm once the base hand pointed along the forearm the rig poses
// (the notation's arm is a straight forearm along the base hand's axis).
const KnownSign kNeverReach[] = {{"", 0.0f}};

TEST(Touch, EveryLexiconSignThatTouchesWithBothHandsComesToTheSurfaceAlone) {
    // Each sign alone in citation form, as `signstim sign GLOSS` signs it (rests of 0.3 s,
    // rate 1), every frame at 30 fps and at its keys' ends: the touch goes no deeper than
    // kContactDepthToleranceMm, and reaches the other hand within 10 mm (issue 22) — or the
    // other arm, for a sign whose contact is on the arm.
    const World& w = world();
    const signer::SignerRig& rig = w.signer.rig();
    std::string deep, apart;
    int checked = 0;
    for (const stimuli::LexiconSign& sign : w.story.lexicon.signs) {
        if (!sign.contact.hands) continue;
        stimuli::Story story;
        story.file = "sign " + sign.gloss;
        stimuli::StorySentence sentence;
        stimuli::StoryItem item;
        item.kind = stimuli::StoryItemKind::Sign;
        item.gloss = sign.gloss;
        sentence.gloss = sign.gloss;
        sentence.items.push_back(item);
        story.sentences.push_back(sentence);
        stimuli::TimelineOptions timing;
        timing.signScale = 1.0;
        timing.restSeconds = 0.3;
        const signer::TimelineClip clip(rig, stimuli::buildTimeline(story, stimuli::VerbVersion::Point, w.story.sources(story), timing));
        const std::vector<signer::ClearanceFrame> frames = signer::clearanceFrames(rig, clip);
        const float gap = touchesTheArm(sign) ? handToArmGap(clip, frames, touchesWithTheForearm(sign))
                                              : signer::checkClearance(clip.timeline(), frames).handsInContactSigns.gapMm;
        ++checked;
        const auto known = [&](const auto& list) {
            for (const KnownSign& k : list)
                if (sign.gloss == k.sign) return std::optional<float>(k.gapMm);
            return std::optional<float>();
        };
        char line[120];
        std::snprintf(line, sizeof line, "\n  %s: %.1f mm", sign.gloss.c_str(), gap);
        const std::optional<float> sinks = known(kSinksIn), reaches = known(kNeverReach);
        if (gap < (sinks ? *sinks : -signer::kContactDepthToleranceMm)) deep += line;
        if (gap > (reaches ? *reaches : 10.0f)) apart += line;
    }
    EXPECT_GT(checked, 30);
    EXPECT_TRUE(deep.empty()) << "deeper than " << signer::kContactDepthToleranceMm << " mm into the other hand:" << deep;
    EXPECT_TRUE(apart.empty()) << "never within 10 mm of the other hand:" << apart;
}
