#include "stimuli/study/study_design.hpp"

#include "common/random.hpp"

#include <numeric>
#include <stdexcept>

namespace signstim::stimuli {
namespace {

// Streams of randomness, kept apart so that e.g. adding phase 2 never changes phase 1.
constexpr std::uint64_t kGroupBlocks = 0x67726f7570ull;  // "group"
constexpr std::uint64_t kPhase1Order = 1;
constexpr std::uint64_t kPhase2Order = 2;

std::uint64_t streamSeed(std::uint64_t seed, std::uint64_t stream, std::uint64_t index) {
    return mixSeed(mixSeed(seed, stream), index);
}

std::vector<std::size_t> shuffledRange(std::size_t count, std::uint64_t seed) {
    std::vector<std::size_t> order(count);
    std::iota(order.begin(), order.end(), std::size_t{0});
    SplitMix64 rng(seed);
    shuffleInPlace(order, rng);
    return order;
}

}  // namespace

std::string designProblem(const StudyDesignSpec& spec) {
    if (spec.versions < 2) return "a study compares at least 2 versions";
    if (spec.versions > 8) return "at most 8 versions (panels A to H)";
    if (spec.stories == 0) return "phase 1 needs at least one story";
    if (spec.participants == 0) return "at least one participant";
    if (spec.stories % spec.versions != 0) {
        const std::size_t below = spec.stories / spec.versions * spec.versions;
        const std::size_t above = below + spec.versions;
        return std::to_string(spec.stories) + " stories cannot be split evenly over " + std::to_string(spec.versions) +
               " versions (each participant must see every version equally often): use a multiple of " +
               std::to_string(spec.versions) + " stories" +
               (below > 0 ? " such as " + std::to_string(below) + " or " + std::to_string(above) : " such as " + std::to_string(above));
    }
    if (spec.likertTrials % spec.versions != 0) {
        const std::size_t above = (spec.likertTrials / spec.versions + 1) * spec.versions;
        return std::to_string(spec.likertTrials) + " side-by-side sentences cannot put every version in every panel equally often: use a multiple of " +
               std::to_string(spec.versions) + " (e.g. " + std::to_string(above) + "), or 0 for no phase 2";
    }
    return {};
}

std::size_t phase1Version(const StudyDesignSpec& spec, std::size_t story, std::size_t group) {
    return (story % spec.versions + group) % spec.versions;
}

std::size_t participantGroup(const StudyDesignSpec& spec, std::size_t participant) {
    const std::size_t block = participant / spec.versions;
    const std::vector<std::size_t> groups = shuffledRange(spec.versions, streamSeed(spec.seed, kGroupBlocks, block));
    return groups[participant % spec.versions];
}

std::vector<std::size_t> likertPanels(const StudyDesignSpec& spec, std::size_t sentence) {
    std::vector<std::size_t> panels(spec.versions);
    for (std::size_t k = 0; k < spec.versions; ++k) panels[k] = (k + sentence) % spec.versions;
    return panels;
}

ParticipantSchedule participantSchedule(const StudyDesignSpec& spec, std::size_t participant) {
    if (const std::string problem = designProblem(spec); !problem.empty()) throw std::invalid_argument(problem);
    ParticipantSchedule schedule;
    schedule.participant = participant;
    schedule.group = participantGroup(spec, participant);
    for (std::size_t story : shuffledRange(spec.stories, streamSeed(spec.seed, kPhase1Order, participant)))
        schedule.phase1.push_back({story, phase1Version(spec, story, schedule.group)});
    for (std::size_t sentence : shuffledRange(spec.likertTrials, streamSeed(spec.seed, kPhase2Order, participant)))
        schedule.phase2.push_back({sentence, likertPanels(spec, sentence)});
    return schedule;
}

std::string panelLabel(std::size_t panel) { return std::string(1, static_cast<char>('A' + panel)); }

}  // namespace signstim::stimuli
