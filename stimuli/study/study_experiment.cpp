#include "stimuli/study/study_experiment.hpp"

#include "stimuli/study/study_exports.hpp"

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string_view>

namespace signstim::stimuli {

// stimuli/study/experiment/experiment.js (its four parts joined: stimuli/CMakeLists.txt) and
// experiment.css, embedded at build time (cmake/Embed.cmake).
namespace embedded {
extern const std::string_view experimentScript;
extern const std::string_view experimentStyleSheet;
}  // namespace embedded

namespace {

constexpr const char* kFolder = "experiment/";

std::string indexHtml(const StudyListing& listing) {
    std::string html =
        "<!DOCTYPE html>\n"
        "<html lang=\"en\">\n"
        "<head>\n"
        "<meta charset=\"utf-8\">\n"
        "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
        "<title>" + escapeHtml(listing.title) + "</title>\n"
        "<!-- The jsPsych experiment of this study, written by signstim " + escapeHtml(listing.toolVersion) +
        " (design " + listing.designHash.substr(0, 12) + "): open it with ?participant=P01 (docs/experiment.md). -->\n"
        "<link rel=\"icon\" href=\"data:,\">\n"  // no favicon request (a 404 on a static server)
        "<link rel=\"stylesheet\" href=\"jspsych/jspsych.css\">\n"
        "<link rel=\"stylesheet\" href=\"experiment.css\">\n";
    for (const ExperimentLibraryFile& file : jspsychLibraryFiles()) {
        const std::string_view path = file.path;
        if (!path.ends_with(".js")) continue;
        html += "<script src=\"" + std::string(path.substr(std::string_view(kFolder).size())) + "\"></script>\n";
    }
    html +=
        "<script src=\"participants/index.js\"></script>\n"
        "<!-- A server's hook (window.signstimHooks, docs/experiment.md) goes here, before experiment.js. -->\n"
        "</head>\n"
        "<body>\n"
        "<main id=\"signstim-start\" class=\"signstim-start\">\n"
        "<noscript><p>This experiment needs JavaScript: please turn it on and reload the page.</p></noscript>\n"
        "</main>\n"
        "<script src=\"experiment.js\"></script>\n"
        "</body>\n"
        "</html>\n";
    return html;
}

// A script setting window.NAME to a JSON value: JSON is valid JavaScript (ES2019 and later).
std::string scriptSetting(const std::string& comment, const std::string& name, std::string_view json) {
    while (!json.empty() && json.back() == '\n') json.remove_suffix(1);
    return "// " + comment + "\nwindow." + name + " = " + std::string(json) + ";\n";
}

std::string participantsIndex(const StudyListing& listing) {
    nlohmann::json study = nlohmann::json::object();
    study["title"] = listing.title;
    study["design_hash"] = listing.designHash;
    nlohmann::json ids = nlohmann::json::array();
    for (const ListedParticipant& participant : listing.participants) ids.push_back(participant.id);
    study["participants"] = std::move(ids);
    // The session's wording and background questions (study file "session", docs/experiment.md).
    study["rating_prompt"] = listing.ratingPrompt;
    study["background"] = listing.background;
    // Issue 24: questions and instructions in ASL ("asl", "english" or "both"); each
    // instruction page's English text and signed clip (docs/experiment.md).
    study["questions"] = listing.questionsShown;
    nlohmann::json instructions = nlohmann::json::object();
    instructions["show"] = listing.instructionsShown;
    nlohmann::json pages = nlohmann::json::object();
    for (const ListedInstruction& page : listing.instructions) {
        nlohmann::json entry = nlohmann::json::object();
        entry["text"] = page.text;
        if (!page.clip.video.empty()) entry["video"] = page.clip.video;
        pages[page.page] = std::move(entry);
    }
    instructions["pages"] = std::move(pages);
    study["instructions"] = std::move(instructions);
    return scriptSetting("signstim: this study's participants, for experiment/index.html (docs/experiment.md).",
                         "signstimStudy", study.dump(2, ' ', false));
}

}  // namespace

const std::vector<ExperimentLibraryFile>& jspsychLibraryFiles() {
    static const std::vector<ExperimentLibraryFile> files = {
        {"jspsych/dist/index.browser.js", "experiment/jspsych/jspsych.js"},
        {"plugin-preload/dist/index.browser.js", "experiment/jspsych/plugin-preload.js"},
        {"plugin-html-button-response/dist/index.browser.js", "experiment/jspsych/plugin-html-button-response.js"},
        {"plugin-video-keyboard-response/dist/index.browser.js", "experiment/jspsych/plugin-video-keyboard-response.js"},
        {"plugin-survey-multi-choice/dist/index.browser.js", "experiment/jspsych/plugin-survey-multi-choice.js"},
        {"plugin-survey-html-form/dist/index.browser.js", "experiment/jspsych/plugin-survey-html-form.js"},
        {"jspsych/css/jspsych.css", "experiment/jspsych/jspsych.css"},
        {"LICENSE.txt", "experiment/jspsych/LICENSE.txt"},
        {"PINS.txt", "experiment/jspsych/PINS.txt"},
    };
    return files;
}

std::vector<ExperimentFile> jspsychExperimentFiles(const StudyListing& listing) {
    for (const ListedStory& story : listing.stories)
        if (story.questions.size() > kExperimentMaxQuestions)
            throw std::invalid_argument("study listing: story " + story.id + " has " +
                                        std::to_string(story.questions.size()) +
                                        " questions; the experiment's results have columns for " +
                                        std::to_string(kExperimentMaxQuestions));
    std::vector<ExperimentFile> files;
    files.push_back({std::string(kFolder) + "index.html", "", indexHtml(listing)});
    files.push_back({std::string(kFolder) + "experiment.js", "", std::string(embedded::experimentScript)});
    files.push_back({std::string(kFolder) + "experiment.css", "", std::string(embedded::experimentStyleSheet)});
    files.push_back({std::string(kFolder) + "participants/index.js", "", participantsIndex(listing)});
    for (std::size_t p = 0; p < listing.participants.size(); ++p) {
        const std::string& id = listing.participants[p].id;
        files.push_back({std::string(kFolder) + "participants/" + id + ".js", id,
                         scriptSetting(id + "'s timeline variables (participants/" + id + "/" + id +
                                           "_timeline_variables.json), for experiment/index.html?participant=" + id +
                                           ".",
                                       "signstimTimeline", jspsychTimelineVariables(listing, p))});
    }
    return files;
}

}  // namespace signstim::stimuli
