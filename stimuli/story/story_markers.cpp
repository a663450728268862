#include "stimuli/story/story_markers.hpp"

#include <stdexcept>

namespace signstim::stimuli {

std::vector<StoryMarker> resolveMarkers(const std::vector<GlossMarker>& written, const Story& story, int line,
                                        const std::function<void(int, const std::string&)>& fail) {
    std::vector<StoryMarker> markers;
    for (const GlossMarker& g : written) {
        StoryMarker m;
        m.marker = g.name;
        m.firstItem = g.firstItem;
        m.lastItem = g.lastItem;
        m.intensity = g.intensity.value_or(1.0);
        m.line = line;
        m.column = g.column;
        if (g.name == "role-shift") {
            m.character = story.characterIndex(g.argument);
            if (m.character < 0) {
                std::vector<std::string> names;
                for (const StoryCharacter& c : story.characters) names.push_back(c.gloss);
                const std::vector<std::string> close = closestNames(g.argument, names);
                std::string list;
                for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
                fail(g.argumentColumn, "rs(" + g.argument + "): " + g.argument + " is not a character of this story (" +
                                           list + ")" + (close.empty() ? "" : "; did you mean " + close.front() + "?"));
                throw std::logic_error("resolveMarkers: fail returned");
            }
        }
        if (g.name == "mouthing") m.word = g.argument;
        markers.push_back(std::move(m));
    }
    return markers;
}

}  // namespace signstim::stimuli
