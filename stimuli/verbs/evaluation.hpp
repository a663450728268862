#pragma once
// Cross-validated errors of the verb models (SPEC §3.8): leave-one-out over a verb's
// examples and leave-one-arc-position-out (every example whose subject or object is at the
// held-out position; object-only verbs: whose object is), beside the uninflected citation
// form and lower-order PointModels.
#include "stimuli/verbs/corpus.hpp"
#include "stimuli/verbs/verbs.hpp"

#include <string>
#include <vector>

namespace signstim::stimuli {

struct ErrorSummary {
    double positionMm = 0.0;      // mean over held-out examples, hands and keyframes
    double directionDeg = 0.0;    // mean angle between predicted and true right-hand Δ
    double orientationDeg = 0.0;  // mean 2·acos|⟨q̂, q⟩| over hands and keyframes
    std::size_t predictions = 0;  // held-out examples scored
};

struct EvaluationRow {
    std::string verb;
    std::string model;  // "point", "vector", "point-quadratic", "point-linear", "uninflected"
    ErrorSummary leaveOneOut;
    ErrorSummary leaveOnePositionOut;
};

std::vector<EvaluationRow> evaluateVerbModels(const Corpus& corpus, const VerbLibrary& verbs);
std::string formatEvaluationTable(const std::vector<EvaluationRow>& rows);  // Markdown

}  // namespace signstim::stimuli
