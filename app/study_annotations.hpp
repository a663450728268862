#pragma once
// The eye-tracking regions and ELAN files of a study unit's clips (docs/study.md, "Eye-tracking
// regions" and "ELAN files"): made beside the clips by the unit renderer (app/study_units.cpp)
// and listed in the unit's record like the clips, so resume, verify, shards and merge treat them
// alike. The writers are signer/screen_regions.hpp and stimuli/study/elan_export.hpp.
#include "app/study_units.hpp"
#include "signer/clip.hpp"
#include "signer/screen_regions.hpp"
#include "signer/signer.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace signstim::app {

// Per clip of the unit (a story's versions in the listing's order, or the one side-by-side
// clip): the regions CSV and the .eaf, empty where the study does not write them.
struct UnitAnnotations {
    std::vector<std::string> regions, elan;
};

// `timelines` and `clips` are the unit's, one per study version.
UnitAnnotations makeUnitAnnotations(const LoadedStudy& s, const signer::Signer& signer,
                                    const signer::ScreenRegionModel& model, const stimuli::StudyUnit& unit,
                                    const std::vector<stimuli::Timeline>& timelines,
                                    const std::vector<const signer::Clip*>& clips);

// Writes clip `i`'s files (atomically) and appends their manifest entries to `files`.
void writeUnitAnnotations(const std::filesystem::path& dir, const stimuli::ListedClip& clip,
                          const UnitAnnotations& annotations, std::size_t i, const nlohmann::json& shows,
                          nlohmann::json& files);

}  // namespace signstim::app
