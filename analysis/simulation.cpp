#include "analysis/simulation.hpp"

#include "analysis/results_file.hpp"
#include "common/number_format.hpp"
#include "common/random.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace signstim::analysis {

namespace {

using stimuli::StudyListing;

// The 1-to-10 scale of the defaults, mapped linearly onto the study's.
double onStudyScale(const StudyListing& study, double onTenPointScale) {
    return study.likertMinimum + (onTenPointScale - 1.0) / 9.0 * (study.likertMaximum - study.likertMinimum);
}
double scaleFactor(const StudyListing& study) { return (study.likertMaximum - study.likertMinimum) / 9.0; }

double byName(const std::map<std::string, double>& values, const std::string& version, double otherwise) {
    const auto it = values.find(version);
    return it == values.end() ? otherwise : it->second;
}

double logistic(double x) { return 1.0 / (1.0 + std::exp(-x)); }
double logit(double p) { return std::log(p / (1.0 - p)); }

std::string row(const std::map<std::string, std::string>& cells) {
    std::string out;
    const std::vector<std::string>& columns = resultsColumns();
    for (std::size_t i = 0; i < columns.size(); ++i) {
        if (i > 0) out += ',';
        const auto it = cells.find(columns[i]);
        if (it != cells.end()) out += it->second;  // ids, letters and numbers: nothing to quote
    }
    return out + "\r\n";
}

}  // namespace

SimulationSettings plantedEffect(const StudyListing& study, std::uint64_t seed) {
    const std::map<std::string, double> accuracy = {{"animator", 0.85}, {"point", 0.75}, {"vector", 0.65}, {"uninflected", 0.50}};
    const std::map<std::string, double> likert = {{"animator", 8.0}, {"point", 6.5}, {"vector", 5.5}, {"uninflected", 4.0}};
    SimulationSettings s;
    s.seed = seed;
    s.effect = "planted";
    for (const std::string& v : study.versions) {
        s.accuracy.push_back(byName(accuracy, v, 0.70));
        s.likertMean.push_back(onStudyScale(study, byName(likert, v, 6.0)));
    }
    s.biasSd *= scaleFactor(study);
    s.ratingSd *= scaleFactor(study);
    return s;
}

SimulationSettings noEffect(const StudyListing& study, std::uint64_t seed) {
    SimulationSettings s;
    s.seed = seed;
    s.effect = "none";
    s.accuracy.assign(study.versions.size(), 0.70);
    s.likertMean.assign(study.versions.size(), onStudyScale(study, 6.0));
    s.biasSd *= scaleFactor(study);
    s.ratingSd *= scaleFactor(study);
    return s;
}

std::string describeSimulation(const StudyListing& study, const SimulationSettings& s) {
    std::string accuracy, likert;
    for (std::size_t v = 0; v < study.versions.size(); ++v) {
        accuracy += (v ? ", " : "") + study.versions[v] + " " + formatNumber(s.accuracy[v]);
        likert += (v ? ", " : "") + study.versions[v] + " " + formatNumber(s.likertMean[v]);
    }
    return "effect " + s.effect + ": accuracy " + accuracy + "; mean rating " + likert + " (scale " +
           std::to_string(study.likertMinimum) + " to " + std::to_string(study.likertMaximum) + "); SD of ability " +
           formatNumber(s.abilitySd) + " (logit), of rating bias " + formatNumber(s.biasSd) + ", of ratings " +
           formatNumber(s.ratingSd) + "; seed " + std::to_string(s.seed);
}

std::vector<SimulatedFile> simulateResults(const StudyListing& study, const SimulationSettings& s) {
    const std::size_t versions = study.versions.size();
    if (s.accuracy.size() != versions || s.likertMean.size() != versions)
        throw std::invalid_argument("simulateResults: one accuracy and one mean rating per version");
    for (double a : s.accuracy)
        if (!(a > 0.0 && a < 1.0)) throw std::invalid_argument("simulateResults: accuracy must be between 0 and 1 (exclusive)");
    for (double m : s.likertMean)
        if (!(m >= study.likertMinimum && m <= study.likertMaximum))
            throw std::invalid_argument("simulateResults: a mean rating is outside the study's scale");
    if (!(s.abilitySd >= 0.0 && s.biasSd >= 0.0 && s.ratingSd >= 0.0))
        throw std::invalid_argument("simulateResults: standard deviations must be >= 0");

    const std::string comment = "# SYNTHETIC participant data made by `signstim simulate-results`, not responses of people: " +
                                describeSimulation(study, s) + "\r\n";
    std::string header;
    for (const std::string& column : resultsColumns()) header += (header.empty() ? "" : ",") + column;
    header += "\r\n";

    std::vector<SimulatedFile> files;
    for (const stimuli::ListedParticipant& participant : study.participants) {
        SplitMix64 rng(mixSeed(s.seed, hashString(participant.id)));
        const double ability = s.abilitySd * rng.normal();
        const double bias = s.biasSd * rng.normal();
        std::string text = comment + header;
        for (const stimuli::ListedPhase1Trial& trial : participant.phase1) {
            const stimuli::ListedStory& story = study.stories[trial.story];
            std::map<std::string, std::string> cells = {{"participant", participant.id},
                                                        {"phase", "1"},
                                                        {"trial", std::to_string(trial.trial)},
                                                        {"story_id", story.id},
                                                        {"version", study.versions[trial.version]}};
            const double pCorrect = logistic(logit(s.accuracy[trial.version]) + ability);
            int correctCount = 0;
            for (std::size_t q = 0; q < story.questions.size() && q < 4; ++q) {
                const stimuli::ListedQuestion& question = story.questions[q];
                // A question with one choice cannot be answered wrongly (the draw is made all the same,
                // so the numbers that follow do not depend on it).
                const bool correct = rng.uniform() < pCorrect || question.choices.size() < 2;
                std::size_t choice = static_cast<std::size_t>(question.answer);
                if (!correct) {
                    // One of the other choices, uniformly.
                    choice = static_cast<std::size_t>(rng.below(question.choices.size() - 1));
                    if (choice >= static_cast<std::size_t>(question.answer)) ++choice;
                }
                correctCount += correct ? 1 : 0;
                const std::string n = std::to_string(q + 1);
                cells["q" + n + "_response"] = std::string(1, static_cast<char>('A' + choice));
                cells["q" + n + "_correct"] = correct ? "1" : "0";
            }
            cells["n_correct"] = std::to_string(correctCount);
            cells["rt_ms"] = std::to_string(20000 + rng.below(40000));
            text += row(cells);
        }
        for (const stimuli::ListedPhase2Trial& trial : participant.phase2) {
            const stimuli::ListedSentence& sentence = study.sentences[trial.sentence];
            std::map<std::string, std::string> cells = {{"participant", participant.id},
                                                        {"phase", "2"},
                                                        {"trial", std::to_string(trial.trial)},
                                                        {"sentence_id", sentence.id},
                                                        {"panel_code", sentence.panelCode}};
            for (std::size_t k = 0; k < sentence.panelVersion.size(); ++k) {
                const std::size_t version = sentence.panelVersion[k];
                const double drawn = s.likertMean[version] + bias + s.ratingSd * rng.normal();
                const long rating = std::clamp(std::lround(drawn), static_cast<long>(study.likertMinimum),
                                               static_cast<long>(study.likertMaximum));
                cells[std::string("rating_") + static_cast<char>('a' + k)] = std::to_string(rating);
                cells["rating_" + study.versions[version]] = std::to_string(rating);
            }
            cells["rt_ms"] = std::to_string(5000 + rng.below(25000));
            text += row(cells);
        }
        files.push_back({"signstim-results_" + participant.id + "_SYNTHETIC.csv", std::move(text)});
    }
    return files;
}

}  // namespace signstim::analysis
