// The study folder's readers: `study verify`, `study merge`, and the manifest's listing for `analyze` (stimuli/study/study_folder.hpp).
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/file_manifest.hpp"
#include "common/sha256.hpp"
#include "stimuli/json_source.hpp"
#include "stimuli/study/study_folder.hpp"
#include "stimuli/study/study_folder_lock.hpp"

#include <optional>
#include <set>

namespace signstim::stimuli {

using nlohmann::json;
namespace fs = std::filesystem;

StudyVerification verifyStudyFolder(const fs::path& dir) {
    const fs::path manifestFile = dir / kStudyManifestFile;
    if (!fs::exists(manifestFile)) {
        std::string why = "no manifest: the study is not complete";
        if (hasStudyPlan(dir)) {
            std::vector<std::string> missing;
            for (const auto& [unit, hash] : planInputHashes(readStudyPlan(dir)))
                if (!unitComplete(dir, unit, hash)) missing.push_back(unit);
            if (!missing.empty()) {
                why += " (" + std::to_string(missing.size()) + " unit" + (missing.size() == 1 ? "" : "s") + " missing: ";
                for (std::size_t i = 0; i < missing.size() && i < 8; ++i) why += (i ? ", " : "") + missing[i];
                why += missing.size() > 8 ? ", ...)" : ")";
            }
        }
        throw InputError(manifestFile.string(), 0, "", why);
    }
    const JsonSource source = readJsonFile(manifestFile);
    source.checkFormat("signstim-study-manifest", 1);
    if (!source.root.contains("files") || !source.root["files"].is_array()) source.failAt("/files", "expected the list of files");
    StudyVerification result;
    result.listed = source.root["files"].size();
    for (const json& f : source.root["files"]) {
        const std::string relative = f.is_object() ? f.value("path", "") : "";
        fs::path path;
        try {
            path = pathInStudyFolder(dir, relative, manifestFile.string());
        } catch (const InputError&) {
            result.problems.push_back("manifest lists a path outside the folder: '" + relative + "'");
            continue;
        }
        const bool frames = f.value("kind", "") == "frames";
        if (frames ? !fs::is_directory(path) : !fs::is_regular_file(path)) {
            result.problems.push_back(relative + ": missing");
            continue;
        }
        const std::uint64_t bytes = frames ? folderBytes(path) : static_cast<std::uint64_t>(fs::file_size(path));
        if (bytes != f.value("bytes", std::uint64_t{0})) {
            result.problems.push_back(relative + ": " + std::to_string(bytes) + " bytes, the manifest says " +
                                      std::to_string(f.value("bytes", std::uint64_t{0})));
            continue;
        }
        if ((frames ? folderDigest(path) : sha256File(path)) != f.value("sha256", "")) {
            result.problems.push_back(relative + ": SHA-256 differs from the manifest's (changed after rendering)");
            continue;
        }
        ++result.checked;
    }
    // Every unit of the plan must be in the manifest.
    if (hasStudyPlan(dir)) {
        std::set<std::string> listed;
        for (const json& u : source.root.value("units", json::array()))
            if (u.is_object()) listed.insert(u.value("id", ""));
        for (const auto& [unit, hash] : planInputHashes(readStudyPlan(dir)))
            if (!listed.count(unit)) result.problems.push_back(unit + ": in the plan but not in the manifest");
    }
    return result;
}

StudyListing readStudyManifestListing(const fs::path& studyDirOrManifest, const std::string& field,
                                      std::string* manifestPath) {
    const fs::path file = fs::is_directory(studyDirOrManifest) ? studyDirOrManifest / kStudyManifestFile : studyDirOrManifest;
    if (fs::is_directory(studyDirOrManifest) && !fs::exists(file))
        throw InputError(studyDirOrManifest.string(), 0, field,
                         "no manifest.json: give the folder of a complete study (`signstim study ... --out DIR`)");
    const JsonSource source = readJsonFile(file);
    source.checkFormat("signstim-study-manifest", 1);
    if (!source.root.is_object() || !source.root.contains("format"))
        source.failAt("", "not a study manifest (no \"format\": \"signstim-study-manifest\")");
    const auto study = source.root.find("study");
    if (study == source.root.end())
        source.failAt("", "this manifest has no \"study\" listing (written by an older signstim?): re-run `signstim study` on the folder");
    if (manifestPath) *manifestPath = file.string();
    return withJsonErrors(source, [&] { return listingFromJson(*study, file.string() + " (/study)"); });
}

namespace {

// Copies UNIT's files from `from` into `to`, each checked against the record, then the record.
void copyUnit(const fs::path& from, const fs::path& to, const std::string& unit) {
    const fs::path recordFile = unitRecordPath(from, unit);
    const json record = readJsonFile(recordFile).root;
    for (const json& f : record["files"]) {
        const std::string relative = f.value("path", "");
        const fs::path source = pathInStudyFolder(from, relative, recordFile.string());
        const fs::path target = pathInStudyFolder(to, relative, recordFile.string());
        if (f.value("kind", "") == "frames") {
            if (folderDigest(source) != f.value("sha256", ""))
                throw InputError(source.string(), 0, "", "its frames differ from the unit's record (changed after rendering?)");
            TemporaryFolder folder(target);
            for (const fs::directory_entry& e : fs::directory_iterator(source))
                writeNewFile(folder.path() / e.path().filename(), readTextFile(e.path()), target / e.path().filename());
            folder.commit();
        } else {
            const std::string bytes = readTextFile(source);
            if (sha256Hex(bytes) != f.value("sha256", ""))
                throw InputError(source.string(), 0, "", "differs from the unit's record (changed after rendering?)");
            writeFileAtomic(target, bytes);
        }
    }
    writeFileAtomic(unitRecordPath(to, unit), record.dump(2) + "\n");
}

}  // namespace

StudyMerge mergeStudyFolders(const std::vector<fs::path>& sources, const fs::path& target, const std::string& experiment) {
    // The plan: the target's, else the first source's; every source must hold the same study.
    std::optional<json> plan;
    fs::path planFrom;
    // Shards of one study may differ in whether they asked for the experiment; the merge writes
    // it when any of them (or `experiment`) did.
    std::string wantedExperiment = experiment == "none" ? "" : experiment;
    const auto withoutOutputs = [](json p) {
        p.erase("outputs");
        return p;
    };
    std::vector<fs::path> all{target};
    all.insert(all.end(), sources.begin(), sources.end());
    for (const fs::path& dir : all) {
        if (!hasStudyPlan(dir)) continue;
        const json p = readStudyPlan(dir);
        if (wantedExperiment.empty()) wantedExperiment = planExperiment(p);
        if (!plan) {
            plan = p;
            planFrom = dir;
        } else if (withoutOutputs(p) != withoutOutputs(*plan)) {
            throw InputError(dir.string(), 0, "",
                             "holds a different study (or the same with other settings) than " + planFrom.string() +
                                 ": merge the shards of one run of one study file");
        }
    }
    if (!plan) throw InputError(sources.front().string(), 0, "", "not a study folder (no .signstim/plan.json)");
    plan->erase("outputs");
    if (!wantedExperiment.empty()) (*plan)["outputs"] = {{"experiment", wantedExperiment}};
    const std::optional<JspsychBundle> jspsych =
        wantedExperiment.empty() ? std::nullopt : std::optional<JspsychBundle>(loadJspsychBundle());
    ensureWritableDirectory(target);
    // No run may be rendering into the target while the merge writes it.
    StudyFolderLock folderLock(target);
    if (folderLock.othersRunning())
        throw EnvironmentError(target.string() + ": is being rendered by " + folderLock.holder() +
                               "; merge when every shard has finished");
    removeStaleTemporaries(target);
    // The target's files are about to change: until the merge completes it, it has no manifest.
    removeStaleFile(target / kStudyManifestFile);
    removeStaleFile(target / kStudyReviewPage);
    writeFileAtomic(target / kStudyPlanFile, plan->dump(2) + "\n");
    StudyMerge merge;
    for (const auto& [unit, hash] : planInputHashes(*plan)) {
        if (unitComplete(target, unit, hash)) continue;
        for (const fs::path& dir : sources) {
            std::error_code error;
            if (fs::equivalent(dir, target, error) || !unitComplete(dir, unit, hash)) continue;
            copyUnit(dir, target, unit);
            ++merge.copied;
            break;
        }
    }
    merge.state = finishStudyFolder(target, *plan, jspsych ? &*jspsych : nullptr);
    return merge;
}

}  // namespace signstim::stimuli
