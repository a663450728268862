#pragma once
// The rig's memory of arm solutions (SignerRig::solveArm): hand::solveArm is a pure function
// of its arm, target and options, and a story's timelines ask for the same solutions many
// times — the four versions share every frame outside the verbs, and the transitions' routing
// and the touches' settling (signer/timeline_clip.hpp) solve the same postures in each. Keyed
// by the exact bits of every input, so an answer from memory is the one a solve gives, to the
// bit. Safe to call from several threads (a study builds timelines on several).
#include "hand/arm_ik.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>

namespace signstim::signer {

class ArmMemo {
public:
    hand::ArmPose solve(const hand::ArmModel& arm, const hand::ArmTarget& target, const hand::ArmSolveOptions& options);
    // Whether the key holds every field of the solver's inputs (false: a field was added to
    // hand::ArmModel, ArmTarget or ArmSolveOptions and not to the key, and every call solves).
    static bool keyComplete();

private:
    // 32-bit words: the inputs' fields, floats by their bits.
    using Key = std::array<std::uint32_t, 42>;
    struct KeyHash {
        std::size_t operator()(const Key& key) const;
    };
    using Map = std::unordered_map<Key, hand::ArmPose, KeyHash>;
    // [D] Two generations of at most this many solutions each (~340 bytes apiece: ≤ ~45 MB):
    // when the newer is full it becomes the older and the oldest is forgotten, so what was
    // asked lately (the versions of one story) stays.
    static constexpr std::size_t kGenerationSize = 1u << 16;
    std::mutex mutex_;
    Map newer_, older_;
};

// The rig's memory of the transition pacer's answers (signer/transition_pacer.cpp), by the
// exact bits of the query: every pacer of the rig shares it (a test or a study makes one per
// story; stories share many transitions). Thread-safe.
class PacerMemo {
public:
    std::optional<double> find(const std::string& key);
    void add(const std::string& key, double seconds);

private:
    std::mutex mutex_;
    std::map<std::string, double> seconds_;
};

}  // namespace signstim::signer
