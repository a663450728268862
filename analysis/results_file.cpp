#include "analysis/results_file.hpp"

#include "analysis/csv_table.hpp"
#include "common/error.hpp"
#include "common/input_limits.hpp"
#include "common/sha256.hpp"
#include "stimuli/json_source.hpp"
#include "stimuli/study/study.hpp"
#include "stimuli/study/study_folder.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>

namespace signstim::analysis {

namespace {

namespace fs = std::filesystem;
using stimuli::StudyListing;

constexpr std::size_t kQuestionColumns = 4;  // q1 .. q4
constexpr std::size_t kPanelColumns = 4;     // rating_a .. rating_d
const char* const kPanelNames[kPanelColumns] = {"a", "b", "c", "d"};
const char* const kVersionColumns[] = {"point", "vector", "animator", "uninflected"};

std::string trimmed(const std::string& text) {
    std::size_t b = 0, e = text.size();
    while (b < e && std::isspace(static_cast<unsigned char>(text[b]))) ++b;
    while (e > b && std::isspace(static_cast<unsigned char>(text[e - 1]))) --e;
    return text.substr(b, e - b);
}

std::string lower(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

std::optional<long long> integerValue(const std::string& text) {
    const std::string t = trimmed(text);
    long long value = 0;
    const auto [end, error] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (t.empty() || error != std::errc() || end != t.data() + t.size()) return std::nullopt;
    return value;
}

std::optional<double> numberValue(const std::string& text) {
    const std::string t = trimmed(text);
    double value = 0.0;
    const auto [end, error] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (t.empty() || error != std::errc() || end != t.data() + t.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

// One row of a results file, its columns by our names.
class Row {
public:
    Row(const CsvTable& table, const CsvRecord& record, const std::map<std::string, std::size_t>& index,
        const ColumnMap& columns)
        : table_(table), record_(record), index_(index), columns_(columns) {}

    std::string text(const std::string& column) const { return trimmed(record_.fields[index_.at(column)]); }
    bool empty(const std::string& column) const { return text(column).empty(); }

    [[noreturn]] void fail(const std::string& column, const std::string& message) const {
        throw InputError(table_.file, record_.line, columns_.describe(column), message);
    }
    std::string warning(const std::string& column, const std::string& message) const {
        return InputError(table_.file, record_.line, columns_.describe(column), message).what();
    }
    int line() const { return record_.line; }

    std::string required(const std::string& column, const std::string& what) const {
        std::string t = text(column);
        if (t.empty()) fail(column, "empty: expected " + what);
        return t;
    }
    long long integer(const std::string& column, const std::string& what) const {
        const std::string t = required(column, what);
        const auto value = integerValue(t);
        if (!value) fail(column, "expected " + what + ", got '" + t + "'");
        return *value;
    }

private:
    const CsvTable& table_;
    const CsvRecord& record_;
    const std::map<std::string, std::size_t>& index_;
    const ColumnMap& columns_;
};

std::optional<bool> flagValue(const std::string& text) {
    const std::string t = lower(trimmed(text));
    if (t == "1" || t == "true") return true;
    if (t == "0" || t == "false") return false;
    return std::nullopt;
}

std::string letter(std::size_t index) { return std::string(1, static_cast<char>('A' + index)); }

std::string questionColumn(std::size_t q, const char* what) { return "q" + std::to_string(q + 1) + "_" + what; }

template <class Item>
std::size_t findById(const std::vector<Item>& items, const std::string& id) {
    for (std::size_t i = 0; i < items.size(); ++i)
        if (items[i].id == id) return i;
    return items.size();
}

std::size_t versionIndex(const StudyListing& study, const std::string& name) {
    for (std::size_t v = 0; v < study.versions.size(); ++v)
        if (study.versions[v] == name) return v;
    return study.versions.size();
}

std::string listOfIds(const std::vector<std::string>& ids) {
    std::string out;
    for (const std::string& id : ids) out += (out.empty() ? "" : ", ") + id;
    return out;
}

}  // namespace

const std::vector<std::string>& resultsColumns() {
    static const std::vector<std::string> columns = [] {
        std::vector<std::string> c = {"participant", "phase", "trial", "story_id", "sentence_id", "version", "panel_code"};
        for (std::size_t q = 0; q < kQuestionColumns; ++q) {
            c.push_back(questionColumn(q, "response"));
            c.push_back(questionColumn(q, "correct"));
        }
        c.push_back("n_correct");
        for (const char* panel : kPanelNames) c.push_back(std::string("rating_") + panel);
        for (const char* version : kVersionColumns) c.push_back(std::string("rating_") + version);
        c.push_back("rt_ms");
        return c;
    }();
    return columns;
}

const std::string& ColumnMap::nameOf(const std::string& ours) const {
    const auto it = theirs.find(ours);
    return it == theirs.end() ? ours : it->second;
}

std::string ColumnMap::describe(const std::string& ours) const {
    const std::string& name = nameOf(ours);
    return name == ours ? ours : name + " (" + ours + ")";
}

ColumnMap parseColumnMap(const stimuli::JsonSource& source) {
    source.checkFormat("signstim-results-columns", 1);
    if (!source.root.is_object()) source.failAt("", "expected an object {\"format\": ..., \"columns\": {...}}");
    for (const auto& [key, value] : source.root.items()) {
        if (key != "format" && key != "version" && key != "columns" && key != "notes")
            source.failAt("/" + stimuli::jsonPointerToken(key), "unknown field (expected format, version, columns, notes)");
    }
    const auto columns = source.root.find("columns");
    if (columns == source.root.end() || !columns->is_object())
        source.failAt("", "expected \"columns\": {\"our_column\": \"their column\", ...}");
    ColumnMap map;
    map.file = source.file;
    const std::vector<std::string>& ours = resultsColumns();
    std::map<std::string, std::string> usedBy;
    for (const auto& [key, value] : columns->items()) {
        const std::string pointer = "/columns/" + stimuli::jsonPointerToken(key);
        if (std::find(ours.begin(), ours.end(), key) == ours.end())
            source.failAt(pointer, "'" + key + "' is not a results column (docs/analysis.md lists them: participant, phase, trial, ...)");
        if (!value.is_string() || trimmed(value.get<std::string>()).empty())
            source.failAt(pointer, "expected the other program's column name as a non-empty string");
        const std::string name = value.get<std::string>();
        if (const auto [it, inserted] = usedBy.emplace(name, key); !inserted)
            source.failAt(pointer, "'" + name + "' is already the column of '" + it->second + "'");
        map.theirs[key] = name;
    }
    return map;
}

ColumnMap readColumnMap(const fs::path& file) {
    const stimuli::JsonSource source = stimuli::readJsonFile(file);
    return parseColumnMap(source);
}

ParticipantResults parseResults(std::string_view text, const std::string& file, const StudyListing& study,
                                const ColumnMap& columns, std::vector<std::string>& warnings) {
    const CsvTable table = parseCsv(text, file);
    ParticipantResults results;
    results.file = file;
    results.fileName = fs::path(file).filename().string();
    results.sha256 = sha256Hex(text);
    for (const std::string& comment : table.comments)
        if (comment.find("SYNTHETIC") != std::string::npos) results.synthetic = true;

    std::map<std::string, std::size_t> index;
    for (const std::string& ours : resultsColumns()) {
        const std::string& name = columns.nameOf(ours);
        const auto it = std::find(table.header.begin(), table.header.end(), name);
        if (it == table.header.end())
            throw InputError(file, table.headerLine, columns.describe(ours),
                             "this column is missing from the header" +
                                 std::string(columns.file.empty() ? " (files of other software: --columns MAP.json, docs/analysis.md)" : ""));
        index[ours] = static_cast<std::size_t>(it - table.header.begin());
    }
    if (table.records.empty()) throw InputError(file, table.headerLine, "", "no rows after the header");
    if (study.versions.size() > kPanelColumns)
        throw InputError(file, 0, "", "the study compares " + std::to_string(study.versions.size()) +
                                          " versions; results files have rating columns for at most 4 panels");

    const std::size_t noStory = study.stories.size();
    std::vector<int> storyLine(study.stories.size(), 0), sentenceLine(study.sentences.size(), 0);
    bool first = true;
    for (const CsvRecord& record : table.records) {
        const Row row(table, record, index, columns);
        const std::string participant = row.required("participant", "the participant's id (P07)");
        if (first) {
            results.participant = participant;
            results.participantIndex = findById(study.participants, participant);
            if (results.participantIndex == study.participants.size())
                row.fail("participant", "'" + participant + "' is not a participant of this study (it has " +
                                            (study.participants.empty() ? std::string("none")
                                                                        : study.participants.front().id + " to " +
                                                                              study.participants.back().id) +
                                            ")");
            first = false;
        } else if (participant != results.participant) {
            row.fail("participant", "'" + participant + "' in a file of '" + results.participant +
                                        "': one file per participant");
        }
        const stimuli::ListedParticipant& who = study.participants[results.participantIndex];
        const std::string phase = row.required("phase", "1 or 2");
        const long long trial = row.integer("trial", "a trial number 1, 2, ...");
        if (trial < 1) row.fail("trial", "expected a trial number 1, 2, ..., got " + std::to_string(trial));
        if (const std::string rt = row.text("rt_ms"); !rt.empty() && !(numberValue(rt) && *numberValue(rt) >= 0))
            row.fail("rt_ms", "expected a response time in milliseconds (a number >= 0) or empty, got '" + rt + "'");

        if (phase == "1") {
            Phase1Result r;
            r.line = row.line();
            r.trial = static_cast<std::size_t>(trial);
            const std::string storyName = row.required("story_id", "a story id (story-03)");
            r.story = findById(study.stories, storyName);
            if (r.story == noStory) row.fail("story_id", "'" + storyName + "' is not a story of this study");
            if (storyLine[r.story] != 0)
                row.fail("story_id", storyName + " again (first on line " + std::to_string(storyLine[r.story]) +
                                         "): a participant sees each story once");
            storyLine[r.story] = row.line();
            const std::string versionName = row.required("version", "a version (" + listOfIds(study.versions) + ")");
            r.version = versionIndex(study, versionName);
            if (r.version == study.versions.size())
                row.fail("version", "'" + versionName + "' is not a version of this study (" + listOfIds(study.versions) + ")");
            const auto scheduled = std::find_if(who.phase1.begin(), who.phase1.end(),
                                                [&](const stimuli::ListedPhase1Trial& t) { return t.story == r.story; });
            if (scheduled == who.phase1.end())
                row.fail("story_id", "the design never showed " + storyName + " to " + results.participant);
            if (scheduled->version != r.version)
                row.fail("version", "the design showed " + storyName + " to " + results.participant + " as '" +
                                        study.versions[scheduled->version] + "' (group " + std::to_string(who.group + 1) +
                                        "), the file says '" + versionName + "': results of another study or participant?");
            if (scheduled->trial != r.trial)
                warnings.push_back(row.warning("trial", "the design showed " + storyName + " as trial " +
                                                            std::to_string(scheduled->trial) + ", the file says " +
                                                            std::to_string(r.trial)));
            const stimuli::ListedStory& story = study.stories[r.story];
            if (story.questions.size() > kQuestionColumns)
                row.fail("story_id", storyName + " has " + std::to_string(story.questions.size()) +
                                         " questions; results files have columns for 4");
            int fileCorrectSum = 0;
            bool fileCorrectComplete = true;
            for (std::size_t q = 0; q < kQuestionColumns; ++q) {
                const std::string responseColumn = questionColumn(q, "response"), correctColumn = questionColumn(q, "correct");
                if (q >= story.questions.size()) {
                    if (!row.empty(responseColumn))
                        row.fail(responseColumn, storyName + " has " + std::to_string(story.questions.size()) +
                                                     " questions: this column must be empty");
                    continue;
                }
                const stimuli::ListedQuestion& question = story.questions[q];
                const std::string response = row.text(responseColumn);
                int choice = kNoAnswer;
                if (response.empty()) {
                    warnings.push_back(row.warning(responseColumn, "no answer; counted as incorrect"));
                } else {
                    const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(response[0])));
                    if (response.size() != 1 || c < 'A' || c >= static_cast<char>('A' + question.choices.size()))
                        row.fail(responseColumn, "expected a choice letter A to " + letter(question.choices.size() - 1) +
                                                     " (or empty: not answered), got '" + response + "'");
                    choice = c - 'A';
                }
                const bool correct = choice == question.answer;
                r.choices.push_back(choice);
                r.correct.push_back(correct);
                const std::string stated = row.text(correctColumn);
                if (stated.empty()) {
                    fileCorrectComplete = false;
                    continue;
                }
                const auto flag = flagValue(stated);
                if (!flag) row.fail(correctColumn, "expected 1 or 0 (true or false), got '" + stated + "'");
                fileCorrectSum += *flag ? 1 : 0;
                if (*flag != correct)
                    warnings.push_back(row.warning(
                        correctColumn, "says " + std::string(*flag ? "1" : "0") + ", but the answer key of " + storyName +
                                           " question " + std::to_string(q + 1) + " is " + letter(static_cast<std::size_t>(question.answer)) +
                                           " and the response is " + (choice == kNoAnswer ? std::string("empty") : letter(static_cast<std::size_t>(choice))) +
                                           ": the recomputed " + (correct ? "1" : "0") + " is analysed"));
            }
            if (!row.empty("n_correct")) {
                const long long stated = row.integer("n_correct", "the number of correct answers");
                const long long recomputed = std::count(r.correct.begin(), r.correct.end(), true);
                if (stated != recomputed)
                    warnings.push_back(row.warning(
                        "n_correct", "says " + std::to_string(stated) + ", the answer key gives " + std::to_string(recomputed) +
                                         (fileCorrectComplete && stated != fileCorrectSum
                                              ? " (and the file's own qN_correct add up to " + std::to_string(fileCorrectSum) + ")"
                                              : std::string())));
            }
            results.phase1.push_back(std::move(r));
        } else if (phase == "2") {
            Phase2Result r;
            r.line = row.line();
            r.trial = static_cast<std::size_t>(trial);
            const std::string sentenceName = row.required("sentence_id", "a sentence id (likert-05)");
            r.sentence = findById(study.sentences, sentenceName);
            if (r.sentence == study.sentences.size())
                row.fail("sentence_id", "'" + sentenceName + "' is not a phase-2 sentence of this study");
            if (sentenceLine[r.sentence] != 0)
                row.fail("sentence_id", sentenceName + " again (first on line " + std::to_string(sentenceLine[r.sentence]) +
                                            "): a participant rates each sentence once");
            sentenceLine[r.sentence] = row.line();
            const stimuli::ListedSentence& sentence = study.sentences[r.sentence];
            const std::string code = row.required("panel_code", "the panel code (" + sentence.panelCode + ")");
            if (code != sentence.panelCode)
                row.fail("panel_code", "the study showed " + sentenceName + " with panels " + sentence.panelCode +
                                           " (panel A " + study.versions[sentence.panelVersion.front()] + "), the file says '" +
                                           code + "'");
            const auto scheduled = std::find_if(who.phase2.begin(), who.phase2.end(),
                                                [&](const stimuli::ListedPhase2Trial& t) { return t.sentence == r.sentence; });
            if (scheduled != who.phase2.end() && scheduled->trial != r.trial)
                warnings.push_back(row.warning("trial", "the design showed " + sentenceName + " as trial " +
                                                            std::to_string(scheduled->trial) + ", the file says " +
                                                            std::to_string(r.trial)));
            r.ratings.assign(study.versions.size(), std::numeric_limits<double>::quiet_NaN());
            const std::string scale =
                std::to_string(study.likertMinimum) + " to " + std::to_string(study.likertMaximum);
            for (std::size_t k = 0; k < kPanelColumns; ++k) {
                const std::string column = std::string("rating_") + kPanelNames[k];
                const std::string value = row.text(column);
                if (k >= sentence.panelVersion.size()) {
                    if (!value.empty())
                        row.fail(column, "the study has " + std::to_string(sentence.panelVersion.size()) +
                                             " panels: this column must be empty");
                    continue;
                }
                const std::size_t version = sentence.panelVersion[k];
                if (value.empty()) {
                    warnings.push_back(row.warning(column, "no rating of panel " + letter(k) + " (" + study.versions[version] +
                                                               "); left out"));
                    continue;
                }
                const auto rating = integerValue(value);
                if (!rating || *rating < study.likertMinimum || *rating > study.likertMaximum)
                    row.fail(column, "expected a whole number " + scale + " (the study's scale), got '" + value + "'");
                r.ratings[version] = static_cast<double>(*rating);
            }
            for (const char* versionName : kVersionColumns) {
                const std::string column = std::string("rating_") + versionName;
                const std::string value = row.text(column);
                const std::size_t version = versionIndex(study, versionName);
                if (version == study.versions.size()) {
                    if (!value.empty()) row.fail(column, std::string("'") + versionName + "' is not a version of this study: this column must be empty");
                    continue;
                }
                if (value.empty()) continue;  // the panels' columns are what was clicked; this one is a convenience
                const auto stated = numberValue(value);
                if (!stated) row.fail(column, "expected a number " + scale + " or empty, got '" + value + "'");
                const double ours = r.ratings[version];
                if (std::isnan(ours) || *stated != ours) {
                    const std::size_t panel = static_cast<std::size_t>(
                        std::find(sentence.panelVersion.begin(), sentence.panelVersion.end(), version) - sentence.panelVersion.begin());
                    warnings.push_back(row.warning(
                        column, "says " + value + ", but " + versionName + " was panel " + letter(panel) + " of " + sentence.panelCode +
                                    ", rated " + (std::isnan(ours) ? std::string("nothing") : row.text(std::string("rating_") + kPanelNames[panel])) +
                                    ": the panel's rating is analysed"));
                }
            }
            results.phase2.push_back(std::move(r));
        } else {
            row.fail("phase", "expected 1 (comprehension) or 2 (side-by-side rating), got '" + phase + "'");
        }
    }

    const stimuli::ListedParticipant& who = study.participants[results.participantIndex];
    std::vector<std::string> missing;
    for (const stimuli::ListedPhase1Trial& t : who.phase1)
        if (storyLine[t.story] == 0) missing.push_back(study.stories[t.story].id);
    if (!missing.empty())
        warnings.push_back(InputError(file, 0, "", results.participant + " has " + std::to_string(results.phase1.size()) + " of " +
                                                       std::to_string(who.phase1.size()) + " phase-1 trials (missing " +
                                                       listOfIds(missing) + ")")
                               .what());
    missing.clear();
    for (const stimuli::ListedPhase2Trial& t : who.phase2)
        if (sentenceLine[t.sentence] == 0) missing.push_back(study.sentences[t.sentence].id);
    if (!missing.empty())
        warnings.push_back(InputError(file, 0, "", results.participant + " has " + std::to_string(results.phase2.size()) + " of " +
                                                       std::to_string(who.phase2.size()) + " phase-2 trials (missing " +
                                                       listOfIds(missing) + ")")
                               .what());
    return results;
}

ParticipantResults readResults(const fs::path& file, const StudyListing& study, const ColumnMap& columns,
                               std::vector<std::string>& warnings) {
    const std::string text = stimuli::readTextFile(file, limits::kCsvFileBytes);
    return parseResults(text, file.string(), study, columns, warnings);
}

std::vector<ParticipantResults> readResultsFiles(const std::vector<fs::path>& files, const StudyListing& study,
                                                 const ColumnMap& columns, std::vector<std::string>& warnings) {
    std::vector<ParticipantResults> all;
    std::map<std::size_t, std::string> fileOf;
    for (const fs::path& file : files) {
        ParticipantResults r = readResults(file, study, columns, warnings);
        if (const auto [it, inserted] = fileOf.emplace(r.participantIndex, r.file); !inserted)
            throw InputError(r.file, 0, "participant",
                             r.participant + " has results in " + it->second + " too: give each participant's file once");
        all.push_back(std::move(r));
    }
    std::sort(all.begin(), all.end(),
              [](const ParticipantResults& a, const ParticipantResults& b) { return a.participantIndex < b.participantIndex; });
    return all;
}

StudyListing readStudyManifest(const fs::path& studyDirOrManifest, std::string* manifestPath) {
    // The study folder's reader (stimuli/study/study_folder.hpp); the folder is named by --study.
    return stimuli::readStudyManifestListing(studyDirOrManifest, "--study", manifestPath);
}

}  // namespace signstim::analysis
