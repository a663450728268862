#pragma once
// A verb instance ready for animation: per hand, keyframes with time, position, orientation
// and handshape (SPEC §3.7). This is the seam to the renderer side: the app turns a
// VerbPerformance into frames (arm IK to reach the hand pose, handshape controls blended
// between keyframes, SPEC §1.5) without knowing which model produced it.
//
//   VerbSources sources{&verbs, &models, scenesDir / "animator"};
//   VerbPerformance p = synthesizeVerb(sources, "ASK", VerbVersion::Point, 0.9, -0.6);
//   for (double t = 0; t <= p.durationSeconds; t += 1 / 30.0)
//       HandSample right = sampleHand(p.hands[0], t);
#include "stimuli/story/handshapes.hpp"
#include "stimuli/verbs/verb_models.hpp"
#include "stimuli/verbs/verbs.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace signstim::stimuli {

enum class VerbVersion { Point, Vector, Animator, Uninflected };
std::string toString(VerbVersion version);  // "point" | "vector" | "animator" | "uninflected"
std::optional<VerbVersion> parseVerbVersion(std::string_view text);

struct PerformanceKeyframe {
    double timeSeconds = 0.0;
    HandPose pose;
    std::string handshape;
    // Where the handshape name was read (VerbPerformance::handshapeFile), for messages.
    int handshapeLine = 0;
    std::string handshapeField;  // JSON pointer
};

struct HandTrack {
    HandSide side = HandSide::Right;
    std::vector<PerformanceKeyframe> keyframes;  // times increase; at least 2
};

struct VerbPerformance {
    std::string verb;
    VerbVersion version = VerbVersion::Uninflected;
    double subject = 0.0;  // 0 for object-only verbs (ignored)
    double object = 0.0;
    double durationSeconds = 0.0;
    std::vector<HandTrack> hands;  // right first
    std::string handshapeFile;     // the verbs file or the animator file the handshapes come from
    SignContact contact;           // the verb's (every version touches as its citation form does)

    const HandTrack* hand(HandSide side) const;
};

// The pose of a hand at time t (clamped to the track): position eased between keyframes
// (smoothstep, so the hand starts and stops gently), orientation by slerp, and the two
// handshapes with the blend weight for interpolating their controls (SPEC §1.5).
struct HandSample {
    HandPose pose;
    std::string handshapeFrom;
    std::string handshapeTo;
    double handshapeBlend = 0.0;  // 0 = from, 1 = to
};
HandSample sampleHand(const HandTrack& track, double timeSeconds);

struct VerbSources {
    const VerbLibrary* verbs = nullptr;
    const TrainedVerbModels* models = nullptr;  // needed for point and vector
    std::filesystem::path animatorDir;          // scenes/animator, needed for animator
    // When given, every handshape of the performance must be in it: an unknown one is refused
    // naming the file, line and field it was read from.
    const HandshapeLibrary* handshapes = nullptr;
};

// Throws InputError for an unknown verb, positions outside [-1, 1] (naming `subjectField` /
// `objectField`), a verb without a trained model, a missing animator file (naming it), an
// unknown handshape (when sources.handshapes is given), and a model that predicts a pose that
// is not finite or outside the signing space (naming the models file): nothing non-finite is
// ever returned.
VerbPerformance synthesizeVerb(const VerbSources& sources, const std::string& verb, VerbVersion version,
                               double subject, double object, const std::string& subjectField = "--subject",
                               const std::string& objectField = "--object");

// synthesizeVerb without the handshape check (what it runs first).
VerbPerformance synthesizeUncheckedVerb(const VerbSources& sources, const std::string& verb, VerbVersion version,
                                        double subject, double object, const std::string& subjectField = "--subject",
                                        const std::string& objectField = "--object");

// Citation times and handshapes around model poses [hand][keyframe]; expands `passes`.
VerbPerformance performanceFromPoses(const VerbDefinition& verb, VerbVersion version, double subject, double object,
                                     const std::vector<std::vector<HandPose>>& poses);

// The keyframe JSON of `signstim verb --json`, which is also the animator file format.
std::string formatPerformanceJson(const VerbPerformance& performance);

// scenes/animator/<VERB>_s<S>_o<O>.json, or <VERB>_o<O>.json for object-only verbs;
// positions printed as in "0.9", "-0.6", "0".
std::string animatorFileName(const VerbDefinition& verb, double subject, double object);

// Reads an animator keyframe file for `verb` at (subject, object); its verb, subject and
// object must match. Its "version" field is informational (a `--version point --json` file
// is a valid starting point).
VerbPerformance loadAnimatorPerformance(const std::filesystem::path& file, const VerbDefinition& verb, double subject,
                                        double object);
VerbPerformance parseAnimatorPerformance(const JsonSource& source, const VerbDefinition& verb, double subject,
                                         double object);

}  // namespace signstim::stimuli
