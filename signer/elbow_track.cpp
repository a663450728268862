#include "signer/elbow_track.hpp"

#include "signer/clip.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace signstim::signer {
namespace {

constexpr float kPi = 3.14159265358979323846f;

float angleBetween(const glm::vec3& a, const glm::vec3& b) { return std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f)); }

// `v` across `axis` (unit), normalised; `fallback` where v lies along the axis.
glm::vec3 across(const glm::vec3& v, const glm::vec3& axis, const glm::vec3& fallback) {
    const glm::vec3 a = v - glm::dot(v, axis) * axis;
    return glm::length(a) > 1e-6f ? glm::normalize(a) : fallback;
}

// The elbow at sample `from` carried along the moving shoulder-wrist axis to every sample up to
// `to` without turning about it (each step the least rotation that takes one axis to the next),
// and the signed turn about the axis at `to` from the carried elbow to the solver's there, the
// way whose middle lies lower (the solver keeps the elbow at or below its shoulder, unless the
// wrist is above the head, by moving a higher one to the nearer end of the allowed arc: a turn
// over the top would flip).
struct Carried {
    std::vector<glm::vec3> elbows;  // samples from..to
    float turnRad = 0.0f;
};
Carried carry(const ElbowTrack::Samples& s, std::size_t from, std::size_t to) {
    Carried c;
    glm::vec3 elbow = s.elbows[from];
    c.elbows.push_back(elbow);
    for (std::size_t k = from + 1; k <= to; ++k) {
        elbow = across(glm::rotation(s.axes[k - 1], s.axes[k]) * elbow, s.axes[k], s.elbows[k]);
        c.elbows.push_back(elbow);
    }
    const glm::vec3& axis = s.axes[to];
    const glm::vec3 target = across(s.elbows[to], axis, elbow);
    float turn = std::atan2(glm::dot(glm::cross(elbow, target), axis), glm::dot(elbow, target));
    const glm::vec3 middle = glm::angleAxis(turn / 2.0f, axis) * elbow;
    if (middle.y > 0.0f && std::fabs(turn) > 1e-4f) turn += turn > 0.0f ? -2.0f * kPi : 2.0f * kPi;
    c.turnRad = turn;
    return c;
}

// The stretches (sample indices, [from, to]) where the solver's elbow turns about the moving
// shoulder-wrist axis faster than `stepRad` a sample, each widened about its middle until the
// turn from its first sample's elbow to its last's keeps within `stepRad` a sample; stretches
// that meet are merged and widened again.
std::vector<ElbowTrack::Blend> blendsOf(const ElbowTrack::Samples& s, float stepRad) {
    std::vector<ElbowTrack::Blend> blends;
    const std::size_t last = s.elbows.empty() ? 0 : s.elbows.size() - 1;
    const auto turnAt = [&](std::size_t k) {  // k -> k + 1
        const glm::vec3 carried = across(s.elbows[k], s.axes[k + 1], s.elbows[k + 1]);
        return angleBetween(carried, across(s.elbows[k + 1], s.axes[k + 1], carried));
    };
    for (std::size_t k = 0; k < last; ++k) {
        if (turnAt(k) <= stepRad) continue;
        std::size_t to = k + 1;
        while (to < last && turnAt(to) > stepRad) ++to;
        blends.push_back({k, to, {}});
        k = to - 1;
    }
    const auto fits = [&](const ElbowTrack::Blend& b) {
        return std::fabs(carry(s, b.from, b.to).turnRad) <= stepRad * static_cast<float>(b.to - b.from);
    };
    const auto widen = [&](ElbowTrack::Blend& b) {
        while (!fits(b) && (b.from > 0 || b.to < last)) {
            if (b.from > 0) --b.from;
            if (b.to < last) ++b.to;
        }
    };
    for (bool changed = true; changed;) {
        changed = false;
        for (ElbowTrack::Blend& b : blends) widen(b);
        std::vector<ElbowTrack::Blend> merged;
        for (const ElbowTrack::Blend& b : blends) {
            if (!merged.empty() && b.from <= merged.back().to) {
                merged.back().to = std::max(merged.back().to, b.to);
                changed = true;
            } else {
                merged.push_back(b);
            }
        }
        blends = std::move(merged);
    }
    // The elbow at every sample of a blend: carried, turned at a constant rate.
    for (ElbowTrack::Blend& b : blends) {
        const Carried c = carry(s, b.from, b.to);
        for (std::size_t k = b.from; k <= b.to; ++k) {
            const float u = static_cast<float>(k - b.from) / static_cast<float>(b.to - b.from);
            b.elbows.push_back(glm::normalize(glm::angleAxis(u * c.turnRad, s.axes[k]) * c.elbows[k - b.from]));
        }
        b.elbows.back() = s.elbows[b.to];
    }
    return blends;
}

}  // namespace

ElbowTrack::ElbowTrack(const SignerRig& rig, double durationSeconds, const std::function<SignerPosture(double)>& posture) {
    const auto samples = static_cast<std::size_t>(std::ceil(std::max(0.0, durationSeconds) * kElbowTrackHz)) + 1;
    const auto step = static_cast<float>(kElbowTurnDegPerSecond / kElbowTrackHz) * kPi / 180.0f;
    Samples right, left;
    for (std::size_t k = 0; k < samples; ++k) {
        const SignerPosture p = posture(std::min(durationSeconds, static_cast<double>(k) / kElbowTrackHz));
        for (const hand::Side side : {hand::Side::Right, hand::Side::Left}) {
            const hand::ArmPose a = rig.solveArm(side, p);
            Samples& s = side == hand::Side::Right ? right : left;
            const glm::vec3 axis = a.wristMm - a.shoulderMm;
            s.elbows.push_back(a.elbowDirection);
            s.axes.push_back(glm::length(axis) > 1e-3f ? glm::normalize(axis) : glm::vec3(0.0f, -1.0f, 0.0f));
        }
    }
    samples_ = samples;
    rightBlends_ = blendsOf(right, step);
    leftBlends_ = blendsOf(left, step);
}

void ElbowTrack::apply(double seconds, SignerPosture& posture) const {
    if (samples_ == 0) return;
    const double at = std::clamp(seconds * kElbowTrackHz, 0.0, static_cast<double>(samples_ - 1));
    const auto blendAt = [&](const std::vector<Blend>& blends, std::optional<glm::vec3>& hint, bool& follow) {
        for (const Blend& b : blends) {
            // Strictly inside: at its ends (samples) the solver's own elbow is the blend's.
            if (at <= static_cast<double>(b.from) + 1e-6 || at >= static_cast<double>(b.to) - 1e-6) continue;
            double whole = std::floor(at);
            // An instant every rate shares (a 60 fps frame) is a sample, whatever the rounding of t.
            if (at - whole > 1.0 - 1e-6) whole += 1.0;
            const auto k = static_cast<std::size_t>(whole) - b.from;
            const auto u = static_cast<float>(std::max(0.0, at - whole));
            const glm::vec3 e = k + 1 < b.elbows.size() && u > 1e-6f ? blendElbowHints(b.elbows[k], b.elbows[k + 1], u) : b.elbows[k];
            hint = e;
            follow = true;
            return;
        }
    };
    blendAt(rightBlends_, posture.rightElbowHint, posture.followRightElbowHint);
    blendAt(leftBlends_, posture.leftElbowHint, posture.followLeftElbowHint);
}

}  // namespace signstim::signer
