#include "app/study_annotations.hpp"

#include "common/atomic_file.hpp"
#include "common/file_manifest.hpp"
#include "stimuli/study/elan_export.hpp"

#include <cmath>

namespace signstim::app {

using namespace signstim::stimuli;

namespace {

// `target` as seen from the folder of `from` (both relative to the study folder, '/'-separated).
std::string relativeTo(const std::string& from, const std::string& target) {
    std::string up;
    for (char c : from)
        if (c == '/') up += "../";
    return up + target;
}

}  // namespace

UnitAnnotations makeUnitAnnotations(const LoadedStudy& s, const signer::Signer& signer,
                                    const signer::ScreenRegionModel& model, const StudyUnit& unit,
                                    const std::vector<Timeline>& timelines, const std::vector<const signer::Clip*>& clips) {
    UnitAnnotations out;
    const double fps = s.frameRate.value();
    const auto make = [&](const ListedClip& clip, const std::vector<std::size_t>& versions, const std::vector<std::string>& labels,
                          const std::vector<std::string>& glosses) {
        std::vector<const signer::Clip*> panels;
        std::vector<ElanPanel> elanPanels;
        for (std::size_t k = 0; k < versions.size(); ++k) {
            // A human-video version (placed after the animated ones) has no signer clip: its panel
            // keeps its place in the grid and has no regions or tiers.
            const bool signed_ = versions[k] < clips.size() && versions[k] < timelines.size();
            panels.push_back(signed_ ? clips[versions[k]] : nullptr);
            elanPanels.push_back({k < labels.size() ? labels[k] : "", signed_ ? &timelines[versions[k]] : nullptr});
        }
        // The grid renderClips draws the panels in (app/study_units.cpp).
        const auto columns = static_cast<std::uint32_t>(std::ceil(std::sqrt(static_cast<double>(panels.size()))));
        const auto rows = static_cast<std::uint32_t>((panels.size() + columns - 1) / columns);
        out.regions.push_back(clip.regions.empty() ? std::string()
                                                   : signer::screenRegionsCsv(signer.avatar(), signer.rig(), model, panels,
                                                                              labels, fps, s.settings.width,
                                                                              s.settings.height, columns, rows));
        ElanDocumentOptions options;
        options.mediaUrl = relativeTo(clip.annotation, clip.video);
        options.framesPerSecond = fps;
        options.sentenceGlosses = glosses;
        out.elan.push_back(clip.annotation.empty() ? std::string() : elanDocument(elanPanels, options));
    };
    if (unit.story) {
        const ListedStory& story = s.listing.stories[unit.index];
        for (std::size_t v = 0; v < story.clips.size(); ++v) {
            if (v < clips.size()) {
                make(story.clips[v], {v}, {}, story.sentences);
            } else {  // a lab's recording: no regions, no ELAN file (stimuli/study/study.cpp)
                out.regions.emplace_back();
                out.elan.emplace_back();
            }
        }
    } else {
        const ListedSentence& sentence = s.listing.sentences[unit.index];
        std::vector<std::string> labels;
        for (std::size_t k = 0; k < sentence.panelVersion.size(); ++k) labels.push_back(panelLabel(k));
        make(sentence.clip, sentence.panelVersion, labels, {sentence.gloss});
    }
    return out;
}

void writeUnitAnnotations(const std::filesystem::path& dir, const ListedClip& clip, const UnitAnnotations& annotations,
                          std::size_t i, const nlohmann::json& shows, nlohmann::json& files) {
    const auto write = [&](const std::string& path, const std::string& bytes, const char* kind) {
        if (path.empty() || i >= annotations.regions.size()) return;
        writeFileAtomic(dir / path, bytes);
        nlohmann::json entry = describeFile(dir, path, kind);
        entry["shows"] = shows;
        files.push_back(entry);
    };
    if (i < annotations.regions.size()) write(clip.regions, annotations.regions[i], "regions");
    if (i < annotations.elan.size()) write(clip.annotation, annotations.elan[i], "annotation");
}

}  // namespace signstim::app
