#pragma once
// The files of a complete study besides its clips: per-participant exports, the overview,
// question and response sheets, and the review page — each a path in the study folder, its
// kind (for the manifest) and its contents, written by the study runner through the atomic
// writer. Everything here is computed from the listing alone, so any run that completes a
// study (or a merge of shards) writes the same bytes.
#include "stimuli/study/jspsych_bundle.hpp"
#include "stimuli/study/study_listing.hpp"

#include <string>
#include <vector>

namespace signstim::stimuli {

struct StudyDocument {
    std::string path;         // relative to the study folder, '/' separators
    std::string kind;         // "conditions", "jspsych", "overview", "sheet", "review", ...
    std::string participant;  // "P03" for a participant's file, else empty
    std::string contents;     // bytes: text, or a copied library file
    std::string shows;        // what it is, for the manifest
};

std::vector<StudyDocument> studyDocuments(const stimuli::StudyListing& listing);

// The jsPsych experiment (stimuli/study/study_experiment.hpp): its own files (kind "experiment") and
// the jsPsych files copied from `jspsych` (kind "experiment-library").
std::vector<StudyDocument> experimentDocuments(const stimuli::StudyListing& listing, const JspsychBundle& jspsych);

}  // namespace signstim::stimuli
