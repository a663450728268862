#pragma once
// The files of a complete study besides its clips: per-participant exports, the overview,
// question and response sheets, and the review page — each a path in the study folder, its
// kind (for the manifest) and its contents, written by the study runner through the atomic
// writer. Everything here is computed from the listing alone, so any run that completes a
// study (or a merge of shards) writes the same bytes.
#include "stimuli/study_listing.hpp"

#include <string>
#include <vector>

namespace signstim::app {

struct StudyDocument {
    std::string path;         // relative to the study folder, '/' separators
    std::string kind;         // "conditions", "jspsych", "overview", "sheet", "review", ...
    std::string participant;  // "P03" for a participant's file, else empty
    std::string contents;
    std::string shows;        // what it is, for the manifest
};

std::vector<StudyDocument> studyDocuments(const stimuli::StudyListing& listing);

}  // namespace signstim::app
