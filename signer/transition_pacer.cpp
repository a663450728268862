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
    // Between items, each end is held for an instant as an item of its own that touches with
    // both hands: where its hands overlap deeper than kTouchDepthMm, the clip settles it
    // (TimelineClip::settleTouches) as it settles the touching item in a story, so the
    // transition is timed from and to where the hands are drawn, with the offsets blended in
    // and out and the detour that keeps a settled touch from going deeper (a hand that leaves
    // the other's palm). Where the ends do not overlap, the holds change nothing.
    // Into an item that touches (query.intoTouch), the item itself follows, settled as in a
    // story, so the transition ends where its touch is drawn (its offsets at its first key
    // come from its deepest instants, not that key's alone).
    const double hold = query.insideItem ? 0.0 : 1.0 / kTouchFramesPerSecond;
    double itemSeconds = 0.0;
    for (const std::vector<stimuli::TimelineKey>& keys : query.intoTouch)
        if (!keys.empty()) itemSeconds = std::max(itemSeconds, keys.back().timeSeconds);
    const bool intoItem = !query.insideItem && itemSeconds > 0.0;
    // The transition's drawn wrists' peak speed when it lasts `seconds`.
    const auto peakAt = [&](double seconds) {
        stimuli::Timeline timeline;
        for (std::size_t h = 0; h < 2; ++h) {
            std::vector<stimuli::TimelineKey>& track = h == 0 ? timeline.right : timeline.left;
            track = {query.from[h], query.to[h]};
            track[0].timeSeconds = hold;
            track[1].timeSeconds = hold + seconds;
            track[0].passThrough = track[1].passThrough = false;
            if (hold > 0.0) {
                track.insert(track.begin(), track.front());
                track.front().timeSeconds = 0.0;
                track.pop_back();
                if (intoItem && !query.intoTouch[h].empty())
                    for (const stimuli::TimelineKey& k : query.intoTouch[h]) {
                        track.push_back(k);
                        track.back().timeSeconds = hold + seconds + k.timeSeconds;
                    }
                else
                    for (const double at : {hold + seconds, hold + seconds + std::max(hold, itemSeconds)}) {
                        track.push_back(query.to[h]);
                        track.back().timeSeconds = at;
                        track.back().passThrough = false;
                    }
            }
        }
        const double end = hold + seconds + std::max(hold, itemSeconds);
        timeline.durationSeconds = query.insideItem ? seconds : end;
        // Inside an item the clip routes nothing (TimelineClip routes only between items).
        if (query.insideItem)
            timeline.spans.push_back({stimuli::SpanKind::Verb, 0.0, seconds, "", 0, 0, 0.0, seconds, {}, 0});
        else
            for (const auto& [start, stop] : {std::pair{0.0, hold}, std::pair{hold + seconds, end}})
                timeline.spans.push_back({stimuli::SpanKind::Sign, start, stop, "", 0, 0, start, stop,
                                          {true, false, intoItem && start > 0.0 && query.intoClasp}, 0});
        // No elbow track: the pacer reads the reached wrists, which the elbow's swivel never moves
        // (SignerRig::reachedWristMm), so a track would be built for nothing on every try.
        const TimelineClip clip(rig, std::move(timeline), /*trackElbows=*/false);
        const auto samples = static_cast<int>(std::ceil(seconds * kSamplesPerSecond));
        double peak = 0.0;
        glm::vec3 right(0.0f), left(0.0f);
        for (int i = 0; i <= samples; ++i) {
            const SignerPosture posture = clip.postureAt(hold + seconds * i / samples);
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
        key += query.intoClasp ? 'c' : 'n';
        // A key's bits: its time (inside intoTouch), flags, pose and hand controls (the touch the
        // transition goes into settles on the hand as its controls shape it).
        const auto addKey = [&key, &add](const stimuli::TimelineKey& k, bool withTime) {
            if (withTime) add(&k.timeSeconds, sizeof k.timeSeconds);
            const double values[] = {k.rest ? 1.0 : 0.0, k.passThrough ? 1.0 : 0.0,
                                     k.pose.positionMm.x, k.pose.positionMm.y, k.pose.positionMm.z,
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
        };
        for (const auto* ends : {&query.from, &query.to})
            for (const stimuli::TimelineKey& k : *ends) addKey(k, false);
        for (const std::vector<stimuli::TimelineKey>& keys : query.intoTouch) {
            key += 'k';
            for (const stimuli::TimelineKey& k : keys) addKey(k, true);
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
