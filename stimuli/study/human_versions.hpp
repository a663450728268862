#pragma once
// Human-video versions of a study (issue 24 §2; docs/study.md "Human-video versions"): versions
// whose clips a lab records and supplies, named by a path pattern per phase-1 story and per
// phase-2 sentence. They are placed in the design like any version — after the animated ones,
// in phase 1 and/or phase 2 as the study file says — because the presence of human video,
// most of all side by side, lowers the animations' ratings (Kacorri, Lu & Huenerfauth, TACCESS
// 2013; SPEC §6.5), so a lab must be able to choose where they appear.
//
// Plain values and text here (the study file's "humanVersions" list, the patterns, the version
// order); probing, normalising and compositing the clips is the app's (app/study_human.*),
// decoding is the renderer's (renderer/video_decoder.hpp).
//
// Version order [D]: the study's animated versions, then the human versions that are in phase 1
// (in the study file's order), then those in phase 2 only. Phase 1 compares the first V1 of
// them (a prefix: a story's clips are one per phase-1 version); phase 2 compares the animated
// versions and the human versions in phase 2.
#include <cstddef>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace signstim::stimuli {

struct JsonSource;
struct StudyFile;

struct HumanVersion {
    std::string name;         // "human": clip names story-03_version-human.mp4, the manifest, exports
    std::string letter;       // "H": panel codes (likert-05_panels-VPHA)
    // Path patterns (relative to the study file; '/' separators) of the lab's recordings, e.g.
    // "human/{story}.mp4" and "human/{sentence}.mp4"; empty: the version is not in that phase.
    std::string phase1Clips;  // placeholders {story} ("story-03"), {storyFile} (the story file's stem)
    std::string phase2Clips;  // placeholders {sentence} ("likert-05"), {sentenceNumber} (1-based in the phase-2 story)
    int line = 0;             // of the entry in the study file, for messages
    std::size_t index = 0;    // in the study file's list (its JSON pointer /humanVersions/INDEX)
};

// The study file's "humanVersions" list. `taken`: names already used (the animated versions'
// names); their letters P, V, A, U are taken too. Fails through `source` (InputError naming
// file, line, field) for anything wrong.
std::vector<HumanVersion> parseHumanVersions(const JsonSource& source, const nlohmann::json& list,
                                             const std::vector<std::string>& taken);

// A pattern with its placeholders filled in; `values` maps "story" -> "story-03" and so on.
std::string expandHumanPattern(const std::string& pattern, const std::map<std::string, std::string>& values);

// The human versions in the study's version order (phase 1's, then phase 2's only).
std::vector<const HumanVersion*> orderedHumanVersions(const StudyFile& study);
// How many versions phase 1 compares (the animated ones and the human ones in phase 1).
std::size_t phase1VersionCount(const StudyFile& study);
// The versions phase 2 compares, as indices into the study's version order.
std::vector<std::size_t> phase2VersionIndices(const StudyFile& study);

// What the pattern names for phase-1 story `storyIndex` / phase-2 sentence `sentenceIndex`
// (relative to the study file's folder unless the pattern is absolute).
std::string humanStoryClip(const StudyFile& study, const HumanVersion& version, std::size_t storyIndex);
std::string humanSentenceClip(const StudyFile& study, const HumanVersion& version, std::size_t sentenceIndex);

}  // namespace signstim::stimuli
