#pragma once
// A sentence's non-manual markers as written (GlossMarker) resolved against the story: the
// role shift's character, the intensity's default. Used by the story loader (story.cpp).
#include "stimuli/story/gloss.hpp"
#include "stimuli/story/story.hpp"

#include <functional>
#include <string>
#include <vector>

namespace signstim::stimuli {

// `fail(column within the sentence, message)` throws (the loader's InputError); it is called
// for a role shift toward someone who is not a character of the story.
std::vector<StoryMarker> resolveMarkers(const std::vector<GlossMarker>& written, const Story& story, int line,
                                        const std::function<void(int, const std::string&)>& fail);

}  // namespace signstim::stimuli
