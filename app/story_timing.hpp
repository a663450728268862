#pragma once
// `story --check`'s timing report (docs/stories.md, "Timing"): per version, the timeline's
// pace (stimuli::measureTimeline) and the posed signer's peak wrist and head speeds, with the
// limits of SPEC §6.2-6.3 they break.
#include "signer/timeline_clip.hpp"
#include "stimuli/story/timeline_builder.hpp"

#include <string>
#include <vector>

namespace signstim::app {

struct StoryPace {
    stimuli::TimelineMeasures measures;
    double peakWristMmPerSecond = 0.0, peakWristSeconds = 0.0;
    double peakHeadDegreesPerSecond = 0.0, peakHeadSeconds = 0.0;
};

// [D] Speeds are measured on the posed signer every 1/120 s (finer than any output's frame
// rate, so the figure is the motion's, not the video's): the wrists' positions and the head's
// rotation, as ClipPoser solves them for rendering.
inline constexpr double kPaceSamplesPerSecond = 120.0;

StoryPace measurePace(const signer::SignerRig& rig, const signer::TimelineClip& clip);

// The limits `pace` breaks, as sentences ("signs/s 0.92 is below 1.7 (SPEC §6.3: ...)").
std::vector<std::string> paceWarnings(const StoryPace& pace);

}  // namespace signstim::app
