#pragma once
// Synthetic participants (docs/analysis.md, "Synthetic participants"): results files with a
// known planted effect, to check that the analysis finds what is there and nothing that is
// not. Every participant of the study answers the trials of their schedule in its order:
//  - phase 1: each question is answered correctly with probability
//    logistic(logit(accuracy[version]) + ability), ability ~ N(0, abilitySd) per participant
//    (logit scale); a wrong answer is one of the other choices, uniformly;
//  - phase 2: each panel is rated round(likertMean[version] + bias + N(0, ratingSd)), clamped
//    to the study's scale, bias ~ N(0, biasSd) per participant.
// All draws come from SplitMix64 (common/random.hpp), seeded from (seed, participant id), so a
// participant's data do not depend on how many others there are. The files say SYNTHETIC in
// their name and in a comment line before the header; the analysis report says so too.
#include "stimuli/study/study_listing.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace signstim::analysis {

struct SimulationSettings {
    std::uint64_t seed = 1;
    std::string effect = "planted";  // "planted", "none" or "custom" (for the description)
    std::vector<double> accuracy;    // per study version: P(correct) of an average participant, 0..1
    std::vector<double> likertMean;  // per study version, on the study's scale
    double abilitySd = 0.5;          // between participants, logit scale
    double biasSd = 0.7;             // between participants, scale points (1-to-10 scale; scaled to others)
    double ratingSd = 1.5;           // within a participant, scale points (1-to-10 scale; scaled to others)
};

// The planted effect, by version name: accuracy animator 0.85 > point 0.75 > vector 0.65 >
// uninflected 0.50; mean rating (1-to-10) animator 8.0 > point 6.5 > vector 5.5 > uninflected 4.0,
// mapped linearly onto the study's scale. The standard deviations are scaled the same way.
SimulationSettings plantedEffect(const stimuli::StudyListing& study, std::uint64_t seed);
// No effect: accuracy 0.70 and mean rating 6.0 (1-to-10, mapped) for every version.
SimulationSettings noEffect(const stimuli::StudyListing& study, std::uint64_t seed);

// "accuracy animator 0.85, point 0.75, ...; mean rating animator 8, ...; seed 1".
std::string describeSimulation(const stimuli::StudyListing& study, const SimulationSettings& settings);

struct SimulatedFile {
    std::string name;  // "signstim-results_P07_SYNTHETIC.csv"
    std::string text;  // a comment line saying SYNTHETIC, the results header, one row per trial (CRLF)
};

// One file per participant of the study. Throws std::invalid_argument when the settings do not
// have one value per version or a value is out of range (the command checks its flags first).
std::vector<SimulatedFile> simulateResults(const stimuli::StudyListing& study, const SimulationSettings& settings);

}  // namespace signstim::analysis
