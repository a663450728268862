#pragma once
// The reference performer (SPEC §3.3): a documented parametric signer that produces the
// shipped, clearly synthetic, reference corpus in the same CSV format a lab's motion capture
// is exported to (stimuli/verbs/corpus.hpp). Its parameters live in
// scenes/corpus/reference_performer.json; docs/verbs.md describes it.
//
// For each verb example (s, o), each hand h and keyframe k, starting from the citation pose C:
//  1. Rule "arc" (default): the hand turns about the vertical torso axis through
//     `torsoPivotMm` by θ = a_s·ψ(s) + a_o·ψ(o) (ψ = 90°·p, SPEC §3.1), and reaches out
//     radially by reachMm·((s − o)/2)²; the palm frame turns about the vertical by
//     b_s·ψ(s) + b_o·ψ(o), or — with "yaw": "path" — by the change of the right hand's path
//     heading. This is the citation path bent toward the subject and the object.
//     Rule "rigidWithRight": k' — the hand keeps its citation pose relative to the right hand
//     at keyframe k' (two hands that move as a pair or touch).
//     Rule "followsRightPath": f — it keeps its citation pose relative to the point at
//     fraction f of the right hand's path, turned with the path's heading (EMAIL's C).
//  2. Personal bias, the same in every example: positions scaled about the pivot by
//     `reachGain`, shifted by `offsetMm`; orientations turned by `yawDeg` about the vertical.
//  3. Noise: independent Gaussian position noise (σ = positionMm per axis) and orientation
//     noise (a rotation vector with σ = orientationDeg per axis), drawn with SplitMix64.
#include "stimuli/verbs/corpus.hpp"
#include "stimuli/json_source.hpp"
#include "stimuli/verbs/verbs.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace signstim::stimuli {

struct PerformerRule {
    enum class Kind { Arc, RigidWithRight, FollowsRightPath } kind = Kind::Arc;
    double towardSubject = 0.0;  // fractions of ψ for the position's turn
    double towardObject = 0.0;
    double reachMm = 0.0;
    bool yawFollowsPath = false;
    double yawTowardSubject = 0.0;  // fractions of ψ for the palm frame's turn
    double yawTowardObject = 0.0;
    int rightKeyframe = 0;      // RigidWithRight
    double pathFraction = 0.0;  // FollowsRightPath
};

struct ReferencePerformer {
    std::uint64_t seed = 2015;
    glm::dvec3 torsoPivotMm{0.0, 0.0, -100.0};
    std::vector<double> arcPositions;  // SPEC §3.3: {−0.9, −0.6, −0.3, 0, 0.3, 0.6, 0.9}
    glm::dvec3 biasOffsetMm{0.0};
    double biasReachGain = 1.0;
    double biasYawDeg = 0.0;
    double noisePositionMm = 0.0;
    double noiseOrientationDeg = 0.0;
    std::vector<std::string> description;  // written as '#' lines into the corpus header
    std::map<std::string, std::vector<std::vector<PerformerRule>>> rules;  // verb → [hand][keyframe]
};

ReferencePerformer loadReferencePerformer(const std::filesystem::path& path, const VerbLibrary& verbs);
ReferencePerformer parseReferencePerformer(const JsonSource& source, const VerbLibrary& verbs);

// The noise-free, bias-free inflected pose of every hand and keyframe (step 1 above).
std::vector<std::vector<HandPose>> performVerb(const ReferencePerformer& performer, const VerbDefinition& verb,
                                               double subject, double object);

// All verbs × (7 positions × 6 others, s ≠ o): 42 examples per verb, bias and noise applied.
Corpus generateReferenceCorpus(const ReferencePerformer& performer, const VerbLibrary& verbs);

}  // namespace signstim::stimuli
