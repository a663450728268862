#include "stimuli/study/study_design.hpp"

#include "common/random.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace signstim::stimuli {
namespace {

// Streams of randomness, kept apart so that e.g. adding phase 2 never changes phase 1.
constexpr std::uint64_t kGroupBlocks = 0x67726f7570ull;  // "group"
constexpr std::uint64_t kPhase1Order = 1;
constexpr std::uint64_t kPhase2Order = 2;
constexpr std::uint64_t kOrderRows = 0x726f7773ull;  // "rows": the balanced order's Williams rows

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
    const std::size_t panels = spec.phase2Versions();
    if (panels > 8) return "at most 8 versions side by side (panels A to H)";
    if (spec.likertTrials > 0 && panels < 2) return "phase 2 compares at least 2 versions side by side";
    if (spec.likertTrials % panels != 0) {
        const std::size_t above = (spec.likertTrials / panels + 1) * panels;
        return std::to_string(spec.likertTrials) + " side-by-side sentences cannot put every version in every panel equally often: use a multiple of " +
               std::to_string(panels) + " (e.g. " + std::to_string(above) + "), or 0 for no phase 2";
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
    const std::size_t versions = spec.phase2Versions();
    std::vector<std::size_t> panels(versions);
    for (std::size_t k = 0; k < versions; ++k) panels[k] = (k + sentence) % versions;
    return panels;
}

std::size_t williamsRows(std::size_t versions) { return versions % 2 == 0 ? versions : 2 * versions; }

std::vector<std::size_t> williamsRow(std::size_t versions, std::size_t row) {
    // Williams (1949): the first row 0, 1, V-1, 2, V-2, ... and its cyclic shifts balance
    // first-order carry-over for even V; odd V needs the mirror images as well.
    std::vector<std::size_t> sequence(versions);
    const std::size_t shift = row % versions;
    for (std::size_t j = 0; j < versions; ++j) {
        const std::size_t first = j % 2 == 1 ? (j + 1) / 2 : (versions - j / 2) % versions;
        sequence[j] = (first + shift) % versions;
    }
    if (row >= versions) std::reverse(sequence.begin(), sequence.end());
    return sequence;
}

namespace {

// The balanced phase-1 order (header): the participant's stories of each version, shuffled,
// dealt out along the participant's Williams row.
std::vector<std::size_t> balancedStoryOrder(const StudyDesignSpec& spec, std::size_t participant, std::size_t group) {
    const std::size_t rows = williamsRows(spec.versions);
    const std::vector<std::size_t> rowOrder =
        shuffledRange(rows, streamSeed(spec.seed, kOrderRows, participant / rows));
    const std::vector<std::size_t> sequence = williamsRow(spec.versions, rowOrder[participant % rows]);
    std::vector<std::vector<std::size_t>> storiesOf(spec.versions);
    for (std::size_t story : shuffledRange(spec.stories, streamSeed(spec.seed, kPhase1Order, participant)))
        storiesOf[phase1Version(spec, story, group)].push_back(story);
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < spec.stories; ++i) order.push_back(storiesOf[sequence[i % spec.versions]][i / spec.versions]);
    return order;
}

}  // namespace

ParticipantSchedule participantSchedule(const StudyDesignSpec& spec, std::size_t participant) {
    if (const std::string problem = designProblem(spec); !problem.empty()) throw std::invalid_argument(problem);
    ParticipantSchedule schedule;
    schedule.participant = participant;
    schedule.group = participantGroup(spec, participant);
    const std::vector<std::size_t> stories =
        spec.order == StoryOrder::Balanced ? balancedStoryOrder(spec, participant, schedule.group)
                                           : shuffledRange(spec.stories, streamSeed(spec.seed, kPhase1Order, participant));
    for (std::size_t story : stories)
        schedule.phase1.push_back({story, phase1Version(spec, story, schedule.group)});
    for (std::size_t sentence : shuffledRange(spec.likertTrials, streamSeed(spec.seed, kPhase2Order, participant)))
        schedule.phase2.push_back({sentence, likertPanels(spec, sentence)});
    return schedule;
}

std::string panelLabel(std::size_t panel) { return std::string(1, static_cast<char>('A' + panel)); }

}  // namespace signstim::stimuli
