#pragma once
// The elbows' path over a clip (issue 21: the elbow swivel changes smoothly, at a pace an arm
// can turn, and the pose stays a function of the clip and the instant).
//
// At each key the arm solver picks the elbow by a rule of the target (hand/arm_ik.hpp: low, out
// of the body, the hand's orientation within the wrist's range), and between keys it seeks the
// swivel near the keys' elbows blended (SignerPosture's hints, kElbowHintWindowDeg). That
// choice is an argmin: where two basins of its cost trade places (a hand orientation at the
// wrist's limits) it jumps 40-57° between two 60 fps frames, and two keys whose elbows lie
// ~100° apart 0.1 s from each other turn it 30-50° a frame. The track samples that choice on a
// fixed grid of the clip's own time (kElbowTrackHz, the same instants at every frame rate) and
// follows it no faster than kElbowTurnDegPerSecond, turning from one sample toward the next;
// an instant between two samples takes their normalised blend. The arm then follows the track
// (SignerPosture::followElbowHint). The track is a function of the clip alone, computed once.
// Measured on the default stories (2026-11-26): the elbow's turn 67° -> 13.9° a frame.
#include "signer/signer_pose.hpp"

#include <functional>
#include <vector>

namespace signstim::signer {

// [D] The grid of the track: a multiple of every output rate's shared instants at 60 fps
// (t·60 whole), so a 60 fps frame falls on a sample.
inline constexpr double kElbowTrackHz = 240.0;
// [D] How fast the elbow may turn: 720°/s, 12° a frame at 60 fps (the motion tests' bound is 15°
// about the moving shoulder-wrist axis). Where the keys ask the elbow to turn faster, it lags
// and the forearm and wrist take up the hand's orientation within their limits — which, at the
// limits, turns the hand from what the sign asks (why TimelineClip does not track by default).
inline constexpr double kElbowTurnDegPerSecond = 720.0;

class ElbowTrack {
public:
    ElbowTrack() = default;
    // `posture(t)` gives the clip's posture with the keys' elbow hints; the track samples the
    // arm solver's elbow there on [0, durationSeconds].
    ElbowTrack(const SignerRig& rig, double durationSeconds, const std::function<SignerPosture(double)>& posture);
    // Sets `posture`'s elbow hints to the track at `seconds` and has the arm follow them (a
    // default-constructed track leaves the posture as it is).
    void apply(double seconds, SignerPosture& posture) const;

private:
    std::vector<glm::vec3> right_, left_;
};

}  // namespace signstim::signer
