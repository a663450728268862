#pragma once
// The design of a two-phase study (SPEC §4.2-4.4): which version of which story each
// participant sees and in what order (phase 1), and which version sits in which panel of each
// side-by-side trial and in what order the trials come (phase 2). Pure values and functions:
// no files, no rendering. Same design and seed -> the same schedules on any machine
// (SplitMix64 and our own Fisher-Yates, common/random.hpp).
//
// Phase 1 [D, SPEC §4.2]: V groups (one per version); story s gets version (pi(s) + g) mod V in
// group g, with pi(s) = s mod V (a rotation Latin square: across the V groups every story x
// version cell appears exactly once). Participants are assigned to groups in permuted blocks
// of V: participants b*V .. b*V+V-1 take the V groups in an order shuffled from (seed,
// block). A participant's story order is a Fisher-Yates shuffle seeded from (seed,
// participant, phase), so it does not depend on how many participants there are.
//
// Phase 2 [D, SPEC §4.3]: trial t shows version (k + t) mod V in panel k (a cyclic Latin
// square over trials: with T a multiple of V, every version sits in every panel T/V times).
// Panels are labelled A, B, C, ... for participants; the mapping is recorded, never shown.
// Each participant's trial order is shuffled from (seed, participant, phase 2).
//
// Phase-1 order (the study file's "order", docs/study.md): "random" (the default, as above)
// or "balanced", a Williams-type design: participant p takes row r of a Williams square over
// the V versions (rows in permuted blocks of R = V, or 2V when V is odd, like the groups), and
// trial position i shows version row_r[i mod V]; which of the participant's stories of that
// version comes is shuffled from (seed, participant, phase 1). Across every complete block of
// R participants each version sits at each trial position exactly R/V times, and within the
// first V positions each version follows each other version equally often (Williams 1949).
#include <cstdint>
#include <string>
#include <vector>

namespace signstim::stimuli {

enum class StoryOrder { Random, Balanced };

struct StudyDesignSpec {
    std::size_t stories = 12;           // phase-1 stories
    std::size_t versions = 4;           // versions compared (point, vector, animator, uninflected)
    std::size_t participants = 24;
    std::size_t likertTrials = 8;       // phase-2 sentences (0: no phase 2)
    std::uint64_t seed = 1;
    StoryOrder order = StoryOrder::Random;  // phase 1's story order (the default keeps old studies unchanged)
    // Versions phase 2 compares when they differ from phase 1's (0: `versions`): a human-video
    // version may be in one phase only (stimuli/study/human_versions.hpp).
    std::size_t likertVersions = 0;
    std::size_t phase2Versions() const { return likertVersions > 0 ? likertVersions : versions; }
};

// Why a design cannot be built (empty when it can): e.g. stories not a multiple of versions,
// with what would work instead.
std::string designProblem(const StudyDesignSpec& spec);

struct Phase1Trial {
    std::size_t story = 0;    // 0-based story index
    std::size_t version = 0;  // 0-based version index
};

struct Phase2Trial {
    std::size_t sentence = 0;               // 0-based phase-2 sentence index
    std::vector<std::size_t> panelVersion;  // panelVersion[k]: the version shown in panel k
};

struct ParticipantSchedule {
    std::size_t participant = 0;  // 0-based id
    std::size_t group = 0;        // phase-1 group
    std::vector<Phase1Trial> phase1;  // in presentation order
    std::vector<Phase2Trial> phase2;  // in presentation order
};

// Version of `story` in `group` (the rotation Latin square).
std::size_t phase1Version(const StudyDesignSpec& spec, std::size_t story, std::size_t group);
// Group of `participant` (permuted blocks of `versions`).
std::size_t participantGroup(const StudyDesignSpec& spec, std::size_t participant);
// The panel arrangement of phase-2 sentence `sentence`, over phase2Versions() (independent of participants: each
// side-by-side clip is rendered once).
std::vector<std::size_t> likertPanels(const StudyDesignSpec& spec, std::size_t sentence);

// Row `row` of the Williams square over `versions` versions: a sequence of all versions
// (rows 0..V-1: the cyclic shifts of 0, 1, V-1, 2, V-2, ...; for odd V rows V..2V-1 are
// those reversed). Rows: williamsRows(versions).
std::vector<std::size_t> williamsRow(std::size_t versions, std::size_t row);
std::size_t williamsRows(std::size_t versions);

// One participant's schedule. Throws std::invalid_argument when designProblem() is not empty.
ParticipantSchedule participantSchedule(const StudyDesignSpec& spec, std::size_t participant);

// Panel labels "A", "B", ... and a compact code of an arrangement from the versions' letters,
// e.g. "VPAU" for vector, point, animator, uninflected (SPEC §5 file names).
std::string panelLabel(std::size_t panel);

}  // namespace signstim::stimuli
