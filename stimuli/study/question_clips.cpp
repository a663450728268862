#include "stimuli/study/question_clips.hpp"

#include "common/error.hpp"
#include "stimuli/json_source.hpp"
#include "stimuli/study/study.hpp"

#include <algorithm>

namespace signstim::stimuli {

using nlohmann::json;

bool showsSigned(std::string_view shown) { return shown == kShowAsl || shown == kShowBoth; }
bool showsEnglish(std::string_view shown) { return shown != kShowAsl; }
bool isShowChoice(std::string_view text) { return text == kShowAsl || text == kShowEnglish || text == kShowBoth; }

namespace {

std::string pageList() {
    std::string list;
    for (std::string_view page : kInstructionPages) list += (list.empty() ? "\"" : ", \"") + std::string(page) + "\"";
    return list;
}

}  // namespace

std::vector<StudyInstruction> readInstructionPages(const JsonSource& source, const std::string& pointer,
                                                   std::initializer_list<const char*> extraKeys) {
    const json& object = pointer.empty() ? source.root : source.root.at(json::json_pointer(pointer));
    if (!object.is_object())
        source.failAt(pointer, "expected {\"welcome\": {\"text\": \"...\", \"gloss\": [\"...\"]}, \"part2\": {...}}");
    std::vector<StudyInstruction> pages;
    for (const auto& item : object.items()) {
        const std::string& key = item.key();
        if (std::find(extraKeys.begin(), extraKeys.end(), key) != extraKeys.end()) continue;
        const std::string at = pointer + "/" + jsonPointerToken(key);
        if (std::find(std::begin(kInstructionPages), std::end(kInstructionPages), key) == std::end(kInstructionPages)) {
            std::string known = pageList();
            for (const char* extra : extraKeys) known += std::string(", \"") + extra + "\"";
            source.failAt(at, "unknown field '" + key + "' (known: " + known + ")");
        }
        const json& page = item.value();
        if (!page.is_object() || !page.contains("text") || !page.contains("gloss"))
            source.failAt(at, "expected {\"text\": \"the page in English\", \"gloss\": [\"the same in ASL gloss\", ...]}");
        for (const auto& field : page.items())
            if (field.key() != "text" && field.key() != "gloss")
                source.failAt(at + "/" + jsonPointerToken(field.key()), "unknown field '" + field.key() + "' (known: text, gloss)");
        StudyInstruction instruction;
        instruction.page = key;
        instruction.file = source.file;
        instruction.line = source.lineAt(at);
        instruction.field = at;
        if (!page["text"].is_string() || page["text"].get<std::string>().empty())
            source.failAt(at + "/text", "expected the page's text in English");
        instruction.text = page["text"].get<std::string>();
        const json& gloss = page["gloss"];
        if (gloss.is_string()) instruction.gloss.push_back(gloss.get<std::string>());
        else if (gloss.is_array())
            for (std::size_t i = 0; i < gloss.size(); ++i) {
                if (!gloss[i].is_string() || gloss[i].get<std::string>().empty())
                    source.failAt(at + "/gloss/" + std::to_string(i), "expected a sentence of gloss");
                instruction.gloss.push_back(gloss[i].get<std::string>());
            }
        if (instruction.gloss.empty() || instruction.gloss.front().empty())
            source.failAt(at + "/gloss", "expected the page in gloss: a sentence, or a list of sentences");
        pages.push_back(std::move(instruction));
    }
    return pages;
}

std::filesystem::path defaultInstructionsFile(const std::filesystem::path& scenesDir) {
    return scenesDir / "studies" / "instructions.json";
}

std::vector<StudyInstruction> loadInstructionsFile(const std::filesystem::path& file) {
    const JsonSource source = readJsonFile(file);
    return withJsonErrors(source, [&] {
        if (!source.root.is_object()) source.failAt("", "expected {\"format\": \"signstim-instructions\", ...}");
        source.checkFormat("signstim-instructions", 1);
        return readInstructionPages(source, "", {"format", "version", "about"});
    });
}

std::vector<StudyInstruction> withDefaultPages(const std::vector<StudyInstruction>& given,
                                               const std::vector<StudyInstruction>& defaults) {
    std::vector<StudyInstruction> pages;
    for (std::string_view page : kInstructionPages) {
        const auto is = [&](const StudyInstruction& i) { return i.page == page; };
        if (const auto it = std::find_if(given.begin(), given.end(), is); it != given.end()) pages.push_back(*it);
        else if (const auto d = std::find_if(defaults.begin(), defaults.end(), is); d != defaults.end()) pages.push_back(*d);
    }
    return pages;
}

std::string questionClipName(std::size_t storyIndex, std::size_t question) {
    return storyId(storyIndex) + "_question-" + std::to_string(question + 1);
}

std::string instructionClipName(const std::string& page) { return "instructions-" + page; }

std::string questionsUnitId(std::size_t storyIndex) {
    return "questions-" + storyId(storyIndex).substr(std::string_view("story-").size());
}

bool hasQuestionClips(const ListedStory& story) {
    return std::any_of(story.questions.begin(), story.questions.end(),
                       [](const ListedQuestion& q) { return !q.clip.video.empty(); });
}

bool hasInstructionClips(const StudyListing& listing) {
    return std::any_of(listing.instructions.begin(), listing.instructions.end(),
                       [](const ListedInstruction& i) { return !i.clip.video.empty(); });
}

}  // namespace signstim::stimuli
