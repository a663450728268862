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
// fixed grid of the clip's own time (kElbowTrackHz, the same instants at every frame rate).
// Where it turns no faster than kElbowTurnDegPerSecond the arm keeps the solver's own elbow (a
// touch or a hand's orientation exact there); where it turns faster, the elbow turns at a
// constant rate from the solver's elbow before the jump to the solver's elbow after it, over a
// stretch centred on the jump and as long as that turn needs (a blend between the two branches,
// not a lag behind the later one). The track is a function of the clip alone, computed once.
// Measured on the default stories (2026-11-26): the elbow's turn 67° -> 12.2° a 60 fps frame.
#include "signer/signer_pose.hpp"

#include <functional>
#include <vector>

namespace signstim::signer {

// [D] The grid of the track: a multiple of every output rate's shared instants at 60 fps
// (t·60 whole), so a 60 fps frame falls on a sample.
inline constexpr double kElbowTrackHz = 240.0;
// [D] How fast the elbow may turn: 720°/s, 12° a frame at 60 fps (the motion tests' bound is 15°
// about the moving shoulder-wrist axis). Within a blend the forearm and wrist take up the hand's
// orientation within their limits, so the hand may turn from what the sign asks for that while.
inline constexpr double kElbowTurnDegPerSecond = 720.0;

class ElbowTrack {
public:
    // A stretch of samples [from, to] where the elbow turns from the solver's at `from` to the
    // solver's at `to` at a constant rate about the moving shoulder-wrist axis; its elbow at
    // each of those samples.
    struct Blend {
        std::size_t from = 0, to = 0;
        std::vector<glm::vec3> elbows;
    };
    // The solver's elbow (ArmPose::elbowDirection) and shoulder-wrist axis (unit) at every sample.
    struct Samples {
        std::vector<glm::vec3> elbows, axes;
    };

    ElbowTrack() = default;
    // `posture(t)` gives the clip's posture with the keys' elbow hints; the track samples the
    // arm solver's elbow there on [0, durationSeconds].
    ElbowTrack(const SignerRig& rig, double durationSeconds, const std::function<SignerPosture(double)>& posture);
    // Inside a blend, sets `posture`'s elbow hint of that arm to the blend at `seconds` and has
    // the arm follow it; elsewhere (and for a default-constructed track) leaves the posture as it
    // is: the solver's own elbow.
    void apply(double seconds, SignerPosture& posture) const;

private:
    std::size_t samples_ = 0;
    std::vector<Blend> rightBlends_, leftBlends_;
};

}  // namespace signstim::signer
