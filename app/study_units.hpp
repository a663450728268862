#pragma once
// The rendering side of `signstim study` (app/study_runner.hpp): a loaded study, and the
// renderer that draws its units and drains their encoders. The study folder's rules (records,
// plan, manifest) are stimuli/study/study_folder.hpp's; this is the wiring to signer/ and
// renderer/.
#include "app/study_human.hpp"
#include "app/study_runner.hpp"
#include "renderer/video_encoder.hpp"
#include "stimuli/story/story.hpp"
#include "stimuli/story/story_world.hpp"
#include "stimuli/story/timeline.hpp"
#include "stimuli/study/study.hpp"
#include "stimuli/study/study_folder.hpp"

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace signstim::app {

struct LoadedStudy {
    stimuli::StudyFile study;
    std::unique_ptr<stimuli::StoryWorld> world;
    std::vector<stimuli::Story> stories;
    std::optional<stimuli::Story> phase2;
    stimuli::StudyRenderSettings settings;
    render::FrameRate frameRate;
    bool pngFrames = false;
    std::string experiment;  // "jspsych"; "none" or "": none (decided by useExperiment)
    stimuli::StudyListing listing;
    std::string dataHash;  // everything every unit depends on (stimuli::studyDataHash)
    std::vector<stimuli::StudyUnit> units;
    HumanClips humanClips;  // the lab's recordings of each unit (app/study_human.hpp)
    // Issue 24: each instruction page's gloss parsed (the pages of study.instructions, in order;
    // empty when the study shows instructions in English only). app/study_questions.hpp.
    std::vector<std::vector<stimuli::StorySentence>> instructionSentences;
    std::vector<std::string> signedTextNotes;  // words fingerspelled in the instructions, for --check
};

// Renders the units of one run: one renderer (the device), encoders running beside it. A
// unit's encoders are finished, its posters written and its record committed on a worker
// while the renderer goes on with the next unit, as long as no more than the encoder limit run.
class UnitRenderer {
public:
    UnitRenderer(const LoadedStudy& s, const StudyRunOptions& options, const std::filesystem::path& dir);
    ~UnitRenderer();
    UnitRenderer(const UnitRenderer&) = delete;
    UnitRenderer& operator=(const UnitRenderer&) = delete;

    // `progress` receives the fraction of the unit drawn.
    void render(const stimuli::StudyUnit& unit, const std::vector<stimuli::Timeline>& timelines,
                const std::string& inputHash, const std::function<void(double)>& progress, StudyRunReport& report);
    // Waits for every unit's encoders and records.
    void finishAll(StudyRunReport& report);

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace signstim::app
