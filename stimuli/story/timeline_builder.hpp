#pragma once
// From a story to its timeline (stimuli/story/timeline.hpp) in one version: the timing rules
// listed there, with the lexicon's signs, the handshape library and the verbs.
#include "stimuli/story/handshapes.hpp"
#include "stimuli/story/lexicon.hpp"
#include "stimuli/story/story.hpp"
#include "stimuli/story/timeline.hpp"
#include "stimuli/verbs/verb_synthesis.hpp"

#include <functional>
#include <string>
#include <vector>

namespace signstim::stimuli {

struct TimelineOptions {
    // [D] Citation timing of the lexicon and verb files is multiplied by 1 / rate: 1 signs at
    // citation speed (~2 signs/s with transitions, near natural storytelling, which runs at
    // roughly 2-2.5 signs/s).
    double rate = 1.0;
    double restSeconds = 0.5;           // at rest before the first and after the last sentence
    double sentencePauseSeconds = 0.3;  // at rest between sentences
    double holdSeconds = 0.3;           // HOLD without a duration
    // [D] Transition time = base + distance / speed, within [minimum, maximum]: quick
    // transitions of a fluent signer take 0.15-0.3 s.
    double transitionBaseSeconds = 0.12;
    double transitionMmPerSecond = 1400.0;
    double transitionMinimumSeconds = 0.15;
    double transitionMaximumSeconds = 0.5;
    double verbTransitionSeconds = 0.3;  // in and out of a verb slot, the same in every version
    double pointingSeconds = 0.35;       // IX held on its referent
    double letterSeconds = 0.2;          // each fingerspelled letter held
    double letterTransitionSeconds = 0.08;
    // Where fingerspelling happens: in front of the right shoulder, below the chin [D].
    glm::dvec3 fingerspellingMm{150.0, 170.0, 230.0};
    // How far the index of IX reaches toward the referent, from the right shoulder [D].
    double pointingReachMm = 330.0;
    // ... but no nearer the chest than this (forward, z) where the hand is in front of it [D:
    // the default signer's chest is ~110 mm deep; the fist needs the rest].
    double pointingMinimumForwardMm = 200.0;
};

// Gives a verb instance in the requested version (point/vector need trained models,
// animator its keyframe files): the same call stimuli::synthesizeVerb makes for `verb`.
using VerbProvider = std::function<VerbPerformance(const std::string& verb, VerbVersion version, double subject,
                                                   double object, int line, int column)>;

struct TimelineSources {
    const Lexicon* lexicon = nullptr;
    const HandshapeLibrary* shapes = nullptr;
    VerbProvider verbs;
    // The versions whose slots must be equally long: all four for a study. `version` must be
    // one of them.
    std::vector<VerbVersion> slotVersions{VerbVersion::Point, VerbVersion::Vector, VerbVersion::Animator,
                                          VerbVersion::Uninflected};
};

// Throws InputError naming the story file, line and column for a sign missing from the
// lexicon, a letter without a handshape, or a verb the provider cannot give.
Timeline buildTimeline(const Story& story, VerbVersion version, const TimelineSources& sources,
                       const TimelineOptions& options = {});

}  // namespace signstim::stimuli
