// The timeline builder's pacer (signer/timeline_clip.hpp, transitionPacer): a transition or a
// verb path is timed by the path the posed wrists take, its detour included, so that no wrist
// passes SPEC §6.2's peak speed. Apart from TimelineClip, which it plays, as its own concern.
#include "signer/arm_memo.hpp"
#include "signer/signer.hpp"
#include "signer/timeline_clip.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace signstim::signer {

double pacedTransitionSeconds(const SignerRig& rig, const stimuli::TransitionQuery& query) {
    // [D] The drawn wrists are sampled every 1/240 s (the speed between neighbouring samples:
    // finer than any output's frames, so the peak is not missed between them).
    constexpr double kSamplesPerSecond = 240.0;
    // [D] Once a length that keeps the limit is found, the shortest one is sought between it
    // and the last too fast, halving the gap this many times (to ~1 % of the step).
    constexpr int kBisections = 4;
    if (!(query.seconds > 0.0) || !(query.peakSpeedMmPerSecond > 0.0)) return query.seconds;
    // The transition's drawn wrists' peak speed when it lasts `seconds`.
    const auto peakAt = [&](double seconds) {
        stimuli::Timeline timeline;
        for (std::size_t h = 0; h < 2; ++h) {
            std::vector<stimuli::TimelineKey>& track = h == 0 ? timeline.right : timeline.left;
            track = {query.from[h], query.to[h]};
            track[0].timeSeconds = 0.0;
            track[1].timeSeconds = seconds;
            track[0].passThrough = track[1].passThrough = false;
        }
        timeline.durationSeconds = seconds;
        // Inside an item the clip routes nothing (TimelineClip routes only between items).
        if (query.insideItem)
            timeline.spans.push_back({stimuli::SpanKind::Verb, 0.0, seconds, "", 0, 0, 0.0, seconds, {}, 0});
        const TimelineClip clip(rig, std::move(timeline));
        const auto samples = static_cast<int>(std::ceil(seconds * kSamplesPerSecond));
        double peak = 0.0;
        glm::vec3 right(0.0f), left(0.0f);
        for (int i = 0; i <= samples; ++i) {
            const SignerPosture posture = clip.postureAt(seconds * i / samples);
            const glm::vec3 r = rig.reachedWristMm(hand::Side::Right, posture);
            const glm::vec3 l = rig.reachedWristMm(hand::Side::Left, posture);
            if (i > 0) peak = std::max(peak, std::max(glm::distance(r, right), glm::distance(l, left)) * samples / seconds);
            right = r;
            left = l;
        }
        return peak;
    };
    double tooFast = 0.0, seconds = query.seconds;
    for (int step = 0;; ++step) {
        const double peak = peakAt(seconds);
        if (peak <= query.peakSpeedMmPerSecond) break;
        if (step + 1 >= kPacerSteps) return seconds;  // the longest tried (the check reports what is left)
        tooFast = seconds;
        seconds *= std::max(1.05, peak / query.peakSpeedMmPerSecond);
    }
    if (tooFast > 0.0)
        for (int i = 0; i < kBisections; ++i) {
            const double middle = 0.5 * (tooFast + seconds);
            (peakAt(middle) <= query.peakSpeedMmPerSecond ? seconds : tooFast) = middle;
        }
    return seconds;
}

namespace {

// `keepAlive` owns what `rig` belongs to (or nothing). The answers are remembered by the rig
// (SignerRig::pacerMemo), so every pacer of the rig shares them.
stimuli::TransitionPacer pacerOf(const SignerRig* rig, std::shared_ptr<const void> keepAlive) {
    return [rig, keepAlive](const stimuli::TransitionQuery& query) {
        // The query's exact bits: its keys' rest flags, poses and hand controls (pacers of
        // different handshape libraries share the rig's memory), its length and limit.
        std::string key;
        const auto add = [&key](const void* bytes, std::size_t size) { key.append(static_cast<const char*>(bytes), size); };
        add(&query.seconds, sizeof query.seconds);
        add(&query.peakSpeedMmPerSecond, sizeof query.peakSpeedMmPerSecond);
        key += query.insideItem ? 'i' : 't';
        for (const auto* ends : {&query.from, &query.to})
            for (const stimuli::TimelineKey& k : *ends) {
                const double values[] = {k.rest ? 1.0 : 0.0, k.pose.positionMm.x, k.pose.positionMm.y, k.pose.positionMm.z,
                                         k.pose.orientation.w, k.pose.orientation.x, k.pose.orientation.y,
                                         k.pose.orientation.z};
                add(values, sizeof values);
                const hand::HandControls& c = k.controls;
                const float thumb[] = {c.thumb.bendDeg, c.thumb.spreadDeg, c.thumb.mcpDeg, c.thumb.ipDeg};
                add(thumb, sizeof thumb);
                for (const hand::FingerControls& f : c.fingers) {
                    const float finger[] = {f.spreadDeg, f.bend, f.hook};
                    add(finger, sizeof finger);
                }
                key += k.handshape;
                key += '\0';
            }
        // Controls with fields the key does not list (hand/hand_model.hpp changed): this
        // pacer's answers are not shared.
        constexpr bool kControlsKeyed = sizeof(hand::HandControls) == sizeof(float) * (4 + 3 * hand::kFingerCount);
        if (!kControlsKeyed) return pacedTransitionSeconds(*rig, query);
        if (const std::optional<double> known = rig->pacerMemo().find(key)) return *known;
        const double seconds = pacedTransitionSeconds(*rig, query);
        rig->pacerMemo().add(key, seconds);
        return seconds;
    };
}

}  // namespace

stimuli::TransitionPacer transitionPacer(std::shared_ptr<const Signer> signer) {
    const SignerRig* rig = &signer->rig();
    return pacerOf(rig, std::move(signer));
}

stimuli::TransitionPacer transitionPacer(const SignerRig& rig) { return pacerOf(&rig, nullptr); }

}  // namespace signstim::signer
