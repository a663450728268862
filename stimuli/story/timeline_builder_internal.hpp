#pragma once
// Inside the timeline builder, for stimuli/story/timeline*.cpp only (not a public header: the
// builder's interface is timeline_builder.hpp): the Builder that tells one story in one
// version, the segments and hand states it passes between its parts, and what they share.
// The parts, by concern: timeline.cpp (the story walk: items in order, holds, spans, gaze,
// coarticulation), timeline_pacing.cpp (transition times, the speed limit, the signer's
// pacer), timeline_items.cpp (each item's keys: signs, IX, fingerspelling, verb slots).
#include "stimuli/story/timeline_builder.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace signstim::stimuli::timeline_detail {

constexpr int kRight = 0, kLeft = 1;
// The peak speed of a minimum-jerk stretch over its mean speed (max of 30u²(1−u)²); no
// coarticulated stretch peaks higher (hermiteEase's slopes are bounded by it).
constexpr double kPeakToMean = 1.875;

// A stretch of keys, times relative to its start (the first key of a used hand at 0).
struct Segment {
    std::array<std::vector<TimelineKey>, 2> hands;  // empty: the hand rests throughout
    double durationSeconds = 0.0;
    SignContact contact;
};

struct HandState {
    bool rest = true;
    HandPose pose;
    std::string handshape;
};

inline TimelineKey key(double t, const HandPose& pose, const std::string& shape) {
    TimelineKey k;
    k.timeSeconds = t;
    k.pose = pose;
    k.handshape = shape;
    return k;
}

// Builder::limitSpeed for any segment (the verb slot's pacing, paceVerbPerformance, shares it).
void limitSegmentSpeed(Segment& segment, bool eachStretch, bool posedPath, const TimelineSources& sources,
                       const TimelineOptions& options);
// A key of a transition query: at rest, or the pose with its handshape's controls.
TimelineKey resolvedQueryKey(const TimelineSources& sources, bool rest, const HandPose& pose, const std::string& handshape);

class Builder {
public:
    Builder(const Story& story, VerbVersion version, const TimelineSources& sources, const TimelineOptions& options,
            double boundaryHoldSeconds);
    Timeline build();

private:
    std::vector<TimelineKey>& track(int h) { return h == kRight ? timeline_.right : timeline_.left; }

    static TimelineKey restKey(double t) {
        TimelineKey k;
        k.timeSeconds = t;
        k.rest = true;
        return k;
    }
    void gaze(double t, std::optional<glm::dvec3> target);

    // How far a hand goes from `from` to `next`: its Fitts amplitude and its wrist's travel.
    struct Travel {
        double amplitudeMm = 0.0, wristMm = 0.0, legacyMm = 0.0;
        void take(const Travel& o) {
            amplitudeMm = std::max(amplitudeMm, o.amplitudeMm);
            wristMm = std::max(wristMm, o.wristMm);
            legacyMm = std::max(legacyMm, o.legacyMm);
        }
    };
    static Travel distanceMm(int h, const HandState& from, const TimelineKey& next);
    static Travel displacementMm(const std::vector<std::array<HandState, 2>>& from, const Segment& segment);

    double transitionSeconds(const Travel& travel, const SignContact& next) const;
    void limitSpeed(Segment& segment, bool eachStretch = false, bool posedPath = false) const;

    TimelineKey queryKey(bool rest, const HandPose& pose, const std::string& handshape) const;

    double paced(double seconds, const std::vector<std::array<HandState, 2>>& from,
                 const std::vector<const Segment*>& to) const;

    void place(const Segment& segment, SpanKind kind, const std::string& label, int sentence, int item,
               std::optional<glm::dvec3> gazeTarget, std::optional<double> verbTransition = std::nullopt,
               int letters = 0);
    void holdAll(double seconds, SpanKind kind, const std::string& label, int sentence, int item);

    void hold(double seconds, const std::string& label, int sentence, int index);
    double itemScale(const std::string& said, bool beforeBoundary);

    void addItem(const StoryItem& item, int sentence, int index, bool beforeBoundary);
    Segment signSegment(const std::string& gloss, const StoryItem& item, double scale) const;

    Segment pointingSegment(double position, double scale) const;
    Segment fingerspellingSegment(const std::string& letters, const StoryItem& item, double scale) const;

    void requireShape(const std::string& shape, const StoryItem& item) const;
    void addVerb(const StoryItem& item, int sentence, int index, bool beforeBoundary);

    void markPassThrough();
    MissingAnimatorFiles missingAnimatorFiles() const;

    const Story& story_;
    VerbVersion version_;
    std::vector<MissingAnimatorFile> missingAnimator_;
    const TimelineSources& sources_;
    const TimelineOptions& options_;
    double boundaryHold_ = 0.0;
    Timeline timeline_;
    std::array<HandState, 2> state_{};
    std::vector<std::array<HandState, 2>> slotEnds_;  // each version's end of the open verb slot
    std::set<std::string> said_;                       // signs and words signed so far
    double now_ = 0.0;
    bool verbSlotOpen_ = false;
};

}  // namespace signstim::stimuli::timeline_detail
