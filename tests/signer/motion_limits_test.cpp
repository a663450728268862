// The signer's motion is a body's (issue 21): on every frame (60 fps) of every default story in
// every version, and on a grid of verb instances, the elbows stay below the shoulders and swing
// smoothly, the wrists and forearms stay within their clinical ranges of motion, the wrists no
// faster than SPEC §6.2 allows, and gaze is eyes and head together within their ranges and the
// head's speed. And the pose is a function of the timeline and the instant alone: the same at
// every frame rate, and the same in every version outside the verbs.
#include "motion_sampling.hpp"
#include "tests/signer/hands_in_frame.hpp"
#include "tests/test_breadth.hpp"

#include "signer/clearance.hpp"
#include "signer/clip.hpp"
#include "signer/hand_capsules.hpp"
#include "signer/screen_regions.hpp"
#include "signer/signer.hpp"
#include "signer/signer_reach.hpp"
#include "signer/timeline_clip.hpp"
#include "signer/verb_clip.hpp"
#include "stimuli/story/story_world.hpp"
#include "stimuli/story/timeline_builder.hpp"
#include "stimuli/verbs/verb_synthesis.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <thread>
#include <vector>

using namespace signstim;

namespace {

const std::filesystem::path kScenes = std::filesystem::path(SIGNSTIM_SOURCE_DIR) / "scenes";
const std::vector<stimuli::VerbVersion> kVersions{stimuli::VerbVersion::Point, stimuli::VerbVersion::Vector,
                                                  stimuli::VerbVersion::Animator, stimuli::VerbVersion::Uninflected};

// [S] Anatomical ranges of motion of a healthy adult: wrist flexion 0–80°, extension 0–70°,
// radial deviation 0–20° (AAOS, Greene & Heckman 1994; Norkin & White 2016); forearm pronation
// 0–85° and supination 0–90°, ulnar deviation up to 30–45° (Kapandji, The Physiology of the
// Joints vol. 1: the active range, wider than the AAOS clinical averages of 80/80/30, which the
// lexicon's contact signs — SON, DAUGHTER, BABY, MARRY, CHANGE — need; tightening to the AAOS
// values sank them, branch `elbow` a573b4c). Ulnar 35° here, the arms' limit (hand/arm_ik.hpp).
// A degree of slack for rounding.
constexpr double kWristFlexionDeg = 80.0, kWristExtensionDeg = 70.0, kRadialDeviationDeg = 20.0,
                 kUlnarDeviationDeg = 35.0, kSupinationDeg = 90.0, kPronationDeg = 85.0, kSlackDeg = 1.0;
// SPEC §6.2: peak wrist speed of natural signing.
constexpr double kWristSpeedMmPerSecond = 2500.0;
// Issue 21: the elbow never above shoulder height unless the hand is above the head
// (motion::elbowAboveShoulderMm: over the head, the elbow may rise as far as the wrist is above
// it). The arm solver caps the elbow there (hand/arm_ik.cpp, capElbowHeight); 10 mm [D] for a
// wrist whose place leaves no elbow low enough, which the cap then holds as low as it can go.
constexpr double kElbowAboveShoulderMm = 10.0;
// [D] Between two frames at 60 fps the elbow turns about the shoulder-wrist axis (the axis's own
// motion apart, tests/signer/motion_sampling.hpp) at most 15°: an elbow track turning at most
// 12° a frame (signer/elbow_track.hpp at 720°/s) measures 13.9°, its direction carried onto the
// moving axis adding ~2°. The arm solver's own choice changes basin between frames: 67°.
constexpr double kSwivelStepDegPerFrame = 15.0;
// [S] Head at most ~45° of yaw, eyes within ~35° of the orbit's centre, head peak speed 300°/s
// (Freedman & Sparks 1997; Goossens & Van Opstal 1997); hand/gaze.hpp.
constexpr double kHeadYawDeg = 45.0, kEyeYawDeg = 35.0, kHeadSpeedDegPerSecond = 300.0;

// The signer and the default scenes, for the tests that tell their own stories: they need not
// build the default stories' 48 timelines (a quarter of a minute; four under ASan).
struct SignerAndScenes {
    signer::Signer signer{kScenes};
    stimuli::StoryWorld world{kScenes.string(), ""};
};

const SignerAndScenes& signerAndScenes() {
    static const SignerAndScenes s;
    return s;
}

// Under SIGNSTIM_TEST_BREADTH=sanitizer (scripts/sanitize.sh) three stories instead of twelve
// (test::storySwept, tests/test_breadth.hpp).
bool inSample(const std::filesystem::path& story) { return test::storySwept(story.stem().string()); }

struct Fixture {
    const signer::Signer& signer = signerAndScenes().signer;
    const stimuli::StoryWorld& world = signerAndScenes().world;
    std::vector<std::string> names;                            // "story-01 point"
    std::vector<std::unique_ptr<signer::TimelineClip>> clips;  // [story * 4 + version]

    Fixture() {
        std::vector<std::filesystem::path> files;
        for (const auto& entry : std::filesystem::directory_iterator(kScenes / "stories"))
            if (entry.path().extension() == ".json" && inSample(entry.path())) files.push_back(entry.path());
        std::sort(files.begin(), files.end());
        test::noteSanitizerBreadth("3 of the 12 default stories (story-01, 06, 10)");
        for (const auto& file : files) {
            const stimuli::Story story = world.loadStory(file);
            // As `signstim story` and `study` build them: transitions paced by the signer's path.
            stimuli::TimelineSources sources = world.sources(story);
            sources.transitions = signer::transitionPacer(signer.rig());
            sources.reach = signer::signerReach(signer.rig());
            for (const stimuli::VerbVersion v : kVersions) {
                names.push_back(file.stem().string() + " " + stimuli::toString(v));
                clips.push_back(
                    std::make_unique<signer::TimelineClip>(signer.rig(), stimuli::buildTimeline(story, v, sources)));
            }
        }
    }
};

// Built once per process: CTest runs the tests that use it in one process (tests/signer/
// CMakeLists.txt, ONE_PROCESS); a new test of the default stories goes into that filter too.
const Fixture& fixture() {
    static const Fixture f;
    return f;
}

void expectElbowsLowAndSmooth(const motion::MotionPeaks& p) {
    EXPECT_LE(p.elbowAboveShoulderMm.value, kElbowAboveShoulderMm) << p.elbowAboveShoulderMm.where;
    EXPECT_LE(p.swivelStepDegPerFrame.value, kSwivelStepDegPerFrame) << p.swivelStepDegPerFrame.where;
}

void expectWristsWithinClinicalRanges(const motion::MotionPeaks& p) {
    EXPECT_LE(p.wristFlexionDeg.value, kWristFlexionDeg + kSlackDeg) << p.wristFlexionDeg.where;
    EXPECT_LE(p.wristExtensionDeg.value, kWristExtensionDeg + kSlackDeg) << p.wristExtensionDeg.where;
    EXPECT_LE(p.ulnarDeviationDeg.value, kUlnarDeviationDeg + kSlackDeg) << p.ulnarDeviationDeg.where;
    EXPECT_LE(p.radialDeviationDeg.value, kRadialDeviationDeg + kSlackDeg) << p.radialDeviationDeg.where;
    EXPECT_LE(p.supinationDeg.value, kSupinationDeg + kSlackDeg) << p.supinationDeg.where;
    EXPECT_LE(p.pronationDeg.value, kPronationDeg + kSlackDeg) << p.pronationDeg.where;
}

void expectGazeWithinEyesAndHead(const motion::MotionPeaks& p) {
    EXPECT_LE(p.headYawDeg.value, kHeadYawDeg + 0.01) << p.headYawDeg.where;
    EXPECT_LE(p.eyeYawDeg.value, kEyeYawDeg + 0.01) << p.eyeYawDeg.where;
    EXPECT_LE(p.headSpeedDegPerSecond.value, kHeadSpeedDegPerSecond) << p.headSpeedDegPerSecond.where;
}

bool samePose(const render::Pose& a, const render::Pose& b, double toleranceRad) {
    if (a.local.size() != b.local.size()) return false;
    for (std::size_t i = 0; i < a.local.size(); ++i) {
        // For nearby unit quaternions the angle between them is 2·|q − q'| (or with −q').
        const glm::quat& p = a.local[i].rotation;
        const glm::quat& q = b.local[i].rotation;
        const double d = std::min(glm::length(glm::vec4(p.x - q.x, p.y - q.y, p.z - q.z, p.w - q.w)),
                                  glm::length(glm::vec4(p.x + q.x, p.y + q.y, p.z + q.z, p.w + q.w)));
        if (2.0 * d > toleranceRad || glm::distance(a.local[i].translation, b.local[i].translation) > 1e-6f) return false;
    }
    return true;
}

}  // namespace

TEST(MotionLimits, GazeIsEyesAndHeadWithinTheirRangesAndTheHeadsSpeed) {
    const Fixture& f = fixture();
    motion::MotionPeaks peaks;
    for (std::size_t i = 0; i < f.clips.size(); ++i) motion::measureClip(f.signer.rig(), *f.clips[i], f.names[i], 60.0, peaks);
    peaks.print("default stories x versions, 60 fps:");
    expectGazeWithinEyesAndHead(peaks);
}

namespace {

// The grid of verb instances of issue 21, each as `signstim verb --out` renders it and a story's
// verb slot plays it (stimuli::paceVerbPerformance: at human speed on the posed wrists' path),
// posed at 60 fps; measured once for the tests below.
struct VerbGrid {
    motion::MotionPeaks peaks;
    std::size_t instances = 0, animatorClips = 0;
    // The drawn wrist short of its target at the instants of the verb's own keyframes (the
    // loci, the contact: where the verb puts its hands), over the grid.
    motion::Peak keyReachShortMm;
    // Every clip whose wrist falls short anywhere (on the keyed path between the keyframes too)
    // by more than kReachShortMm: "VERB version" and its most, with where.
    std::vector<std::pair<std::string, motion::Peak>> shortPaths;
    // Both hands inside the waist-up frame (issue 21 §2): the frames checked, and every clip and
    // aspect where a hand leaves it ("VERB version s= o= 4:3: N of M frames, first at T: where").
    std::size_t inFrameFrames = 0;
    std::vector<std::string> outOfFrame;
};

// Issue 21's in-frame property in the aspects the in-frame tests of stories and signs alone
// check (test::kFrameAspects, hands_in_frame.hpp), at 30 fps: the rate the default study
// renders at; the frames are every other one of the 60 fps sweep (the same instants, so the
// arm solutions come from the rig's memory).
using test::kFrameAspects;
constexpr double kInFrameFramesPerSecond = 30.0;

// Every figure of `from` into `into` (the larger, with where).
void takePeaks(motion::MotionPeaks& into, const motion::MotionPeaks& from) {
    for (motion::Peak motion::MotionPeaks::*m :
         {&motion::MotionPeaks::elbowAboveShoulderMm, &motion::MotionPeaks::elbowSwingDegPerFrame,
          &motion::MotionPeaks::elbowTurnDegPerFrame, &motion::MotionPeaks::swivelStepDegPerFrame,
          &motion::MotionPeaks::hintStepDegPerFrame, &motion::MotionPeaks::wristFlexionDeg,
          &motion::MotionPeaks::wristExtensionDeg, &motion::MotionPeaks::ulnarDeviationDeg,
          &motion::MotionPeaks::radialDeviationDeg, &motion::MotionPeaks::supinationDeg,
          &motion::MotionPeaks::pronationDeg, &motion::MotionPeaks::wristSpeedMmPerSecond, &motion::MotionPeaks::reachShortMm,
          &motion::MotionPeaks::headYawDeg, &motion::MotionPeaks::eyeYawDeg, &motion::MotionPeaks::eyePitchDeg,
          &motion::MotionPeaks::headSpeedDegPerSecond})
        (into.*m).take((from.*m).value, (from.*m).where);
}

// [D] A verb's hand reaches where the verb puts it: the drawn wrist at most 10 mm from its
// target (the arm solver's rounding is 0.5 mm; a settled touch moves a target a few mm).
constexpr double kReachShortMm = 10.0;

// Built once per process, as the story fixture (ONE_PROCESS in tests/signer/CMakeLists.txt).
const VerbGrid& verbGrid() {
    static const VerbGrid grid = [] {
        // All 8 verbs; subject and object over -1..1 in steps of 0.1 (s != o where the verb has
        // both); point, vector, uninflected; animator where its file exists. Under
        // SIGNSTIM_TEST_BREADTH=sanitizer (tests/test_breadth.hpp) subject and object at -1, 0
        // and 1, and the instances that have animator files.
        const SignerAndScenes& f = signerAndScenes();
        const stimuli::StoryWorld& w = f.world;
        const std::filesystem::path animator = kScenes / "animator";
        const stimuli::VerbSources sources{&w.verbs, &w.models, animator, &w.shapes};
        test::noteSanitizerBreadth("verb instances with subject and object at -1, 0, 1, and those with animator files");
        std::vector<std::pair<const stimuli::VerbDefinition*, std::pair<int, int>>> instances;
        for (const auto& verb : w.verbs.verbs)
            for (int s = -10; s <= 10; ++s)
                for (int o = -10; o <= 10; ++o) {
                    const bool objectOnly = verb.objectOnly();
                    if (objectOnly && s != 0) continue;
                    if (!objectOnly && s == o) continue;
                    if (test::sanitizerBreadth() && (s % 10 != 0 || o % 10 != 0) &&
                        !std::filesystem::exists(animator / stimuli::animatorFileName(verb, s / 10.0, o / 10.0)))
                        continue;
                    instances.push_back({&verb, {s, o}});
                }
        // As `signstim verb --out` paces it: the signer's pacer, whose answers the rig remembers.
        stimuli::TimelineSources pacing;
        pacing.shapes = &w.shapes;
        pacing.transitions = signer::transitionPacer(f.signer.rig());
        pacing.reach = signer::signerReach(f.signer.rig());
        motion::MotionPeaks peaks[2];
        motion::Peak keyReachShort[2];
        std::vector<std::pair<std::string, motion::Peak>> shortPaths[2];
        std::size_t animatorClips[2] = {0, 0};
        const signer::ScreenRegionModel regions(f.signer.avatar(), f.signer.rig());
        std::vector<render::Camera> cameras;
        std::vector<render::ViewCell> cells;
        for (const test::FrameAspect& a : kFrameAspects) {
            cameras.push_back(signer::clipCamera(f.signer.avatar(), f.signer.rig(), a.width, a.height, 1, 1));
            cells.push_back(render::viewCell(a.width, a.height, 1, 1, 0));
        }
        std::size_t inFrameFrames[2] = {0, 0};
        std::map<const stimuli::VerbDefinition*, std::pair<int, int>> firstOfVerb;
        for (const auto& [verb, so] : instances) firstOfVerb.emplace(verb, so);
        std::vector<std::string> outOfFrame[2];
        const auto work = [&](int part) {
            for (std::size_t i = static_cast<std::size_t>(part); i < instances.size(); i += 2) {
                const stimuli::VerbDefinition& verb = *instances[i].first;
                const double s = instances[i].second.first / 10.0, o = instances[i].second.second / 10.0;
                for (const stimuli::VerbVersion v : kVersions) {
                    if (v == stimuli::VerbVersion::Animator && !std::filesystem::exists(animator / stimuli::animatorFileName(verb, s, o)))
                        continue;
                    stimuli::VerbPerformance performance = stimuli::synthesizeVerb(sources, verb.name, v, s, o);
                    if (v == stimuli::VerbVersion::Animator) ++animatorClips[part];
                    const signer::VerbClip clip(f.signer.rig(), w.shapes, stimuli::paceVerbPerformance(std::move(performance), pacing));
                    char name[96];
                    std::snprintf(name, sizeof name, "%s %s s=%.1f o=%.1f", verb.name.c_str(), stimuli::toString(v).c_str(), s, o);
                    motion::MotionPeaks own;
                    motion::measureClip(f.signer.rig(), clip, name, 60.0, own);
                    takePeaks(peaks[part], own);
                    if (own.reachShortMm.value > kReachShortMm)
                        shortPaths[part].push_back({verb.name + " " + stimuli::toString(v), own.reachShortMm});
                    // At the keyframes themselves (the clip's lead-in, then the paced keys).
                    for (const stimuli::HandTrack& track : clip.performance().hands)
                        for (const stimuli::PerformanceKeyframe& key : track.keyframes) {
                            const double t = signer::ClipTiming{}.leadInSeconds + key.timeSeconds;
                            const hand::Side side = track.side == stimuli::HandSide::Right ? hand::Side::Right : hand::Side::Left;
                            char at[160];
                            std::snprintf(at, sizeof at, "%s %s key at t=%.3f s", name, side == hand::Side::Right ? "right" : "left", t);
                            keyReachShort[part].take(f.signer.rig().solveArm(side, clip.postureAt(t)).reachErrorMm, at);
                        }
                    // Both hands, fingertips included, inside the frame at every aspect. The
                    // uninflected clip is the same for every subject and object: once a verb.
                    if (v == stimuli::VerbVersion::Uninflected && instances[i].second != firstOfVerb.at(&verb)) continue;  // the loop body's last check
                    const signer::ClipPoser poser(f.signer.rig(), clip);
                    const int frames = static_cast<int>(std::floor(clip.durationSeconds() * kInFrameFramesPerSecond + 1e-9)) + 1;
                    int outside[std::size(kFrameAspects)] = {};
                    std::string first[std::size(kFrameAspects)];
                    for (int k = 0; k < frames; ++k) {
                        const double t = k / kInFrameFramesPerSecond;
                        const render::Pose pose = poser.next(t);
                        ++inFrameFrames[part];
                        for (std::size_t a = 0; a < std::size(kFrameAspects); ++a) {
                            const std::string edge = test::handsOutOfFrame(regions.boxes(pose, cameras[a], cells[a]),
                                                                           kFrameAspects[a].width, kFrameAspects[a].height);
                            if (edge.empty()) continue;
                            if (outside[a]++ == 0) {
                                char at[32];
                                std::snprintf(at, sizeof at, "%.3f s:", t);
                                first[a] = at + edge;
                            }
                        }
                    }
                    for (std::size_t a = 0; a < std::size(kFrameAspects); ++a)
                        if (outside[a] > 0)
                            outOfFrame[part].push_back(std::string(name) + " " + kFrameAspects[a].name + ": " + std::to_string(outside[a]) +
                                                       " of " + std::to_string(frames) + " frames, first at " + first[a]);
                }
            }
        };
        std::thread other(work, 1);
        work(0);
        other.join();
        VerbGrid g;
        g.peaks = peaks[0];
        takePeaks(g.peaks, peaks[1]);
        g.keyReachShortMm = keyReachShort[0];
        g.keyReachShortMm.take(keyReachShort[1].value, keyReachShort[1].where);
        for (const auto& part : shortPaths) g.shortPaths.insert(g.shortPaths.end(), part.begin(), part.end());
        std::sort(g.shortPaths.begin(), g.shortPaths.end(),
                  [](const auto& a, const auto& b) { return a.second.where < b.second.where; });
        g.instances = instances.size();
        g.animatorClips = animatorClips[0] + animatorClips[1];
        g.inFrameFrames = inFrameFrames[0] + inFrameFrames[1];
        for (const auto& part : outOfFrame) g.outOfFrame.insert(g.outOfFrame.end(), part.begin(), part.end());
        std::sort(g.outOfFrame.begin(), g.outOfFrame.end());
        std::printf("%zu instances, %zu animator clips\n", g.instances, g.animatorClips);
        g.peaks.print("verb grid, 60 fps:");
        std::printf("  %-28s %9.2f  at %s\n", "wrist short at the keys (mm)", g.keyReachShortMm.value, g.keyReachShortMm.where.c_str());
        for (const auto& [what, peak] : g.shortPaths) std::printf("  short by %.1f mm: %s\n", peak.value, peak.where.c_str());
        std::printf("in the waist-up frame: %zu frames at %.0f fps, each in %zu aspects; %zu clip x aspect leave it\n",
                    g.inFrameFrames, kInFrameFramesPerSecond, std::size(kFrameAspects), g.outOfFrame.size());
        for (const std::string& out : g.outOfFrame) std::printf("  out of frame: %s\n", out.c_str());
        return g;
    }();
    return grid;
}

}  // namespace

// Issue 21, item 2. Before the verb clip was paced (2026-11-26) this test posed the synthesis's
// own timing, which `signstim verb --out` rendered as it was: the wrists peaked at 4.65 m/s
// (SEND point s=-1 o=1 at 0.68 s: its straight path passes ~130 mm from the right shoulder
// joint, inside the folded arm's reach, and the arm solution pushes the wrist around it). Now
// the clip plays the performance as a story's verb slot does, slowed to SPEC §6.2 on the posed
// wrists' path (stimuli::paceVerbPerformance): 2.03 m/s (COPY point s=0.9 o=-1.0; the elbow
// 0 mm above its bound, the wrists' angles at the arms' limits, within the cited ranges;
// 2562 instances, 33 animator clips; measured 2026-11-26; the same with the verb clip's elbow
// track). The elbow's swivel is EveryVerbInstanceTurnsItsElbowsSmoothly's.
TEST(MotionLimits, EveryVerbInstanceKeepsItsWristsAndElbowsWithinTheBodysLimits) {
    const VerbGrid& grid = verbGrid();
    EXPECT_GT(grid.animatorClips, 0u);
    EXPECT_LE(grid.peaks.elbowAboveShoulderMm.value, kElbowAboveShoulderMm) << grid.peaks.elbowAboveShoulderMm.where;
    expectWristsWithinClinicalRanges(grid.peaks);
    EXPECT_LE(grid.peaks.wristSpeedMmPerSecond.value, kWristSpeedMmPerSecond) << grid.peaks.wristSpeedMmPerSecond.where;
}

// Issue 21. Before the verb clip had an elbow track (signer::VerbClip, as a story's:
// signer/elbow_track.hpp) its elbow turned 66.0° about the shoulder-wrist axis in one frame
// (COPY point s=1.0 o=-0.9 right at 0.917 s, the verb clip paced); with it 12.1° (MEET point
// s=0.9 o=-0.9 right at 0.783 s; measured 2026-11-26), the bound the stories keep.
TEST(MotionLimits, EveryVerbInstanceTurnsItsElbowsSmoothly) {
    const VerbGrid& grid = verbGrid();
    EXPECT_LE(grid.peaks.swivelStepDegPerFrame.value, kSwivelStepDegPerFrame) << grid.peaks.swivelStepDegPerFrame.where;
}

// Issue 21. The point and vector models put the wrist beyond the arm's reach (580 mm from the
// shoulder joint on the default signer) on much of the grid, and the arm locked straight across
// the chest at shoulder height, short of the target: on the grid 185 mm (GIVE vector s=-1.0
// o=0.9 left at 1.183 s), EMAIL point s=0.9 o=-0.6 64 mm (elbow flexion 0°, the shoulder
// elevated 78°; the animator file for that instance reaches with the elbow bent 29°); on a 0.2
// grid of subject and object 339 clips fell more than 10 mm short (75 GIVE point, 53 ASK point,
// 42 SEND point, 40 EMAIL point ...), the uninflected never. A story's verb slots the same:
// story-11 point's GIVE, the left wrist 145 mm short at 12.25 s. Now the point and vector
// versions' keyframes are drawn within the signer's comfortable reach where they meet it (stimuli::withinReach,
// stimuli/verbs/verb_reach.hpp, given signer::signerReach): the far ones toward the shoulder,
// within 0.9 of the arm; with that alone 60 mm were left (COPY point s=1.0 o=-1.0: the straight
// path from the far left to the right side passes 128 mm from the right shoulder joint, nearer
// than the folded arm's 187 mm; ASK point s=1.0's first key 168 mm from it), so keys nearer
// than the folded arm are pushed out and a path that passes too near is moved forward.
// With both, 41.8 mm were left (2026-11-26, over the 0.1 grid). Measured at the keyframes
// themselves, three animator files put the right wrist's first key inside the folded arm (ASK
// s=0.9 o=-0.3 162 mm from the shoulder joint: 24.8 mm short; ASK s=0.9 o=-0.6 21.7 mm; SEND
// s=0.9 o=-0.6 15.2 mm; the authored versions are not drawn within reach): those keys now sit
// 40-60 mm further forward (scenes/animator/), clear of it by kFoldedMarginMm, and every key of
// every instance is reached within 8.4 mm (EMAIL animator s=0.9 o=0.3's first right key, a
// default story's instance, 181 mm from the shoulder joint; the point and vector keys 0.0 mm;
// measured 2026-11-27). Three point/vector clips fell more than 10 mm short on
// the path between keys, all TELL from the chin toward a far-right object: point o=1.0 41.8 mm (right at 0.733 s), point
// o=0.9 24.4 mm, vector o=0.9 16.5 mm. The keys are reachable (the chin key 259 mm from the
// right shoulder joint, the locus 315 mm); the straight path between them passes 145 mm in
// front of and below that joint, inside the folded arm's 187 mm, where the forearm would have
// to lie inside the upper arm. The arm folds to its limit and the solver sets the wrist out
// radially (by the 42 mm), with the hand's orientation 80° beyond the wrist there and the
// forearm turning from 90° supination to 85° pronation in one 60 fps frame (the sheet of TELL
// point o=1: the finger snaps from up at the shoulder to pointing right). Moving the locus
// forward until the path clears, as the untouched verbs' tracks are (only the key away from the
// touch, the chin kept), would take o=1.0 forward 181 mm (123 mm to the bare folded reach) and
// turn it from 95° to 74° right of straight ahead, o=0.9 from 88° to 73°, o=0.8 from 80° to 72°:
// the far-right loci would all land where o=0.7 points (73°), and the verb would no longer
// point at its object. The keys are where the verb puts its hands; what is left is the route
// between them (a signer's hand bows forward around the shoulder), which belongs to the path
// between keyframes (stimuli/verbs/verb_synthesis.cpp, sampleHand; issue 21, transitions
// routed around the body), not to where the keys are.
//
// Since a verb's path sweeps about the torso's axis where its chord would dip toward the body
// (stimuli/verbs/signing_space.hpp, sweptPathPoint; 2026-11-27), TELL's route bows out past the
// folded arm too: TELL point o=1.0 42 -> under 10 mm, the grid's worst 8.4 mm (EMAIL animator
// s=0.9 o=0.3, at its first key). So: at every keyframe of every instance the wrist reaches its
// target within kReachShortMm (the loci and the contact: where the verb puts its hands), and on
// every frame between them too.
TEST(MotionLimits, EveryVerbInstanceReachesWhereTheVerbPutsItsHands) {
    const VerbGrid& grid = verbGrid();
    EXPECT_LE(grid.keyReachShortMm.value, kReachShortMm) << grid.keyReachShortMm.where;
    std::string shortClips;
    for (const auto& [what, peak] : grid.shortPaths)
        shortClips += "\n  " + std::to_string(peak.value) + " mm short: " + what + " " + peak.where;
    EXPECT_TRUE(shortClips.empty()) << "clips short of their target beyond kReachShortMm:" << shortClips;
}

// Issue 21 §2: both hands, fingertips included, inside the camera frame for every aspect (4:3
// and 16:9) on every frame of every verb instance of the grid, as `signstim verb --out` renders
// it (the waist-up view; the face preset frames the head alone): each hand's screen box
// (signer/screen_regions.hpp: every bone of the hand, the fingertips in, grown by
// kScreenRegionMarginMm) inside the view at 640×480 and 640×360, at 30 fps. The same property
// for the default stories is tests/signer/story_in_frame_test.cpp, for signs alone
// sign_in_frame_test.cpp. Measured on the grid's clips (built once, verbGrid()); the uninflected
// clip, the same for every subject and object, once a verb: 234 972 frames, ~11 s of the grid's
// ~69 s of CPU (gcc, RelWithDebInfo, on a loaded 2-core machine; 2026-11-27), most of it posing
// the hands. Before the waist-up view was kept 1.75 m wide (signer/avatar_render.cpp; it was
// 1.65 m) 6 clips left the 4:3 frame, SEND point s=-0.7..-1.0 o=0.9..1.0 (16-19 frames each:
// the right fingertips past the left edge, the point model carrying the sweep past the far
// right locus); at 16:9 none.
TEST(MotionLimits, EveryVerbInstanceKeepsBothHandsInsideTheWaistUpFrame) {
    const VerbGrid& grid = verbGrid();
    EXPECT_GT(grid.inFrameFrames, grid.instances * 20);
    std::string out;
    for (const std::string& clip : grid.outOfFrame) out += "\n  " + clip;
    EXPECT_TRUE(out.empty()) << "a hand (fingertips included) leaves the waist-up frame:" << out;
}

TEST(FrameRateIndependence, ThePoseAtAnInstantIsTheSameAtEveryFrameRate) {
    // 15, 24, 25, 30, 60 and 30000/1001 fps, each posed frame after frame as the renderer does;
    // an instant two rates share (t·60 whole) is compared with 60 fps's frame there.
    const Fixture& f = fixture();
    const std::vector<std::pair<double, double>> rates{{15, 1}, {24, 1}, {25, 1}, {30, 1}, {30000, 1001}};
    for (std::size_t i = 0; i < f.clips.size(); ++i) {
        const signer::ClipPoser reference(f.signer.rig(), *f.clips[i]);
        const auto total60 = static_cast<std::uint64_t>(std::floor(f.clips[i]->durationSeconds() * 60.0 + 1e-9)) + 1;
        std::vector<render::Pose> at60;
        for (std::uint64_t k = 0; k < total60; ++k) at60.push_back(reference.next(static_cast<double>(k) / 60.0));
        std::size_t compared = 0;
        for (const auto& [num, den] : rates) {
            const signer::ClipPoser poser(f.signer.rig(), *f.clips[i]);
            const double fps = num / den;
            const auto total = static_cast<std::uint64_t>(std::floor(f.clips[i]->durationSeconds() * fps + 1e-9)) + 1;
            for (std::uint64_t k = 0; k < total; ++k) {
                const double t = static_cast<double>(k) * den / num;
                const render::Pose pose = poser.next(t);
                const double frame60 = static_cast<double>(k) * den * 60.0 / num;
                if (std::fabs(frame60 - std::round(frame60)) > 1e-9 || std::round(frame60) >= total60) continue;
                ++compared;
                ASSERT_TRUE(samePose(pose, at60[static_cast<std::size_t>(std::round(frame60))], 1e-6))
                    << f.names[i] << " at " << t << " s, " << fps << " fps";
            }
        }
        EXPECT_GT(compared, 0u) << f.names[i];
    }
}

// The verb clip's elbow track keeps its pose a function of t: COPY point s=1.0 o=-0.9, whose
// elbow the track blends across a 66° jump (EveryVerbInstanceTurnsItsElbowsSmoothly), and GIVE
// vector s=-0.5 o=0.8, posed at each rate as `signstim verb --out` does and compared with 60 fps
// at the instants they share.
TEST(FrameRateIndependence, AVerbClipsPoseAtAnInstantIsTheSameAtEveryFrameRate) {
    const SignerAndScenes& f = signerAndScenes();
    const stimuli::StoryWorld& w = f.world;
    const stimuli::VerbSources sources{&w.verbs, &w.models, kScenes / "animator", &w.shapes};
    stimuli::TimelineSources pacing;
    pacing.shapes = &w.shapes;
    pacing.transitions = signer::transitionPacer(f.signer.rig());
    pacing.reach = signer::signerReach(f.signer.rig());
    struct Instance {
        const char* verb;
        stimuli::VerbVersion version;
        double s, o;
    };
    for (const Instance& in : {Instance{"COPY", stimuli::VerbVersion::Point, 1.0, -0.9},
                               Instance{"GIVE", stimuli::VerbVersion::Vector, -0.5, 0.8}}) {
        const signer::VerbClip clip(f.signer.rig(), w.shapes,
                                    stimuli::paceVerbPerformance(stimuli::synthesizeVerb(sources, in.verb, in.version, in.s, in.o), pacing));
        const signer::ClipPoser poser(f.signer.rig(), clip);
        const auto total60 = static_cast<std::uint64_t>(std::floor(clip.durationSeconds() * 60.0 + 1e-9)) + 1;
        std::vector<render::Pose> at60;
        for (std::uint64_t k = 0; k < total60; ++k) at60.push_back(poser.next(static_cast<double>(k) / 60.0));
        std::size_t compared = 0;
        for (const auto& [num, den] : std::vector<std::pair<double, double>>{{15, 1}, {24, 1}, {25, 1}, {30, 1}, {30000, 1001}}) {
            const double fps = num / den;
            const auto total = static_cast<std::uint64_t>(std::floor(clip.durationSeconds() * fps + 1e-9)) + 1;
            for (std::uint64_t k = 0; k < total; ++k) {
                const double t = static_cast<double>(k) * den / num;
                const double frame60 = static_cast<double>(k) * den * 60.0 / num;
                if (std::fabs(frame60 - std::round(frame60)) > 1e-9 || std::round(frame60) >= total60) continue;
                ++compared;
                ASSERT_TRUE(samePose(poser.next(t), at60[static_cast<std::size_t>(std::round(frame60))], 1e-6))
                    << in.verb << " at " << t << " s, " << fps << " fps";
            }
        }
        EXPECT_GT(compared, 0u) << in.verb;
    }
}

TEST(FrameRateIndependence, FramesOutsideTheVerbsAreTheSameInEveryVersion) {
    const Fixture& f = fixture();
    for (std::size_t story = 0; story + 3 < f.clips.size(); story += 4) {
        const stimuli::Timeline& timeline = f.clips[story]->timeline();
        std::size_t shared = 0;
        for (std::uint64_t k = 0; static_cast<double>(k) / 60.0 <= f.clips[story]->durationSeconds(); ++k) {
            const double t = static_cast<double>(k) / 60.0;
            bool inVerb = false;
            for (const stimuli::TimelineSpan& span : timeline.spans)
                inVerb = inVerb || (span.kind == stimuli::SpanKind::Verb && t >= span.startSeconds && t <= span.endSeconds);
            if (inVerb) continue;
            const render::Pose first = signer::ClipPoser(f.signer.rig(), *f.clips[story]).next(t);
            for (std::size_t v = 1; v < 4; ++v)
                ASSERT_TRUE(samePose(first, signer::ClipPoser(f.signer.rig(), *f.clips[story + v]).next(t), 0.0))
                    << f.names[story + v] << " at " << t << " s";
            ++shared;
        }
        EXPECT_GT(shared, 0u) << f.names[story];
    }
}

// Issue 21. Before the elbow's height cap (hand/arm_ik.cpp, capElbowHeight; 2026-11-26, 60 fps)
// the elbow rose 63 mm above the shoulder in a fingerspelled P (story-04 point 1.48 s: its
// "pointing down" orientation beyond the wrist's reach). The cap first held it at
// max(shoulder, wrist), which let a hand at the face lift it (FORGET in story-01: 128 mm above
// the shoulder); since 2026-11-27 it holds it at the shoulder unless the wrist is above the head.
TEST(MotionLimits, EveryStoryFrameKeepsItsWristsAndElbowsWithinTheBodysLimits) {
    const Fixture& f = fixture();
    motion::MotionPeaks peaks;
    for (std::size_t i = 0; i < f.clips.size(); ++i) motion::measureClip(f.signer.rig(), *f.clips[i], f.names[i], 60.0, peaks);
    peaks.print("default stories x versions, 60 fps:");
    EXPECT_LE(peaks.elbowAboveShoulderMm.value, kElbowAboveShoulderMm) << peaks.elbowAboveShoulderMm.where;
    expectWristsWithinClinicalRanges(peaks);
}

// Without an elbow track the elbow turned 66.8° about the shoulder-wrist axis in one frame
// (story-08 point 4.57 s, LATE -> IX; measured 2026-11-26): the arm solver's argmin changes basin
// between frames (a hand orientation at the wrist's limits), and two keys' elbows lie up to ~100°
// apart 0.1 s from each other. A track that lagged behind the solver's elbow (elbow2) brought it
// to 13.9° but sank COOK 22 mm into the body and turned posed hands 10-50° from what they ask.
// The track now (signer/elbow_track.hpp) keeps the solver's own elbow wherever it turns no faster
// than 720°/s and blends across its jumps only: 12.2° a frame (story-01 point 10.98 s; measured
// 2026-11-26).
TEST(MotionLimits, EveryStoryFrameTurnsItsElbowsSmoothly) {
    const Fixture& f = fixture();
    motion::MotionPeaks peaks;
    for (std::size_t i = 0; i < f.clips.size(); ++i) motion::measureClip(f.signer.rig(), *f.clips[i], f.names[i], 60.0, peaks);
    expectElbowsLowAndSmooth(peaks);
}

// SPEC §6.2 on the path the wrists actually travel, detours and settled touches included.
// Before the timeline's transitions were paced by the signer's path (signer::transitionPacer),
// the clearance detours TimelineClip adds took the wrists to 3.42 m/s (story-10 point at
// 13.25 s, BOSS -> NICE: 230 mm forward within 0.1 s of a 0.375 s transition), 3.15 (story-06
// at 11.0 s) and 3.14 (story-09 at 8.68 s); measured 2026-11-26. Paced, they peaked at 2.45 m/s;
// then the touches came to the surface (TimelineClip::settleTouches), whose offsets the pacer
// did not see: 2.77 m/s at story-03 uninflected t=4.017 s (into EMAIL), 2.72 in story-01 at
// 14.33 s (out of HOMEWORK). Now a settled touch's offsets change only within the headroom
// the wrists' own motion leaves (signer/settled_pace.hpp), and the pacer times a transition
// to and from the settled touch (TransitionQuery::intoTouch): 2.46 m/s (measured 2026-11-26).
TEST(MotionLimits, NoWristFasterThanSpec62) {
    const Fixture& f = fixture();
    motion::MotionPeaks peaks;
    for (std::size_t i = 0; i < f.clips.size(); ++i) motion::measureClip(f.signer.rig(), *f.clips[i], f.names[i], 60.0, peaks);
    std::printf("peak wrist speed %.0f mm/s at %s\n", peaks.wristSpeedMmPerSecond.value, peaks.wristSpeedMmPerSecond.where.c_str());
    EXPECT_LE(peaks.wristSpeedMmPerSecond.value, kWristSpeedMmPerSecond) << peaks.wristSpeedMmPerSecond.where;
}

// SPEC §6.3: conversational ASL runs at ~2-2.3 signs/s (Bellugi & Fischer 1972); `story --check`
// warns outside 1.7-2.3. Every default story in every version as it is rendered (transitions
// paced by the signer's path), at --rate 1 — within the speed limit above.
TEST(StoryTiming, EveryDefaultStoryAsRenderedSignsAtConversationalPace) {
    const Fixture& f = fixture();
    for (std::size_t i = 0; i < f.clips.size(); ++i) {
        const stimuli::TimelineMeasures m = stimuli::measureTimeline(f.clips[i]->timeline());
        if (i % 4 == 0) std::printf("%s: %.3f signs/s\n", f.names[i].c_str(), m.signsPerSecond());
        // Story 01 (ten IXs between loci 1.5 apart, five fingerspelled names, three verbs) is the
        // slowest: 1.636 signs/s once the lexicon took ASL-LEX 2.0's longer citation forms (issue
        // 22) with signs in context still scaled for the old ones; 1.706 with signScale 0.4, the
        // sign in context back at its length before issue 22 (timeline_builder.hpp); 1.700 after
        // issue 22's posed-touch fixes, and 1.73 once sentence 3 points at Tom and Ann, already
        // named and placed, instead of spelling their names again (as sentence 4 does).
        EXPECT_GE(m.signsPerSecond(), 1.7) << f.names[i];
        EXPECT_LE(m.signsPerSecond(), 2.3) << f.names[i];
    }
}

// A verb slot is as long as the longest of the versions' paths at human speed (timeline_builder.hpp):
// every verb, subject and object over -1..1 in steps of 0.5, told in a one-sentence story
// (synthetic: two fingerspelled characters placed, then "AL VERB ED"), in the point, vector and uninflected
// versions (the animator files cover only the default stories' instances), posed at 60 fps.
TEST(MotionLimits, EveryVerbSlotKeepsItsWristsWithinSpec62) {
    const SignerAndScenes& f = signerAndScenes();
    // Under SIGNSTIM_TEST_BREADTH=sanitizer subject and object at -1, 0 and 1 only: the far and
    // the centre loci, 6 of the 20 pairs per verb (tests/test_breadth.hpp).
    const int step = test::sanitizerBreadth() ? 2 : 1;
    test::noteSanitizerBreadth("subject and object at -1, 0, 1 (6 of 20 pairs per verb)");
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("signstim-verb-slots-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    std::filesystem::create_directories(dir);
    motion::MotionPeaks peaks;
    std::size_t slots = 0;
    const std::vector<stimuli::VerbVersion> versions{stimuli::VerbVersion::Point, stimuli::VerbVersion::Vector,
                                                     stimuli::VerbVersion::Uninflected};
    for (const auto& verb : f.world.verbs.verbs)
        for (int s = -2; s <= 2; s += step)
            for (int o = -2; o <= 2; o += step) {
                if (s == o) continue;
                char text[512];
                std::snprintf(text, sizeof text,
                              R"json({"format": "signstim-story", "version": 1, "title": "synthetic verb slot",
 "characters": [{"gloss": "AL", "position": %.1f}, {"gloss": "ED", "position": %.1f}],
 "sentences": ["AL IX(%.1f)", "ED IX(%.1f)", "AL %s ED"], "questions": []})json",
                              s / 2.0, o / 2.0, s / 2.0, o / 2.0, verb.name.c_str());
                const std::filesystem::path file = dir / (verb.name + "_" + std::to_string(s) + "_" + std::to_string(o) + ".json");
                { std::ofstream(file) << text; }
                const stimuli::Story story = f.world.loadStory(file);
                stimuli::TimelineSources sources = f.world.sources(story);
                sources.transitions = signer::transitionPacer(f.signer.rig());
                sources.reach = signer::signerReach(f.signer.rig());
                sources.slotVersions = versions;
                for (const stimuli::VerbVersion v : versions) {
                    const signer::TimelineClip clip(f.signer.rig(), stimuli::buildTimeline(story, v, sources));
                    motion::measureClip(f.signer.rig(), clip, verb.name + " " + stimuli::toString(v) + " s=" +
                                                                  std::to_string(s / 2.0) + " o=" + std::to_string(o / 2.0),
                                        60.0, peaks);
                    ++slots;
                }
            }
    std::filesystem::remove_all(dir);
    std::printf("%zu verb slots: peak wrist speed %.0f mm/s at %s\n", slots, peaks.wristSpeedMmPerSecond.value,
                peaks.wristSpeedMmPerSecond.where.c_str());
    EXPECT_LE(peaks.wristSpeedMmPerSecond.value, kWristSpeedMmPerSecond) << peaks.wristSpeedMmPerSecond.where;
}

// ---- The hands keep clear of each other and of the body in every verb instance ----
// Issue 21, item 2 ("the hands never pass through each other or the body"), on the verb grid:
// the rules StoryClearance holds on the default stories (signer/clearance.hpp: checkClearance
// and its thresholds) on every 60 fps frame of every verb instance, each played as a story's
// verb slot plays it (verbSlotTimeline): its lead-in a transition from rest, routed around the
// hands and the body; its keys and the hold on the last one the verb, which may touch only as
// verbs.json says its citation form does (MEET, COPY and SEND the hands, settled as in
// a story; TELL the body; EMAIL's index slides into the C untouched). Its own sweep, apart from verbGrid()'s motion figures.
namespace {

// A verb instance as a story's verb slot plays it (a one-item timeline, synthetic): the hands
// rise from rest in ClipTiming's lead-in, play the paced performance, and hold its last keys
// for ClipTiming's hold (as `signstim verb --out` times it); a touch of the hands is settled
// (TimelineClip::settleTouches) as in any story.
stimuli::Timeline verbSlotTimeline(const stimuli::VerbPerformance& performance, const stimuli::HandshapeLibrary& shapes) {
    const signer::ClipTiming timing;
    const double keysStart = timing.leadInSeconds, keysEnd = keysStart + performance.durationSeconds;
    stimuli::Timeline timeline;
    timeline.story = "verb grid";
    timeline.version = stimuli::toString(performance.version);
    timeline.durationSeconds = keysEnd + timing.holdSeconds;
    for (const stimuli::HandSide side : {stimuli::HandSide::Right, stimuli::HandSide::Left}) {
        std::vector<stimuli::TimelineKey>& keys = side == stimuli::HandSide::Right ? timeline.right : timeline.left;
        stimuli::TimelineKey rest;
        rest.rest = true;
        keys.push_back(rest);
        if (const stimuli::HandTrack* track = performance.hand(side)) {
            for (const stimuli::PerformanceKeyframe& k : track->keyframes) {
                stimuli::TimelineKey key;
                key.timeSeconds = keysStart + k.timeSeconds;
                key.pose = k.pose;
                key.handshape = k.handshape;
                key.controls = shapes.at(k.handshape).controls;
                keys.push_back(key);
            }
        } else {
            rest.timeSeconds = keysStart;
            keys.push_back(rest);
        }
        stimuli::TimelineKey last = keys.back();
        last.timeSeconds = timeline.durationSeconds;
        keys.push_back(last);
    }
    timeline.spans = {{stimuli::SpanKind::Rest, 0.0, 0.0, "rest", -1, -1, 0.0, 0.0, {}},
                      {stimuli::SpanKind::Verb, 0.0, timeline.durationSeconds, performance.verb, 0, 0, keysStart,
                       timeline.durationSeconds, performance.contact}};
    timeline.gaze = {{0.0, std::nullopt}, {timeline.durationSeconds, std::nullopt}};
    return timeline;
}

struct VerbClearanceBreak {
    std::string verb, version, text;
    bool hands = true;
    float gapMm = 0.0f;
};

struct VerbGridClearance {
    std::map<std::string, signer::ClearanceExtreme> hands, body;  // per verb: the closest approach in the verb
    std::map<std::string, std::string> handsAt, bodyAt;
    std::vector<VerbClearanceBreak> breaks;  // the deepest frame of each offending stretch
    std::size_t clips = 0, frames = 0;

    void take(const VerbGridClearance& other) {
        clips += other.clips;
        frames += other.frames;
        breaks.insert(breaks.end(), other.breaks.begin(), other.breaks.end());
        for (const bool h : {true, false})
            for (const auto& entry : h ? other.hands : other.body) {
                auto& into = h ? hands : body;
                if (!into.count(entry.first) || entry.second.gapMm < into[entry.first].gapMm) {
                    into[entry.first] = entry.second;
                    (h ? handsAt : bodyAt)[entry.first] = (h ? other.handsAt : other.bodyAt).at(entry.first);
                }
            }
    }
};

// Every frame of the slot at 60 fps (and its keys' ends), judged by the story's rules.
void checkVerbSlotClearance(const signer::SignerRig& rig, const signer::TimelineClip& clip, const std::string& name,
                            VerbGridClearance& out) {
    const std::vector<signer::ClearanceFrame> frames = signer::clearanceFrames(rig, clip, 60.0);
    out.frames += frames.size();
    ++out.clips;
    const signer::ClearanceSummary summary = signer::checkClearance(clip.timeline(), frames);
    const stimuli::TimelineSpan& verb = clip.timeline().spans.back();
    for (const bool hands : {true, false}) {
        const signer::ClearanceExtreme& e = hands ? (verb.contact.hands ? summary.handsInContactSigns : summary.handsInSigns)
                                                  : (verb.contact.body ? summary.bodyInContactSigns : summary.body);
        auto& worst = hands ? out.hands : out.body;
        if (worst.count(verb.label) && e.gapMm >= worst[verb.label].gapMm) continue;
        worst[verb.label] = e;
        char where[128];
        std::snprintf(where, sizeof where, "%s at %.3f s", name.c_str(), e.seconds);
        (hands ? out.handsAt : out.bodyAt)[verb.label] = where;
    }
    // Where an instant falls among the verb's keys (either hand's: both are keyed together),
    // so that a keyframe the model puts in the body is told from a path that enters it.
    const auto amongKeys = [&](double seconds) {
        const std::vector<stimuli::TimelineKey>& keys = clip.timeline().right;
        constexpr double kAtKey = 0.5 / 60.0;
        std::size_t k = 0;
        for (std::size_t i = 1; i + 1 < keys.size(); ++i) {  // the verb's keys: between the first rest and the last hold
            if (std::abs(keys[i].timeSeconds - seconds) <= kAtKey) return "at key " + std::to_string(k);
            if (keys[i].timeSeconds < seconds) ++k;
        }
        return k == 0 ? std::string("before the keys") : "after key " + std::to_string(k - 1);
    };
    for (const signer::ClearanceViolation& v : summary.violations) {
        char line[240];
        std::snprintf(line, sizeof line, "%s: %s%s %.1f mm apart at %.3f s, %s (at least %.1f allowed)", name.c_str(),
                      v.transition ? "lead-in: " : "", v.hands ? "hands" : "hand and body", v.gapMm, v.seconds,
                      amongKeys(v.seconds).c_str(), v.allowedMm);
        out.breaks.push_back({verb.label, clip.timeline().version, line, v.hands, v.gapMm});
    }
}

// Verb instances whose hands still go deeper than the rules allow, held at their depth (mm, to
// 0.5 mm) per verb, version and what they go into (the other hand, or the body); a break not
// listed, or deeper, fails. Remove a line when its cause is fixed. Measured 2026-11-26 on this
// sweep; the test's first run found 86 breaks, MEET's among them (point -13.8 mm at s=-1 o=0.5,
// the moving-day story's -17.1 mm at s=-0.45 o=0.75): its hands start in each other where the
// subject is left of the object, fixed by verbs.json "handsBySide" (now -2.0 mm, the settled
// touch). Then 87, 55 of them a hand in the body where an inflected path swept across the
// signer (s and o far apart on either side: ASK point -63, COPY point -61, GIVE point -18, SEND
// point -76 at s=+-1 o=-+1, TELL point -14 at o=1): the keyframes are turned about the torso
// pivot and the hand went straight between them, a chord that cut into the torso. Fixed by
// sweeping a verb's path about the torso's axis where its chord dips toward it near the body
// (stimuli/verbs/signing_space.hpp, sweptPathPoint): those lines are gone (63 breaks, 31 of them
// hand-body). Left then, the hand in the body (hand-body) where a model's own keyframe lay in
// it — "at key 0" in the record, or the stretch leaving or reaching such a key: GIVE vector
// with s and o both left (-92.5 mm at s=-1 o=-0.8; 26 instances), SEND vector -42.1, EMAIL
// vector -20.2, ASK vector -8.4; the path cannot route round a key. The vector model
// places a verb's start by the right hand's location likelihood alone (SPEC §3.5, the paper's
// model, kept as it is), so with both loci on the left GIVE's pair starts centre-right and its
// left hand, set relative to the right one as the pair turns left, lands behind it in the
// torso. Since 2026-11-27 every point and vector key is pushed out of the torso along its
// normal, the hand's extent toward the body and a clearance kept (stimuli::clearOfTorso, in
// withinReach, given the rig's torso by signer::signerReach), and this sweep plays each
// instance with the signer's reach as stories and `verb --out` do (before, without it): no
// hand-body line is left (the closest approach 4.1 mm, SEND vector s=-1 o=-0.5; GIVE vector
// s=-1 o=-0.8 4.6 mm in its lead-in).
// And the hands' touches that settling leaves deeper than kContactDepthToleranceMm: none now,
// COPY's and EMAIL's left on 2026-11-27 (below).
// Those touches are not settling's failure: the data asks for a path through the other hand (measured 2026-11-27 on the capsules, session 12):
//  - COPY s=-1 o=0.5: the right hand leaves the base palm 15 mm clear and 0.1 s into the
//    stroke its spread 5 sweeps through the base B's fingers (-18 mm in a story at those
//    places): the performer (scenes/corpus/reference_performer.json) keeps the base hand
//    rigid with the right hand's start, which turns toward the object by half its arc angle,
//    while the path turns toward the far-left subject, so the base hand ends up on the path.
//    Turning both right keyframes with the path ("yaw": "path", as EMAIL's C) took these two
//    lines out of the sweep but added COPY vector s=-1 o=1 hand-body (-8.8 mm), and a story at
//    s=-1 o=1 then sank -19/-20 mm (point, vector) where the isolated slot did not: not kept.
//    Fixed 2026-11-27: COPY's citation lifts the right hand 65 mm off the base palm (a middle
//    key at 0.2 s that the performer keeps turned with the start, toward the object) before it
//    turns toward the subject, so it pulls away above the base B's fingers: COPY's two lines
//    are gone (sweep: hands -2.0 mm at the settled touch, hand-body >= 16 mm).
//  - EMAIL (gone, 2026-11-27): the bent-B hand was wider than the C's cavity and the upright C
//    was not posed as asked (the left wrist cannot extend so far). Now as ASL-LEX 2.0 'email'
//    codes it: the 1 hand's index slides into a palm-down C without contact (scenes/verbs.json),
//    the aim, the slide and the C turned together by the performer; over the sweep its hands
//    keep >= 7 mm apart and >= 4 mm from the body (were -21 mm both).
// SEND animator s=0.9 o=-0.6's right hand 12.1 mm into the
// body at 0.5 s (at key 0) is gone too (2026-11-27): its first key lay inside the folded arm
// (EveryVerbInstanceReachesWhereTheVerbPutsItsHands) and now sits 40 mm further forward.
struct KnownVerbBreak {
    const char* verb;
    const char* version;
    bool hands;
    float deepestMm;
};
// EMAIL's new form had 24 breaks of its own here once the sweep played the signer's reach
// (2026-11-27): at the arc's far ends the performer turned the C and the slide half the way to
// the object (towardObject 0.5), the left arm held the C out at the object's side, and the
// comfortable reach pulled the index's keys without the C through its wall (point -18.4 mm,
// vector -6.2). A fifth of the way (scenes/corpus/reference_performer.json; corpus and models
// regenerated) keeps the C before the body: none left (hands >= 4.3 mm over the grid).
// None now; add {verb, version, hands, deepestMm} with the measured cause above.
const std::vector<KnownVerbBreak> kKnownVerbBreaks{};

}  // namespace

// The sweep: all 8 verbs, subject and object over -1..1 in steps of 0.1 (s != o where the verb
// has both), point and vector, with animator where its file exists (and point and vector
// there); uninflected once per verb (the citation form, the same for every subject and
// object). A verb that touches with both hands in steps of 0.5: settling a touch costs ~0.15 s
// of CPU a clip, 15-40 times an untouched one (the arm solved for every way out it tries).
// 2001 clips, ~37 s of CPU (gcc, RelWithDebInfo; measured 2026-11-26). Under
// SIGNSTIM_TEST_BREADTH=sanitizer subject and object at -1, 0, 1, and the instances with
// animator files: 191 clips, ~8 s of CPU before ASan's slowdown.
TEST(MotionLimits, EveryVerbInstanceKeepsItsHandsOutOfEachOtherAndTheBody) {
    const SignerAndScenes& f = signerAndScenes();
    const stimuli::StoryWorld& w = f.world;
    const std::filesystem::path animator = kScenes / "animator";
    const stimuli::VerbSources sources{&w.verbs, &w.models, animator, &w.shapes};
    test::noteSanitizerBreadth("verb instances with subject and object at -1, 0, 1, and those with animator files");
    struct Instance {
        const stimuli::VerbDefinition* verb;
        stimuli::VerbVersion version;
        int s, o;  // tenths
    };
    std::vector<Instance> instances;
    for (const auto& verb : w.verbs.verbs) {
        instances.push_back({&verb, stimuli::VerbVersion::Uninflected, 0, verb.objectOnly() ? 1 : 0});
        const int step = verb.contact.hands ? 5 : 1;
        for (int s = -10; s <= 10; ++s)
            for (int o = -10; o <= 10; ++o) {
                if (verb.objectOnly() ? s != 0 : s == o) continue;
                const bool animated = std::filesystem::exists(animator / stimuli::animatorFileName(verb, s / 10.0, o / 10.0));
                if (animated) instances.push_back({&verb, stimuli::VerbVersion::Animator, s, o});
                // Point and vector on the grid, and where an animator's file is (the default
                // stories' instances) in every breadth.
                const bool onGrid = test::sanitizerBreadth() ? s % 10 == 0 && o % 10 == 0 : s % step == 0 && o % step == 0;
                if (!onGrid && !animated) continue;
                for (const stimuli::VerbVersion v : {stimuli::VerbVersion::Point, stimuli::VerbVersion::Vector})
                    instances.push_back({&verb, v, s, o});
            }
    }
    stimuli::TimelineSources pacing;
    pacing.shapes = &w.shapes;
    pacing.transitions = signer::transitionPacer(f.signer.rig());
    pacing.reach = signer::signerReach(f.signer.rig());  // as a story's verb slot and `verb --out`
    const std::size_t threads = std::max(2u, std::thread::hardware_concurrency());
    std::vector<VerbGridClearance> parts(threads);
    const auto work = [&](std::size_t part) {
        for (std::size_t i = part; i < instances.size(); i += threads) {
            const Instance& in = instances[i];
            const double s = in.s / 10.0, o = in.o / 10.0;
            const signer::TimelineClip clip(
                f.signer.rig(),
                verbSlotTimeline(stimuli::paceVerbPerformance(stimuli::synthesizeVerb(sources, in.verb->name, in.version, s, o), pacing),
                                 w.shapes));
            char name[96];
            std::snprintf(name, sizeof name, "%s %s s=%.1f o=%.1f", in.verb->name.c_str(), stimuli::toString(in.version).c_str(), s, o);
            checkVerbSlotClearance(f.signer.rig(), clip, name, parts[part]);
        }
    };
    std::vector<std::thread> pool;
    for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(work, t);
    work(0);
    for (std::thread& t : pool) t.join();
    VerbGridClearance all;
    for (const VerbGridClearance& part : parts) all.take(part);
    std::printf("%zu verb clips, %zu frames (60 fps); closest approach inside the verb (mm; negative: overlap):\n",
                all.clips, all.frames);
    for (const auto& entry : all.hands)
        std::printf("  %-6s hands %7.1f (%s)  hand-body %7.1f (%s)\n", entry.first.c_str(), entry.second.gapMm,
                    all.handsAt[entry.first].c_str(), all.body[entry.first].gapMm, all.bodyAt[entry.first].c_str());
    std::sort(all.breaks.begin(), all.breaks.end(),
              [](const VerbClearanceBreak& a, const VerbClearanceBreak& b) { return a.text < b.text; });
    std::string found;
    std::size_t unknown = 0;
    for (const VerbClearanceBreak& b : all.breaks) {
        bool known = false;
        for (const KnownVerbBreak& k : kKnownVerbBreaks)
            known = known || (b.verb == k.verb && b.version == k.version && b.hands == k.hands && b.gapMm >= k.deepestMm - 0.5f);
        std::printf("  %s%s\n", known ? "" : "NEW: ", b.text.c_str());  // the record (ctest -V)
        if (known) continue;
        if (++unknown <= 40) found += "\n  " + b.text;
    }
    std::printf("%zu stretches break a rule (%zu of them not among kKnownVerbBreaks)\n", all.breaks.size(), unknown);
    EXPECT_EQ(unknown, 0u) << found;
}
