#include "stimuli/study/human_versions.hpp"

#include "stimuli/json_source.hpp"
#include "stimuli/study/study.hpp"

#include <algorithm>
#include <filesystem>

namespace signstim::stimuli {
namespace {

using nlohmann::json;

const std::vector<std::string> kStoryPlaceholders = {"story", "storyFile"};
const std::vector<std::string> kSentencePlaceholders = {"sentence", "sentenceNumber"};

// The placeholders a pattern uses, or the first thing wrong with it.
std::vector<std::string> placeholders(const std::string& pattern, std::string& problem) {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] == '}') {
            problem = "a '}' without its '{'";
            return names;
        }
        if (pattern[i] != '{') continue;
        const std::size_t end = pattern.find('}', i);
        if (end == std::string::npos) {
            problem = "a '{' without its '}'";
            return names;
        }
        names.push_back(pattern.substr(i + 1, end - i - 1));
        i = end;
    }
    return names;
}

bool validName(const std::string& name) {
    if (name.empty() || name.size() > 32 || name.front() == '-' || name.back() == '-') return false;
    return std::all_of(name.begin(), name.end(),
                       [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-'; });
}

std::string twoDigits(std::size_t n) { return n < 10 ? "0" + std::to_string(n) : std::to_string(n); }

std::string resolveAgainstStudy(const StudyFile& study, const std::string& written) {
    const std::filesystem::path path(written);
    if (path.is_absolute()) return written;
    return (std::filesystem::path(study.file).parent_path() / path).lexically_normal().string();
}

}  // namespace

std::vector<HumanVersion> parseHumanVersions(const JsonSource& source, const json& list,
                                             const std::vector<std::string>& taken) {
    const std::string example =
        "[{\"name\": \"human\", \"phase1Clips\": \"human/{story}.mp4\", \"phase2Clips\": \"human/{sentence}.mp4\"}]";
    if (!list.is_array()) source.failAt("/humanVersions", "expected a list of human-video versions, e.g. " + example);
    std::vector<std::string> names = taken;
    std::vector<std::string> letters = {"P", "V", "A", "U"};  // the animated versions' (study.cpp versionLetter)
    std::vector<HumanVersion> versions;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string at = "/humanVersions/" + std::to_string(i);
        const json& entry = list[i];
        if (!entry.is_object()) source.failAt(at, "expected {\"name\": \"human\", \"phase1Clips\": \"human/{story}.mp4\"}");
        for (const auto& item : entry.items())
            if (item.key() != "name" && item.key() != "letter" && item.key() != "phase1Clips" && item.key() != "phase2Clips")
                source.failAt(at + "/" + jsonPointerToken(item.key()),
                              "unknown field '" + item.key() + "' (known: name, letter, phase1Clips, phase2Clips)");
        HumanVersion version;
        version.index = i;
        version.line = source.lineAt(at);
        if (!entry.contains("name") || !entry["name"].is_string() || !validName(entry["name"].get<std::string>()))
            source.failAt(at + "/name", "expected a name of lowercase letters, digits and '-' (up to 32), e.g. \"human\": "
                                        "it names the clips (story-03_version-human.mp4)");
        version.name = entry["name"].get<std::string>();
        if (std::find(names.begin(), names.end(), version.name) != names.end() || parseVerbVersion(version.name))
            source.failAt(at + "/name", "\"" + version.name + "\" is already a version name: each version needs its own");
        names.push_back(version.name);
        std::string letter(1, static_cast<char>(version.name.front() - 'a' + 'A'));
        if (version.name.front() < 'a' || version.name.front() > 'z') letter = "H";
        if (entry.contains("letter")) {
            const json& l = entry["letter"];
            if (!l.is_string() || l.get<std::string>().size() != 1 || l.get<std::string>()[0] < 'A' || l.get<std::string>()[0] > 'Z')
                source.failAt(at + "/letter", "expected one capital letter, e.g. \"H\" (panel codes such as VPHA)");
            letter = l.get<std::string>();
        }
        if (std::find(letters.begin(), letters.end(), letter) != letters.end())
            source.failAt(at + (entry.contains("letter") ? "/letter" : "/name"),
                          "the letter " + letter + " is already another version's: give \"letter\", e.g. \"H\"");
        letters.push_back(letter);
        version.letter = letter;
        for (const char* phase : {"phase1Clips", "phase2Clips"}) {
            if (!entry.contains(phase)) continue;
            const std::string field = at + "/" + phase;
            const bool first = std::string(phase) == "phase1Clips";
            const json& value = entry[phase];
            if (!value.is_string() || value.get<std::string>().empty())
                source.failAt(field, std::string("expected a path pattern, e.g. \"") +
                                         (first ? "human/{story}.mp4" : "human/{sentence}.mp4") + "\"");
            const std::string pattern = value.get<std::string>();
            std::string problem;
            const std::vector<std::string> used = placeholders(pattern, problem);
            const std::vector<std::string>& allowed = first ? kStoryPlaceholders : kSentencePlaceholders;
            for (const std::string& name : used)
                if (problem.empty() && std::find(allowed.begin(), allowed.end(), name) == allowed.end())
                    problem = "unknown placeholder {" + name + "} (known here: {" + allowed[0] + "}, {" + allowed[1] + "})";
            if (problem.empty() && used.empty())
                problem = std::string("it names one file for every ") + (first ? "story" : "sentence") + ": use {" +
                          allowed[0] + "}, e.g. \"" + (first ? "human/{story}.mp4" : "human/{sentence}.mp4") + "\"";
            if (!problem.empty()) source.failAt(field, "\"" + pattern + "\": " + problem);
            (first ? version.phase1Clips : version.phase2Clips) = pattern;
        }
        if (version.phase1Clips.empty() && version.phase2Clips.empty())
            source.failAt(at, "expected \"phase1Clips\" and/or \"phase2Clips\": the phases the version is shown in");
        // A version in phase 2 only (no phase1Clips) is left out of phase 1's design and comes
        // after the phase-1 versions (orderedHumanVersions), so a story's clips are the first
        // versions (stimuli/study/study_listing.hpp).
        versions.push_back(std::move(version));
    }
    return versions;
}

std::string expandHumanPattern(const std::string& pattern, const std::map<std::string, std::string>& values) {
    std::string out;
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        const std::size_t end = pattern[i] == '{' ? pattern.find('}', i) : std::string::npos;
        if (end == std::string::npos) {
            out += pattern[i];
            continue;
        }
        const auto value = values.find(pattern.substr(i + 1, end - i - 1));
        out += value != values.end() ? value->second : pattern.substr(i, end - i + 1);
        i = end;
    }
    return out;
}

std::vector<const HumanVersion*> orderedHumanVersions(const StudyFile& study) {
    std::vector<const HumanVersion*> order;
    for (const HumanVersion& v : study.humanVersions)
        if (!v.phase1Clips.empty()) order.push_back(&v);
    for (const HumanVersion& v : study.humanVersions)
        if (v.phase1Clips.empty()) order.push_back(&v);
    return order;
}

std::size_t phase1VersionCount(const StudyFile& study) {
    return study.versions.size() + static_cast<std::size_t>(std::count_if(
                                       study.humanVersions.begin(), study.humanVersions.end(),
                                       [](const HumanVersion& v) { return !v.phase1Clips.empty(); }));
}

std::vector<std::size_t> phase2VersionIndices(const StudyFile& study) {
    std::vector<std::size_t> indices;
    for (std::size_t v = 0; v < study.versions.size(); ++v) indices.push_back(v);
    const std::vector<const HumanVersion*> order = orderedHumanVersions(study);
    for (std::size_t h = 0; h < order.size(); ++h)
        if (!order[h]->phase2Clips.empty()) indices.push_back(study.versions.size() + h);
    return indices;
}

std::string humanStoryClip(const StudyFile& study, const HumanVersion& version, std::size_t storyIndex) {
    const std::string written = expandHumanPattern(
        version.phase1Clips,
        {{"story", storyId(storyIndex)}, {"storyFile", std::filesystem::path(study.stories.at(storyIndex).written).stem().string()}});
    return resolveAgainstStudy(study, written);
}

std::string humanSentenceClip(const StudyFile& study, const HumanVersion& version, std::size_t sentenceIndex) {
    const std::size_t number = static_cast<std::size_t>(study.phase2Sentences.at(sentenceIndex)) + 1;
    const std::string written =
        expandHumanPattern(version.phase2Clips, {{"sentence", likertId(sentenceIndex)}, {"sentenceNumber", twoDigits(number)}});
    return resolveAgainstStudy(study, written);
}

}  // namespace signstim::stimuli
