#include "analysis/mixed_models.hpp"

#include "analysis/child_process.hpp"
#include "analysis/csv_table.hpp"
#include "analysis/models_r.hpp"  // kModelsR: analysis/models.R, embedded by CMake
#include "common/atomic_file.hpp"
#include "common/error.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <map>
#include <sstream>

namespace signstim::analysis {

namespace {

namespace fs = std::filesystem;

const char* const kHeader[] = {"model", "section", "term", "estimate", "std_error", "statistic", "df", "p", "p_holm", "note"};
// What models.R prints (and exits 3) when lme4 or ordinal is not installed.
constexpr std::string_view kMissingPackages = "signstim-models: missing R packages:";
const char* const kInstallHint =
    "Install R with the packages lme4 and ordinal (Debian/Ubuntu: apt install r-base-core r-cran-lme4 r-cran-ordinal; "
    "elsewhere, in R: install.packages(c(\"lme4\", \"ordinal\"))) and run signstim analyze again, or run the script "
    "the report holds: Rscript REPORT/models/models.R";

// An R string literal (the study's version names are plain words, but quote anyway).
std::string rString(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string out = "\"";
    for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

double parseNumber(const std::string& text, int line, const std::string& column) {
    if (text == "NA") return NAN;
    double value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        throw EnvironmentError("R's model output, line " + std::to_string(line) + ", column '" + column +
                               "': expected a number or NA, got '" + text + "'");
    return value;
}

std::string lastLines(const std::string& text, std::size_t count) {
    std::size_t at = text.size();
    while (at > 0 && (text[at - 1] == '\n' || text[at - 1] == ' ')) --at;
    const std::size_t end = at;
    for (std::size_t lines = 0; at > 0; --at)
        if (text[at - 1] == '\n' && ++lines == count) break;
    return text.substr(at, end - at);
}

}  // namespace

const ModelFit* MixedModels::find(const std::string& name) const {
    for (const ModelFit& m : models)
        if (m.name == name) return &m;
    return nullptr;
}

std::string modelReference(const stimuli::StudyListing& study, const std::string& requested) {
    const auto has = [&](const std::string& v) { return std::find(study.versions.begin(), study.versions.end(), v) != study.versions.end(); };
    if (!requested.empty()) {
        if (!has(requested)) throw InputError("<command line>", 0, "--reference", "'" + requested + "' is not a version of this study");
        return requested;
    }
    if (has("uninflected")) return "uninflected";
    return study.versions.empty() ? std::string() : study.versions.front();
}

ModelInputs modelInputs(const stimuli::StudyListing& study, const std::vector<ParticipantResults>& results,
                        const std::string& reference) {
    ModelInputs in;
    in.reference = reference;
    bool synthetic = false;
    std::string comprehension, ratings;
    for (const ParticipantResults& r : results) {
        synthetic = synthetic || r.synthetic;
        for (const Phase1Result& t : r.phase1) {
            const stimuli::ListedStory& story = study.stories[t.story];
            for (std::size_t q = 0; q < t.correct.size(); ++q)
                comprehension += csvField(r.participant) + "," + csvField(story.id) + "," +
                                 csvField(q < story.questions.size() ? story.questions[q].probeVerb : "") + "," +
                                 std::to_string(q + 1) + "," + csvField(study.versions[t.version]) + "," +
                                 (t.correct[q] ? "1" : "0") + "\n";
        }
        for (const Phase2Result& t : r.phase2) {
            const stimuli::ListedSentence& sentence = study.sentences[t.sentence];
            for (std::size_t v = 0; v < t.ratings.size(); ++v) {
                if (std::isnan(t.ratings[v])) continue;  // not rated
                ratings += csvField(r.participant) + "," + csvField(sentence.id) + "," + csvField(sentence.verb) + "," +
                           csvField(study.versions[v]) + "," + std::to_string(std::lround(t.ratings[v])) + "\n";
            }
        }
    }
    const std::string banner = synthetic ? "# SYNTHETIC DATA (signstim simulate-results): not responses of people\n" : "";
    if (!comprehension.empty()) in.comprehensionCsv = banner + "participant,story,verb,question,version,correct\n" + comprehension;
    if (!ratings.empty()) in.ratingsCsv = banner + "participant,sentence,verb,version,rating\n" + ratings;
    std::string versions;
    for (const std::string& v : study.versions) versions += (versions.empty() ? "" : ", ") + rString(v);
    in.script = replaceAll(replaceAll(std::string(kModelsR), "@VERSIONS@", versions), "\"@REFERENCE@\"", rString(reference));
    return in;
}

MixedModels parseModelOutput(std::string_view text) {
    CsvTable table;
    try {
        table = parseCsv(text, "models-output.csv");
    } catch (const InputError& e) {
        throw EnvironmentError(std::string("R's model output is not the CSV models.R writes: ") + e.what());
    }
    const std::vector<std::string> header(std::begin(kHeader), std::end(kHeader));
    if (table.header != header) throw EnvironmentError("R's model output does not start with the header models.R writes");
    MixedModels out;
    out.status = ModelStatus::Ran;
    out.output = std::string(text);
    std::map<std::string, std::size_t> index;
    for (const CsvRecord& record : table.records) {
        const std::vector<std::string>& f = record.fields;
        const std::string &model = f[0], &section = f[1];
        ModelRow row;
        row.term = f[2];
        row.estimate = parseNumber(f[3], record.line, "estimate");
        row.stdError = parseNumber(f[4], record.line, "std_error");
        row.statistic = parseNumber(f[5], record.line, "statistic");
        row.df = parseNumber(f[6], record.line, "df");
        row.p = parseNumber(f[7], record.line, "p");
        row.pHolm = parseNumber(f[8], record.line, "p_holm");
        row.note = f[9];
        const auto bad = [&](const std::string& what) {
            return EnvironmentError("R's model output, line " + std::to_string(record.line) + ": " + what);
        };
        if (model == "all") {
            if (section != "info") throw bad("section '" + section + "' of 'all'");
            if (row.term == "R") out.rVersion = row.note;
            else if (row.term == "lme4") out.lme4Version = row.note;
            else if (row.term == "ordinal") out.ordinalVersion = row.note;
            else if (row.term == "reference") out.reference = row.note;
            else throw bad("unknown information '" + row.term + "'");
            continue;
        }
        if (model != "comprehension" && model != "ratings") throw bad("unknown model '" + model + "'");
        if (!index.count(model)) {
            index[model] = out.models.size();
            out.models.push_back(ModelFit{});
            out.models.back().name = model;
        }
        ModelFit& m = out.models[index[model]];
        if (section == "info") {
            if (row.term == "formula") m.formula = row.note;
            else if (row.term == "family") m.family = row.note;
            else {
                if (row.term == "observations") m.observations = row.estimate;
                m.info.push_back(row);
            }
        } else if (section == "fixed") {
            m.fixed.push_back(row);
        } else if (section == "threshold") {
            m.thresholds.push_back(row);
        } else if (section == "random") {
            m.random.push_back(row);
        } else if (section == "fit") {
            m.fit.push_back(row);
        } else if (section == "pair") {
            m.pairs.push_back(row);
        } else if (section == "lrt") {
            if (m.hasLrt) throw bad("a second likelihood-ratio test");
            m.lrt = row;
            m.hasLrt = true;
        } else if (section == "warning") {
            m.warnings.push_back(row);
        } else if (section == "error") {
            m.errors.push_back(row.term.empty() ? row.note : row.term + ": " + row.note);
        } else {
            throw bad("unknown section '" + section + "'");
        }
    }
    for (const ModelFit& m : out.models)
        if (m.errors.empty() && (m.fixed.empty() || !m.hasLrt || m.pairs.empty()))
            throw EnvironmentError("R's model output lacks the estimates, pairs or likelihood-ratio test of '" + m.name +
                                   "' without saying why");
    return out;
}

MixedModels runMixedModels(const ModelInputs& inputs, const ModelRunOptions& options) {
    MixedModels result;
    result.reference = inputs.reference;
    // A folder of our own under the system's temporary folder, registered for removal on a
    // signal and removed when done (never committed).
    TemporaryFolder folder(fs::temp_directory_path() / "signstim-models");
    const fs::path dir = folder.path();
    writeNewFile(dir / "models.R", inputs.script);
    if (!inputs.comprehensionCsv.empty()) writeNewFile(dir / "comprehension.csv", inputs.comprehensionCsv);
    if (!inputs.ratingsCsv.empty()) writeNewFile(dir / "ratings.csv", inputs.ratingsCsv);
    const fs::path output = dir / "models-output.csv";
    const ChildRun run = runChild({options.rscript, "--vanilla", (dir / "models.R").string(), dir.string(), output.string()},
                                  dir / "r.log", options.timeoutSeconds, /*fixedAddresses=*/true);
    result.seconds = run.seconds;
    if (run.notFound) {
        result.status = ModelStatus::RMissing;
        result.message = "'" + options.rscript + "' was not found" +
                         (options.rscript.find('/') == std::string::npos ? " on PATH" : "") +
                         ", so the mixed models were not fitted. " + kInstallHint + ".";
        return result;
    }
    result.status = ModelStatus::Failed;
    if (!run.startError.empty()) {
        result.message = "'" + options.rscript + "' could not be run: " + run.startError;
        return result;
    }
    if (run.timedOut) {
        result.message = "R did not finish within " + std::to_string(static_cast<long>(options.timeoutSeconds)) +
                         " s (--models-timeout) and was stopped; its last lines:\n" + lastLines(run.output, 12);
        return result;
    }
    if (run.exitCode == 3 && run.output.find(kMissingPackages) != std::string::npos) {
        result.status = ModelStatus::PackagesMissing;
        const std::size_t at = run.output.find(kMissingPackages) + kMissingPackages.size();
        std::string packages = run.output.substr(at, run.output.find('\n', at) - at);
        while (!packages.empty() && (packages.back() == '\r' || packages.back() == ' ')) packages.pop_back();
        result.message = "R is there without the package(s)" + packages + ", so the mixed models were not fitted. " +
                         kInstallHint + ".";
        return result;
    }
    if (!run.succeeded()) {
        result.message = "R failed (" +
                         (run.signal ? "killed by signal " + std::to_string(run.signal) : "exit status " + std::to_string(run.exitCode)) +
                         "); its last lines:\n" + lastLines(run.output, 12);
        return result;
    }
    std::ifstream in(output, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) {
        result.message = "R exited without writing its output (" + output.filename().string() + ")";
        return result;
    }
    try {
        MixedModels parsed = parseModelOutput(text.str());
        parsed.seconds = run.seconds;
        return parsed;
    } catch (const EnvironmentError& e) {
        result.message = e.what();
        return result;
    }
}

}  // namespace signstim::analysis
