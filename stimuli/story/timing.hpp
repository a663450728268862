#pragma once
// The `timing` object of story and study files (docs/stories.md, "Timing"): which timing
// model a timeline is built with — the natural preset (SPEC §6.3: conversational rate, holds at
// sentence boundaries, Huenerfauth's boundary and repetition rules) or the legacy one (the
// timing before issue 21, for comparison studies) — and named fields that override it.
// Kept apart from the timeline builder so that the story file can hold it as a plain value.
#include "stimuli/json_source.hpp"

#include <map>
#include <string>

namespace signstim::stimuli {

struct StoryTiming {
    // "natural" unless a story or study says otherwise (SPEC §6.3); "legacy" is the timing
    // before issue 21, kept for comparison studies ({"preset": "legacy"}, `story --timing legacy`).
    std::string preset = "natural";        // "natural" | "legacy"
    std::map<std::string, double> fields;  // explicit fields by their JSON name (booleans 0/1)
    int line = 0;                          // where the object is written; 0: not given
    bool given() const { return line > 0; }
};

// Reads `object` at `pointer` (e.g. "/timing"): unknown fields, wrong types and values out of
// range throw InputError naming the file, line and field.
StoryTiming parseStoryTiming(const JsonSource& source, const nlohmann::json& object, const std::string& pointer);

// "natural", or "legacy" with the fields that differ from it: "legacy, pauseShare 0.1".
std::string describeTiming(const StoryTiming& timing);

}  // namespace signstim::stimuli
