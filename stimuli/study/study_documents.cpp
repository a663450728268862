#include "stimuli/study/study_documents.hpp"

#include "stimuli/study/review_page.hpp"
#include "stimuli/study/study_experiment.hpp"
#include "stimuli/study/study_exports.hpp"

namespace signstim::stimuli {

std::vector<StudyDocument> studyDocuments(const stimuli::StudyListing& listing) {
    std::vector<StudyDocument> documents;
    documents.push_back({"index.html", "review", "", stimuli::reviewPageHtml(listing),
                         "review page: every participant's set, every story's versions, the phase-2 mappings"});
    documents.push_back({"overview.csv", "overview", "", stimuli::overviewCsv(listing), "story x group -> version"});
    documents.push_back({"question-sheets.html", "sheet", "", stimuli::questionSheetHtml(listing),
                         "every story's gloss and questions with the answer key (printable)"});
    for (std::size_t p = 0; p < listing.participants.size(); ++p) {
        const std::string id = listing.participants[p].id;
        const std::string folder = "participants/" + id + "/";
        documents.push_back({folder + id + "_conditions.csv", "conditions", id, stimuli::conditionsCsv(listing, p),
                             id + "'s trials in order, for PsychoPy and OpenSesame"});
        documents.push_back({folder + id + "_gorilla.csv", "conditions", id, stimuli::gorillaSpreadsheetCsv(listing, p),
                             id + "'s Gorilla spreadsheet: instructions, trials, break, end (docs/exports.md)"});
        documents.push_back({folder + id + "_timeline_variables.json", "jspsych", id,
                             stimuli::jspsychTimelineVariables(listing, p), id + "'s trials for jsPsych timeline_variables"});
        if (!listing.sentences.empty())
            documents.push_back({folder + id + "_likert-response-sheet.html", "sheet", id,
                                 stimuli::likertResponseSheetHtml(listing, p),
                                 id + "'s phase-2 response sheet (printable; no mapping shown)"});
    }
    return documents;
}

std::vector<StudyDocument> experimentDocuments(const stimuli::StudyListing& listing, const JspsychBundle& jspsych) {
    std::vector<StudyDocument> documents;
    for (stimuli::ExperimentFile& file : stimuli::jspsychExperimentFiles(listing)) {
        std::string shows = file.participant.empty() ? "the jsPsych experiment (docs/experiment.md)"
                                                     : file.participant + "'s session data for the jsPsych experiment";
        documents.push_back({std::move(file.path), "experiment", std::move(file.participant), std::move(file.contents),
                             std::move(shows)});
    }
    for (const JspsychBundle::File& file : jspsych.files)
        documents.push_back({file.path, "experiment-library", "", file.contents, "jsPsych 8 (pinned; third_party/jspsych)"});
    return documents;
}

}  // namespace signstim::stimuli
