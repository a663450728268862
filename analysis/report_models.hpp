#pragma once
// The mixed models in the report (docs/analysis.md, "Mixed models"): next to each phase's rank
// tests, the model's likelihood-ratio test, its estimates against the reference version (log
// odds or log cumulative odds, SE, z, p, odds ratio with its Wald 95% interval), the random
// effects, the CLMM's thresholds, every pair's Wald test beside the Mann–Whitney test of the
// same pair, and every warning R gave. When the models were not run, the report says why and
// how to get them.
#include "analysis/mixed_models.hpp"
#include "analysis/study_analysis.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace signstim::analysis {

// The model's part of a phase's section ("comprehension" with the phase-1 comparison,
// "ratings" with phase 2).
std::string modelPhaseHtml(const StudyAnalysis& analysis, const Comparison& ranks, const MixedModels& models,
                           const std::string& modelName);

// The section on the models: software, how to rerun them, and the status when not run.
std::string modelsSectionHtml(const MixedModels& models);

// summary.json's "mixedModels".
nlohmann::json modelsJson(const MixedModels& models);

// One line for the command's summary on stdout.
std::string modelsSummaryLine(const MixedModels& models);

}  // namespace signstim::analysis
