// Synthetic participants on the paper's design (12 stories x 4 versions, 24 participants,
// 8 side-by-side sentences): the analysis recovers a planted ordering with significant
// Kruskal–Wallis tests, finds nothing at a fixed seed without an effect, and over many seeds
// without an effect rejects at about alpha or less. The files are deterministic and a
// participant's file does not depend on how many others there are.
#include "analysis/simulation.hpp"
#include "analysis/study_analysis.hpp"
#include "tests/stimuli/review_page_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace {

using namespace signstim::analysis;
using signstim::stimuli::StudyListing;

const StudyListing& study() {
    static const StudyListing listing = signstim::stimuli::testing::reviewFixtureListing();
    return listing;
}

StudyAnalysis analyzeSimulation(const SimulationSettings& settings, std::vector<std::string>* warningsOut = nullptr) {
    std::vector<ParticipantResults> results;
    std::vector<std::string> warnings;
    for (const SimulatedFile& f : simulateResults(study(), settings))
        results.push_back(parseResults(f.text, f.name, study(), {}, warnings));
    if (warningsOut) *warningsOut = warnings;
    return analyzeStudy(study(), results, {});
}

std::size_t versionIndex(const std::string& name) {
    return static_cast<std::size_t>(std::find(study().versions.begin(), study().versions.end(), name) - study().versions.begin());
}

// Versions from the highest mean to the lowest.
std::vector<std::string> ordering(const Comparison& c) {
    std::vector<std::string> names = study().versions;
    std::sort(names.begin(), names.end(), [&](const std::string& a, const std::string& b) {
        return c.descriptives[versionIndex(a)].mean > c.descriptives[versionIndex(b)].mean;
    });
    return names;
}

const PairTest& pair(const Comparison& c, const std::string& a, const std::string& b) {
    for (const PairTest& p : c.pairs)
        if (study().versions[p.first] == a && study().versions[p.second] == b) return p;
    for (const PairTest& p : c.pairs)
        if (study().versions[p.first] == b && study().versions[p.second] == a) return p;
    throw std::logic_error("no such pair");
}

TEST(Simulation, PlantedOrderingIsRecoveredWithSignificantKruskalWallis) {
    std::vector<std::string> warnings;
    const StudyAnalysis a = analyzeSimulation(plantedEffect(study(), 1), &warnings);
    EXPECT_TRUE(warnings.empty());
    EXPECT_TRUE(a.synthetic);
    const std::vector<std::string> planted = {"animator", "point", "vector", "uninflected"};
    EXPECT_EQ(ordering(a.comprehension), planted);
    EXPECT_EQ(ordering(a.likert), planted);
    EXPECT_LT(a.comprehension.kruskalWallis.p, 0.001) << a.comprehension.kruskalWallis.h;
    EXPECT_LT(a.likert.kruskalWallis.p, 1e-10) << a.likert.kruskalWallis.h;
    // One score per participant and version in phase 1, one per rating in phase 2.
    for (std::size_t v = 0; v < 4; ++v) {
        EXPECT_EQ(a.comprehension.descriptives[v].n, 24u);
        EXPECT_EQ(a.likert.descriptives[v].n, 24u * 8u);
    }
    // The largest planted differences are significant after Holm, in the planted direction.
    for (const Comparison* c : {&a.comprehension, &a.likert}) {
        const PairTest& extreme = pair(*c, "animator", "uninflected");
        EXPECT_TRUE(extreme.significant);
        EXPECT_LT(extreme.pHolm, 0.001);
        const double r = extreme.test.rankBiserial * (study().versions[extreme.first] == "animator" ? 1 : -1);
        EXPECT_GT(r, 0.5);
    }
    // Per verb: 8 ratings-comparisons, each with 24 ratings per version.
    ASSERT_EQ(a.likertByVerb.size(), 8u);
    for (const Comparison& c : a.likertByVerb) EXPECT_EQ(c.descriptives[0].n, 24u) << c.verb;
}

TEST(Simulation, NoEffectFindsNoSignificantDifferenceAtAFixedSeed) {
    const StudyAnalysis a = analyzeSimulation(noEffect(study(), 1));
    EXPECT_GT(a.comprehension.kruskalWallis.p, 0.05);
    EXPECT_GT(a.likert.kruskalWallis.p, 0.05);
    for (const Comparison* c : {&a.comprehension, &a.likert})
        for (const PairTest& p : c->pairs) EXPECT_FALSE(p.significant);
}

// Over 200 seeds without an effect, the Kruskal–Wallis tests reject at about alpha or less.
// With participants' own levels (ability, rating bias) shared by every version, the tests
// that treat scores as independent are conservative (docs/analysis.md); without them they
// should be near 0.05. Binomial(200, 0.05) has SD 0.015.
TEST(Simulation, FalsePositiveRateOverSeedsIsNearAlphaOrBelow) {
    for (const bool participantEffects : {true, false}) {
        int phase1 = 0, phase2 = 0;
        const int seeds = 200;
        for (int seed = 1; seed <= seeds; ++seed) {
            SimulationSettings s = noEffect(study(), static_cast<std::uint64_t>(seed));
            if (!participantEffects) s.abilitySd = s.biasSd = 0.0;
            const StudyAnalysis a = analyzeSimulation(s);
            phase1 += a.comprehension.kruskalWallis.p < 0.05;
            phase2 += a.likert.kruskalWallis.p < 0.05;
        }
        const double rate1 = static_cast<double>(phase1) / seeds, rate2 = static_cast<double>(phase2) / seeds;
        RecordProperty(participantEffects ? "with_participant_effects" : "without",
                       std::to_string(rate1) + " " + std::to_string(rate2));
        EXPECT_LE(rate1, 0.09) << participantEffects;
        EXPECT_LE(rate2, 0.09) << participantEffects;
        if (!participantEffects) {
            EXPECT_GE(rate1, 0.015);
            EXPECT_GE(rate2, 0.015);
        }
    }
}

TEST(Simulation, SameSeedSameBytesAndParticipantsDoNotDependOnEachOther) {
    const std::vector<SimulatedFile> a = simulateResults(study(), plantedEffect(study(), 9));
    const std::vector<SimulatedFile> b = simulateResults(study(), plantedEffect(study(), 9));
    ASSERT_EQ(a.size(), 24u);
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].name, b[i].name);
        EXPECT_EQ(a[i].text, b[i].text);
    }
    EXPECT_EQ(a[6].name, "signstim-results_P07_SYNTHETIC.csv");
    EXPECT_EQ(a[6].text.rfind("# SYNTHETIC participant data", 0), 0u);
    EXPECT_NE(a[0].text, simulateResults(study(), plantedEffect(study(), 10))[0].text);
    // A study of 28 participants: the first 24 have the same schedules, so the same files.
    signstim::stimuli::testing::ReviewFixtureShape shape;
    shape.participants = 28;
    const StudyListing larger = signstim::stimuli::testing::reviewFixtureListing(shape);
    const std::vector<SimulatedFile> c = simulateResults(larger, plantedEffect(larger, 9));
    ASSERT_EQ(c.size(), 28u);
    for (std::size_t i = 0; i < 24; ++i) EXPECT_EQ(c[i].text, a[i].text) << i;
}

TEST(Simulation, CustomEffectsAndScalesAreHonoured) {
    StudyListing fivePoint = study();
    fivePoint.likertMinimum = 1;
    fivePoint.likertMaximum = 5;
    SimulationSettings s = plantedEffect(fivePoint, 2);
    EXPECT_DOUBLE_EQ(s.likertMean[versionIndex("animator")], 1.0 + 7.0 / 9.0 * 4.0);
    s.accuracy = {0.2, 0.2, 0.95, 0.2};
    std::vector<ParticipantResults> results;
    std::vector<std::string> warnings;
    for (const SimulatedFile& f : simulateResults(fivePoint, s)) {
        results.push_back(parseResults(f.text, f.name, fivePoint, {}, warnings));
        for (const Phase2Result& t : results.back().phase2)
            for (double r : t.ratings) {
                EXPECT_GE(r, 1.0);
                EXPECT_LE(r, 5.0);
            }
    }
    const StudyAnalysis a = analyzeStudy(fivePoint, results, {});
    EXPECT_EQ(ordering(a.comprehension).front(), "animator");
    EXPECT_THROW(simulateResults(study(), SimulationSettings{}), std::invalid_argument);
}

}  // namespace
