#pragma once
// Whether a sign written in the notation realizes the ASL-LEX 2.0 code it claims (issue 22:
// "every lexicon sign realizes its claimed code"): the code derived from its description, the
// entry's code it follows (provenance), and the compiled motion measured — handshape at the
// hold, the nearest place, the number of hands and their relation, the contact events reached
// within 10 mm, the hands apart elsewhere, the repetitions, circles closed, via points passed
// without stopping, the citation duration within ±20 % of ASL-LEX's SignDuration.
#include "stimuli/story/lexicon.hpp"
#include "stimuli/story/sign_notation.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace signstim::stimuli {

// [R: issue 22, Tests] A contact event is reached when the hand's point is this near its place.
inline constexpr double kContactReachedMm = 10.0;
// [D] Away from its contact events the touching point clears its place by at least this.
inline constexpr double kApartMm = 10.0;
// [R: issue 22 §3] Citation durations within ±20 % of ASL-LEX 2.0's SignDuration.
inline constexpr double kDurationTolerance = 0.2;

// The ASL-LEX code of each part as the description says it: the handshape's ASL-LEX label, the
// sign type from the hands' relation and handshapes, the movement from the path, repetition,
// the places' major and minor locations (aslLexLocation), contact from the events.
std::vector<AslLexCode> deriveAslLexCode(const SignNotation& notation, const HandshapeLibrary& shapes);

// ASL-LEX 2.0's MajorLocation and MinorLocation for a place name (a body location of
// scenes/lexicon/ or "hand:palm" ...) and how far from it the hand is: beyond 60 mm a place on
// the head is HeadAway (BodyAway, HandAway, ArmAway), and "neutral..." places are Neutral.
std::pair<std::string, std::string> aslLexLocation(const std::string& place, double distanceMm);

struct NotationCheck {
    std::string name;  // "code 1", "duration", "contact 1 chin", ...
    bool ok = false;
    std::string detail;
};

// A hand as a body posed it: its wrist and palm frame (signing space) where the arm solution
// put it, and the elbow (signing space, mm) its forearm comes from.
struct PosedHand {
    HandPose pose;
    glm::dvec3 elbowMm{0.0};
    // How far the posed hand is turned from the orientation the sign's motion asks there
    // (degrees): what the wrist's and forearm's limits leave of it (hand::ArmPose).
    double orientationErrorDeg = 0.0;
};
// The hands as the signer's body poses them `seconds` into the sign's own keys (nullopt: that
// hand rests). stimuli/ knows no body: `signstim sign` and the signer's tests give it from the
// arm solution of the clip that signs the sign alone (signer::signingSpaceFromArm). Issue 22:
// a contact is an event the motion must reach, and the motion a viewer sees is the posed one;
// a wrist at its limits leaves the posed hand off the orientation the notation asks.
using PosedHands = std::function<std::optional<PosedHand>(hand::Side side, double seconds)>;
// [D] How far the posed hand may turn from the orientation the sign's motion asks, at any
// instant of the sign's keys: 20 degrees, about what a viewer reads as the same palm and finger
// direction (ASL-LEX 2.0 codes no orientation; the notation's directions are the six axes and
// their 45-degree mixes, so 20 degrees keeps the posed hand nearer the asked direction than to
// its neighbour, 22.5 degrees off).
inline constexpr double kPosedOrientationDeg = 20.0;

// Every check of `sign` (a sign with a notation; none for a keyframe sign). With `posed`, also
// the checks on the posed hands: each contact event reached within kContactReachedMm by the
// posed hand at its moment (a place on the other hand or arm, on that hand or arm as posed), and
// each hand's orientation within kPosedOrientationDeg of the notation's.
std::vector<NotationCheck> checkSignNotation(const LexiconSign& sign, const Lexicon& lexicon, const HandshapeLibrary& shapes,
                                             const hand::HandModel& model, const PosedHands& posed = {});

// "handshape open_b, OneHanded, Straight, Head/Chin, contact, repeated" for messages.
std::string describeAslLexCode(const AslLexCode& code);

}  // namespace signstim::stimuli
