#pragma once
// The verb models of SPEC §3.4–§3.6, trained on a corpus (stimuli/verbs/corpus.hpp):
//  * PointModel: per hand and keyframe, x, y, z as cubic polynomials of (s, o) (object-only
//    verbs: of o), least squares.
//  * VectorModel (2015): the right hand's movement Δ_k = P_k − P_0 as polynomials; the left
//    hand relative to the right hand per keyframe; a Gaussian mixture of right-hand location
//    (EM, components by BIC) from which the start P_0 is chosen so that the path runs through
//    the most likely region.
//  * Orientation (shared by both, SPEC §3.6): per hand and keyframe the mean rotation q̄ and
//    the SORA vector of q̄⁻¹q fitted component-wise with the same polynomials.
#include "stimuli/verbs/corpus.hpp"
#include "stimuli/verbs/gmm.hpp"
#include "stimuli/verbs/polynomial.hpp"
#include "stimuli/verbs/verbs.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace signstim::stimuli {

struct Vector3Polynomial {
    Polynomial x, y, z;
    glm::dvec3 operator()(double subject, double object) const;
};

struct OrientationModel {
    std::vector<std::vector<glm::dquat>> mean;                 // [hand][keyframe]
    std::vector<std::vector<Vector3Polynomial>> relativeSora;  // Φ of q̄⁻¹q, radians
    glm::dquat predict(std::size_t hand, std::size_t keyframe, double subject, double object) const;
};

struct PointModel {
    std::vector<std::vector<Vector3Polynomial>> position;  // [hand][keyframe], mm
};

struct VectorModel {
    std::vector<Vector3Polynomial> rightMovement;  // keyframes 1..K−1: P_k − P_0, mm
    std::vector<Vector3Polynomial> leftRelative;   // keyframes 0..K−1: L_k − R_k (two-handed)
    GaussianMixture rightLocation;
    glm::dvec3 searchMinMm{0.0};  // bounding box of the mixture's training points
    glm::dvec3 searchMaxMm{0.0};
};

struct VerbModel {
    std::string verb;
    int sourceLine = 0;  // line of its entry in the models file (0: trained in memory)
    PolynomialBasis basis;
    std::size_t hands = 0;
    std::size_t keyframes = 0;
    std::size_t trainingExamples = 0;
    PointModel point;
    VectorModel vector;
    OrientationModel orientation;
};

struct TrainedVerbModels {
    std::string corpusDescription;  // what they were trained on (file name, first comment)
    std::string sourceFile;         // the models file they were read from, or the corpus trained on
    std::vector<VerbModel> verbs;
    const VerbModel* find(const std::string& verb) const;
};

struct ModelOptions {
    int degree = 3;      // SPEC §3.4; 1 and 2 are the evaluation's lower-order baselines
    double ridge = 0.0;  // optional small ridge (SPEC §3.4)
    MixtureFitOptions mixture;
};

// Throws InputError when there are fewer examples than polynomial terms.
VerbModel trainVerbModel(const VerbDefinition& verb, const std::vector<const CorpusExample*>& examples,
                         const ModelOptions& options = {});
// Every verb of the library that has examples in the corpus.
TrainedVerbModels trainVerbModels(const Corpus& corpus, const VerbLibrary& verbs, const ModelOptions& options = {});

// Poses [hand][keyframe]. Subject is ignored by object-only verbs.
std::vector<std::vector<HandPose>> predictPoint(const VerbModel& model, double subject, double object);
std::vector<std::vector<HandPose>> predictVector(const VerbModel& model, double subject, double object);

// SPEC §3.5 [D]: P₀* = argmax Σⱼ log p(P₀ + offset_j) over points j/10 along each segment of
// the path given by `offsets` (offsets[0] = 0): a 9×9×9 grid over the box, then a pattern
// search with halving steps.
glm::dvec3 mostLikelyStart(const GaussianMixture& mixture, const glm::dvec3& boxMin, const glm::dvec3& boxMax,
                           const std::vector<glm::dvec3>& offsets);
std::vector<glm::dvec3> pathSamples(const std::vector<glm::dvec3>& keyframePositions);  // j/10 along segments

// JSON: deterministic text (numbers rounded to 10 significant digits) so that training the
// same corpus reproduces the file byte for byte.
std::string formatVerbModels(const TrainedVerbModels& models);
// formatVerbModels, then the text read back through parseVerbModels before it is returned, so
// that `signstim train` never writes a file it would refuse to read: a refusal is an InputError
// naming the corpus (models.sourceFile) and what the reader said.
std::string formatCheckedVerbModels(const TrainedVerbModels& models, const VerbLibrary& verbs,
                                    const std::string& outputName);
// Checks the models against the verb library (hands, keyframes, class); a mismatch asks to
// retrain with `signstim train`. Every number must be finite and within its range
// (stimuli/number_ranges.hpp).
TrainedVerbModels parseVerbModels(const JsonSource& source, const VerbLibrary& verbs);
TrainedVerbModels loadVerbModels(const std::filesystem::path& path, const VerbLibrary& verbs);

}  // namespace signstim::stimuli
