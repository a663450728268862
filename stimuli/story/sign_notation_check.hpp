#pragma once
// Whether a sign written in the notation realizes the ASL-LEX 2.0 code it claims (issue 22:
// "every lexicon sign realizes its claimed code"): the code derived from its description, the
// entry's code it follows (provenance), and the compiled motion measured — handshape at the
// hold, the nearest place, the number of hands and their relation, the contact events reached
// within 10 mm, the hands apart elsewhere, the repetitions, circles closed, via points passed
// without stopping, the citation duration within ±20 % of ASL-LEX's SignDuration.
#include "stimuli/story/lexicon.hpp"
#include "stimuli/story/sign_notation.hpp"

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

// Every check of `sign` (a sign with a notation; none for a keyframe sign).
std::vector<NotationCheck> checkSignNotation(const LexiconSign& sign, const Lexicon& lexicon, const HandshapeLibrary& shapes,
                                             const hand::HandModel& model);

// "handshape open_b, OneHanded, Straight, Head/Chin, contact, repeated" for messages.
std::string describeAslLexCode(const AslLexCode& code);

}  // namespace signstim::stimuli
