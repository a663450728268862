#include "signer/clearance.hpp"

#include "signer/clip.hpp"
#include "signer/timeline_clip.hpp"

#include <algorithm>
#include <cmath>

namespace signstim::signer {

std::vector<ClearanceFrame> clearanceFrames(const SignerRig& rig, const TimelineClip& clip, double framesPerSecond) {
    const stimuli::Timeline& timeline = clip.timeline();
    const auto total = static_cast<std::uint64_t>(std::floor(clip.durationSeconds() * framesPerSecond + 1e-9)) + 1;
    // The frames, and the instants where each item's own keys start and end: a transition is
    // judged against the items at its ends as they are there, not at the nearest frame, which
    // at the natural pace can be mid-movement (a tap lifted off, hands opening) while the
    // item's last key has them touching (docs/stories.md, "Clearance").
    std::vector<double> instants;
    instants.reserve(total + 2 * timeline.spans.size());
    for (std::uint64_t f = 0; f < total; ++f) instants.push_back(static_cast<double>(f) / framesPerSecond);
    for (const stimuli::TimelineSpan& span : timeline.spans)
        for (const double t : {span.keysStartSeconds, span.keysEndSeconds})
            if (t >= 0.0 && t <= clip.durationSeconds()) instants.push_back(t);
    std::sort(instants.begin(), instants.end());
    instants.erase(std::unique(instants.begin(), instants.end(), [](double a, double b) { return b - a < 1e-9; }),
                   instants.end());
    std::vector<ClearanceFrame> frames;
    frames.reserve(instants.size());
    ClipPoser poser(rig, clip);
    for (const double t : instants) {
        ClearanceFrame frame;
        frame.seconds = t;
        SignerPosture posture;
        PoseReport report;
        poser.next(frame.seconds, &posture, &report);
        frame.clearance = clearance(signerCapsules(rig, posture, report));
        for (std::size_t s = 0; s < timeline.spans.size(); ++s)
            if (frame.seconds >= timeline.spans[s].keysStartSeconds && frame.seconds <= timeline.spans[s].keysEndSeconds) {
                frame.span = static_cast<int>(s);
                break;
            }
        frames.push_back(frame);
    }
    return frames;
}

ClearanceSummary checkClearance(const stimuli::Timeline& timeline, const std::vector<ClearanceFrame>& frames,
                                float toleranceMm, float contactDepthMm) {
    ClearanceSummary summary;
    for (const bool hands : {true, false}) {
        const auto gapOf = [&](std::size_t i) { return hands ? frames[i].clearance.hands.gapMm : frames[i].clearance.body.gapMm; };
        // Stretches of frames in the same item, or between the same two items.
        for (std::size_t i = 0; i < frames.size();) {
            std::size_t end = i;
            while (end < frames.size() && frames[end].span == frames[i].span) ++end;
            const bool transition = frames[i].span < 0;
            bool touches = false;
            int before = frames[i].span, after = frames[i].span;
            float allowed = -toleranceMm;
            ClearanceExtreme* extreme = nullptr;  // which closest approach these frames count for
            if (transition) {
                before = i > 0 ? frames[i - 1].span : -1;
                after = end < frames.size() ? frames[end].span : -1;
                // As close as the frames on either side, which are the items' own.
                if (i > 0) allowed = std::min(allowed, gapOf(i - 1) - toleranceMm);
                if (end < frames.size()) allowed = std::min(allowed, gapOf(end) - toleranceMm);
                // A transition that leaves or reaches a contact counts with the contact.
                if (allowed == -toleranceMm) extreme = hands ? &summary.handsAtTransitions : &summary.body;
            } else {
                const stimuli::TimelineSpan& span = timeline.spans[static_cast<std::size_t>(frames[i].span)];
                touches = hands ? span.contact.hands : span.contact.body;
                if (touches) allowed = -contactDepthMm;
                extreme = hands ? (touches ? &summary.handsInContactSigns
                                   : span.kind == stimuli::SpanKind::Rest ? nullptr
                                                                          : &summary.handsInSigns)
                                : (touches ? &summary.bodyInContactSigns : &summary.body);
            }
            std::size_t deepest = i;
            for (std::size_t j = i; j < end; ++j)
                if (gapOf(j) < gapOf(deepest)) deepest = j;
            if (extreme && gapOf(deepest) < extreme->gapMm)
                *extreme = {gapOf(deepest), frames[deepest].seconds, before, after};
            if (gapOf(deepest) < allowed)
                summary.violations.push_back(
                    {hands, transition, touches, before, after, frames[deepest].seconds, gapOf(deepest), allowed});
            i = end;
        }
    }
    std::stable_sort(summary.violations.begin(), summary.violations.end(),
                     [](const ClearanceViolation& a, const ClearanceViolation& b) { return a.seconds < b.seconds; });
    return summary;
}

std::string describeClearancePlace(const stimuli::Timeline& timeline, int before, int after) {
    const auto name = [&](int span) {
        return span < 0 ? std::string("rest") : timeline.spans[static_cast<std::size_t>(span)].label;
    };
    const int sentenceOf = after >= 0 ? after : before;
    const int sentence = sentenceOf >= 0 ? timeline.spans[static_cast<std::size_t>(sentenceOf)].sentence : -1;
    std::string place = before == after ? name(after) : name(before) + " -> " + name(after);
    if (sentence >= 0) place += " (sentence " + std::to_string(sentence + 1) + ")";
    return place;
}

}  // namespace signstim::signer
