#include "stimuli/story/mouthing.hpp"

namespace signstim::stimuli {

// PLACEHOLDER until the mouthing branch lands (issue 23 §4): no lip shapes yet. The grammar may
// call this; nothing may claim mouthing works while this returns nothing.
std::vector<NonManualTrack> mouthingTracks(const std::string&, double, double, double) { return {}; }

}  // namespace signstim::stimuli
