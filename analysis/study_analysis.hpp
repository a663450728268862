#pragma once
// The paper's analysis (Huenerfauth, Lu & Kacorri 2015, Figures 6-8; docs/analysis.md):
//  - phase 1: comprehension accuracy per version, as each participant's proportion of
//    questions answered correctly in the stories they saw in that version, then across
//    participants (one score per participant and version);
//  - phase 2: the 1-to-10 ratings per version (one score per participant, sentence and version);
//  - the same per verb: phase-1 questions belong to the verb they ask about (probeVerb),
//    phase-2 sentences to their verb.
// Each comparison gets descriptives per version, a Kruskal–Wallis test across the versions and
// Mann–Whitney U tests for every pair, Holm-adjusted within the comparison. A pair is marked
// significant when its Holm-adjusted p and the Kruskal–Wallis p are both below alpha.
#include "analysis/rank_tests.hpp"
#include "analysis/results_file.hpp"
#include "stimuli/study/study_listing.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace signstim::analysis {

struct PairTest {
    std::size_t first = 0, second = 0;  // version indices, first < second
    MannWhitneyResult test;
    double pHolm = 0.0;                 // NaN when the test is not defined
    bool significant = false;
};

struct Comparison {
    std::string id;       // "phase1-comprehension", "phase2-likert", "phase2-likert-verb-ASK"
    int phase = 1;
    std::string verb;     // empty: all verbs
    std::string measure;  // "proportion correct", "rating"
    std::vector<std::vector<double>> scores;       // per version
    std::vector<std::vector<std::string>> sources; // per version and score: "P07" or "P07 likert-05"
    std::vector<Descriptives> descriptives;        // per version
    KruskalWallisResult kruskalWallis;
    bool omnibusSignificant = false;               // Kruskal–Wallis p < alpha
    std::vector<PairTest> pairs;                   // (0,1), (0,2), ... (V-2,V-1)
};

// Descriptives, tests and Holm adjustment of per-version scores.
Comparison compareVersions(std::vector<std::vector<double>> scores, std::vector<std::vector<std::string>> sources,
                           double alpha);

struct AnalysisSettings {
    double alpha = 0.05;
};

struct StudyAnalysis {
    std::vector<std::string> versions;  // study order
    double alpha = 0.05;
    int likertMinimum = 1, likertMaximum = 10;
    std::size_t participantsInStudy = 0;
    std::size_t participantsWithData = 0;
    bool synthetic = false;  // any input file says SYNTHETIC
    Comparison comprehension;  // Figure 6
    Comparison likert;         // Figure 7
    std::vector<Comparison> comprehensionByVerb;  // verbs in alphabetical order
    std::vector<Comparison> likertByVerb;         // Figure 8
};

StudyAnalysis analyzeStudy(const stimuli::StudyListing& study, const std::vector<ParticipantResults>& results,
                           const AnalysisSettings& settings);

}  // namespace signstim::analysis
