// `signstim analyze` and `signstim simulate-results` (docs/analysis.md): experiment results
// back to the paper's figures and tests, and synthetic results with a planted effect to check
// that analysis against.
#include "analysis/figure_png.hpp"
#include "analysis/mixed_models.hpp"
#include "analysis/report.hpp"
#include "analysis/report_models.hpp"
#include "analysis/results_file.hpp"
#include "analysis/simulation.hpp"
#include "analysis/study_analysis.hpp"
#include "analysis/text_format.hpp"
#include "app/cli_values.hpp"
#include "app/commands.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/number_format.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <set>

namespace signstim::app {
namespace {

namespace fs = std::filesystem;
using namespace signstim::analysis;

struct AnalyzeOptions {
    std::vector<std::string> results;
    std::string study;
    std::string out;
    std::string columns;
    double alpha = 0.05;
    bool strict = false;
    bool quiet = false;
    std::string models = "auto";  // auto, require, none
    std::string reference;
    double modelsTimeout = 600;
    std::string rscript = "Rscript";
    double dpi = 0;
};

struct SimulateOptions {
    std::string study;
    std::string out;
    std::string effect = "planted";
    std::uint64_t seed = 1;
    std::string accuracy;
    std::string likert;
    double abilitySd = -1, biasSd = -1, ratingSd = -1;  // < 0: the effect's default
};

// Every file an analysis report consists of: a report folder holding anything else is not
// replaced (it might be someone's work).
bool isReportFile(const fs::path& relative) {
    static const std::set<std::string> top = {"report.html", "results.csv", "tests.csv", "scores.csv", "summary.json",
                                              "models", "models/models.R", "models/comprehension.csv", "models/ratings.csv",
                                              "models/models-output.csv", "models/models-rerun.csv"};
    const std::string text = relative.generic_string();
    if (top.count(text)) return true;
    if (text == "figures") return true;
    return text.rfind("figures/", 0) == 0 && relative.has_extension() &&
           (relative.extension() == ".svg" || relative.extension() == ".png") && relative.parent_path() == "figures";
}

void checkReportFolder(const fs::path& out) {
    std::error_code error;
    if (!fs::exists(out, error)) return;
    if (!fs::is_directory(out, error))
        throw InputError(out.string(), 0, "--out", "is a file; the report is a folder: choose a new or empty folder");
    for (auto it = fs::recursive_directory_iterator(out, error); !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
        const fs::path relative = fs::relative(it->path(), out);
        if (!isReportFile(relative))
            throw InputError(out.string(), 0, "--out",
                             "holds '" + relative.generic_string() +
                                 "', which is not part of an analysis report; choose a new or empty folder (nothing is deleted "
                                 "that signstim did not write)");
    }
}

// RESULTS: files, or folders whose *.csv files are taken (sorted by name).
std::vector<fs::path> resultsFiles(const std::vector<std::string>& arguments) {
    std::vector<fs::path> files;
    for (const std::string& argument : arguments) {
        const fs::path path = withoutTrailingSeparators(argument);
        if (fs::is_directory(path)) {
            std::vector<fs::path> inside;
            for (const fs::directory_entry& e : fs::directory_iterator(path))
                if (e.is_regular_file() && e.path().extension() == ".csv") inside.push_back(e.path());
            std::sort(inside.begin(), inside.end());
            if (inside.empty()) throw InputError(path.string(), 0, "RESULTS", "a folder without .csv files");
            files.insert(files.end(), inside.begin(), inside.end());
        } else {
            files.push_back(path);
        }
    }
    return files;
}

std::string kruskalSummary(const Comparison& c) {
    const KruskalWallisResult& kw = c.kruskalWallis;
    if (!kw.defined()) return "not enough data";
    return "Kruskal-Wallis H(" + std::to_string(kw.df) + ") = " + formatFixed(kw.h, 2) + ", " + formatP(kw.p) + ", N = " +
           std::to_string(kw.n);
}

std::string meansSummary(const StudyAnalysis& a, const Comparison& c, bool asPercent) {
    std::vector<std::size_t> order;
    for (std::size_t v = 0; v < a.versions.size(); ++v)
        if (c.descriptives[v].n > 0) order.push_back(v);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t x, std::size_t y) { return c.descriptives[x].mean > c.descriptives[y].mean; });
    std::string s;
    for (std::size_t v : order)
        s += (s.empty() ? "" : " > ") + a.versions[v] + " " +
             (asPercent ? percent(c.descriptives[v].mean) : formatFixed(c.descriptives[v].mean, 2));
    return s;
}

void runAnalyze(const AnalyzeOptions& o) {
    if (!(o.alpha > 0.0 && o.alpha <= 0.5)) throw commandLineError("--alpha", rangeMessage(0.0, 0.5, "", o.alpha) + " (exclusive of 0)");
    if (o.models != "auto" && o.models != "require" && o.models != "none")
        throw commandLineError("--models", "expected auto, require or none, got '" + o.models + "'");
    const fs::path out = withoutTrailingSeparators(o.out);
    static const std::set<std::string> fileExtensions = {".html", ".htm", ".csv", ".json", ".svg", ".png", ".pdf", ".txt"};
    if (fileExtensions.count(out.extension().string()))
        throw commandLineError("--out", "'" + o.out + "': the report is a folder (report.html, figures/, ...); give a folder name");
    checkReportFolder(out);
    checkOutputWritable(out);

    std::string manifestPath;
    const stimuli::StudyListing study = readStudyManifest(o.study, &manifestPath);
    const ColumnMap columns = o.columns.empty() ? ColumnMap{} : readColumnMap(o.columns);
    std::vector<std::string> warnings;
    const std::vector<ParticipantResults> results = readResultsFiles(resultsFiles(o.results), study, columns, warnings);
    if (!o.quiet)
        for (const std::string& w : warnings) std::fprintf(stderr, "signstim: warning: %s\n", w.c_str());
    if (o.strict && !warnings.empty())
        throw InputError(std::to_string(warnings.size()) + " data check(s) failed (listed above; --strict makes them errors)");

    AnalysisSettings settings;
    settings.alpha = o.alpha;
    const StudyAnalysis analysis = analyzeStudy(study, results, settings);

    // The mixed models (docs/analysis.md, "Mixed models"): R fits them when it is there; the
    // script and its data go into the report either way.
    const ModelInputs modelData = modelInputs(study, results, modelReference(study, o.reference));
    MixedModels models;
    models.reference = modelData.reference;
    models.message = "not requested (--models none)";
    if (o.models != "none") {
        ModelRunOptions run;
        run.rscript = o.rscript;
        run.timeoutSeconds = o.modelsTimeout;
        models = runMixedModels(modelData, run);
        if (!models.ran() && o.models == "require")
            throw EnvironmentError("the mixed models were not fitted (--models require): " + models.message);
        if (!models.ran() && !o.quiet) std::fprintf(stderr, "signstim: warning: %s\n", models.message.c_str());
    }
    ReportInputs inputs;
    inputs.studyTitle = study.title;
    inputs.designHash = study.designHash;
    const fs::path manifest(manifestPath);
    inputs.manifestName = (manifest.parent_path().filename() / manifest.filename()).generic_string();
    inputs.columnMapName = o.columns.empty() ? "" : fs::path(o.columns).filename().string();
    inputs.results = &results;
    inputs.warnings = warnings;
    inputs.modelInputs = &modelData;
    inputs.models = &models;
    inputs.dpi = o.dpi;
    const std::vector<ReportFile> files = analysisReport(analysis, inputs);

    TemporaryFolder folder(out);
    for (const ReportFile& f : files) {
        const fs::path path = folder.path() / f.path;
        fs::create_directories(path.parent_path());
        writeNewFile(path, f.bytes, out / f.path);
    }
    folder.commit();

    std::printf("%s: %s%zu of %zu participants; %zu data warning(s)\n", (out / "report.html").string().c_str(),
                analysis.synthetic ? "SYNTHETIC DATA; " : "", analysis.participantsWithData, analysis.participantsInStudy,
                warnings.size());
    std::printf("  phase 1 comprehension: %s; %s\n", meansSummary(analysis, analysis.comprehension, true).c_str(),
                kruskalSummary(analysis.comprehension).c_str());
    std::printf("  phase 2 ratings: %s; %s\n", meansSummary(analysis, analysis.likert, false).c_str(),
                kruskalSummary(analysis.likert).c_str());
    for (const Comparison* c : {&analysis.comprehension, &analysis.likert})
        for (const PairTest& p : c->pairs)
            if (p.significant)
                std::printf("  phase %d: %s vs %s: Holm-adjusted %s, r = %s\n", c->phase, analysis.versions[p.first].c_str(),
                            analysis.versions[p.second].c_str(), formatP(p.pHolm).c_str(),
                            formatFixed(p.test.rankBiserial, 2).c_str());
    std::printf("  %s\n", modelsSummaryLine(models).c_str());
}

// "animator=0.9,point=0.7" -> per-version values over `values` (study order).
void overrideByVersion(const std::string& text, const std::string& flag, const stimuli::StudyListing& study, double low,
                       double high, bool openInterval, std::vector<double>& values) {
    std::size_t at = 0;
    std::set<std::string> seen;
    while (at <= text.size()) {
        const std::size_t comma = std::min(text.find(',', at), text.size());
        const std::string item = text.substr(at, comma - at);
        const std::size_t equals = item.find('=');
        if (equals == std::string::npos)
            throw commandLineError(flag, "expected VERSION=VALUE,... (e.g. animator=" + formatNumber(high) + "), got '" + item + "'");
        const std::string name = item.substr(0, equals), number = item.substr(equals + 1);
        const auto version = std::find(study.versions.begin(), study.versions.end(), name);
        if (version == study.versions.end()) throw commandLineError(flag, "'" + name + "' is not a version of this study");
        if (!seen.insert(name).second) throw commandLineError(flag, "'" + name + "' is given twice");
        double value = 0;
        const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
        if (number.empty() || error != std::errc() || end != number.data() + number.size() || !std::isfinite(value) ||
            value < low || value > high || (openInterval && (value == low || value == high)))
            throw commandLineError(flag, name + ": expected a number " + (openInterval ? "between " : "from ") + formatNumber(low) +
                                             (openInterval ? " and " : " to ") + formatNumber(high) +
                                             (openInterval ? " (exclusive)" : "") + ", got '" + number + "'");
        values[static_cast<std::size_t>(version - study.versions.begin())] = value;
        at = comma + 1;
    }
}

void runSimulate(const SimulateOptions& o) {
    if (o.effect != "planted" && o.effect != "none")
        throw commandLineError("--effect", "expected planted or none, got '" + o.effect + "'");
    const fs::path out = withoutTrailingSeparators(o.out);
    const stimuli::StudyListing study = readStudyManifest(o.study);
    SimulationSettings s = o.effect == "planted" ? plantedEffect(study, o.seed) : noEffect(study, o.seed);
    if (!o.accuracy.empty()) overrideByVersion(o.accuracy, "--accuracy", study, 0.0, 1.0, true, s.accuracy);
    if (!o.likert.empty())
        overrideByVersion(o.likert, "--likert", study, study.likertMinimum, study.likertMaximum, false, s.likertMean);
    if (!o.accuracy.empty() || !o.likert.empty()) s.effect = "custom (from " + o.effect + ")";
    if (o.abilitySd >= 0) s.abilitySd = o.abilitySd;
    if (o.biasSd >= 0) s.biasSd = o.biasSd;
    if (o.ratingSd >= 0) s.ratingSd = o.ratingSd;
    ensureWritableDirectory(out);
    const std::vector<SimulatedFile> files = simulateResults(study, s);
    for (const SimulatedFile& f : files) writeFileAtomic(out / f.name, f.text);
    std::printf("%s: %zu SYNTHETIC results files (%s ... %s), not data of people\n  %s\n", out.string().c_str(), files.size(),
                files.front().name.c_str(), files.back().name.c_str(), describeSimulation(study, s).c_str());
}

}  // namespace

void registerAnalysisCommands(Commands& commands) {
    auto a = std::make_shared<AnalyzeOptions>();
    CLI::App* analyze = commands.root.add_subcommand(
        "analyze",
        "The paper's analysis of a study's results (docs/analysis.md): comprehension accuracy (phase 1) and\n"
        "side-by-side ratings (phase 2) per version and per verb, Kruskal-Wallis and pairwise Mann-Whitney U\n"
        "tests (Holm-adjusted) with effect sizes, figures like the paper's Figures 6-8 (SVG, and PNG at --dpi),\n"
        "tables, and one self-contained report.html. Beside the paper's tests, mixed models through R when\n"
        "Rscript is found (R with lme4 and ordinal; Debian: apt install r-base-core r-cran-lme4 r-cran-ordinal):\n"
        "a logistic GLMM of comprehension and a cumulative-link mixed model of the ratings, with participant\n"
        "and story/sentence random intercepts. Without R the report says how to get them (exit status\n"
        "unchanged; --models require makes it exit 3). REPORT/models/ holds the R script and its data:\n"
        "rerun them with Rscript REPORT/models/models.R.\n"
        "RESULTS: one CSV per participant (signstim-results_P07.csv), or folders of them.\n"
        "Every answer is re-scored from the study's answer keys and every rating unmapped from its panel code;\n"
        "disagreements with the file's own columns are warnings (--strict: errors).\n"
        "Examples:\n"
        "  signstim analyze results/*.csv --study my-study --out my-analysis\n"
        "  signstim analyze gorilla/ --study my-study --columns gorilla-columns.json --out my-analysis");
    analyze->add_option("RESULTS", a->results, "Results files (CSV), or folders of them")->required();
    analyze->add_option("--study", a->study, "The rendered study: its folder (manifest.json) or the manifest file")->required();
    analyze->add_option("--out", a->out, "Report folder (created; an earlier report there is replaced)")->required();
    analyze->add_option("--columns", a->columns,
                        "JSON map of our column names to another program's (PsychoPy, Gorilla): docs/analysis.md");
    analyze->add_option("--alpha", a->alpha, "Significance level (default 0.05)");
    analyze->add_flag("--strict", a->strict, "Treat data warnings (scoring that disagrees, missing answers or trials) as errors");
    analyze->add_flag("--quiet", a->quiet, "Do not list data warnings on stderr (the report lists them)");
    analyze->add_option("--models", a->models,
                        "Mixed models through R (lme4 GLMM of comprehension, ordinal CLMM of ratings): auto (default: fit\n"
                        "them when Rscript is found, else the report says how to get them), require (no R, missing\n"
                        "packages or R's failure: exit 3), none (not fitted). The script and its data go into\n"
                        "REPORT/models/ either way (rerun: Rscript REPORT/models/models.R)");
    analyze->add_option("--reference", a->reference,
                        "The version the models' estimates are relative to (default uninflected, else the first version)");
    analyze->add_option("--models-timeout", a->modelsTimeout, "Seconds R may take before it is stopped (default 600)")
        ->check(CLI::Range(1.0, 86400.0));
    analyze->add_option("--rscript", a->rscript, "The Rscript program (default: Rscript on PATH)");
    analyze->add_option("--dpi", a->dpi,
                        "Resolution of the figures' PNGs (default 300): a figure is 6.25 inches wide (600 SVG units,\n"
                        "1/96 inch each), 1875 pixels at 300 dpi; text in DejaVu Sans (fonts-dejavu-core)")
        ->check(CLI::Range(kMinimumFigureDpi, kMaximumFigureDpi));
    analyze->callback([a] { runAnalyze(*a); });

    auto s = std::make_shared<SimulateOptions>();
    CLI::App* simulate = commands.root.add_subcommand(
        "simulate-results",
        "SYNTHETIC results files for a rendered study, with a known planted effect (docs/analysis.md):\n"
        "every participant of the study answers their schedule; correct answers and ratings are drawn\n"
        "(SplitMix64, seeded) from per-version accuracies and mean ratings. For checking the analysis,\n"
        "never as data: the files say SYNTHETIC in their names and first line, and so does the report.\n"
        "Default effect (planted): accuracy animator 0.85 > point 0.75 > vector 0.65 > uninflected 0.50,\n"
        "mean rating animator 8 > point 6.5 > vector 5.5 > uninflected 4 (1-to-10). --effect none: all equal.\n"
        "Example:\n"
        "  signstim simulate-results --study my-study --out synthetic --seed 3\n"
        "  signstim analyze synthetic --study my-study --out synthetic-analysis");
    simulate->add_option("--study", s->study, "The rendered study: its folder (manifest.json) or the manifest file")->required();
    simulate->add_option("--out", s->out, "Folder for the files signstim-results_PNN_SYNTHETIC.csv")->required();
    simulate->add_option("--effect", s->effect, "planted (default) or none");
    simulate->add_option("--seed", s->seed, "Seed (default 1)");
    simulate->add_option("--accuracy", s->accuracy, "Per-version probability of a correct answer: animator=0.9,point=0.7,...");
    simulate->add_option("--likert", s->likert, "Per-version mean rating on the study's scale: animator=8,uninflected=3,...");
    simulate->add_option("--ability-sd", s->abilitySd, "Between-participant SD of ability, logit scale (default 0.5)")
        ->check(CLI::Range(0.0, 5.0));
    simulate->add_option("--bias-sd", s->biasSd, "Between-participant SD of rating bias, scale points (default 0.7 on 1-to-10)")
        ->check(CLI::Range(0.0, 100.0));
    simulate->add_option("--rating-sd", s->ratingSd, "Within-participant SD of ratings, scale points (default 1.5 on 1-to-10)")
        ->check(CLI::Range(0.0, 100.0));
    simulate->callback([s] { runSimulate(*s); });
}

}  // namespace signstim::app
