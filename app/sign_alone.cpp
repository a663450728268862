// One lexicon sign signed alone (app/sign_alone.hpp).
#include "app/sign_alone.hpp"

#include "signer/clip.hpp"

#include <algorithm>

namespace signstim::app {

using namespace signstim::stimuli;

// The sign alone in citation form, between rests, as the signer signs it.
signer::TimelineClip signAlone(const StoryWorld& world, const signer::Signer& signer, const LexiconSign& sign) {
    Story story;
    story.file = "sign " + sign.gloss;
    StorySentence sentence;
    StoryItem item;
    item.kind = StoryItemKind::Sign;
    item.gloss = sign.gloss;
    sentence.gloss = sign.gloss;
    sentence.items.push_back(item);
    story.sentences.push_back(sentence);
    TimelineOptions timing;
    timing.signScale = 1.0;
    timing.restSeconds = kSignRestSeconds;
    return signer::TimelineClip(signer.rig(), buildTimeline(story, VerbVersion::Point, world.sources(story), timing));
}

// The clip's time of `seconds` into the sign's own keys: the timeline builder may lengthen a
// stretch between two keys (the wrist's speed limit, TimelineOptions::peakSpeedMmPerSecond) or
// shorten a repetition's, so each stretch between the sign's keys maps onto its own stretch of
// the clip (the same easing between the same keys); uniformly when the keys do not pair up.
double clipSeconds(const signer::TimelineClip& clip, const LexiconSign& sign, double seconds) {
    double start = 0.0, end = 0.0;
    for (const TimelineSpan& span : clip.timeline().spans)
        if (span.kind == SpanKind::Sign) start = span.keysStartSeconds, end = span.keysEndSeconds;
    std::vector<double> ours, theirs;
    for (const VerbKeyframe& k : sign.keyframes.front()) ours.push_back(k.timeSeconds);
    for (const TimelineKey& k : clip.timeline().right)
        if (k.timeSeconds >= start - 1e-9 && k.timeSeconds <= end + 1e-9) theirs.push_back(k.timeSeconds);
    if (ours.size() < 2 || ours.size() != theirs.size())
        return start + seconds * (end - start) / std::max(1e-9, sign.durationSeconds());
    std::size_t k = 0;
    while (k + 2 < ours.size() && seconds > ours[k + 1]) ++k;
    const double f = (seconds - ours[k]) / std::max(1e-9, ours[k + 1] - ours[k]);
    return theirs[k] + f * (theirs[k + 1] - theirs[k]);
}

// The hands of `clip` as the signer's arms pose them (issue 22: the checks judge the hand a
// viewer sees, not the pose the notation asks), `seconds` into the sign's own keys.
PosedHands posedHands(const signer::Signer& signer, const signer::TimelineClip& clip, const LexiconSign& sign) {
    return [&signer, &clip, &sign](hand::Side side, double seconds) -> std::optional<PosedHand> {
        const signer::ClipPoser poser(signer.rig(), clip);
        signer::SignerPosture posture;
        signer::PoseReport arms;
        poser.next(clipSeconds(clip, sign, seconds), &posture, &arms);
        const bool right = side == hand::Side::Right;
        if (!(right ? posture.rightWrist : posture.leftWrist)) return std::nullopt;
        const hand::ArmPose& arm = right ? arms.right : arms.left;
        PosedHand posed;
        posed.pose = signer::signingSpaceFromArm(arm.wristMm, arm.hand);
        posed.elbowMm = glm::dvec3(signer::bodyFromSigningSpace(arm.elbowMm));  // the mirror is its own inverse
        posed.orientationErrorDeg = arm.orientationErrorDeg;
        return posed;
    };
}

}  // namespace signstim::app
