#pragma once
// The signer's reach as the plain value stimuli/ draws a verb's keyframes within (issue 21,
// stimuli/verbs/verb_reach.hpp): each arm's shoulder joint in the signing-space frame and its
// length, read from the rig. Given to the timeline's sources beside the transition pacer
// (TimelineSources::reach, StoryWorld::reach), so stimuli/ needs to know nothing of the body.
#include "signer/signer_pose.hpp"
#include "stimuli/verbs/verb_reach.hpp"

namespace signstim::signer {

// Both arms of `rig`: the shoulder joint (its rest position, hand::ArmModel::shoulderMm,
// mirrored into the signing-space frame), upper arm + forearm, the nearest the wrist comes with
// the elbow at its flexion limit, with the comfortable
// fraction of stimuli::kComfortableReachFraction; and the torso (the sections of
// bodyCapsules, signing-space mm) with the hand's extent (rig.handModel() scaled by
// rig.handScale()) that stimuli::clearOfTorso keeps the keys out of.
stimuli::SignerReach signerReach(const SignerRig& rig);

}  // namespace signstim::signer
