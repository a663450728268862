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
#include "common/error.hpp"
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
    // An animator file marked "draft": true — a starting point (`signstim animator draft`), not
    // yet an animator's work. A study refuses it unless --allow-draft-animator (docs/verbs.md).
    bool draft = false;

    const HandTrack* hand(HandSide side) const;
};

// The pose of a hand at time t (clamped to the track): position eased between keyframes
// (smoothstep, so the hand starts and stops gently) on the path swept about the torso's axis
// (signing_space.hpp, sweptPathPoint: around the chest, not through it), orientation by
// slerp, and the two
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

// What synthesizeVerb throws when the animator version's keyframe file is missing: an
// InputError naming the file, which `file()` also gives. Callers that can do without the
// animator version (point, vector and uninflected stories) catch it (stimuli/story/timeline.hpp).
class MissingAnimatorFile : public InputError {
public:
    MissingAnimatorFile(const std::string& file, const std::string& message, std::string animatorFile)
        : InputError(file, 0, "", message), animatorFile_(std::move(animatorFile)) {}
    MissingAnimatorFile(const std::string& file, int line, int column, const std::string& message, std::string animatorFile)
        : InputError(file, line, column, "", message), animatorFile_(std::move(animatorFile)) {}
    const std::string& animatorFile() const { return animatorFile_; }

private:
    std::string animatorFile_;
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

// The keyframe JSON of `signstim verb --json`, which is also the animator file format (with
// "draft": true when performance.draft).
std::string formatPerformanceJson(const VerbPerformance& performance);

// The starting animator file for (verb, subject, object): the point model's performance,
// marked "draft": true (`signstim animator draft`).
std::string formatAnimatorDraft(const VerbSources& sources, const std::string& verb, double subject, double object);

// Whether two performances have the same keyframes (times, positions, orientations and
// handshapes, to the precision formatPerformanceJson writes): an animator file that is not
// marked as a draft but equals the point model's output is a copied draft (story --check warns).
bool sameKeyframes(const VerbPerformance& a, const VerbPerformance& b);

// scenes/animator/<VERB>_s<S>_o<O>.json, or <VERB>_o<O>.json for object-only verbs;
// positions printed as in "0.9", "-0.6", "0".
std::string animatorFileName(const VerbDefinition& verb, double subject, double object);

// Reads an animator keyframe file for `verb` at (subject, object); its verb, subject and
// object must match. Its "version" field is informational (a `--version point --json` file
// is a valid starting point); "draft" (optional, true or false) sets VerbPerformance::draft.
VerbPerformance loadAnimatorPerformance(const std::filesystem::path& file, const VerbDefinition& verb, double subject,
                                        double object);
VerbPerformance parseAnimatorPerformance(const JsonSource& source, const VerbDefinition& verb, double subject,
                                         double object);

}  // namespace signstim::stimuli
