#include "app/study_documents.hpp"

#include "stimuli/review_page.hpp"
#include "stimuli/study_experiment.hpp"
#include "stimuli/study_exports.hpp"

namespace signstim::app {

std::vector<StudyDocument> studyDocuments(const stimuli::StudyListing& listing) {
    std::vector<StudyDocument> documents;
    documents.push_back({"index.html", "review", "", stimuli::reviewPageHtml(listing)});
    documents.push_back({"overview.csv", "overview", "", stimuli::overviewCsv(listing)});
    documents.push_back({"question-sheets.html", "sheet", "", stimuli::questionSheetHtml(listing)});
    for (std::size_t p = 0; p < listing.participants.size(); ++p) {
        const std::string id = listing.participants[p].id;
        const std::string folder = "participants/" + id + "/";
        documents.push_back({folder + id + "_conditions.csv", "conditions", id, stimuli::conditionsCsv(listing, p)});
        documents.push_back({folder + id + "_timeline_variables.json", "jspsych", id,
                             stimuli::jspsychTimelineVariables(listing, p)});
        if (!listing.sentences.empty())
            documents.push_back({folder + id + "_likert-response-sheet.html", "sheet", id,
                                 stimuli::likertResponseSheetHtml(listing, p)});
    }
    return documents;
}

std::vector<StudyDocument> experimentDocuments(const stimuli::StudyListing& listing, const JspsychBundle& jspsych) {
    std::vector<StudyDocument> documents;
    for (stimuli::ExperimentFile& file : stimuli::jspsychExperimentFiles(listing))
        documents.push_back({std::move(file.path), "experiment", std::move(file.participant), std::move(file.contents)});
    for (const JspsychBundle::File& file : jspsych.files)
        documents.push_back({file.path, "experiment-library", "", file.contents});
    return documents;
}

}  // namespace signstim::app
