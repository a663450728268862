#include "app/study_documents.hpp"

#include "stimuli/review_page.hpp"
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

}  // namespace signstim::app
