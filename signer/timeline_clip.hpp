#pragma once
// A story timeline (stimuli/story/timeline.hpp) as a clip of the signer: each frame samples the
// timeline's hands, gaze and non-manual channels (face, head, torso, shoulders: nonManualAt)
// and resolves them on the rig — a resting hand goes to the rig's
// resting place, relaxed; a keyed hand to its wrist target and handshape; gaze toward the
// viewer or a referent.
//
// Gaze is eyes and head together: the eyes follow the timeline's gaze (quick, like a saccade);
// the head follows with a minimum-jerk turn to where hand::solveGaze puts it for the new
// target, no faster than kHeadPeakDegPerSecond at its peak and starting only when its previous
// turn has ended, so its velocity is smooth in t; the eyes take up the difference within the
// orbit's range. The head's turns depend on the gaze keys alone (the same in every version).
//
// Transitions are routed around the hands and the body. Between two items the timeline's
// hands blend straight from one pose to the next (minimum jerk), and a straight blend knows
// nothing of the hands' shape: fingers turning toward the resting place, or one hand passing
// the other, would go through the other hand or the body. Where it would (signer/hand_capsules.hpp
// geometry, on the wrist targets), the wrists take a detour: each moving hand is pushed aside
// by an offset times a bump that is 0, with zero velocity and acceleration, at both ends of the
// transition, so the keys and the smoothness of the profile are kept. The detour keeps the
// hands at least kTransitionClearanceMm apart, or as close as they are at the transition's
// ends when an item there has them touching; a bump adds at most kDetourPeakSpeedMmPerSecond
// (transition_route.cpp) to the wrist's speed. The detour is sought on instants of the
// transition's own time (kRoutingFramesPerSecond) and judged between them, by a bound on how
// far the hands' capsules travel from one instant to the next, refined where the bound falls
// short; an instant found short there is judged too, and the transition routed again (issue
// 21: the hands go into neither the body nor each other at any output's frames). A detour
// depends only on the keys at its ends, so frames outside the verb slots stay the same in
// every version.
//
// Touches come to the surface (issue 22: contact as an event the motion reaches; issue 21:
// the hands never pass through each other). A sign's keys say where the wrists go, from
// places and points of the hand that know nothing of the rest of the hand's shape: the base
// hand's thumb lying across its palm (B), the acting hand's curled fingers below its palm or
// knuckles (S, A, flat-O), a trained verb's keyframes — so a hand meant to land on the other
// lands in it, 12-23 mm deep; and between two keys the hands can pass through each other.
// Inside an item that touches with both hands, its keys and instants between them are settled
// (settleTouches): where the hands' capsules overlap deeper than kTouchDepthMm, the hand that
// moves in the item (both, half each, when both or neither do) is moved out along the line
// between the closest points until they meet at that depth. The offsets depend on the
// timeline alone (the pose stays a function of it and t); an instant that touches still
// touches, one clear of the other hand is left alone. They change only within the headroom
// the wrists' own motion leaves under kSettledPeakSpeedMmPerSecond (signer/settled_pace.hpp),
// so that settling makes no wrist faster than SPEC §6.2 allows: inside the item (as slowly as
// kTouchRateMmPerSecond at most), and in the transitions into and out of it (blendTouches,
// signer/touch_blend.cpp: with the keys' blend where the headroom allows, and keeping a hand
// that comes to or leaves the other from passing deeper on the way where its offset can). The
// pacer (transitionPacer) times a transition into a touching item with the item settled.
// A clasp (SignContact::clasp: two curled hands that grip each other, HUSBAND's C on C) is
// settled first by its digits: held off by the wrists, two C hands whose thumbs and curled
// fingers cross each other's ended 58-64 mm apart, the touch lost. Its hands' digits yield
// instead — both hands' thumbs and fingers opened toward straight (clasped), by the least
// share, up to kMostClaspYield, that brings the touch to kTouchDepthMm, as a grip's fingers
// curl only until they meet the other hand — and the wrists settle only what that leaves.
// The share changes no faster than kClaspYieldPerSecond inside the item and follows the
// keys' blend in the transitions into and out of it.
#include "signer/clip.hpp"
#include "signer/elbow_track.hpp"
#include "stimuli/story/timeline.hpp"
#include "stimuli/story/timeline_builder.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace signstim::signer {

class Signer;

class TimelineClip final : public Clip {
public:
    // The keys carry their hand controls (resolved by the timeline's builder). `trackElbows`:
    // the elbows follow an elbow track (signer/elbow_track.hpp: the solver's elbow, blended
    // across its jumps); false, the arm solver's choice near the keys' elbows at each instant.
    TimelineClip(const SignerRig& rig, stimuli::Timeline timeline, bool trackElbows = true);

    double durationSeconds() const override { return timeline_.durationSeconds; }
    SignerPosture postureAt(double seconds) const override;
    const stimuli::Timeline& timeline() const { return timeline_; }

private:
    // A transition's detour: bumps of the wrists' paths, each of a shape (timeline_clip.cpp)
    // and with the wrists' offsets at its peak (body frame, mm).
    struct Bump {
        int shape = 0;
        glm::vec3 rightMm{0.0f}, leftMm{0.0f};
    };
    struct Detour {
        double startSeconds = 0.0, endSeconds = 0.0;
        std::vector<Bump> bumps;
    };
    // The head's share of a gaze shift, moving at its own pace (timeline_clip.cpp): from `from`
    // to `to` (yaw, pitch in degrees) with a minimum-jerk profile.
    struct HeadMove {
        double startSeconds = 0.0, durationSeconds = 0.0;
        glm::vec2 fromDeg{0.0f}, toDeg{0.0f};
    };
    // `settled`: with the settled touches' offsets (settleTouches); false: the keys' own.
    SignerPosture straightPostureAt(double seconds, bool settled = true) const;
    glm::vec2 headAt(double seconds) const;
    PoseReport arms(const SignerPosture& posture) const;
    // A transition's detour (signer/transition_route.cpp), and a bump's shape at u in [0, 1].
    Detour routeTransition(double startSeconds, double endSeconds) const;
    static float bumpAt(int shape, double u);
    void settleTouches();
    void blendTouches();  // settleTouches' offsets into and out of the settled items

    const SignerRig* rig_;
    stimuli::Timeline timeline_;
    std::vector<Detour> detours_;  // in time order
    ElbowTrack elbows_;
    std::vector<glm::vec3> rightElbows_, leftElbows_;  // per key of each track: the solver's elbow there
    std::vector<glm::vec3> rightTouch_, leftTouch_;    // per key of each track: its wrist's settling offset (body frame, mm)
    std::vector<float> rightYield_, leftYield_;        // per key of each track: its clasp's yield (0: the handshape's own)
    // Per key of each track: whether the way to the next key is a verb's path, swept about the
    // torso's axis (stimuli/verbs/signing_space.hpp, sweptPathPoint) rather than straight: both
    // keys inside one verb span's keys, neither at rest.
    std::vector<bool> rightSwept_, leftSwept_;
    // An item whose touch is settled, or a transition into or out of one (blendTouches): the
    // wrists' offsets at its instants (body frame, mm).
    struct TouchSpan {
        double startSeconds = 0.0, endSeconds = 0.0;
        std::vector<double> times;
        std::vector<glm::vec3> right, left;
        std::vector<float> yield;  // a settled clasp's: its digits' yield at the instants (both hands); else empty
        glm::vec3 at(double seconds, bool rightHand) const;  // linear between the instants
        float yieldAt(double seconds) const;                 // linear between the instants
    };
    std::vector<TouchSpan> touchSpans_;  // in time order
    glm::vec2 headStartDeg_{0.0f};
    std::vector<HeadMove> headMoves_;  // in time order, one after the other
};

// [D] How far apart a transition keeps the hands (and each hand from the body).
inline constexpr float kTransitionClearanceMm = 5.0f;
// [D] How deep a settled touch of the two hands goes: the capsules pressed 2 mm into each
// other, within kClearanceToleranceMm (signer/clearance.hpp: skin dents under a press), so
// the touch is seen to reach the surface and not to pass it.
inline constexpr float kTouchDepthMm = 2.0f;
// [D] A clasp's digits yield by at most 60 % of their way to straight (a C stays a curved
// hand, its thumb apart from the palm; HUSBAND's C on C needs 50-60 %), and change that share
// by at most 3 a second (a grip's fingers settle on the other hand over a fifth of a second,
// not in a frame).
inline constexpr float kMostClaspYield = 0.6f;
inline constexpr double kClaspYieldPerSecond = 3.0;
// [D] A touch is settled at the item's keys and at this many instants per second of the
// timeline between them (its own time, as kRoutingFramesPerSecond): the hands interpolated
// from key to key can pass through each other where the keys do not (a hand turning over,
// fingers opening).
inline constexpr double kTouchFramesPerSecond = 60.0;
// [D] How fast a settled touch's offset may grow or shrink at most: 0.3 m/s, an eighth of SPEC
// §6.2's 2.5 m/s peak wrist speed (a hand seen to slide out of the other, not to jump).
inline constexpr double kTouchRateMmPerSecond = 300.0;
// SPEC §6.2: 2.5 m/s peak wrist speed, less the timing's margin (TimelineOptions::
// peakSpeedMmPerSecond, 2.45 m/s, to which the pacer times the keys' path). A settled touch's
// offsets change only within the headroom the wrist's own motion leaves under it
// (signer/settled_pace.hpp), inside the item and in the transitions into and out of it.
inline constexpr double kSettledPeakSpeedMmPerSecond = 2450.0;
// [D] The transitions into and out of a settled touch blend its offsets on a grid of this many
// instants per second of the timeline's own time from the transition's start (as the pacer
// samples the wrists: finer than any output's frames, so no frame falls between two peaks).
inline constexpr double kTouchBlendFramesPerSecond = 240.0;

// A clasping hand's digits yielded by `share` (0..1) of their way to straight, the thumb to its
// rest (hand::HandControls{}), the fingers' spread kept (TimelineClip::settleTouches).
hand::HandControls claspYielded(const hand::HandControls& controls, float share);
// [D] A transition's clearance is checked at this many instants per second from its start (a
// grid of the timeline's own time, not of any output's frames: the detour, like every pose,
// depends on the timeline alone; and on the transition alone, not where it falls), and
// between them by a bound on the hands' motion (transition_route.cpp), so that a finer grid
// is not needed for any output rate.
inline constexpr double kRoutingFramesPerSecond = 30.0;

// [S] Peak head angular speed in gaze shifts: up to ~300°/s for large shifts (Freedman &
// Sparks 1997; Goossens & Van Opstal 1997). [D] Planned at 250°/s, so the yaw-pitch turn
// stays under 300°/s.
inline constexpr double kHeadPeakDegPerSecond = 250.0;

// The timeline builder's pacer of transitions (stimuli::TransitionPacer; issue 21, SPEC §6.2):
// the transition of the query played as a TimelineClip of its two ends — straight blend,
// routed around the hands and the body exactly as in a story, each end held an instant as a
// touch that is settled where its hands overlap, and the item after it played settled where
// the query gives it (TransitionQuery::intoTouch) — and its drawn wrists' peak
// speed measured (the arm solution's, every 1/240 s); while it peaks above the query's
// limit the transition is lengthened in proportion (at least 5 % a step, at most
// kPacerSteps steps) and routed again, since a longer transition allows a gentler detour;
// then the shortest length that keeps the limit is sought between the last two (bisection). So
// a transition's pace comes from the path the wrists actually travel, detour included, and
// stimuli/ needs to know nothing of the body. A transition the clip routes inside a story is
// the same: its ends are the same keys (a coarticulated end, which keeps a neighbour's
// velocity, differs a little; the timing's 2.45 m/s under SPEC §6.2's 2.5 m/s covers it).
// The rig remembers what it answered (SignerRig::pacerMemo: the builder asks again for every
// version, and every pacer of the rig shares it); safe to call from several threads. The
// pacer keeps `signer` alive.
stimuli::TransitionPacer transitionPacer(std::shared_ptr<const Signer> signer);
// The same with a rig that outlives the pacer (tests that hold a Signer).
stimuli::TransitionPacer transitionPacer(const SignerRig& rig);
// The seconds the query's transition needs (what the pacer answers, without its memory).
double pacedTransitionSeconds(const SignerRig& rig, const stimuli::TransitionQuery& query);
// [D] How many times the pacer lengthens a transition at most (by 5 % or more each: at least
// 1.05^12 ≈ 1.8 times, in practice what the peak asks for in one or two steps).
inline constexpr int kPacerSteps = 12;

// The timeline's non-manual channels at `seconds` (stimuli::sampleNonManual of each track;
// unknown head/torso/shoulder names are ignored, as a body that cannot show them would). A pure
// function of the timeline and t: the same at any frame rate.
NonManualPosture nonManualAt(const stimuli::Timeline& timeline, double seconds);

// Where the eyes go for a referent at a signing-space point: toward it horizontally, a little
// below eye level (a signer glances at the locus, not down at the chest), body frame.
// `eyeHeightMm`: the signer's eyes above the chest centre (the rig's, SignerRig::gaze().eyesMm.y:
// 355 mm on the default avatar, measured from its head bone), so a gaze at the viewer is level.
glm::vec3 gazePointForReferent(const glm::dvec3& signingSpaceMm, double eyeHeightMm);
// Straight at the viewer (the camera) at the eyes' height, body frame.
glm::vec3 gazePointForViewer(double eyeHeightMm);
// Where a gaze key looks, body frame.
glm::vec3 gazePoint(const stimuli::GazeKey& key, double eyeHeightMm);

}  // namespace signstim::signer
