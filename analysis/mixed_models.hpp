#pragma once
// Mixed-effects models of a study's results, fitted by R (docs/analysis.md, "Mixed models"):
//  - comprehension: logistic GLMM (lme4::glmer, binomial), one row per question,
//        correct ~ version + (1 | participant) + (1 | story);
//  - ratings: cumulative-link mixed model (ordinal::clmm, logit), one row per rating,
//        rating ~ version + (1 | participant) + (1 | sentence).
// The rank tests treat repeated measures as independent; these models give participants and
// items random intercepts (the assumption the paper's tests do not meet).
//
// signstim writes the data (CSV) and the R script (analysis/models.R, embedded) into a
// temporary folder, runs Rscript on them as a child process with a time limit (registered
// with common/cleanup.hpp, so SIGINT/SIGTERM end it), and parses the CSV the script writes,
// strictly. The same script and data go into the report (models/), so that a researcher can
// rerun them as they are and get the same numbers.
#include "analysis/results_file.hpp"
#include "stimuli/study/study_listing.hpp"

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace signstim::analysis {

// What the report's models/ folder holds besides R's output.
struct ModelInputs {
    std::string reference;        // the version every estimate is relative to
    std::string script;           // models.R, with the study's versions and the reference filled in
    std::string comprehensionCsv; // participant,story,verb,question,version,correct ("" without phase-1 data)
    std::string ratingsCsv;       // participant,sentence,verb,version,rating ("" without phase-2 data)
};

// The reference version: `requested` when not empty (InputError on the command line when it
// is not a version of the study), else "uninflected" when the study has it (the paper's
// baseline: the sentence without verb inflection), else the study's first version.
std::string modelReference(const stimuli::StudyListing& study, const std::string& requested);

// The long-format data of every result (recomputed correctness; ratings unmapped from the
// panels, unrated panels left out) and the filled-in script. Synthetic results make CSVs
// whose first line says so (a '#' comment, which R's read.csv skips).
ModelInputs modelInputs(const stimuli::StudyListing& study, const std::vector<ParticipantResults>& results,
                        const std::string& reference);

// One line of R's output (analysis/models.R writes them): a number not defined is NaN.
struct ModelRow {
    std::string term;
    double estimate = NAN, stdError = NAN, statistic = NAN, df = NAN, p = NAN, pHolm = NAN;
    std::string note;
};

struct ModelFit {
    std::string name;     // "comprehension" or "ratings"
    std::string formula;  // as R wrote it
    std::string family;
    double observations = NAN;
    std::vector<ModelRow> info;        // observations, participants, stories / sentences
    std::vector<ModelRow> fixed;       // (Intercept) and each version but the reference (vs the reference)
    std::vector<ModelRow> thresholds;  // the CLMM's cut points "1|2", ...
    std::vector<ModelRow> random;      // SD per grouping factor (estimate)
    std::vector<ModelRow> fit;         // logLik, AIC, condHess
    std::vector<ModelRow> pairs;       // "a - b": Wald z, Holm over the pairs
    ModelRow lrt;                      // version vs none: chi-squared (statistic), df, p
    bool hasLrt = false;
    std::vector<ModelRow> warnings;    // term: where (fit, convergence, singular, null model); note: R's message
    std::vector<std::string> errors;   // a model that could not be fitted
};

enum class ModelStatus {
    Skipped,          // --models none
    RMissing,         // no Rscript
    PackagesMissing,  // R without lme4 or ordinal
    Failed,           // R exited with an error, timed out or wrote something unreadable
    Ran,
};

struct MixedModels {
    ModelStatus status = ModelStatus::Skipped;
    std::string message;  // why they were not run, and how to get them (not Ran)
    std::string rVersion, lme4Version, ordinalVersion, reference;
    std::vector<ModelFit> models;  // comprehension first, then ratings (those with data)
    std::string output;            // R's output CSV, as written (models/models-output.csv)
    double seconds = 0;            // how long R ran (not in the report: it varies)
    bool ran() const { return status == ModelStatus::Ran; }
    const ModelFit* find(const std::string& name) const;
};

// Parses what models.R wrote. Anything but its exact header, known sections and numbers
// (or NA) throws EnvironmentError naming the line: R's output is not user input.
MixedModels parseModelOutput(std::string_view csv);

struct ModelRunOptions {
    std::string rscript = "Rscript";  // a name looked up on PATH, or a path
    double timeoutSeconds = 600;
};

// Writes `inputs` into a temporary folder, runs `Rscript --vanilla models.R FOLDER OUTPUT`
// and parses OUTPUT. Never throws for R's problems: the status and message say what happened
// (no Rscript, missing packages, R's error with the end of what it printed, timed out).
MixedModels runMixedModels(const ModelInputs& inputs, const ModelRunOptions& options);

}  // namespace signstim::analysis
