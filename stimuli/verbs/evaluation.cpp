#include "stimuli/verbs/evaluation.hpp"

#include "stimuli/verbs/sora.hpp"
#include "stimuli/verbs/verb_models.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <numbers>
#include <set>

namespace signstim::stimuli {
namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

using Predictor = std::function<std::vector<std::vector<HandPose>>(const std::vector<const CorpusExample*>& training,
                                                                   const CorpusExample& heldOut)>;

struct Accumulator {
    double position = 0.0, direction = 0.0, orientation = 0.0;
    std::size_t positionCount = 0, directionCount = 0, examples = 0;

    void add(const std::vector<std::vector<HandPose>>& predicted, const CorpusExample& truth) {
        for (std::size_t h = 0; h < truth.poses.size(); ++h)
            for (std::size_t k = 0; k < truth.poses[h].size(); ++k) {
                position += glm::length(predicted[h][k].positionMm - truth.poses[h][k].positionMm);
                orientation += rotationAngleBetween(predicted[h][k].orientation, truth.poses[h][k].orientation);
                ++positionCount;
            }
        const glm::dvec3 d0 = predicted[0].back().positionMm - predicted[0].front().positionMm;
        const glm::dvec3 d1 = truth.poses[0].back().positionMm - truth.poses[0].front().positionMm;
        if (glm::length(d0) > 1e-9 && glm::length(d1) > 1e-9) {
            direction += std::acos(std::clamp(glm::dot(glm::normalize(d0), glm::normalize(d1)), -1.0, 1.0));
            ++directionCount;
        }
        ++examples;
    }
    ErrorSummary summary() const {
        ErrorSummary s;
        if (positionCount) {
            s.positionMm = position / positionCount;
            s.orientationDeg = orientation / positionCount * kDegreesPerRadian;
        }
        if (directionCount) s.directionDeg = direction / directionCount * kDegreesPerRadian;
        s.predictions = examples;
        return s;
    }
};

}  // namespace

std::vector<EvaluationRow> evaluateVerbModels(const Corpus& corpus, const VerbLibrary& verbs) {
    std::vector<EvaluationRow> rows;
    for (const VerbDefinition& verb : verbs.verbs) {
        const std::vector<const CorpusExample*> examples = corpus.examplesOf(verb.name);
        if (examples.empty()) continue;
        const std::string& corpusFile = corpus.sourceFile;
        const auto trained = [&verb, &corpusFile](int degree, bool vector) -> Predictor {
            return [&verb, &corpusFile, degree, vector](const std::vector<const CorpusExample*>& training, const CorpusExample& heldOut) {
                ModelOptions options;
                options.degree = degree;
                const VerbModel model = [&] {
                    try {
                        return trainVerbModel(verb, training, options);
                    } catch (const InputError& e) {
                        // Too few examples for a fold: name the corpus and the verb's first row.
                        throw InputError(corpusFile, training.empty() ? 0 : training.front()->firstLine, "verb",
                                         e.detail() + " (leave-one-out folds train on one example fewer)");
                    }
                }();
                return vector ? predictVector(model, heldOut.subject, heldOut.object)
                              : predictPoint(model, heldOut.subject, heldOut.object);
            };
        };
        const Predictor uninflected = [&verb](const std::vector<const CorpusExample*>&, const CorpusExample&) {
            std::vector<std::vector<HandPose>> poses;
            for (const auto& track : verb.citation) {
                poses.emplace_back();
                for (const VerbKeyframe& key : track) poses.back().push_back(key.pose);
            }
            return poses;
        };
        const std::vector<std::pair<std::string, Predictor>> predictors{
            {"point", trained(3, false)},       {"vector", trained(3, true)}, {"point-quadratic", trained(2, false)},
            {"point-linear", trained(1, false)}, {"uninflected", uninflected}};
        std::set<double> positions;
        for (const CorpusExample* e : examples) {
            positions.insert(e->object);
            if (!verb.objectOnly()) positions.insert(e->subject);
        }
        for (const auto& [name, predict] : predictors) {
            EvaluationRow row;
            row.verb = verb.name;
            row.model = name;
            Accumulator leaveOne;
            for (std::size_t i = 0; i < examples.size(); ++i) {
                std::vector<const CorpusExample*> training;
                for (std::size_t j = 0; j < examples.size(); ++j)
                    if (j != i) training.push_back(examples[j]);
                leaveOne.add(predict(training, *examples[i]), *examples[i]);
            }
            row.leaveOneOut = leaveOne.summary();
            Accumulator leavePosition;
            for (double p : positions) {
                std::vector<const CorpusExample*> training, held;
                for (const CorpusExample* e : examples) {
                    const bool involves = e->object == p || (!verb.objectOnly() && e->subject == p);
                    (involves ? held : training).push_back(e);
                }
                if (held.empty() || training.size() < PolynomialBasis{verb.inflection, 3}.termCount()) continue;
                for (const CorpusExample* e : held) leavePosition.add(predict(training, *e), *e);
            }
            row.leaveOnePositionOut = leavePosition.summary();
            rows.push_back(row);
        }
    }
    return rows;
}

std::string formatEvaluationTable(const std::vector<EvaluationRow>& rows) {
    std::string out =
        "| verb | model | LOO position (mm) | LOO direction (°) | LOO orientation (°) | LOPO position (mm) | "
        "LOPO direction (°) | LOPO orientation (°) |\n"
        "|---|---|---:|---:|---:|---:|---:|---:|\n";
    char buffer[256];
    for (const EvaluationRow& r : rows) {
        std::snprintf(buffer, sizeof buffer, "| %s | %s | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f |\n", r.verb.c_str(),
                      r.model.c_str(), r.leaveOneOut.positionMm, r.leaveOneOut.directionDeg, r.leaveOneOut.orientationDeg,
                      r.leaveOnePositionOut.positionMm, r.leaveOnePositionOut.directionDeg,
                      r.leaveOnePositionOut.orientationDeg);
        out += buffer;
    }
    // Means per model over the verbs.
    std::map<std::string, std::pair<std::array<double, 6>, int>> means;
    std::vector<std::string> order;
    for (const EvaluationRow& r : rows) {
        auto [it, inserted] = means.try_emplace(r.model);
        if (inserted) order.push_back(r.model);
        const std::array<double, 6> v{r.leaveOneOut.positionMm,         r.leaveOneOut.directionDeg,
                                      r.leaveOneOut.orientationDeg,     r.leaveOnePositionOut.positionMm,
                                      r.leaveOnePositionOut.directionDeg, r.leaveOnePositionOut.orientationDeg};
        for (int i = 0; i < 6; ++i) it->second.first[static_cast<std::size_t>(i)] += v[static_cast<std::size_t>(i)];
        ++it->second.second;
    }
    for (const std::string& model : order) {
        const auto& [sum, count] = means[model];
        std::snprintf(buffer, sizeof buffer, "| **all** | %s | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f |\n", model.c_str(),
                      sum[0] / count, sum[1] / count, sum[2] / count, sum[3] / count, sum[4] / count, sum[5] / count);
        out += buffer;
    }
    return out;
}

}  // namespace signstim::stimuli
