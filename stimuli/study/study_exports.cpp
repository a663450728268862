#include "stimuli/study/study_exports.hpp"

#include "common/number_format.hpp"
#include "stimuli/study/question_clips.hpp"
#include "stimuli/study/study_design.hpp"
#include "stimuli/study/study_listing_check.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace signstim::stimuli {
namespace {

using nlohmann::json;
using exports_detail::checkedParticipant;
using exports_detail::checkStudy;
using exports_detail::choiceLetter;
using exports_detail::count;
using exports_detail::inconsistent;

std::string lowercase(std::string text) {
    for (char& c : text)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return text;
}

// "clips/story-03_version-point.mp4" -> "story-03_version-point.mp4": platforms with a flat
// stimulus pool (Gorilla) refer to files by name alone.
std::string fileName(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

// Durations as the CSV writes them (3 decimals); the JSON reads that text back so both files
// carry the same number.
std::string durationText(double seconds) { return formatFixed(seconds, 3); }

double durationValue(double seconds) {
    const std::string text = durationText(seconds);
    double value = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), value);
    return value;
}

// ---- CSV ----------------------------------------------------------------------------------

// A table whose every row has every column. Cells are set by column name, so a misspelt name
// is caught at once instead of shifting a column.
class CsvTable {
public:
    explicit CsvTable(std::vector<std::string> columns) : columns_(std::move(columns)) {}

    void addRow() { rows_.emplace_back(columns_.size()); }

    void set(std::string_view column, std::string value) {
        const auto found = std::find(columns_.begin(), columns_.end(), column);
        if (found == columns_.end()) throw std::logic_error("export table: no column '" + std::string(column) + "'");
        rows_.back()[static_cast<std::size_t>(found - columns_.begin())] = std::move(value);
    }

    // RFC 4180 with CRLF line ends.
    std::string text() const {
        std::string out;
        writeLine(out, columns_);
        for (const std::vector<std::string>& row : rows_) writeLine(out, row);
        return out;
    }

private:
    static void writeLine(std::string& out, const std::vector<std::string>& fields) {
        for (std::size_t i = 0; i < fields.size(); ++i) {
            if (i > 0) out += ',';
            out += csvField(fields[i]);
        }
        out += "\r\n";
    }

    std::vector<std::string> columns_;
    std::vector<std::vector<std::string>> rows_;
};

std::size_t mostQuestions(const StudyListing& listing) {
    std::size_t most = 0;
    for (const ListedStory& story : listing.stories) most = std::max(most, story.questions.size());
    return most;
}

// Whether any question has a signed clip (the study's questions "asl" or "both"): only then do the
// files carry qN_video_file and qN_video_name, so an English-only study's columns are unchanged.
bool signsQuestions(const StudyListing& listing) {
    return std::any_of(listing.stories.begin(), listing.stories.end(),
                       [](const ListedStory& story) { return hasQuestionClips(story); });
}

std::size_t mostChoices(const StudyListing& listing) {
    std::size_t most = 0;
    for (const ListedStory& story : listing.stories)
        for (const ListedQuestion& question : story.questions) most = std::max(most, question.choices.size());
    return most;
}

std::string questionColumn(std::size_t question, std::string_view field) {
    return "q" + count(question + 1) + "_" + std::string(field);
}

std::string panelColumn(std::size_t panel) { return "panel_" + lowercase(panelLabel(panel)) + "_version"; }

// The columns depend on the whole study (its most questions, most choices, its versions), not
// on one participant, so every participant's file has the same header.
// `participant_id`, not `participant`: PsychoPy's own session field is `participant`, and a
// conditions column of the same name is overwritten by it in the saved data (both columns hold
// the dialog's value; the issue-24 lab lost "P01" that way). Python tests
// (tests/stimuli/check_conditions_for_psychopy.py) apply importConditions' rules to the files.
std::vector<std::string> conditionsColumns(const StudyListing& listing) {
    std::vector<std::string> columns = {
        "display",  "phase",       "trial",   "participant_id", "group",                          // every row
        "story_id", "story_title", "version",                                                    // phase 1
        "sentence_id", "gloss", "verb",                                                          // phase 2
        "video_file", "video_name", "poster_file", "poster_name", "duration_s"};                 // every row
    const std::size_t choices = mostChoices(listing);
    const bool signedQuestions = signsQuestions(listing);
    for (std::size_t q = 0; q < mostQuestions(listing); ++q) {
        columns.push_back(questionColumn(q, "text"));
        if (signedQuestions)  // issue 24: the signed question, played before the choices
            for (const char* field : {"video_file", "video_name"}) columns.push_back(questionColumn(q, field));
        for (std::size_t c = 0; c < choices; ++c) columns.push_back(questionColumn(q, "choice_" + lowercase(choiceLetter(c))));
        columns.push_back(questionColumn(q, "answer"));
        columns.push_back(questionColumn(q, "answer_index"));
        columns.push_back(questionColumn(q, "answer_text"));
    }
    for (std::size_t panel = 0; panel < likertPanelCount(listing); ++panel) columns.push_back(panelColumn(panel));
    columns.push_back("panel_code");
    return columns;
}

void setClipCells(CsvTable& table, const ListedClip& clip) {
    table.set("video_file", clip.video);
    table.set("video_name", fileName(clip.video));
    table.set("poster_file", clip.poster);
    table.set("poster_name", fileName(clip.poster));
    table.set("duration_s", durationText(clip.durationSeconds));
}

}  // namespace

std::string csvField(std::string_view text) {
    if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
    std::string quoted = "\"";
    for (char c : text) {
        if (c == '"') quoted += '"';
        quoted += c;
    }
    quoted += '"';
    return quoted;
}

std::string escapeHtml(std::string_view text) {
    std::string escaped;
    escaped.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '&': escaped += "&amp;"; break;
            case '<': escaped += "&lt;"; break;
            case '>': escaped += "&gt;"; break;
            case '"': escaped += "&quot;"; break;
            case '\'': escaped += "&#39;"; break;
            default: escaped += c;
        }
    }
    return escaped;
}

namespace {

// The Gorilla spreadsheet's own rows (display name, text) around the trials (docs/exports.md).
struct GorillaText {
    std::string display, text;
};

std::string gorillaIntro(const StudyListing& listing) {
    return "In this study you watch short videos of an animated signer using American Sign Language (ASL). Part 1: " +
           count(listing.stories.size()) +
           " stories. Each story plays once, without pause or replay; after each you answer questions about it.";
}

std::string gorillaPart2(const StudyListing& listing) {
    return "Part 2: each video shows one sentence signed " + count(likertPanelCount(listing)) +
           " times side by side; the panels differ only in how the verb is signed. Replay it as often as you like, "
           "then rate the quality of the verb in each panel from " +
           std::to_string(listing.likertMinimum) + " (very poor) to " + std::to_string(listing.likertMaximum) +
           " (very good).";
}

// The trial rows of both files; `gorilla` adds the instruction, break and end rows and the
// columns Gorilla's conventions name (text, ANSWER, randomise_blocks, randomise_trials).
std::string trialTable(const StudyListing& listing, std::size_t participantIndex, bool gorilla) {
    checkStudy(listing);
    const ListedParticipant& participant = checkedParticipant(listing, participantIndex);
    std::vector<std::string> columns = conditionsColumns(listing);
    if (gorilla) {
        columns.insert(columns.begin() + 1, "text");
        for (const char* extra : {"ANSWER", "randomise_blocks", "randomise_trials"}) columns.push_back(extra);
    }
    CsvTable table(std::move(columns));
    const std::size_t questions = mostQuestions(listing);
    const auto setCommon = [&](std::string display, int phase, std::size_t trial) {
        table.addRow();
        table.set("display", std::move(display));
        table.set("phase", std::to_string(phase));
        table.set("trial", count(trial));
        table.set("participant_id", participant.id);
        table.set("group", count(participant.group + 1));
        // Never empty: pandas (PsychoPy's importConditions) reads a column with an empty cell
        // as floats, and 1.0 cannot index a list. -1: the row has no question N.
        for (std::size_t q = 0; q < questions; ++q) table.set(questionColumn(q, "answer_index"), "-1");
    };
    // A text row; when the study signs its instructions, the page's clip in the clip columns and
    // the page's own text (what the clip signs) in place of the default wording.
    const auto textRow = [&](const std::string& display, const std::string& text, int phase, std::string_view page) {
        setCommon(display, phase, 0);
        table.set("text", text);
        table.set("duration_s", "0.000");
        for (const ListedInstruction& instruction : listing.instructions) {
            if (instruction.page != page || instruction.clip.video.empty()) continue;
            table.set("text", instruction.text);
            setClipCells(table, instruction.clip);
        }
    };
    if (gorilla) textRow("instructions", gorillaIntro(listing), 1, "welcome");
    for (const ListedPhase1Trial& trial : participant.phase1) {
        const ListedStory& story = listing.stories[trial.story];
        setCommon("story", 1, trial.trial);
        table.set("story_id", story.id);
        table.set("story_title", story.title);
        table.set("version", listing.versions[trial.version]);
        setClipCells(table, story.clips[trial.version]);
        for (std::size_t q = 0; q < story.questions.size(); ++q) {
            const ListedQuestion& question = story.questions[q];
            table.set(questionColumn(q, "text"), question.text);
            if (!question.clip.video.empty()) {
                table.set(questionColumn(q, "video_file"), question.clip.video);
                table.set(questionColumn(q, "video_name"), fileName(question.clip.video));
            }
            for (std::size_t c = 0; c < question.choices.size(); ++c)
                table.set(questionColumn(q, "choice_" + lowercase(choiceLetter(c))), question.choices[c]);
            table.set(questionColumn(q, "answer"), choiceLetter(static_cast<std::size_t>(question.answer)));
            table.set(questionColumn(q, "answer_index"), std::to_string(question.answer));
            table.set(questionColumn(q, "answer_text"), question.choices[static_cast<std::size_t>(question.answer)]);
            // Gorilla scores a response against ANSWER by the button's text.
            if (gorilla && q == 0) table.set("ANSWER", question.choices[static_cast<std::size_t>(question.answer)]);
        }
    }
    if (gorilla && !participant.phase2.empty()) textRow("break", gorillaPart2(listing), 2, "part2");
    for (const ListedPhase2Trial& trial : participant.phase2) {
        const ListedSentence& sentence = listing.sentences[trial.sentence];
        setCommon("likert", 2, trial.trial);
        table.set("sentence_id", sentence.id);
        table.set("gloss", sentence.gloss);
        table.set("verb", sentence.verb);
        setClipCells(table, sentence.clip);
        for (std::size_t panel = 0; panel < sentence.panelVersion.size(); ++panel)
            table.set(panelColumn(panel), listing.versions[sentence.panelVersion[panel]]);
        table.set("panel_code", sentence.panelCode);
    }
    if (gorilla)
        textRow("end", "Thank you! You have finished. Please tell the experimenter.", participant.phase2.empty() ? 1 : 2, "");
    return table.text();
}

}  // namespace

std::string conditionsCsv(const StudyListing& listing, std::size_t participantIndex) {
    return trialTable(listing, participantIndex, false);
}

std::string gorillaSpreadsheetCsv(const StudyListing& listing, std::size_t participantIndex) {
    return trialTable(listing, participantIndex, true);
}

std::string jspsychTimelineVariables(const StudyListing& listing, std::size_t participantIndex) {
    checkStudy(listing);
    const ListedParticipant& participant = checkedParticipant(listing, participantIndex);

    json phase1 = json::array();
    for (const ListedPhase1Trial& trial : participant.phase1) {
        const ListedStory& story = listing.stories[trial.story];
        const ListedClip& clip = story.clips[trial.version];
        json questions = json::array();
        for (std::size_t q = 0; q < story.questions.size(); ++q) {
            const ListedQuestion& question = story.questions[q];
            const auto answer = static_cast<std::size_t>(question.answer);
            // jsPsychSurveyMultiChoice writes prompt and options into its page as HTML (the
            // options into value="..." attributes too), so they are escaped here; the response
            // it records is the browser's reading of that attribute, i.e. the plain text, which
            // correct_text holds for scoring.
            json options = json::array();
            for (const std::string& choice : question.choices) options.push_back(escapeHtml(choice));
            json entry = json::object();
            entry["prompt"] = escapeHtml(question.text);
            entry["options"] = std::move(options);
            entry["required"] = true;
            entry["name"] = "q" + count(q + 1);
            entry["correct"] = answer;
            entry["correct_letter"] = choiceLetter(answer);
            entry["correct_text"] = question.choices[answer];
            // Issue 24: the question signed (played before the choices when the study shows it).
            if (!question.clip.video.empty()) {
                entry["gloss"] = question.gloss;
                entry["video"] = json::array({question.clip.video});
                entry["duration_s"] = durationValue(question.clip.durationSeconds);
            }
            questions.push_back(std::move(entry));
        }
        json element = json::object();
        element["trial"] = trial.trial;
        element["story"] = story.id;
        element["title"] = story.title;
        element["version"] = listing.versions[trial.version];
        element["video"] = json::array({clip.video});  // jsPsych's video `stimulus` is an array of sources
        element["poster"] = clip.poster;
        element["duration_s"] = durationValue(clip.durationSeconds);
        element["questions"] = std::move(questions);
        phase1.push_back(std::move(element));
    }

    json phase2 = json::array();
    for (const ListedPhase2Trial& trial : participant.phase2) {
        const ListedSentence& sentence = listing.sentences[trial.sentence];
        json panels = json::object();
        for (std::size_t panel = 0; panel < sentence.panelVersion.size(); ++panel)
            panels[panelLabel(panel)] = listing.versions[sentence.panelVersion[panel]];
        json element = json::object();
        element["trial"] = trial.trial;
        element["sentence"] = sentence.id;
        element["gloss"] = sentence.gloss;
        element["verb"] = sentence.verb;
        element["video"] = json::array({sentence.clip.video});
        element["poster"] = sentence.clip.poster;
        element["duration_s"] = durationValue(sentence.clip.durationSeconds);
        element["panels"] = std::move(panels);
        element["panel_code"] = sentence.panelCode;
        phase2.push_back(std::move(element));
    }

    json study = json::object();
    study["title"] = listing.title;
    study["design_hash"] = listing.designHash;
    study["seed"] = std::to_string(listing.seed);  // a string: JavaScript numbers hold 53 bits, seeds 64
    study["tool_version"] = listing.toolVersion;
    json likert = json::object();
    likert["minimum"] = listing.likertMinimum;
    likert["maximum"] = listing.likertMaximum;

    json document = json::object();
    document["participant"] = participant.id;
    document["group"] = participant.group + 1;
    document["study"] = std::move(study);
    document["likert"] = std::move(likert);
    document["phase1"] = std::move(phase1);
    document["phase2"] = std::move(phase2);
    try {
        return document.dump(2, ' ', false) + "\n";
    } catch (const json::type_error& error) {  // text that is not UTF-8
        inconsistent(std::string("text that JSON cannot hold: ") + error.what());
    }
}

std::string overviewCsv(const StudyListing& listing) {
    checkStudy(listing);
    if (listing.groupVersion.empty()) inconsistent("groupVersion is empty; the overview is written from it");
    for (std::size_t p = 0; p < listing.participants.size(); ++p) checkedParticipant(listing, p);

    const std::size_t groups = listing.groupVersion.front().size();
    std::vector<std::string> columns = {"story", "title"};
    for (std::size_t group = 0; group < groups; ++group) columns.push_back("group_" + count(group + 1));
    CsvTable table(std::move(columns));
    for (std::size_t s = 0; s < listing.stories.size(); ++s) {
        table.addRow();
        table.set("story", listing.stories[s].id);
        table.set("title", listing.stories[s].title);
        for (std::size_t group = 0; group < groups; ++group)
            table.set("group_" + count(group + 1), listing.versions[listing.groupVersion[s][group]]);
    }
    return table.text();
}

}  // namespace signstim::stimuli
