#include "signer/arm_memo.hpp"

#include <cstring>

namespace signstim::signer {
namespace {

// The sizes of the inputs whose fields the key lists (x86-64, gcc and clang): a field added to
// one of them changes its size, and the memory is bypassed until the key lists it too.
constexpr bool kKnownSizes = sizeof(hand::ArmModel) == 96 && sizeof(hand::ArmTarget) == 28 &&
                             sizeof(hand::ArmSolveOptions) == 44 && sizeof(hand::ArmLimits) == 48;

struct KeyWriter {
    std::array<std::uint32_t, 42>& key;
    std::size_t at = 0;
    void add(float v) {
        std::uint32_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        key[at++] = bits;
    }
    void add(const glm::vec3& v) {
        add(v.x);
        add(v.y);
        add(v.z);
    }
    void add(const glm::quat& q) {
        add(q.w);
        add(q.x);
        add(q.y);
        add(q.z);
    }
    void add(const hand::AngleRange& r) {
        add(r.minDeg);
        add(r.maxDeg);
    }
};

}  // namespace

bool ArmMemo::keyComplete() { return kKnownSizes; }

std::size_t ArmMemo::KeyHash::operator()(const Key& key) const {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the words
    for (const std::uint32_t word : key) {
        h ^= word;
        h *= 1099511628211ull;
    }
    return static_cast<std::size_t>(h ^ (h >> 29));
}

hand::ArmPose ArmMemo::solve(const hand::ArmModel& arm, const hand::ArmTarget& target,
                             const hand::ArmSolveOptions& options) {
    if (!kKnownSizes) return hand::solveArm(arm, target, options);
    Key key{};
    KeyWriter w{key};
    key[w.at++] = arm.side == hand::Side::Right ? 1u : 2u;
    w.add(arm.shoulderMm);
    w.add(arm.upperArmLengthMm);
    w.add(arm.forearmLengthMm);
    for (const hand::AngleRange* r : {&arm.limits.elbowFlexion, &arm.limits.shoulderElevation, &arm.limits.shoulderPlane,
                                      &arm.limits.supination, &arm.limits.wristFlexion, &arm.limits.wristUlnarDeviation})
        w.add(*r);
    w.add(arm.poleOutward);
    w.add(arm.poleBackward);
    w.add(arm.poleOutwardWhenHigh);
    w.add(arm.minElbowLateralMm);
    w.add(arm.torsoFrontMm);
    w.add(arm.elbowRiseWristAboveShoulderMm);
    w.add(target.wristMm);
    w.add(target.handRotation);
    key[w.at++] = options.previousElbowDirection ? 1u : 0u;
    w.add(options.previousElbowDirection.value_or(glm::vec3(0.0f)));
    w.add(options.maxSwivelStepDeg);
    w.add(options.hintYieldPerWristDeg);
    w.add(options.swivelWindowDeg);
    w.add(options.poleWeight);
    w.add(options.wristComfortWeight);
    w.add(options.shoulderLimitWeight);
    w.add(options.torsoWeight);
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (const auto found = newer_.find(key); found != newer_.end()) return found->second;
        if (const auto found = older_.find(key); found != older_.end()) return found->second;
    }
    const hand::ArmPose pose = hand::solveArm(arm, target, options);
    const std::lock_guard<std::mutex> lock(mutex_);
    if (newer_.size() >= kGenerationSize) {
        older_ = std::move(newer_);
        newer_ = Map();
    }
    newer_.emplace(key, pose);
    return pose;
}

std::optional<double> PacerMemo::find(const std::string& key) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (const auto found = seconds_.find(key); found != seconds_.end()) return found->second;
    return std::nullopt;
}

void PacerMemo::add(const std::string& key, double seconds) {
    const std::lock_guard<std::mutex> lock(mutex_);
    seconds_.emplace(key, seconds);
}

}  // namespace signstim::signer
