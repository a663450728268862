// The timeline builder's items (timeline_builder_internal.hpp): the keys of a lexical sign, an
// IX, a fingerspelled word, and a verb's slot in every version.
#include "stimuli/story/timeline_builder_internal.hpp"

#include "stimuli/verbs/signing_space.hpp"
#include "stimuli/verbs/sora.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace signstim::stimuli::timeline_detail {
namespace {

// The right shoulder joint in signing space (the default signer: 175 mm out, 130 mm up).
constexpr glm::dvec3 kRightShoulderMm{175.0, 130.0, 0.0};
// [D] The second of a doubled letter slides this far toward the signer's right.
constexpr double kDoubledLetterSlideMm = 35.0;

glm::dquat orientationOf(const glm::dvec3& fingers, const glm::dvec3& palm) { return orientationFromFingersPalm(fingers, palm); }

HandPose poseAt(const glm::dvec3& position, const glm::dquat& orientation) {
    HandPose pose;
    pose.positionMm = position;
    pose.orientation = orientation;
    return pose;
}

// Keyframes [hand][k] played forth and back `passes` times (as verbs do), scaled by 1/rate.
std::vector<TimelineKey> expandPasses(const std::vector<VerbKeyframe>& keys, int passes, double rate) {
    std::vector<TimelineKey> out;
    const double path = keys.back().timeSeconds;
    for (int pass = 0; pass < passes; ++pass) {
        const bool backward = pass % 2 == 1;
        for (std::size_t j = (pass == 0 ? 0 : 1); j < keys.size(); ++j) {
            const std::size_t k = backward ? keys.size() - 1 - j : j;
            const double local = backward ? path - keys[k].timeSeconds : keys[k].timeSeconds;
            out.push_back(key((pass * path + local) / rate, keys[k].pose, keys[k].handshape));
        }
    }
    return out;
}

}  // namespace

Segment Builder::signSegment(const std::string& gloss, const StoryItem& item, double scale) const {
    const LexiconSign* sign = sources_.lexicon->find(gloss);
    if (!sign)
        throw InputError(story_.file, item.line, item.column, "",
                         "the lexicon (" + sources_.lexicon->file + ") has no sign " + gloss);
    Segment segment;
    segment.contact = sign->contact;
    const double rate = options_.rate / (options_.signScale * scale);
    for (std::size_t h = 0; h < sign->hands.size(); ++h) {
        const int slot = sign->hands[h] == HandSide::Right ? kRight : kLeft;
        segment.hands[slot] = expandPasses(sign->keyframes[h], sign->passes, rate);
        segment.durationSeconds = std::max(segment.durationSeconds, segment.hands[slot].back().timeSeconds);
    }
    limitSpeed(segment, true);
    return segment;
}

Segment Builder::pointingSegment(double position, double scale) const {
    const glm::dvec3 target = arcPoint(position);
    glm::dvec3 direction = glm::normalize(target - options_.pointingOriginMm);
    glm::dvec3 hand = options_.pointingOriginMm + options_.pointingReachMm * direction;
    // Toward a referent on the left the reach crosses the chest: the hand stays in front
    // of it there and points from where it is.
    if (hand.x < kRightShoulderMm.x && hand.z < options_.pointingMinimumForwardMm) {
        hand.z = options_.pointingMinimumForwardMm;
        direction = glm::normalize(target - hand);
    }
    // Index along the pointing direction, palm turned down (toward -y), as IX is signed.
    const glm::dquat orientation = orientationOf(direction, glm::dvec3(0.0, -1.0, 0.0));
    const HandPose pose = poseAt(hand, orientation);
    Segment segment;
    segment.durationSeconds = options_.pointingSeconds * scale / options_.rate;
    segment.hands[kRight] = {key(0.0, pose, "1"), key(segment.durationSeconds, pose, "1")};
    return segment;
}

Segment Builder::fingerspellingSegment(const std::string& letters, const StoryItem& item, double scale) const {
    Segment segment;
    const double hold = options_.letterSeconds * scale / options_.rate;
    const double between = options_.letterTransitionSeconds * scale / options_.rate;
    const glm::dquat upright = orientationOf({0.0, 1.0, 0.0}, {0.0, 0.0, 1.0});      // palm to the viewer
    const glm::dquat sideways = orientationOf({-1.0, 0.0, 0.0}, {0.0, 0.0, -1.0});   // G, H: index across
    const glm::dquat downward = orientationOf({0.0, -0.8, 0.6}, {-0.6, -0.3, -0.4}); // P, Q: pointing down
    double t = 0.0;
    std::vector<TimelineKey>& keys = segment.hands[kRight];
    for (std::size_t i = 0; i < letters.size(); ++i) {
        const char letter = letters[i];
        const bool doubled = i > 0 && letters[i - 1] == letter;
        glm::dvec3 at = options_.fingerspellingMm;
        if (doubled) at.x += kDoubledLetterSlideMm;
        const glm::dquat orientation = (letter == 'G' || letter == 'H') ? sideways
                                       : (letter == 'P' || letter == 'Q') ? downward
                                                                          : upright;
        if (i > 0) t += between;
        // J and Z: their strokes take time in proportion to a letter's hold, so they
        // quicken with the rest of the word.
        if (letter == 'J') {
            // J: the I hand draws a hook down and toward the signer's left, turning the palm in.
            requireShape("I", item);
            keys.push_back(key(t, poseAt(at, upright), "I"));
            keys.push_back(key(t + hold * 0.6, poseAt(at + glm::dvec3(0, -40, 0), upright), "I"));
            keys.push_back(key(t + hold * 1.4, poseAt(at + glm::dvec3(-30, -55, -10), orientationOf({0, 1, 0}, {-1, 0, 0})), "I"));
            t += hold * 1.4;
        } else if (letter == 'Z') {
            // Z: the index traces a Z from the signer's own point of view.
            requireShape("1", item);
            const double w = 30.0;
            const glm::dvec3 corners[] = {{-w, w, 0}, {w, w, 0}, {-w, -w, 0}, {w, -w, 0}};
            // SPEC §6.2: the diagonal stroke no faster than the wrist may move.
            double stroke = hold * 0.5;
            if (options_.peakSpeedMmPerSecond > 0.0)
                stroke = std::max(stroke, kPeakToMean * glm::length(corners[2] - corners[1]) / options_.peakSpeedMmPerSecond);
            for (int c = 0; c < 4; ++c) keys.push_back(key(t + c * stroke, poseAt(at + corners[c], upright), "1"));
            t += 3 * stroke;
        } else {
            const std::string shape(1, letter);
            requireShape(shape, item);
            keys.push_back(key(t, poseAt(at, orientation), shape));
            keys.push_back(key(t + hold, poseAt(at, orientation), shape));
            t += hold;
        }
    }
    segment.durationSeconds = t;
    return segment;
}

void Builder::requireShape(const std::string& shape, const StoryItem& item) const {
    if (!sources_.shapes->find(shape))
        throw InputError(story_.file, item.line, item.column, "",
                         "no handshape " + shape + " in " + sources_.shapes->file + " for fingerspelling");
}

void Builder::addVerb(const StoryItem& item, int sentence, int index, bool beforeBoundary) {
    const double subject = item.subject >= 0 ? story_.characters[static_cast<std::size_t>(item.subject)].position : 0.0;
    // A question's verb may lack its object ("TOM ASK WHO", issue 24): signed uninflected,
    // toward the centre of the arc.
    const double object = item.object >= 0 ? story_.characters[static_cast<std::size_t>(item.object)].position : 0.0;
    const double rate = options_.rate / itemScale("", beforeBoundary);
    // Every version's path at its own timing, slowed where it would be faster than human;
    // the slot is as long as the longest, the transitions in and out as long as the
    // farthest version needs.
    double longest = 0.0;
    Segment mine;
    std::vector<std::array<HandState, 2>> ends;
    Travel farthestIn;
    std::vector<Segment> versions;  // each version's performance (for its first keys)
    for (VerbVersion v : sources_.slotVersions) {
        VerbPerformance p;
        try {
            p = sources_.verbs(item.gloss, v, subject, object, item.line, item.column);
        } catch (const MissingAnimatorFile& e) {
            // Point, vector and uninflected never need animator files: the missing animator
            // slot is as long as the point model's performance (what `signstim animator
            // draft` writes). The animator version names every missing file at the end.
            missingAnimator_.push_back(e);
            p = sources_.verbs(item.gloss, VerbVersion::Point, subject, object, item.line, item.column);
        }
        // At the story's rate, slowed to human speed (what `signstim verb --out` plays too).
        p = paceVerbPerformance(std::move(p), sources_, options_, rate);
        Segment segment;
        segment.durationSeconds = p.durationSeconds;
        segment.contact = p.contact;
        for (const HandTrack& trackOfHand : p.hands) {
            const int h = trackOfHand.side == HandSide::Right ? kRight : kLeft;
            for (const PerformanceKeyframe& k : trackOfHand.keyframes) segment.hands[h].push_back(key(k.timeSeconds, k.pose, k.handshape));
        }
        longest = std::max(longest, segment.durationSeconds);
        farthestIn.take(displacementMm({state_}, segment));
        std::array<HandState, 2> end{};
        for (int h : {kRight, kLeft})
            if (!segment.hands[h].empty())
                end[h] = HandState{false, segment.hands[h].back().pose, segment.hands[h].back().handshape};
        ends.push_back(end);
        if (v == version_) mine = segment;
        versions.push_back(std::move(segment));
    }
    mine.durationSeconds = longest;
    for (auto& keys : mine.hands) {
        // Padded with a hold to the slot's length, so every version's slot is as long.
        if (!keys.empty() && keys.back().timeSeconds < longest) {
            TimelineKey pad = keys.back();
            pad.timeSeconds = longest;
            keys.push_back(pad);
        }
    }
    std::vector<const Segment*> starts;
    for (const Segment& segment : versions) starts.push_back(&segment);
    const double in = options_.verbTransitionSeconds > 0.0
                          ? options_.verbTransitionSeconds
                          : paced(transitionSeconds(farthestIn, mine.contact), {state_}, starts);
    place(mine, SpanKind::Verb, item.gloss, sentence, index, arcPoint(object), in);
    slotEnds_ = std::move(ends);
}

}  // namespace signstim::stimuli::timeline_detail
