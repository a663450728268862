#pragma once
// The analysis report folder (docs/analysis.md, "Outputs"), as files in memory; the command
// writes them as one unit (common/atomic_file.hpp TemporaryFolder):
//   report.html         self-contained: every figure inline (SVG), tables, data checks, methods
//   figures/NAME.svg    each figure as a vector file
//   figures/NAME.png    the same drawing rasterized at ReportInputs::dpi (analysis/figure_png.hpp)
//   results.csv         descriptives of every cell of every figure (comparison x version)
//   tests.csv           every Kruskal–Wallis and Mann–Whitney test with Holm-adjusted p
//   scores.csv          every score that went into a test (to re-run it elsewhere)
//   summary.json        all of the above as one JSON document, with the inputs' SHA-256
//   models/             the mixed models' R script, its data and R's output (analysis/mixed_models.hpp)
// Same analysis, same bytes: no dates, file names without their folders, numbers to 6
// significant digits (never NaN or infinity: an undefined value is null in JSON, an empty cell
// in CSV and a dash in HTML).
#include "analysis/figures.hpp"
#include "analysis/mixed_models.hpp"
#include "analysis/results_file.hpp"
#include "analysis/study_analysis.hpp"

#include <string>
#include <vector>

namespace signstim::analysis {

struct ReportInputs {
    std::string studyTitle;
    std::string designHash;
    std::string manifestName;   // "manifest.json" of the study folder's name: "small-study/manifest.json"
    std::string columnMapName;  // "" when none
    const std::vector<ParticipantResults>* results = nullptr;
    std::vector<std::string> warnings;
    // The mixed models: their script and data (written to models/ whenever given) and what R
    // made of them (or why it did not run). Null: the report has no models section.
    const ModelInputs* modelInputs = nullptr;
    const MixedModels* models = nullptr;
    // The PNG figures' resolution (analysis/figure_png.hpp).
    double dpi = 0;  // 0: the default
};

struct ReportFile {
    std::string path;  // relative to the report folder, '/' separators
    std::string bytes;
};

std::vector<ReportFile> analysisReport(const StudyAnalysis& analysis, const ReportInputs& inputs);

}  // namespace signstim::analysis
