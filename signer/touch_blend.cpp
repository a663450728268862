// The transitions into and out of a settled touch (TimelineClip::blendTouches, signer/
// timeline_clip.hpp): how its offsets are blended in and out within the headroom the wrists'
// own motion leaves (signer/settled_pace.hpp), apart from the clip's other concerns.
#include "signer/hand_capsules.hpp"
#include "signer/settled_pace.hpp"
#include "signer/signer.hpp"
#include "signer/timeline_clip.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace signstim::signer {

void TimelineClip::blendTouches() {
    // The intervals between two keys of a track, outside the settled items, across which a
    // wrist's settling offset changes (into or out of a settled touch), in time order.
    const auto insideSettled = [&](double start, double end) {
        for (const TouchSpan& span : touchSpans_)
            if (span.startSeconds <= start + 1e-9 && end <= span.endSeconds + 1e-9) return true;
        return false;
    };
    std::vector<std::pair<double, double>> intervals;
    for (const bool right : {true, false}) {
        const std::vector<stimuli::TimelineKey>& track = right ? timeline_.right : timeline_.left;
        const std::vector<glm::vec3>& touch = right ? rightTouch_ : leftTouch_;
        for (std::size_t k = 0; k + 1 < track.size(); ++k)
            if (touch[k] != touch[k + 1] && track[k + 1].timeSeconds > track[k].timeSeconds &&
                !insideSettled(track[k].timeSeconds, track[k + 1].timeSeconds))
                intervals.emplace_back(track[k].timeSeconds, track[k + 1].timeSeconds);
    }
    std::sort(intervals.begin(), intervals.end());
    intervals.erase(std::unique(intervals.begin(), intervals.end()), intervals.end());
    std::vector<TouchSpan> blends;
    for (std::size_t n = 0; n < intervals.size(); ++n) {
        const auto [start, end] = intervals[n];
        // Both hands' keys must bound the same interval (they do at a transition's ends); where
        // they do not, the offsets keep the keys' blend (straightPostureAt).
        if ((n > 0 && intervals[n - 1].second > start) || (n + 1 < intervals.size() && intervals[n + 1].first < end))
            continue;
        TouchSpan blend;
        blend.startSeconds = start;
        blend.endSeconds = end;
        for (int f = 0; start + f / kTouchBlendFramesPerSecond < end; ++f) blend.times.push_back(start + f / kTouchBlendFramesPerSecond);
        blend.times.push_back(end);
        // Both hands' offsets at the interval's ends (a, b) and their wrists' own (unsettled,
        // posed) velocity between the instants.
        std::array<glm::vec3, 2> a{}, b{};
        std::array<std::vector<glm::dvec3>, 2> velocity;
        bool sameKeys = true;
        for (std::size_t h = 0; h < 2 && sameKeys; ++h) {
            const std::vector<stimuli::TimelineKey>& track = h == 0 ? timeline_.right : timeline_.left;
            const stimuli::TimelineSample sample = stimuli::sampleTrack(track, 0.5 * (start + end));
            sameKeys = sample.from && std::abs(sample.from->timeSeconds - start) < 1e-9 && std::abs(sample.to->timeSeconds - end) < 1e-9;
            if (!sameKeys) break;
            const std::vector<glm::vec3>& touch = h == 0 ? rightTouch_ : leftTouch_;
            a[h] = touch[static_cast<std::size_t>(sample.from - track.data())];
            b[h] = touch[static_cast<std::size_t>(sample.to - track.data())];
        }
        if (!sameKeys) continue;
        std::vector<SignerPosture> straight;
        std::vector<double> keysBlend;  // the keys' own blend (the right track's; both hands' keys bound the interval)
        for (const double t : blend.times) {
            straight.push_back(straightPostureAt(t, false));
            keysBlend.push_back(t >= end ? 1.0 : stimuli::sampleTrack(timeline_.right, t).blend);
        }
        for (std::size_t h = 0; h < 2; ++h) {
            const hand::Side side = h == 0 ? hand::Side::Right : hand::Side::Left;
            glm::vec3 before(0.0f);
            for (std::size_t i = 0; i < straight.size(); ++i) {
                const glm::vec3 wrist = rig_->solveArm(side, straight[i]).wristMm;
                if (i > 0) velocity[h].push_back(glm::dvec3(wrist - before) / (blend.times[i] - blend.times[i - 1]));
                before = wrist;
            }
        }
        // Into a touch (no offset at the start) or out of one (none at the end): the share of the
        // touch's offset kept, q, must keep the hands from passing deeper into each other than
        // kTouchDepthMm on the way (a hand comes to or leaves the other's palm from outside it,
        // and the transition's routing, which asks the same, adds no detour); the least share
        // that does at each instant, halved 6 times [D] (to 1/64).
        const bool into = a[0] == glm::vec3(0.0f) && a[1] == glm::vec3(0.0f);
        const bool outOf = b[0] == glm::vec3(0.0f) && b[1] == glm::vec3(0.0f);
        // [D] Half a millimetre inside kTouchDepthMm (the routing's tolerance).
        const float deepest = -kTouchDepthMm + 0.5f;
        std::vector<float> need;
        if (into != outOf) {
            const auto gapAt = [&](std::size_t i, double q) {
                SignerPosture posture = straight[i];
                posture.rightWrist->wristMm += static_cast<float>(q) * (into ? b[0] : a[0]);
                posture.leftWrist->wristMm += static_cast<float>(q) * (into ? b[1] : a[1]);
                const SignerCapsules capsules = signerCapsules(*rig_, posture, arms(posture));
                return closestApproach(capsules.right, capsules.left).gapMm;
            };
            need.assign(blend.times.size(), 0.0f);
            bool unreachable = false;
            for (std::size_t i = 1; i + 1 < blend.times.size() && !unreachable; ++i) {
                if (gapAt(i, 0.0) >= deepest) continue;
                double low = 0.0, high = 1.0;
                unreachable = gapAt(i, high) < deepest;
                for (int k = 0; k < 6 && !unreachable; ++k) (gapAt(i, 0.5 * (low + high)) < deepest ? low : high) = 0.5 * (low + high);
                need[i] = static_cast<float>(high);
            }
            need.front() = into ? 0.0f : 1.0f;
            need.back() = into ? 1.0f : 0.0f;
            // Where even the whole offset does not keep the hands apart, the routing's detour
            // must (they cross on the way): the offsets then follow the keys.
            if (unreachable) need.clear();
        }
        // One progress p (0 at the start, 1 at the end) for both hands, within both headrooms.
        // The headroom is the unsettled wrists'; the arm solution is not linear in its target
        // near the reach's limits, so the drawn wrists with the offsets are measured, and an
        // interval where they pass the limit trusts less of its headroom (at most kPasses times).
        constexpr int kPasses = 4;
        std::vector<double> trust(blend.times.size() - 1, 1.0), progress;
        for (int pass = 0; pass < kPasses; ++pass) {
            std::vector<RateBounds> bounds;
            for (std::size_t i = 0; i + 1 < blend.times.size(); ++i) {
                RateBounds both{-1e6, 1e6};
                for (std::size_t h = 0; h < 2; ++h) {
                    const RateBounds hand = offsetRateBounds(velocity[h][i], glm::dvec3(b[h] - a[h]), kSettledPeakSpeedMmPerSecond);
                    both = {std::max(both.lo, trust[i] * hand.lo), std::min(both.hi, trust[i] * hand.hi)};
                }
                bounds.push_back(both);
            }
            progress = easedProgress(blend.times, keysBlend, bounds);
            if (!need.empty()) {
                std::vector<RateBounds> shareBounds = bounds;
                if (!into)
                    for (RateBounds& r : shareBounds) r = {-r.hi, -r.lo};
                const std::vector<float> share = rateLimitedEnvelope(blend.times, need, shareBounds);
                for (std::size_t i = 1; i + 1 < progress.size(); ++i)
                    progress[i] = into ? std::max(progress[i], std::min(1.0, static_cast<double>(share[i])))
                                       : std::min(progress[i], std::max(0.0, 1.0 - static_cast<double>(share[i])));
            }
            bool within = true;
            for (std::size_t h = 0; h < 2; ++h) {
                const hand::Side side = h == 0 ? hand::Side::Right : hand::Side::Left;
                if (a[h] == b[h]) continue;
                glm::vec3 before(0.0f);
                for (std::size_t i = 0; i < straight.size(); ++i) {
                    SignerPosture posture = straight[i];
                    glm::vec3& wrist = (h == 0 ? posture.rightWrist : posture.leftWrist)->wristMm;
                    wrist += a[h] + static_cast<float>(progress[i]) * (b[h] - a[h]);
                    const glm::vec3 drawn = rig_->solveArm(side, posture).wristMm;
                    if (i > 0) {
                        const double speed = glm::distance(drawn, before) / (blend.times[i] - blend.times[i - 1]);
                        if (speed > std::max(kSettledPeakSpeedMmPerSecond, glm::length(velocity[h][i - 1])) + 1.0) {
                            trust[i - 1] *= 0.7;  // [D] a step that settles in a few passes
                            within = false;
                        }
                    }
                    before = drawn;
                }
            }
            if (within) break;
        }
        for (const double p : progress) {
            blend.right.push_back(a[0] + static_cast<float>(p) * (b[0] - a[0]));
            blend.left.push_back(a[1] + static_cast<float>(p) * (b[1] - a[1]));
        }
        blends.push_back(std::move(blend));
    }
    for (TouchSpan& blend : blends) touchSpans_.push_back(std::move(blend));
    std::stable_sort(touchSpans_.begin(), touchSpans_.end(),
                     [](const TouchSpan& a, const TouchSpan& b) { return a.startSeconds < b.startSeconds; });
}

}  // namespace signstim::signer
