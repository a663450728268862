#include "app/study_documents.hpp"

namespace signstim::app {

std::vector<StudyDocument> studyDocuments(const stimuli::StudyListing& listing) {
    (void)listing;
    return {};
}

}  // namespace signstim::app
