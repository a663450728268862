#include "stimuli/study/study_folder.hpp"

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/file_manifest.hpp"
#include "common/sha256.hpp"
#include "stimuli/json_source.hpp"
#include "stimuli/study/study_documents.hpp"

#include <algorithm>
#include <optional>

namespace signstim::stimuli {

using nlohmann::json;
namespace fs = std::filesystem;

// ---- units and shards ------------------------------------------------------------------------

std::vector<StudyUnit> studyUnits(const StudyListing& listing) {
    std::vector<StudyUnit> units;
    for (std::size_t i = 0; i < listing.stories.size(); ++i) units.push_back({listing.stories[i].id, true, i});
    for (std::size_t i = 0; i < listing.sentences.size(); ++i) units.push_back({listing.sentences[i].id, false, i});
    // Issue 24: signed questions (one unit per story that has them) and instructions.
    for (std::size_t i = 0; i < listing.stories.size(); ++i)
        if (hasQuestionClips(listing.stories[i])) units.push_back({questionsUnitId(i), false, i, StudyUnitKind::Questions});
    if (hasInstructionClips(listing)) units.push_back({kInstructionsUnitId, false, 0, StudyUnitKind::Instructions});
    std::sort(units.begin(), units.end(), [](const StudyUnit& a, const StudyUnit& b) { return a.id < b.id; });
    return units;
}

std::vector<StudyUnit> shardUnits(const std::vector<StudyUnit>& units, std::size_t index, std::size_t count) {
    std::vector<StudyUnit> mine;
    for (std::size_t i = 0; i < units.size(); ++i)
        if (count > 0 && i % count == index) mine.push_back(units[i]);
    return mine;
}

// ---- what a unit depends on --------------------------------------------------------------------

namespace {

void hashFile(Sha256& hash, const fs::path& file) { hash.update(file.filename().string() + " " + sha256File(file) + "\n"); }

void hashFolder(Sha256& hash, const fs::path& folder) {
    if (!fs::is_directory(folder)) {
        if (fs::exists(folder)) hashFile(hash, folder);
        return;
    }
    std::vector<fs::path> files;
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(folder))
        if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) hash.update(f.lexically_relative(folder).generic_string() + " " + sha256File(f) + "\n");
}

}  // namespace

StudyInputs studyInputs(const fs::path& scenes, const fs::path& lexicon, const fs::path& labLexicon,
                        const fs::path& avatar) {
    // labLexicon: empty without --lexicon (nothing hashed for it).
    return {{scenes / "handshapes.json", scenes / "verbs.json", scenes / "models" / "verb_models.json", avatar},
            {lexicon, labLexicon, scenes / "animator"}};
}

std::string studyDataHash(const std::string& toolVersion, const StudyRenderSettings& settings, bool pngFrames,
                          const std::vector<std::string>& versions, const StudyInputs& inputs) {
    Sha256 hash;
    hash.update("signstim " + toolVersion + "\n" + settings.text() + "\npng " + (pngFrames ? "yes" : "no") + "\nversions");
    for (const std::string& v : versions) hash.update(" " + v);
    hash.update("\n");
    for (const fs::path& f : inputs.files) hashFile(hash, f);
    for (const fs::path& f : inputs.folders) hashFolder(hash, f);
    return hash.hexDigest();
}

std::string unitInputHash(const std::string& dataHash, const StudyUnit& unit, const StudyFile& study,
                          const StudyListing& listing) {
    Sha256 hash;
    hash.update(dataHash + "\n" + unit.id + "\n");
    if (unit.kind == StudyUnitKind::Questions) {
        // The story file (its characters, where they stand, the questions' gloss) and the clips.
        hash.update(readTextFile(study.stories[unit.index].path));
        for (const ListedQuestion& q : listing.stories[unit.index].questions) hash.update(q.gloss + " " + q.clip.video + "\n");
    } else if (unit.kind == StudyUnitKind::Instructions) {
        for (const ListedInstruction& page : listing.instructions) {
            hash.update(page.page + " " + page.clip.video + "\n");
            for (const std::string& gloss : page.gloss) hash.update(gloss + "\n");
        }
    } else if (unit.story) {
        hash.update(readTextFile(study.stories[unit.index].path));
        for (const ListedClip& c : listing.stories[unit.index].clips)
            hash.update(c.video + "\n" + c.regions + "\n" + c.annotation + "\n");
    } else {
        hash.update(readTextFile(study.phase2Story.path));
        const ListedSentence& sentence = listing.sentences[unit.index];
        hash.update(std::to_string(study.phase2Sentences[unit.index]) + " " + sentence.panelCode + " " + sentence.clip.video +
                    "\n" + sentence.clip.regions + "\n" + sentence.clip.annotation + "\n");
    }
    return hash.hexDigest();
}

// ---- the plan ----------------------------------------------------------------------------------

json studyPlan(const StudyListing& listing, const StudyRenderSettings& settings, bool pngFrames,
               const std::vector<StudyUnit>& units, const std::vector<std::string>& inputHashes,
               const std::string& experiment) {
    json plan;
    plan["format"] = "signstim-study-plan";
    plan["version"] = 1;
    plan["render"] = {{"size", listing.size}, {"fps", listing.fps}, {"msaa", settings.msaa}, {"rate", settings.rate},
                      {"pngFrames", pngFrames}};
    json list = json::array();
    for (std::size_t i = 0; i < units.size(); ++i) list.push_back({{"id", units[i].id}, {"inputHash", inputHashes.at(i)}});
    plan["units"] = list;
    plan["listing"] = listingToJson(listing);
    // Not part of what a unit depends on: a re-run with another choice only rewrites the documents.
    if (!experiment.empty()) plan["outputs"] = {{"experiment", experiment}};
    return plan;
}

bool hasStudyPlan(const fs::path& dir) { return fs::exists(dir / kStudyPlanFile); }

json readStudyPlan(const fs::path& dir) {
    const fs::path file = dir / kStudyPlanFile;
    if (!fs::exists(file))
        throw InputError(file.string(), 0, "", "not a study folder (no plan): run `signstim study ... --out " + dir.string() + "` first");
    const JsonSource source = readJsonFile(file);
    source.checkFormat("signstim-study-plan", 1);
    if (!source.root.contains("units") || !source.root["units"].is_array() || !source.root.contains("listing") ||
        !source.root.contains("render"))
        source.failAt("", "incomplete plan (units, listing, render)");
    for (const json& u : source.root["units"])
        if (!u.is_object() || !u.contains("id") || !u["id"].is_string() || !u.contains("inputHash") || !u["inputHash"].is_string())
            source.failAt("/units", "expected {\"id\", \"inputHash\"} for every unit");
    return source.root;
}

std::map<std::string, std::string> planInputHashes(const json& plan) {
    std::map<std::string, std::string> hashes;
    for (const json& u : plan.at("units")) hashes[u.at("id").get<std::string>()] = u.at("inputHash").get<std::string>();
    return hashes;
}

std::string planExperiment(const json& plan) {
    if (!plan.contains("outputs") || !plan["outputs"].is_object()) return "";
    return plan["outputs"].value("experiment", "");
}

// ---- unit records -------------------------------------------------------------------------------

fs::path unitRecordPath(const fs::path& dir, const std::string& unit) {
    return pathInStudyFolder(dir, std::string(kStudyUnitFolder) + "/" + unit + ".json", (dir / kStudyPlanFile).string());
}

fs::path pathInStudyFolder(const fs::path& dir, const std::string& relative, const std::string& source) {
    const fs::path path(relative);
    const auto refuse = [&](const std::string& why) {
        return InputError(source, 0, "path", "'" + relative + "' " + why + ": a study folder's records name files inside it");
    };
    if (relative.empty() || path.is_absolute() || path.has_root_name() || path.has_root_directory())
        throw refuse("is not a path relative to the folder");
    fs::path walked = dir;
    for (const fs::path& part : path) {
        if (part == ".." || part == "." || part.empty()) throw refuse("leaves the folder or is not plain");
        walked /= part;
        std::error_code error;
        if (fs::is_symlink(fs::symlink_status(walked, error))) throw refuse("goes through a symbolic link");
    }
    return walked;
}

void writeUnitRecord(const fs::path& dir, const std::string& unit, const std::string& inputHash, std::uint64_t frames,
                     const json& files) {
    json record;
    record["unit"] = unit;
    record["inputHash"] = inputHash;
    record["frames"] = frames;
    record["files"] = files;
    writeFileAtomic(unitRecordPath(dir, unit), record.dump(2) + "\n");
}

namespace {

// The record of UNIT, when it has the input hash and lists files; nullopt otherwise (a record
// that is not JSON is an incomplete unit, rendered again).
std::optional<json> readRecord(const fs::path& dir, const std::string& unit, const std::string& inputHash) {
    const fs::path file = unitRecordPath(dir, unit);
    if (!fs::is_regular_file(file)) return std::nullopt;
    json record;
    try {
        record = readJsonFile(file).root;
    } catch (const InputError&) {
        return std::nullopt;
    }
    if (!record.is_object() || !record.contains("inputHash") || record["inputHash"] != inputHash) return std::nullopt;
    if (!record.contains("files") || !record["files"].is_array()) return std::nullopt;
    for (const json& f : record["files"])
        if (!f.is_object() || !f.contains("path") || !f["path"].is_string()) return std::nullopt;
    return record;
}

}  // namespace

bool unitComplete(const fs::path& dir, const std::string& unit, const std::string& inputHash) {
    const std::optional<json> record = readRecord(dir, unit, inputHash);
    if (!record) return false;
    const std::string source = unitRecordPath(dir, unit).string();
    for (const json& f : (*record)["files"]) {
        const fs::path path = pathInStudyFolder(dir, f["path"].get<std::string>(), source);
        const bool frames = f.value("kind", "") == "frames";
        if (frames ? !fs::is_directory(path) : !fs::is_regular_file(path)) return false;
        const std::uint64_t bytes = frames ? folderBytes(path) : static_cast<std::uint64_t>(fs::file_size(path));
        if (bytes != f.value("bytes", std::uint64_t{0})) return false;
        if ((frames ? folderDigest(path) : sha256File(path)) != f.value("sha256", "")) return false;
    }
    return true;
}

// ---- finishing ----------------------------------------------------------------------------------

namespace {

// The listing with every clip's frame count and duration from the unit records; the units
// that have no valid record are returned in `missing`.
StudyListing completedListing(const fs::path& dir, StudyListing listing, const std::map<std::string, std::string>& inputHashes,
                              std::vector<std::string>& missing, std::vector<json>& records) {
    std::map<std::string, json> videos;  // path -> entry
    for (const auto& [unit, hash] : inputHashes) {
        if (!unitComplete(dir, unit, hash)) {
            missing.push_back(unit);
            continue;
        }
        json record = *readRecord(dir, unit, hash);
        for (const json& f : record["files"])
            if (f.value("kind", "") == "video") videos[f.value("path", "")] = f;
        records.push_back(std::move(record));
    }
    const auto fill = [&](ListedClip& clip) {
        const auto it = videos.find(clip.video);
        if (it == videos.end()) return;
        clip.frameCount = it->second.value("frames", std::uint64_t{0});
        clip.durationSeconds = it->second.value("durationSeconds", 0.0);
    };
    for (ListedStory& story : listing.stories)
        for (ListedClip& clip : story.clips) fill(clip);
    for (ListedSentence& sentence : listing.sentences) fill(sentence.clip);
    for (ListedStory& story : listing.stories)
        for (ListedQuestion& question : story.questions)
            if (!question.clip.video.empty()) fill(question.clip);
    for (ListedInstruction& page : listing.instructions)
        if (!page.clip.video.empty()) fill(page.clip);
    return listing;
}

void writeFinalFiles(const fs::path& dir, const json& plan, const StudyListing& listing, const std::vector<json>& records,
                     const JspsychBundle* jspsych, StudyFolderState& state) {
    json files = json::array();
    for (const json& record : records)
        for (const json& f : record["files"]) files.push_back(f);
    std::vector<StudyDocument> documents = studyDocuments(listing);
    if (jspsych) {
        std::vector<StudyDocument> experiment = experimentDocuments(listing, *jspsych);
        documents.insert(documents.end(), std::make_move_iterator(experiment.begin()),
                         std::make_move_iterator(experiment.end()));
        state.experiment = true;
        if (!listing.participants.empty()) state.firstParticipant = listing.participants.front().id;
    }
    for (const StudyDocument& document : documents) {
        writeFileAtomic(dir / document.path, document.contents);
        json entry;
        entry["path"] = document.path;
        entry["kind"] = document.kind;
        entry["sha256"] = sha256Hex(document.contents);
        entry["bytes"] = static_cast<std::uint64_t>(document.contents.size());
        if (!document.participant.empty()) entry["participant"] = document.participant;
        entry["shows"] = document.shows;
        files.push_back(entry);
    }
    std::sort(files.begin(), files.end(), [](const json& a, const json& b) { return a["path"] < b["path"]; });
    json units = json::array();
    for (const json& record : records)
        units.push_back({{"id", record["unit"]}, {"inputHash", record["inputHash"]}, {"frames", record["frames"]}});
    json manifest;
    manifest["format"] = "signstim-study-manifest";
    manifest["version"] = 1;
    manifest["tool"] = std::string("signstim ") + listing.toolVersion;
    manifest["title"] = listing.title;
    manifest["seed"] = listing.seed;
    manifest["designHash"] = listing.designHash;
    manifest["render"] = plan.at("render");
    manifest["units"] = units;
    manifest["files"] = files;
    manifest["study"] = listingToJson(listing);
    writeManifest(dir / kStudyManifestFile, manifest);
}

}  // namespace

StudyFolderState finishStudyFolder(const fs::path& dir, const json& plan, const JspsychBundle* jspsych) {
    StudyFolderState state;
    std::vector<json> records;
    const std::map<std::string, std::string> hashes = planInputHashes(plan);
    const StudyListing listing =
        completedListing(dir, listingFromJson(plan.at("listing"), (dir / kStudyPlanFile).string()), hashes, state.missing, records);
    state.units = hashes.size();
    state.complete = state.missing.empty();
    if (state.complete) writeFinalFiles(dir, plan, listing, records, jspsych, state);
    return state;
}

}  // namespace signstim::stimuli
